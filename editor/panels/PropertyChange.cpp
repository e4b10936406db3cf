#include "editor/panels/PropertyChange.h"

#include <QStringList>

namespace throng::editor {

namespace {

bool oneOf(const QString& key, const QStringList& keys)
{
    return keys.contains(key);
}

}  // namespace

SceneField propertyField(ItemKind kind, const QString& key)
{
    // A table's key carries a serial after a slash ("points/3"): the first part names it.
    const QString name = key.section('/', 0, 0);
    if (kind == ItemKind::Settings)
        return SceneField::Settings;
    if (name == "type" && kind != ItemKind::AgentType)
        return SceneField::Type;
    if (name == "brain")
        return SceneField::Brain;
    if (oneOf(name, {"goal", "path", "leader", "exits", "lane", "stopLines"}))
        return SceneField::Route;
    if (oneOf(name, {"x", "z", "points", "minX", "minZ", "maxX", "maxZ", "centreX", "centreZ", "fromX", "fromZ", "toX",
                     "toZ", "at"}))
        return SceneField::Position;
    switch (kind) {
    case ItemKind::Agent:
        if (name == "heading")
            return SceneField::Heading;
        if (name == "group")
            return SceneField::Group;
        if (oneOf(name, {"look", "tint", "heightScale"}))
            return SceneField::Look;
        break;
    case ItemKind::AgentType:
        if (oneOf(name, {"looks", "tints", "character", "heightMin", "heightMax"}))
            return SceneField::Look;
        break;
    case ItemKind::Group:
        if (oneOf(name, {"shape", "radius", "altitudeMin", "altitudeMax"}))
            return SceneField::Shape;
        break;
    case ItemKind::Path:
    case ItemKind::Obstacle:
    case ItemKind::FlowStroke:
    case ItemKind::Crosswalk:
    case ItemKind::Hero:
        // Their other numbers and switches are sizes: radius, clearance, closed, width, ...
        return SceneField::Shape;
    case ItemKind::Goal:
    case ItemKind::ActionPoint:
        if (oneOf(name, {"radius", "faces", "facing"}))
            return SceneField::Shape;
        break;
    case ItemKind::Source:
        if (name == "shape")
            return SceneField::Shape;
        break;
    case ItemKind::Lane:
        if (oneOf(name, {"width", "loop"}))
            return SceneField::Shape;
        break;
    default:
        break;
    }
    return SceneField::Parameters;
}

SceneChange propertyChange(ItemKind kind, const QString& key, std::vector<std::size_t> indices)
{
    return SceneChange::of(kind, std::move(indices), propertyField(kind, key));
}

}  // namespace throng::editor
