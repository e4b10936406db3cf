#pragma once
// The timecode of a frame, as the timeline and the viewport's HUD show it: "HH:MM:SS:FF"
// at `fps` frames a second (FF counts whole frames of the nominal rate: no drop-frame).

#include <QString>

#include <cstddef>

namespace throng::editor {

QString timecode(std::size_t frame, double fps);

}  // namespace throng::editor
