#pragma once
// Built-in benchmark scenes, generated from a few numbers so the CLI, bench/ and the
// tests measure the same thing. Plain scenes: they go through the same World as files.

#include "simcore/scene/Scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace throng::sim {

// `cross`: agents on circles walk to the antipodal point through the centre (the classic
// avoidance test, RVO2's Circle example), many circles at once: concentric rings
// `ringGapM` apart, from `innerRadiusM` outwards, each filled with agents `spacingM` apart
// along it, so the rings reach the centre one after another, like circles started one
// after another. More agents = more rings further out. Every agent crosses the centre
// region and meets those of the rings inside it on their way out; the spacing leaves room
// to walk between those that have arrived (they stand still on their goals, which are the
// other agents' starts). The DetourCrowd peer gets the same agents and goals
// (bench/compare-detourcrowd.sh, bench/peers).
struct CrossLayout {
    float innerRadiusM = 30.0f;  // radius of the innermost ring
    float ringGapM = 6.0f;       // between rings
    float spacingM = 3.0f;       // between neighbours on a ring
    float agentRadiusM = 0.5f;   // DetourCrowd's default
    float speed = 1.4f;          // m/s
};
Scene makeCrossScenario(std::uint32_t agents, std::uint64_t seed = 1, const CrossLayout& layout = {});
// `cross-brain`: `cross`, every walker running the 40-node pedestrian brain
// (benchPedestrianBrain, BenchBrains.h) on top of its steering and reciprocal avoidance.
Scene makeCrossBrainScenario(std::uint32_t agents, std::uint64_t seed = 1);
// One line naming the layout's numbers, for the bench JSON.
std::string crossLayoutDescription(const CrossLayout& layout = {});
// `flock`: 3D boids migrating around a closed circuit. They start on a lattice, numbered
// along x, then up, then along z (RowByRow, the scenario), or up each column first
// (ByColumn): the order the World's neighbour grid visits them in, cell by cell. Each bird
// keeps its id, place and heading either way, so the two differ only in the order the World
// stores them in (exactly, when `agents` is a cube; else the lattice's last points differ).
enum class FlockNumbering { RowByRow, ByColumn };
Scene makeFlockScenario(std::uint32_t agents, std::uint64_t seed = 1,
                        FlockNumbering numbering = FlockNumbering::RowByRow);
// `army`: two masses charge each other across a field.
Scene makeArmyScenario(std::uint32_t agents, std::uint64_t seed = 1);
// `corridor`: two groups walk in opposite directions between two long walls.
Scene makeCorridorScenario(std::uint32_t agents, std::uint64_t seed = 1);

const std::vector<std::string>& benchScenarioNames();
// Builds the named scenario; false when the name is unknown.
bool makeBenchScenario(const std::string& name, std::uint32_t agents, Scene& out);

}  // namespace throng::sim
