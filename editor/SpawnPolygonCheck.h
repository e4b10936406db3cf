#pragma once
// Whether corners drawn or typed in the editor make a polygon a spawn group can take
// (the scene reader's rules: 3 corners or more, an outline that does not cross itself,
// some area), as a sentence for the user. Never edits anything.

#include <glm/vec2.hpp>

#include <QString>

#include <span>

namespace throng::editor {

// Empty when the corners make a valid spawn polygon; else why not, and what to do.
QString spawnPolygonProblem(std::span<const glm::vec2> corners);

}  // namespace throng::editor
