#pragma once
// Tells, before QApplication starts, whether this process can open OpenGL windows, so
// `throng` explains a missing display instead of aborting inside Qt. Reads only the
// environment.

#include <QString>

namespace throng::editor {

// Empty when a display looks usable; otherwise what is wrong and how to fix it.
QString missingDisplayReason();

}  // namespace throng::editor
