#pragma once
// The boids kernel: one agent step (sense, steer, integrate) fused for a flier type whose
// behaviours are only separation, alignment, cohesion, pursuit, containment and wander
// (Reynolds 1987). BoidKernel owns which types it runs, their constants and the collide
// pass's per-boid flag; a BoidPass is one thread's run of boid steps over the step's view
// (BoidKernel.cpp senses, BoidKernelSense.cpp senses four at once, BoidKernelLanes.cpp
// steers one, four or eight at once). A pass writes only its boids' next state, their
// neighbours and their flags.

#include "simcore/world/AgentColumns.h"
#include "simcore/world/AgentTypes.h"
#include "simcore/world/NearestList.h"
#include "simcore/world/NeighbourGrid.h"
#include "simcore/world/StaticSet.h"
#include "simcore/world/StepClock.h"
#include "simcore/world/StepView.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace throng::sim {

class BoidKernel {
public:
    // Which types step through the kernel and their constants, once per World. `plain`:
    // the World has no brains, layers, priorities or signals (those keep the general
    // path). collideShortcut: the collide pass may trust the kernel's flags (slackM);
    // steerEight: eight boids at a time where the CPU can (canSteerEight).
    void build(const AgentTypes& types, float dt, std::size_t agents, bool enabled, bool plain, bool collideShortcut,
               bool steerEight);
    bool runs(std::size_t typeIndex) const { return m_runs[typeIndex] != 0; }
    // How many boids it steers at once: 8 where the CPU has AVX2 and build asked for it, else 4.
    int lanes() const { return m_steerEight ? 8 : 4; }
    static bool canSteerEight();
    // An agent added after build.
    void addAgent() { m_collideFree.push_back(0); }
    // Per agent, written by a pass: kCollideFree (Collide.h) when none of its k nearest can
    // be within contact distance after the step, provided every agent's next position lies
    // within slackM() of where its old velocity would take it (the collide phase checks).
    std::vector<std::uint8_t>& collideFree() { return m_collideFree; }
    float slackM() const { return m_slackM; }

private:
    friend class BoidPass;
    // Per type, the parameters made usable once: weights (0 = off), gains = mass /
    // response time, lengths in m.
    struct BoidType {
        float wContainment, wSeparation, wPursuit, wAlignment, wCohesion, wWander;
        float mass, maxForce, range, damping;
        float gainPursuit, gainAlignment, gainCohesion, gainWander;
        float predictionCapS, slowingM, jitterM, wanderRadiusM, wanderDistanceM;
        float minSpeed, bankGain, bankBlend;
    };
    std::vector<std::uint8_t> m_runs;  // per type
    std::vector<BoidType> m_boidTypes;
    std::vector<std::uint8_t> m_collideFree;
    float m_slackM = 0.0f;
    bool m_steerEight = false;
};

// One thread's boid steps in a step: the kernel's two halves over the step's view. The
// names of what it reads are the World's, so the kernel reads as it did there.
class BoidPass {
public:
    BoidPass(BoidKernel& kernel, const StepView& v, AgentColumns& agents);

    // Boid i's next state from the old one. sweep: the thread's cursor when boids are
    // stepped in the grid's order, else null.
    void stepBoid(std::size_t i, NeighbourGrid::Sweep* sweep);
    // What a boid's sense hands its steering (stepBoid in two halves, senseBoid finds the
    // k nearest and sums over them, the branchy part; steerBoid steers and integrates,
    // chains of square roots and divisions, few branches). The move phase (MovePhase.cpp)
    // runs them over batches of boids, one half after the other: the same arithmetic,
    // about 5 % faster than boid by boid, and the steering then goes four or eight at once.
    struct BoidSense {
        glm::vec3 push, headings, velocities, centre;
        std::uint32_t count;
        // Where each neighbour's old velocity takes it (x, y and z apart, so the check of
        // a boid's next position against all of them is one vector's), and how close it
        // may come.
        float driftX[kMaxNeighbours], driftY[kMaxNeighbours], driftZ[kMaxNeighbours];
        float keepOut[kMaxNeighbours];
    };
    // senseBoid for boid[0, count), up to four consecutive boids of the grid's order in one
    // cell, searched together (BoidKernelSense.cpp).
    void senseFourBoids(const std::uint32_t* boid, int count, NeighbourGrid::Sweep& sweep, BoidSense* out);
    // steerBoid for boid[0, count), eight or four at a time where it can.
    void steerBoids(const std::uint32_t* boid, const BoidSense* sensed, std::size_t count);

private:
    using BoidType = BoidKernel::BoidType;
    using BoidNearest = NearestList<kMaxNeighbours>;
    void senseBoid(std::size_t i, NeighbourGrid::Sweep* sweep, BoidSense& out);
    // senseBoid's two parts: the k nearest within a squared bound (keyed by index, or by
    // rank: TieOrder.h), then the sums over them.
    void searchBoid(std::size_t i, NeighbourGrid::Sweep* sweep, float startBound, BoidNearest& best,
                    bool byRank) const;
    // After a search within guess2: within the whole perception when fewer than k lay in
    // it, and again by rank should two candidates have come at the same distance.
    void finishSearch(std::size_t i, NeighbourGrid::Sweep* sweep, float guess2, float perception2,
                      BoidNearest& best) const;
    void sumBoid(std::size_t i, const BoidNearest& best, BoidSense& out);
    // The steering and integration (BoidKernelLanes.cpp), written once as steerLanes over
    // a lane type F of one, four or eight floats, for boid[0, width).
    void steerBoid(std::size_t i, const BoidSense& in);
    template <class F>
    void steerLanes(const std::uint32_t* boid, const BoidSense* sensed);
    void steerFourBoids(const std::uint32_t* boid, const BoidSense* sensed);
    void steerEightBoids(const std::uint32_t* boid, const BoidSense* sensed);  // only where canSteerEight
    // steerLanes' last part, lane by lane: the ground (for a boid below its floor, or over
    // a height field), and the collide pass's flag and the next state stored.
    void groundBoid(std::size_t i, glm::vec3& pos, glm::vec3& vel, glm::vec3 nextFwd) const;
    void storeBoid(std::size_t i, bool collideFree, glm::vec3 pos, glm::vec3 vel, glm::vec3 nextFwd, glm::vec3 side,
                   glm::vec3 nextUp, const WanderState& wanderNext);

    const AgentTypes& m_types;
    const StaticSet& m_set;
    const StepClock& m_clock;
    const NeighbourGrid& m_grid;
    const TieOrder& m_ties;
    AgentColumns& m_agents;
    const std::vector<BoidType>& m_boidTypes;
    std::uint8_t* m_collideFree;
    float m_boidSlackM;
    bool m_steerEight;
    bool m_neighbourSweep;  // the step's warmSearch
    std::uint64_t m_seed;
};

}  // namespace throng::sim
