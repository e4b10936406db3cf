#pragma once
// The brain phase of a World: compiles each agent type's brain once (and the brains
// placed agents carry of their own), fills the sensor columns its program reads from the
// previous state, evaluates it for all its agents each step before steering, and takes up
// the choices that are the agent's own state (its goal, its action). The steering phases
// then ask it how a brain changes an agent's steering: the weight of each behaviour, a
// turn, a speed cap, the clip. Reads the World through a StepView; each method names the
// agent columns it writes (WorldBrain.cpp, WorldBrainSense.cpp).

#include "simcore/steering/Neighbour.h"
#include "simcore/world/AgentColumns.h"
#include "simcore/world/FrameCache.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace throng::sim {

class BrainEvaluator;
enum class Behaviour : std::uint8_t;
struct Scene;
struct StepView;
struct WorldTraffic;

namespace detail {
struct TypeBrain;
struct WorldBrains;
}  // namespace detail

class BrainPhase {
public:
    // Compiles the scene's brains for the World's agents (v.agents); no runtime at all
    // when no type or placed agent has a brain.
    void build(const Scene& scene, const StepView& v);
    bool active() const { return m_brains != nullptr; }

    // The step: sense, evaluate, and take up each agent's new goal (writes agents' goal,
    // goalSpot and, for the types whose sensors need them, nearIndex and nearCount) and
    // the speeds brain-driven vehicles ask the traffic for.
    void run(const StepView& v, AgentColumns& agents, WorldTraffic& traffic);

    // What a brain changes in agent i's steering; each is the identity for an agent that
    // runs no brain. Whether the brain's sense phase of this step gathered its neighbours
    // (in agents.nearIndex).
    bool gatheredNeighbours(std::size_t i) const;
    // m/s: its max speed, or less where its brain asks.
    float speedCap(const StepView& v, std::size_t i) const;
    // The brain's speed as a cap on agent i's next velocity; its next position, reached
    // from `from` (where it stood at the step's start), moves with it.
    void capToSpeed(const StepView& v, std::size_t i, glm::vec3 from, glm::vec3& position, glm::vec3& velocity) const;
    // A move `move` over `seconds` kept within the brain's speed: along the way a walker
    // wants to go at most that, sideways and back at most `aside` (m/s).
    glm::vec3 limited(const StepView& v, std::size_t i, glm::vec3 move, float aside, float seconds) const;
    // Multiplies the type's weight of behaviour b.
    float weight(std::size_t i, Behaviour b) const;
    // Agent i's brain looked up once, for a caller that reads several of its answers (the
    // walker kernel): row(i).weight(b) is weight(i, b), row(i).turnForce(...) is
    // turnForce(i, ...), row(i).gathered() is gatheredNeighbours(i).
    struct Row {
        const float* const* weights = nullptr;  // per behaviour: its brain's column, or null
        const float* turn = nullptr;            // degrees/s, or null
        const float* speed = nullptr;           // m/s, or null
        std::int32_t local = -1;                // the agent's row in them; -1: no brain
        bool gathers = false;                   // its senses gathered its neighbours this step

        bool gathered() const { return local >= 0 && gathers; }
        float weight(Behaviour b) const
        {
            if (local < 0)
                return 1.0f;
            const float* w = weights[std::size_t(b)];
            return w ? std::max(0.0f, w[local]) : 1.0f;
        }
        // Turn (degrees/s, + = left) as a sideways force: the centripetal acceleration v·ω
        // of a turn at that rate, toward the agent's left.
        glm::vec3 turnForce(glm::vec3 forward, glm::vec3 velocity, float mass) const
        {
            if (local < 0 || !turn)
                return glm::vec3(0.0f);
            const float omega = glm::radians(turn[local]);
            const glm::vec3 left(forward.z, 0.0f, -forward.x);
            return left * (omega * std::max(glm::length(velocity), 0.1f) * mass);
        }
    };
    Row row(std::size_t i) const;
    // capToSpeed with agent i's row looked up already.
    void capToSpeed(const StepView& v, const Row& row, std::size_t i, glm::vec3 from, glm::vec3& position,
                    glm::vec3& velocity) const;
    // The brain's turn (degrees/s) as a sideways force on agent i, of that heading,
    // velocity and mass at the step's start.
    glm::vec3 turnForce(std::size_t i, glm::vec3 forward, glm::vec3 velocity, float mass) const;
    // The clip of the action the brain chose, else `bySpeed`.
    Clip clip(std::size_t i, Clip bySpeed) const;

    // For the World's facade (World.h documents them).
    int action(std::size_t i) const;
    std::string actionName(std::size_t i) const;
    const std::vector<std::string>& errors() const;
    const BrainEvaluator* evaluator(std::size_t typeIndex) const;
    const BrainEvaluator* agentEvaluator(std::size_t i) const;
    void pickAgent(std::ptrdiff_t i, std::size_t agentCount);

    // The runtime, for saving and restoring its state (WorldState.cpp); null when inactive.
    detail::WorldBrains* runtime() { return m_brains.get(); }
    const detail::WorldBrains* runtime() const { return m_brains.get(); }

private:
    // speedCap with agent i's row looked up already.
    float speedCap(const StepView& v, const Row& row, std::size_t i) const;
    // Fills the sensor columns of one batch of agents (WorldBrainSense.cpp).
    void sense(const StepView& v, AgentColumns& agents, detail::TypeBrain& brain) const;

    std::shared_ptr<detail::WorldBrains> m_brains;  // null when no type has a brain
};

}  // namespace throng::sim
