#include "editor/EditorArguments.h"

#include <QRegularExpression>

namespace throng::editor {

namespace {

constexpr int kMinSidePx = 16;
constexpr int kMaxSidePx = 16384;

// Reads the value after an option, advancing `i`; empty with `error` set when missing.
QString takeValue(const QStringList& args, qsizetype& i, QString& error)
{
    if (i + 1 >= args.size()) {
        error = QStringLiteral("%1 needs a value").arg(args[i]);
        return {};
    }
    return args[++i];
}

}  // namespace

QString EditorArguments::usage()
{
    return QStringLiteral(
        "usage: throng [SCENE.yaml]\n"
        "       throng --screenshot OUT.png SCENE.yaml [--frame N] [--size WxH] [--camera top|persp]\n"
        "\n"
        "  --screenshot OUT.png  render the scene to an image and exit (needs a display: xvfb-run -a)\n"
        "  --frame N             simulate N steps first (default 0, the initial state)\n"
        "  --size WxH            image size in pixels (default 1280x720)\n"
        "  --camera top|persp    top orthographic view (default) or the perspective view\n"
        "                        (also --view top|3d)\n"
        "  -h, --help            show this help\n");
}

EditorArguments EditorArguments::parse(const QStringList& args)
{
    EditorArguments a;
    if (args.contains("-h") || args.contains("--help")) {
        a.mode = Mode::Help;
        return a;
    }
    QStringList positional;
    bool screenshotOnly = false;  // an option that means nothing without --screenshot
    for (qsizetype i = 0; i < args.size() && a.error.isEmpty(); ++i) {
        const QString& arg = args[i];
        if (arg == "--screenshot") {
            a.mode = Mode::Screenshot;
            a.screenshot.outputPath = takeValue(args, i, a.error);
        } else if (arg == "--frame") {
            screenshotOnly = true;
            bool ok = false;
            const QString value = takeValue(args, i, a.error);
            a.screenshot.frame = value.toInt(&ok);
            if (a.error.isEmpty() && (!ok || a.screenshot.frame < 0))
                a.error = QStringLiteral("--frame needs a whole number >= 0, got '%1'").arg(value);
        } else if (arg == "--size") {
            screenshotOnly = true;
            const QString value = takeValue(args, i, a.error);
            static const QRegularExpression kSize(QStringLiteral("^(\\d{1,5})x(\\d{1,5})$"));
            const QRegularExpressionMatch m = kSize.match(value);
            const int w = m.hasMatch() ? m.captured(1).toInt() : 0, h = m.hasMatch() ? m.captured(2).toInt() : 0;
            if (a.error.isEmpty() && (w < kMinSidePx || h < kMinSidePx || w > kMaxSidePx || h > kMaxSidePx))
                a.error = QStringLiteral("--size needs WxH with each side in %1..%2 pixels, got '%3'")
                              .arg(kMinSidePx)
                              .arg(kMaxSidePx)
                              .arg(value);
            a.screenshot.sizePx = {w, h};
        } else if (arg == "--view" || arg == "--camera") {
            // --camera top|persp is the spelling; --view top|3d the first one.
            screenshotOnly = true;
            const QString value = takeValue(args, i, a.error);
            if (value == "top")
                a.screenshot.view = ViewMode::Top;
            else if (value == "3d" || value == "persp")
                a.screenshot.view = ViewMode::Orbit;
            else if (a.error.isEmpty())
                a.error = QStringLiteral("%1 must be top, persp or 3d, got '%2'").arg(arg, value);
        } else if (arg.startsWith('-') && arg != "-") {
            a.error = QStringLiteral("unknown option '%1'").arg(arg);
        } else {
            positional << arg;
        }
    }
    if (!a.error.isEmpty())
        return a;
    if (positional.size() > 1)
        a.error = QStringLiteral("give one scene file, got %1: %2").arg(positional.size()).arg(positional.join(' '));
    else if (a.mode == Mode::Screenshot && positional.isEmpty())
        a.error = QStringLiteral("--screenshot needs a scene file");
    else if (a.mode == Mode::Editor && screenshotOnly)
        a.error = QStringLiteral("--frame, --size and --view go with --screenshot");
    if (!a.error.isEmpty())
        return a;
    const QString scene = positional.value(0);
    if (a.mode == Mode::Screenshot)
        a.screenshot.scenePath = scene;
    else
        a.scenePath = scene;
    return a;
}

}  // namespace throng::editor
