#include "editor/DisplayCheck.h"

#include <QtGlobal>

namespace throng::editor {

QString missingDisplayReason()
{
    const QString platform = qEnvironmentVariable("QT_QPA_PLATFORM");
    if (platform.startsWith(QLatin1String("offscreen")) || platform.startsWith(QLatin1String("minimal")))
        return QStringLiteral("QT_QPA_PLATFORM=%1 has no OpenGL; unset it and run under a display "
                              "(xvfb-run -a throng ...)")
            .arg(platform);
    if (!platform.isEmpty())
        return {};
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
        return QStringLiteral("no display (neither DISPLAY nor WAYLAND_DISPLAY is set); on a headless "
                              "machine run under xvfb-run -a");
    return {};
}

}  // namespace throng::editor
