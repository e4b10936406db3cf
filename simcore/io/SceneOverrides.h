#pragma once
// Scene values set from the command line (throng-cli run --set, and every variant of a
// wedge): `KEY=VALUE`, KEY a path into the scene file's YAML, VALUE any YAML. Each segment
// of the path names a map's key or, in a list, the item with that `name` (or at that
// index): `settings.seed=7`, `agent_types.walker.max_speed=1.2`, `groups.crowd.count=500`,
// `agent_types.walker.variation.speed=[0.9, 1.1]`. The scene is then read as if the file
// said so, with every check of the format.

#include "simcore/io/SceneIO.h"

#include <optional>
#include <span>
#include <string>

namespace throng::sim {

struct SceneOverride {
    std::string key;    // "agent_types.walker.max_speed"
    std::string value;  // "1.2"
    bool operator==(const SceneOverride&) const = default;
};

// "KEY=VALUE" as an override; nullopt with `error` set when it has no '=' or an empty key
// or segment.
std::optional<SceneOverride> parseOverride(const std::string& text, std::string& error);

// loadScene with `overrides` applied, in order, before the scene is read. A key that leads
// nowhere (no such item in a list, a value where a map should be), a VALUE that is not
// YAML, and a key the format does not know are errors naming the `--set`; a value the
// format refuses is its usual error, said to come with the overrides.
LoadResult loadScene(const std::string& path, std::span<const SceneOverride> overrides);

}  // namespace throng::sim
