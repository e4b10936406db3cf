#pragma once
// The move phase: steer, avoid, integrate and constrain, agent by agent. Each agent's next
// state comes from the old one through the general path (steer, Steer.h; then reciprocal
// avoidance, the vehicle model and the constraints), or through the walker kernel
// (WalkKernel.h) or the boids kernel (BoidKernel.h) for the types they run. It owns the
// kernels; it writes the agents' next state, their neighbours and held forces, and the
// traffic's signal state (WorldTraffic::obeySignal).

#include "simcore/world/AgentColumns.h"
#include "simcore/world/AgentTypes.h"
#include "simcore/world/BoidKernel.h"
#include "simcore/world/StaticSet.h"
#include "simcore/world/StepView.h"
#include "simcore/world/WalkKernel.h"

#include <cstddef>

namespace throng::sim {

class BrainPhase;
class WorldTraffic;

class MovePhase {
public:
    // Which kernels may run (WorldOptions: boidKernel, walkKernel, collideShortcut, steerEight).
    struct Kernels {
        bool boids = true, walkers = true, collideShortcut = true, steerEight = true;
    };
    // Which kernels the World allows: the boids kernel where it has no brains, layers,
    // priorities or signals; the walker kernel where it has no layers, priorities or
    // signals (it takes up brains' weights, turns and speeds).
    struct Plain {
        bool boids = true, walkers = true;
    };
    // Once per World, after its agents are added.
    void build(const AgentTypes& types, const StaticSet& set, float dt, std::size_t agents, const Plain& plain,
               const Kernels& kernels);
    // An agent added after build.
    void addAgent() { m_boids.addAgent(); }
    // One step: every agent's next state. hasStatics: walls or obstacles to constrain against.
    void run(const StepView& v, const BrainPhase& brains, WorldTraffic& traffic, AgentColumns& agents,
             bool hasStatics);

    const WalkKernel& walk() const { return m_walk; }
    const BoidKernel& boids() const { return m_boids; }
    // The boids' flags for the collide pass (BoidKernel::collideFree).
    BoidKernel& boids() { return m_boids; }

private:
    class Pass;
    WalkKernel m_walk;
    BoidKernel m_boids;
};

}  // namespace throng::sim
