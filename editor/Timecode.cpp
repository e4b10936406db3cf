#include "editor/Timecode.h"

#include <algorithm>
#include <cmath>

namespace throng::editor {

QString timecode(std::size_t frame, double fps)
{
    const std::size_t perSecond = std::max<std::size_t>(1, std::size_t(std::lround(fps)));
    const std::size_t seconds = frame / perSecond;
    auto two = [](std::size_t n) { return QString::number(n).rightJustified(2, '0'); };
    return QStringLiteral("%1:%2:%3:%4")
        .arg(two(seconds / 3600), two(seconds / 60 % 60), two(seconds % 60), two(frame % perSecond));
}

}  // namespace throng::editor
