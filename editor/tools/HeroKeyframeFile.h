#pragma once
// Reads a hero's keyframe text file: one "x y z" line per frame (as Maya writes it),
// blank lines and '#' comments skipped. Reports the first bad line as file:line:col.
// Plain reading; edits nothing.

#include <glm/vec3.hpp>

#include <QString>

#include <vector>

namespace throng::editor {

struct KeyframeFileResult {
    std::vector<glm::vec3> positions;  // one per frame
    QString error;                     // "file:line:col: why"; empty when read
};

KeyframeFileResult readKeyframeFile(const QString& path);

}  // namespace throng::editor
