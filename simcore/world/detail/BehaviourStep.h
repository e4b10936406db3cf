#pragma once
// What a steering behaviour's request (its descriptor, BehaviourTable.h) sees of one agent
// in the steer phase: the agent, its goal, leader and neighbours, and queries of the
// static set and the agent's columns. Built per agent by steer (Steer.cpp) from the
// previous state; reads it only, and writes nothing but the agent's new wander state.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/steering/Neighbour.h"
#include "simcore/steering/SteeringAgent.h"
#include "simcore/steering/Wander.h"
#include "simcore/world/Sense.h"
#include "simcore/world/StepView.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace throng::sim::detail {

struct BehaviourStep {
    const StepView& v;
    std::size_t i;  // the agent's index
    const SteeringAgent& self;
    bool flying;                        // its type flies (TypeSteering::vehicle)
    glm::vec3 goal;                     // its goal (the navigation's target on the way), or a metre ahead
    bool hasGoal = false;
    const Neighbour* leader = nullptr;  // null without a leader
    std::span<const Neighbour> avoided{};  // the neighbours it avoids: not those making way for it
    std::span<const Neighbour> near{};     // every neighbour it sees
    WanderState* wanderOut = nullptr;      // its new wander state (steer only)
    bool formed = false;                   // it walks on a slot round its anchor (Formations.h)

    bool onPath() const { return !formed && v.agents.path[i] >= 0; }
    // The path it follows; only when onPath().
    SteeringPath path() const
    {
        const auto k = std::size_t(v.agents.path[i]);
        return {v.set.pathPoints[k], v.set.paths[k].radiusM, v.set.paths[k].closed};
    }
    float pathProgressM() const { return v.agents.pathAlong[i]; }
    // Its goal is an exit walked through, not stopped at (no navigation target leads there).
    bool walksThroughGoal() const { return v.walksThroughGoal(i); }
    const WalkableBox& bounds() const { return v.set.bounds; }
    bool hasFlow() const { return !v.set.flow.empty(); }
    glm::vec3 flowAt(glm::vec3 p) const { return flowDirection(v, p); }

    // fn(walls) with the walls within reachM (at most kMaxNearWalls); not called when none is.
    template <class Fn>
    void withWallsNear(float reachM, Fn&& fn) const
    {
        if (v.set.walls.segments().empty())
            return;
        std::array<WallSegment, kMaxNearWalls> walls;
        std::size_t n = 0;
        v.set.walls.forEachNear(xz(self.position), reachM, [&](std::uint32_t k) {
            if (n < walls.size()) {
                const Segment& seg = v.set.walls.segment(k);
                walls[n++] = {glm::vec3(seg.a.x, 0.0f, seg.a.y), glm::vec3(seg.b.x, 0.0f, seg.b.y)};
            }
        });
        if (n > 0)
            fn(std::span<const WallSegment>(walls.data(), n));
    }
    // fn(circles, boxes) with the obstacles within reachM (at most kMaxNearObstacles of
    // each); called wherever the world has obstacles, even with none near.
    template <class Fn>
    void withObstaclesNear(float reachM, Fn&& fn) const
    {
        if (v.set.circles.empty() && v.set.boxes.empty())
            return;
        std::array<CircleObstacle, kMaxNearObstacles> circles;
        std::array<BoxObstacle, kMaxNearObstacles> boxes;
        std::size_t nc = 0, nb = 0;
        v.set.obstacleGrid.forEachNear(xz(self.position), reachM, [&](std::uint32_t k) {
            if (k < v.set.circles.size()) {
                if (nc < circles.size())
                    circles[nc++] = v.set.circles[k];
            } else if (nb < boxes.size()) {
                boxes[nb++] = v.set.boxes[k - v.set.circles.size()];
            }
        });
        fn(std::span<const CircleObstacle>(circles.data(), nc), std::span<const BoxObstacle>(boxes.data(), nb));
    }

    const WanderState& wanderState() const { return v.agents.wander[i]; }
    void setWanderState(const WanderState& s) const { *wanderOut = s; }
    // This step's three seeded draws in [-1, 1] for wander.
    glm::vec3 wanderRandom() const { return wanderDraws(v.seed, v.agents.info[i].id, v.clock.step); }
};

}  // namespace throng::sim::detail
