#pragma once
// What the World senses and decides for one agent, published for drawing: the classic
// steering annotations of Reynolds (1999) and OpenSteer (view cone, neighbours, each
// behaviour's force and their blend, feelers, the planned way, the field it follows and
// where it steers). The World publishes to a sink only for the agents it is asked about
// (World::describeAgent), never for the whole crowd and never from inside the step.
// Qt-free; the editor draws what a DebugRecorder kept.
//
// Positions are in the World's coordinates (relative to World::origin, as its frames are).

#include "simcore/world/FrameCache.h"
#include "simcore/world/TypeSteering.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace throng::sim {

class DebugSink {
public:
    virtual ~DebugSink() = default;
    // The agent the calls that follow describe, where it stands and how it moves.
    virtual void agent(AgentId id, glm::vec3 position, glm::vec3 forward, glm::vec3 velocity, float radiusM) = 0;
    // Its perception: neighbours within rangeM and inside the cone of full angle
    // viewAngleRad about its forward direction (2 pi = all round).
    virtual void viewCone(float rangeM, float viewAngleRad) = 0;
    // A neighbour it sensed at the last step.
    virtual void neighbour(AgentId other, glm::vec3 position) = 0;
    // One behaviour's force (N) and the weight the blend gives it.
    virtual void force(Behaviour behaviour, glm::vec3 force, float weight) = 0;
    // The steering force the behaviours combine to (N), before avoidance and limits.
    virtual void steering(glm::vec3 force) = 0;
    // A feeler probing for walls or obstacles ahead, from the body to its tip.
    virtual void feeler(glm::vec3 from, glm::vec3 to) = 0;
    // The way it plans to walk from where it stands (A* waypoints or its path), in order.
    virtual void plannedPath(std::span<const glm::vec3> points) = 0;
    // Where it steers this step (its goal spot, its next waypoint or the field's way).
    virtual void target(glm::vec3 point) = 0;
    // One sample of the field it follows (its goal's navigation flow field, or the scene's
    // flow strokes), on a square of kFieldSamples x kFieldSamples points about it: the
    // unit direction of travel there, or zero where the field gives none (a wall, an
    // unreachable cell, no stroke near).
    virtual void field(glm::vec3 at, glm::vec3 direction) = 0;
};

// The field's samples on each side of the agent make a square of this many points a side,
// one navigation cell apart for a flow field and kFlowSampleStepM apart for the strokes.
inline constexpr int kFieldSamples = 5;
inline constexpr float kFlowSampleStepM = 1.0f;

// One agent's annotations as plain data, for drawing on another thread.
struct AgentDebug {
    AgentId id = 0;
    glm::vec3 position{0.0f}, forward{1.0f, 0.0f, 0.0f}, velocity{0.0f};
    float radiusM = 0.0f;
    float rangeM = 0.0f, viewAngleRad = 0.0f;
    struct Seen {
        AgentId id;
        glm::vec3 position;
    };
    std::vector<Seen> neighbours;
    struct Force {
        Behaviour behaviour;
        glm::vec3 force;
        float weight;
    };
    std::vector<Force> forces;
    glm::vec3 steering{0.0f};
    struct Feeler {
        glm::vec3 from, to;
    };
    std::vector<Feeler> feelers;
    std::vector<glm::vec3> path;
    bool hasTarget = false;
    glm::vec3 target{0.0f};
    struct FieldSample {
        glm::vec3 at, direction;
    };
    std::vector<FieldSample> field;
};

// A sink that keeps what it is told, one AgentDebug per agent() call.
class DebugRecorder final : public DebugSink {
public:
    std::vector<AgentDebug>& agents() { return m_agents; }
    const std::vector<AgentDebug>& agents() const { return m_agents; }

    void agent(AgentId id, glm::vec3 position, glm::vec3 forward, glm::vec3 velocity, float radiusM) override;
    void viewCone(float rangeM, float viewAngleRad) override;
    void neighbour(AgentId other, glm::vec3 position) override;
    void force(Behaviour behaviour, glm::vec3 force, float weight) override;
    void steering(glm::vec3 force) override;
    void feeler(glm::vec3 from, glm::vec3 to) override;
    void plannedPath(std::span<const glm::vec3> points) override;
    void target(glm::vec3 point) override;
    void field(glm::vec3 at, glm::vec3 direction) override;

private:
    AgentDebug& current();
    std::vector<AgentDebug> m_agents;
};

}  // namespace throng::sim
