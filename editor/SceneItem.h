#pragma once
// Names one thing of the scene that can be selected: its list and its index there.
// Plain data shared by the outliner, the properties panel and the select tool.

#include "simcore/scene/Scene.h"

#include <QString>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace throng::editor {

enum class ItemKind {
    Settings, AgentType, Group, Agent, Path, Wall, Obstacle, Goal, TrafficLight, Lane, FlowStroke, Hero, Brain,
    Crosswalk, Vehicle, ActionPoint, Source, Measurement, LayoutOp
};
// How many kinds there are (the last kind + 1).
inline constexpr int kItemKindCount = int(ItemKind::LayoutOp) + 1;

struct SceneItem {
    ItemKind kind = ItemKind::Settings;
    std::size_t index = 0;
    bool operator==(const SceneItem&) const = default;
};

using Selection = std::vector<SceneItem>;

// How many items of `kind` the scene holds (1 for Settings).
std::size_t itemCount(const sim::Scene& scene, ItemKind kind);
// What the outliner calls the item: its name, or "<Kind> <index + 1>" for unnamed ones.
QString itemLabel(const sim::Scene& scene, SceneItem item);
// The plural heading of a kind in the outliner ("Walls").
QString kindTitle(ItemKind kind);
// What a layout operation of `kind` is called in the editor ("Time offset").
QString layoutKindTitle(sim::LayoutKind kind);
// The item a diagnostic's key path names ("obstacles[3].radius" = obstacle 3); empty
// when the key names no item.
std::optional<SceneItem> itemForKey(const std::string& key);

}  // namespace throng::editor
