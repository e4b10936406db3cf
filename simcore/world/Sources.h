#pragma once
// The source phase (Scene.h, Source): agents that enter the scene during the run. When the
// World is built, every arrival of every source before the run's duration is worked out
// from the scene and the seed alone (its time, type, place and heading), and each becomes
// an agent of the World from the start, waiting off stage: out and stopped (never
// simulated or perceived) and not present in the frames. At the start of each step, the
// phase lets in those whose time has come, in time order, where their body fits: one
// whose place another body still covers waits there, and the ones after it from the same
// source wait behind it, so a stream backs up when its street does instead of piling
// bodies on top of each other. Serial and in a fixed order: the same for any thread count.

#include "simcore/scene/Scene.h"
#include "simcore/world/AgentColumns.h"
#include "simcore/world/NeighbourGrid.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace throng::sim {

struct SourceArrival {
    double timeS = 0.0;        // when it is due, s from the start
    std::uint32_t source = 0;  // index into Scene::sources
    std::uint16_t type = 0;    // index into Scene::agentTypes
    glm::vec2 place{0.0f};     // where it enters (x, z)
    float headingRad = 0.0f;   // counter-clockwise seen from above, 0 = +x
};

// Every arrival of source `s` (index into scene.sources) within its windows and the
// scene's duration, in time order, up to its cap. Types, places and Poisson gaps are
// seeded by (seed, source, arrival), so editing one source never moves another's.
std::vector<SourceArrival> sourceArrivals(const Scene& scene, std::size_t s, std::uint64_t seed);
// How many agents each source lets in over the run (sourceArrivals' sizes).
std::vector<std::uint32_t> sourceCounts(const Scene& scene, std::uint64_t seed);

class SourcePhase {
public:
    // The off-stage agents: dense index, due time and source of each.
    void build(std::vector<std::uint32_t> agents, std::vector<double> timesS, std::vector<std::uint32_t> sources);
    // Puts every one of them off stage (out and stopped too), as at the start.
    void sendOffstage(AgentColumns& agents) const;
    // Lets in the agents due by timeS (the step's start) whose body fits where they enter,
    // each at rest facing its heading; returns how many entered. `grid` indexes the agents'
    // current positions (those in the scene), whose bodies are at most largestRadiusM.
    // `entered`, when given, gets their dense indices.
    std::size_t enter(double timeS, AgentColumns& agents, const NeighbourGrid& grid, float largestRadiusM,
                      std::vector<std::uint32_t>* entered = nullptr);
    // Agents the sources will let in over the run, and how many are still off stage.
    std::size_t scheduled() const { return m_agent.size(); }
    std::size_t offstage(const AgentColumns& agents) const;
    // After a checkpoint is put back: agents let in later may be off stage again.
    void rewind() { m_done = 0; }

private:
    // No body in the scene (those in the grid, and those let in by this call so far)
    // overlaps agent i's where it enters.
    bool fits(std::size_t i, const AgentColumns& agents, const NeighbourGrid& grid, float largestRadiusM) const;

    std::vector<std::uint32_t> m_agent;   // dense index, in (time, index) order
    std::vector<double> m_timeS;          // due time, same order
    std::vector<std::uint32_t> m_source;  // source, same order
    std::vector<std::uint8_t> m_blocked;  // per source, scratch for one call of enter
    std::vector<std::uint32_t> m_enteredNow;  // scratch for one call of enter: not in the grid yet
    std::size_t m_done = 0;               // m_agent[0, m_done) have all entered
};

}  // namespace throng::sim
