#pragma once
// The `throng` command line: open the editor on an optional scene, or render a scene to
// an image with --screenshot. Parses and explains usage; runs nothing itself.

#include "editor/viewport/CameraRig.h"

#include <QSize>
#include <QString>
#include <QStringList>

namespace throng::editor {

struct ScreenshotOptions {
    QString outputPath;             // image to write; the format follows the suffix (.png)
    QString scenePath;
    int frame = 0;                  // simulation steps before the picture, >= 0
    QSize sizePx{1280, 720};
    ViewMode view = ViewMode::Top;
};

struct EditorArguments {
    enum class Mode { Editor, Screenshot, Help };
    Mode mode = Mode::Editor;
    QString scenePath;              // Editor: the scene to open, may be empty
    ScreenshotOptions screenshot;   // Screenshot only
    QString error;                  // non-empty: the command line is wrong, say this and exit 2

    // `args` excludes the program name.
    static EditorArguments parse(const QStringList& args);
    static QString usage();
};

}  // namespace throng::editor
