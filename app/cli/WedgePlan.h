#pragma once
// A wedge: one scene run with every combination of some values (--set KEY=V1,V2,...) for
// every seed of a range (--seeds A..B), each combination a variant with its own folder.
// Expands the variants and reads and writes the plan (DIR/wedge.yaml); runs nothing.

#include "simcore/io/SceneOverrides.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace throng::cli {

struct WedgeAxis {
    std::string key;                  // a scene key (SceneOverrides.h)
    std::vector<std::string> values;  // in the order given
};

struct WedgeVariant {
    std::size_t index = 0;
    std::string folder;                       // "v003", under the wedge's folder
    std::vector<sim::SceneOverride> overrides;  // one per axis
    std::optional<std::uint64_t> seed;        // none: the scene's own
};

struct WedgePlan {
    std::string scene;  // absolute path
    std::vector<WedgeAxis> axes;
    std::vector<std::uint64_t> seeds;  // empty: the scene's own
    std::vector<WedgeVariant> variants;
};

// "KEY=V1,V2,..." as an axis; commas inside [ ] or { } belong to a value. nullopt with
// `error` when it is not KEY=VALUES or a value is empty.
std::optional<WedgeAxis> parseAxis(const std::string& text, std::string& error);
// "A..B" (A <= B) or "A,B,C" as seeds; nullopt with `error` otherwise.
std::optional<std::vector<std::uint64_t>> parseSeeds(const std::string& text, std::string& error);

// Every combination of the axes' values (the first axis slowest), for every seed.
std::vector<WedgeVariant> expandVariants(const std::vector<WedgeAxis>& axes, const std::vector<std::uint64_t>& seeds);

// The plan as YAML text (wedge.yaml), and back; nullopt with `error` for text that is not
// one.
std::string planToYaml(const WedgePlan& plan);
std::optional<WedgePlan> planFromYaml(const std::string& text, std::string& error);

}  // namespace throng::cli
