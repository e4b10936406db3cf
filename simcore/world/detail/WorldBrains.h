#pragma once
// The World's brain runtime (internal to simcore/world): per agent type its compiled
// program, evaluator and sensor columns; per agent its slot and chosen action. Filled by
// World::buildBrains, advanced by World::runBrains; never touched by another module.

#include "simcore/brain/BrainEvaluator.h"
#include "simcore/brain/NodeCatalogue.h"
#include "simcore/world/TypeSteering.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace throng::sim::detail {

enum class SensorFill : std::uint8_t {
    Speed, GoalBearing, GoalDistance, PathOffset, FlowBearing, NeighbourCount, NeighbourDensity,
    NearestDistance, NearestBearing, VisionLeft, VisionCentre, VisionRight, FeelerLeft, FeelerCentre,
    FeelerRight, WallDistance, LightState, StopLineDistance, HeroDistance, HeroBearing, TerrainSlope, Time,
    AttrMaxSpeed, AttrRadius, AttrMass, AttrMaxForce, AttrPerception, AttrSpeedFactor,
    NeighbourDistance, NeighbourBearing, NeighbourSpeed, NeighbourHeading, NeighbourTag,  // per neighbour: last
};

struct TypeBrain {
    std::shared_ptr<const BrainProgram> program;  // null: the type has no brain
    std::unique_ptr<BrainEvaluator> evaluator;
    std::vector<std::uint32_t> agents;            // World indices of this type's agents
    std::vector<SensorFill> fills;                // parallel to program->sensors
    std::vector<std::uint32_t> fillTag;           // parallel to fills: NeighbourTag's index into WorldBrains::tags
    std::vector<std::pair<std::uint32_t, const float*>> tagOutputs;  // tag index -> last evaluate's column
    std::vector<std::vector<float>> columns;      // parallel to program->sensors
    std::vector<std::uint8_t> neighbourCount;     // per agent of the type
    std::vector<std::uint64_t> keys;              // per agent: stable random key
    float viewDeg = 360.0f;                       // the type's full view angle
    bool gathersNeighbours = false;               // the sense phase fills m_nearIndex for its agents
    // Outputs of the last evaluate, by the type's agent index; null = not driven.
    const float* speed = nullptr;
    const float* turn = nullptr;
    const float* action = nullptr;
    const float* goal = nullptr;
    std::array<const float*, kBehaviourCount> weight{};
    std::vector<std::int32_t> goalIndex;  // the brain's goal names -> World goal index (-1 = unknown)
    std::vector<std::int8_t> actionClip;  // the brain's actions -> Clip, -1 = no clip of its own
};

struct WorldBrains {
    std::vector<TypeBrain> types;      // by type index
    std::vector<std::int32_t> local;   // per agent: index among its type's agents, -1 = no brain
    std::vector<std::int16_t> action;  // per agent: the chosen action index, -1 = none
    std::vector<std::string> errors;   // why a brain does not run (the type then steers without it)
    std::vector<std::string> tags;                 // every tag a brain publishes or senses
    std::vector<std::vector<float>> tagValues;     // per tag, per agent: published at the last step (0 = none)
};

}  // namespace throng::sim::detail
