#pragma once
// Built-in benchmark scenes, generated from a few numbers so the CLI, bench/ and the
// tests measure the same thing. Plain scenes: they go through the same World as files.

#include "simcore/scene/Scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace throng::sim {

// `cross`: agents on concentric rings walk to the antipodal point (the classic avoidance
// test), laid out like the DetourCrowd peer's `circle` scenario.
Scene makeCrossScenario(std::uint32_t agents, std::uint64_t seed = 1);
// `flock`: 3D boids migrating around a closed circuit.
Scene makeFlockScenario(std::uint32_t agents, std::uint64_t seed = 1);
// `army`: two masses charge each other across a field.
Scene makeArmyScenario(std::uint32_t agents, std::uint64_t seed = 1);
// `corridor`: two groups walk in opposite directions between two long walls.
Scene makeCorridorScenario(std::uint32_t agents, std::uint64_t seed = 1);

const std::vector<std::string>& benchScenarioNames();
// Builds the named scenario; false when the name is unknown.
bool makeBenchScenario(const std::string& name, std::uint32_t agents, Scene& out);

}  // namespace throng::sim
