#pragma once
// `throng --screenshot`: loads a scene, simulates the asked number of steps, renders the
// viewport offscreen framing the whole scene and writes the image. Reports through the
// given streams; never opens the editor window.

#include "editor/EditorArguments.h"

#include <iosfwd>

namespace throng::editor {

class ScreenshotCommand {
public:
    // `out` gets the written path, `err` every diagnostic and failure.
    ScreenshotCommand(ScreenshotOptions options, std::ostream& out, std::ostream& err);

    // Needs a QApplication on a display with OpenGL 3.3. Returns the exit status: 0 when
    // the image was written, 1 otherwise (scene errors as file:line:col: error: ...).
    int run();

private:
    ScreenshotOptions m_options;
    std::ostream& m_out;
    std::ostream& m_err;
};

}  // namespace throng::editor
