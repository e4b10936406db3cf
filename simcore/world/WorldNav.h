#pragma once
// The navigation side of a World: the scene's NavGrid, shared A* plans, one flow field per
// goal that flow-field walkers head for, and per walker where it steers this step (its
// current waypoint, the field's way, or a side-step). The navigation phase (WorldNav.cpp)
// owns this state and reads the World through a StepView; it never moves agents itself.

#include "simcore/nav/AStar.h"
#include "simcore/nav/FlowField.h"
#include "simcore/nav/NavFollow.h"
#include "simcore/nav/NavGrid.h"
#include "simcore/nav/NavReach.h"
#include "simcore/nav/PlanCache.h"
#include "simcore/nav/SketchField.h"
#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace throng::sim {

struct NavCounters {
    std::uint64_t replans = 0;     // stalled A* walkers that planned around the blockage
    std::uint64_t sideSteps = 0;   // stalled walkers that found no way round and stepped aside
    std::uint64_t stalePlans = 0;  // plans made again because the grid changed
    std::uint64_t lostPlans = 0;   // walkers pushed off their way (waypoint out of sight) that planned afresh
};

struct StepView;

struct WorldNav {
    bool active = false;  // some walker navigates by A* or a flow field
    NavGrid grid;
    PlanCache cache;
    AStar astar;
    std::vector<FlowField> fields;     // one per goal index; built only for goals flow-field walkers use
    std::vector<std::uint8_t> hasField;// per goal index
    std::optional<SketchField> sketch; // the scene's flow strokes as an RBF field, when it solved
    NavCounters counters;
    // Which places the smallest navigating body can walk between (NavReach), built the
    // first time a plan or a field finds no way (WorldNav.cpp): the grid above is
    // inflated by a margin, and a door a body fits through may be closed on it.
    NavReach reach;
    NavShapes reachShapes;
    float reachRadiusM = 0.0f;

    // Per World agent.
    std::vector<Navigation> mode;
    std::vector<std::shared_ptr<const NavPlan>> plan;  // A* walkers: the shared plan or a detour
    std::vector<std::int32_t> planGoal;  // the goal the plan leads to (a brain may change goals)
    std::vector<std::uint32_t> waypoint; // index into plan->waypoints
    std::vector<float> waypointRadiusM;  // per-agent advance radius, m
    std::vector<StallWatch> stall;
    std::vector<std::uint8_t> replan;    // stalled this step: plan around the blockage next step
    std::vector<float> sideStepS;        // s left of a side-step, 0 = none
    std::vector<glm::vec2> sideDir;      // unit: the side-step's direction
    std::vector<glm::vec2> target;       // where the agent steers this step (x, z)
    std::vector<std::uint8_t> hasTarget; // 0: steer at the goal's own spot as before
    // Held at a light (1), or queued right behind someone who waits (their depth + 1), as
    // of the last step (the step being computed writes waitingNext); 0 = not waiting.
    // Waiting is not being stuck. The depth is capped, so a ring of walkers each waiting
    // for the next with nobody held at a light stops counting as a queue within a second.
    std::vector<std::uint8_t> waiting, waitingNext;
    std::vector<std::uint8_t> lostSteps; // A* walkers: steps the current waypoint has been out of sight
    std::vector<std::uint8_t> noWay;     // 1: no body of its size can get to its goal from where it is; it waits

    // Where agent i's seek and arrival aim: its navigation target this step, or its own
    // goalSpot when it has none.
    glm::vec3 goal(std::size_t i, glm::vec3 goalSpot) const
    {
        if (!active || !hasTarget[i])
            return goalSpot;
        return {target[i].x, goalSpot.y, target[i].y};
    }
    // The sketched field's direction at p (zero where the field is weaker than
    // kSketchMinStrength); false when the scene has no sketched field.
    bool sketchedFlow(glm::vec3 p, glm::vec3& direction) const;

    // The phase (WorldNav.cpp). build: the grid, fields and plans for a World's agents,
    // once; beforeStep: plans, then each walker's target for this step. Both read the
    // World only through the view and write only this state.
    void build(const Scene& scene, const StepView& v);
    void beforeStep(const StepView& v);
    // Builds goal g's flow field where walkers navigate and it has none yet (for an exit
    // that walkers may choose, ExitChoice.h).
    void ensureField(const StepView& v, std::size_t g);

private:
    glm::vec2 startOf(const StepView& v,
                      std::size_t i) const; // where its way starts: its place, or where it walks out to
    bool noWayToGoal(const StepView& v, std::size_t i);        // no body of its size gets to its goal (builds reach)
    void planFor(const StepView& v, std::size_t i);
    std::uint8_t queueDepth(const StepView& v, std::size_t i) const;
    void updateTarget(const StepView& v, std::size_t i);
    float crowdSpeedFraction(const StepView& v, std::size_t i, glm::vec2 way) const;  // Weidmann, of free speed, (0, 1]
};

}  // namespace throng::sim
