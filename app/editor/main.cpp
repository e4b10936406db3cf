// throng: opens the editor, or renders a scene with --screenshot (EditorArguments).
#include "editor/DarkTheme.h"
#include "editor/DisplayCheck.h"
#include "editor/EditorArguments.h"
#include "editor/MainWindow.h"
#include "editor/ScreenshotCommand.h"
#include "editor/viewport/Viewport.h"

#include <QApplication>
#include <QSurfaceFormat>

#include <iostream>

int main(int argc, char** argv)
{
    using namespace throng::editor;
    QStringList args;
    for (int i = 1; i < argc; ++i)
        args << QString::fromLocal8Bit(argv[i]);
    const EditorArguments parsed = EditorArguments::parse(args);
    if (!parsed.error.isEmpty()) {
        std::cerr << "throng: " << parsed.error.toStdString() << "\n\n" << EditorArguments::usage().toStdString();
        return 2;
    }
    if (parsed.mode == EditorArguments::Mode::Help) {
        std::cout << EditorArguments::usage().toStdString();
        return 0;
    }
    if (const QString problem = missingDisplayReason(); !problem.isEmpty()) {
        std::cerr << "throng: error: " << problem.toStdString() << '\n';
        return 1;
    }

    QSurfaceFormat::setDefaultFormat(Viewport::surfaceFormat());
    QApplication app(argc, argv);
    QApplication::setOrganizationName("Throng");
    QApplication::setApplicationName("Throng");
    applyDarkTheme(app);
    if (parsed.mode == EditorArguments::Mode::Screenshot)
        return ScreenshotCommand(parsed.screenshot, std::cout, std::cerr).run();

    MainWindow window;
    window.show();
    // Changes a crash left behind come first; the scene named on the command line otherwise.
    if (!window.offerRecovery() && !parsed.scenePath.isEmpty())
        window.openScene(parsed.scenePath);
    return QApplication::exec();
}
