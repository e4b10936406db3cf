#include "editor/SpawnPolygonCheck.h"

#include "simcore/scene/GroundPolygon.h"

#include <QCoreApplication>

namespace throng::editor {

namespace {
QString tr(const char* text)
{
    return QCoreApplication::translate("SpawnPolygonCheck", text);
}
constexpr double kMinAreaM2 = 1e-6;  // the reader's: under a square millimetre is no area
}  // namespace

QString spawnPolygonProblem(std::span<const glm::vec2> corners)
{
    if (corners.size() < 3)
        return tr("A polygon needs at least 3 corners (it has %1).").arg(corners.size());
    if (const auto crossing = sim::polygonSelfCrossing(corners))
        return tr("The polygon crosses itself (its edges from corner %1 and from corner %2 meet): "
                  "move or remove a corner.")
            .arg(crossing->first + 1)
            .arg(crossing->second + 1);
    if (sim::polygonArea(corners) < kMinAreaM2)
        return tr("The polygon has no area: its corners lie on one line.");
    return {};
}

}  // namespace throng::editor
