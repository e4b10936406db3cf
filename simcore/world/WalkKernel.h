#pragma once
// The walker kernel: one agent step (sense, steer, avoid, integrate, constrain) fused for
// a ground type whose behaviours are only arrival, seek, separation, unaligned collision
// avoidance, containment, wall following, obstacle avoidance, wander and reciprocal
// avoidance (those of `cross`, `corridor` and of an ordinary crowd). It owns which types
// it runs and their constants; the agents' state it reads from the step's view and
// writes only agent i's next state, neighbours and held force.

#include "simcore/world/AgentColumns.h"
#include "simcore/world/AgentTypes.h"
#include "simcore/world/StaticSet.h"
#include "simcore/world/StepView.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace throng::sim {

class BrainPhase;

class WalkKernel {
public:
    // Which types step through the kernel and their constants, once per World. `plain`:
    // the World has no layers, priorities or signals (those keep the general path; its
    // agents' brains the kernel takes up); dt: the step's length, s.
    void build(const AgentTypes& types, const StaticSet& set, float dt, bool enabled, bool plain);
    // Walkers of this type without a path step through the kernel.
    bool runs(std::size_t typeIndex) const { return m_runs[typeIndex] != 0; }
    // Agent i's next state from the old one (WalkKernel.cpp).
    void step(const StepView& v, const BrainPhase& brains, AgentColumns& agents, std::size_t i) const;

private:
    // step, for a World with brains (kBrain) and with ids out of index order (kWatch).
    template <bool kBrain, bool kWatch>
    void stepAgent(const StepView& v, const BrainPhase& brains, AgentColumns& agents, std::size_t i) const;
    // Per type, the kernel's parameters made usable once.
    struct WalkType {
        float wContainment, wSeparation, wUnaligned, wArrival, wSeek, wWander;
        bool reciprocal;
        float keepRight;     // as AgentTypes::keepRight
        bool aroundStatics;  // wall following or obstacle avoidance, and walls or obstacles to steer round
        bool constrained;    // walls or circles to hold the body out of (constrain, Constraints.h)
        float maxForce, range, damping, horizonS, marginM, brake;
        float gainArrival, gainSeek, dtOverMass;
    };
    std::vector<std::uint8_t> m_runs;  // per type
    std::vector<WalkType> m_walkTypes;
};

}  // namespace throng::sim
