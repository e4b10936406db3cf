#pragma once
// The runtime of a scene: one array per agent attribute, advanced by fixed steps.
// Reads only the previous state within a step, so results do not depend on the thread
// count. Never reads a clock, never allocates inside step(), never draws.

#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/NeighbourGrid.h"
#include "simcore/world/SegmentGrid.h"
#include "simcore/world/StepCounters.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace throng::sim {

struct WorldOptions {
    std::uint64_t seed = 0;     // 0 = the scene's seed
    bool overrideSeed = false;
    int threads = 0;            // 0 = OpenMP's default
};

class World {
public:
    // Builds the runtime from a validated scene: placed agents, spawned groups (seeded),
    // goals and paths resolved to indices, walls and obstacles into lookup structures.
    World(const Scene& scene, const WorldOptions& options = {});

    // Advances exactly one fixed step of 1 / fps seconds.
    void step();

    std::size_t agentCount() const { return m_pos.size(); }
    std::uint64_t stepIndex() const { return m_step; }
    float dt() const { return m_dt; }
    double timeS() const { return double(m_step) * m_dt; }
    std::uint64_t seed() const { return m_seed; }
    int threads() const { return m_threads; }

    std::span<const glm::vec3> positions() const { return m_pos; }
    std::span<const glm::vec3> velocities() const { return m_vel; }
    std::span<const glm::vec3> forwards() const { return m_fwd; }
    std::span<const float> radii() const { return m_radius; }
    AgentId id(std::size_t i) const { return m_info[i].id; }
    const std::vector<AgentInfo>& agentInfo() const { return m_info; }
    bool hasArrived(std::size_t i) const { return m_arrived[i] != 0; }
    // Agents with a goal or an open path to finish.
    std::size_t agentsWithGoal() const;

    // The current state as one frame for the cache.
    void snapshot(std::vector<AgentFrame>& out) const;
    // Starts `cache` for this world's agents and records the current state as frame 0.
    void startRecording(FrameCache& cache) const;
    // Running totals of the quality figures since construction.
    const StepCounters& counters() const { return m_counters; }

    // Light state of a traffic light at the current time: 0 green, 1 yellow, 2 red.
    int lightState(std::size_t light) const;

private:
    void buildAgents(const Scene& scene);
    void spawnGroup(const Scene& scene, const SpawnGroup& group, std::size_t groupIndex);
    void addAgent(const Scene& scene, AgentId id, std::uint16_t type, glm::vec3 pos, float headingRad,
                  int goal, int path);
    glm::vec3 desiredVelocity(std::size_t i) const;
    void constrain(std::size_t i, glm::vec3 from, glm::vec3& to) const;
    void countStep();

    // Per-type constants (index = AgentInfo::typeIndex).
    struct TypeParams {
        float radius, maxSpeed, maxForce, mass, perception;
        AgentKind kind;
        float separation;  // weight of separation, 0 = off
    };
    std::vector<TypeParams> m_types;
    struct CircleObstacle { glm::vec2 c; float r; };
    SegmentGrid m_walls;  // walls and the 4 sides of box obstacles
    std::vector<CircleObstacle> m_circles;
    std::vector<Goal> m_goals;
    std::vector<Path> m_paths;
    std::vector<TrafficLight> m_lights;
    struct CrosswalkBox { glm::vec2 a, b; float halfWidth; int light; };  // light -1 = uncontrolled
    std::vector<CrosswalkBox> m_crosswalks;

    // Structure of arrays, dense agent index.
    std::vector<AgentInfo> m_info;
    std::vector<glm::vec3> m_pos, m_vel, m_fwd;
    std::vector<glm::vec3> m_nextPos, m_nextVel;
    std::vector<float> m_radius, m_speedFactor, m_phase, m_stride;
    std::vector<int> m_goal, m_path, m_waypoint;
    std::vector<std::uint8_t> m_arrived, m_onCrosswalk;

    NeighbourGrid m_grid;
    StepCounters m_counters;
    std::uint64_t m_seed = 1;
    std::uint64_t m_step = 0;
    float m_dt = 1.0f / 24.0f;
    int m_threads = 1;
};

}  // namespace throng::sim
