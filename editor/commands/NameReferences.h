#pragma once
// Who refers to a scene item by its name (a group following a path, a vehicle on a lane,
// an agent of a type) or by its agent id (a leader). Plain functions over the scene,
// shared by renames (which rewrite the references) and deletes (which refuse or clear).

#include "editor/SceneChange.h"
#include "editor/SceneItem.h"

#include <QString>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace throng::editor {

// One reference to a name: where the referring string lives and who holds it.
struct NameUse {
    std::function<std::string&(sim::Scene&)> locate;
    std::optional<SceneItem> user;  // empty for things the outliner does not list
    QString who;                    // "group nw_walkers", "vehicle 3"
};

// True for the kinds whose items carry a `name` the editor can rename.
bool hasName(ItemKind kind);
// The name of `item` (kinds with hasName() only).
std::function<std::string&(sim::Scene&)> nameLocate(SceneItem item);
std::string nameOf(const sim::Scene& scene, SceneItem item);
// The names every item of `kind` carries, in scene order.
std::vector<std::string> namesOf(const sim::Scene& scene, ItemKind kind);
// Every reference to `name` as an item of `kind` (types, brains, paths, goals, lanes,
// crosswalks).
std::vector<NameUse> nameUses(const sim::Scene& scene, ItemKind kind, const std::string& name);

// A rename of `item` that rewrites `uses` (its references) too: the item's name and, in
// each user, the field that names it (a group's path is its route, an agent's type its
// type). The simulation reads it when it reads the name or a reference changes.
SceneChange renameChange(SceneItem item, const std::vector<NameUse>& uses);

// One reference to an agent id (a `leader`): the agents and groups that follow it.
struct LeaderUse {
    std::function<std::uint32_t&(sim::Scene&)> locate;
    SceneItem user;
};
std::vector<LeaderUse> leaderUses(const sim::Scene& scene, std::uint32_t id);

}  // namespace throng::editor
