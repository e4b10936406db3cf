#pragma once
// The World's brain runtime (internal to simcore/world): per agent type its compiled
// program, evaluator and sensor columns; per agent its slot and chosen action. Filled by
// BrainPhase::build, advanced by BrainPhase::run; never touched by another module.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/brain/BrainEvaluator.h"
#include "simcore/brain/NodeCatalogue.h"
#include "simcore/world/TypeSteering.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace throng::sim::detail {

enum class SensorFill : std::uint8_t {
    Speed, GoalBearing, GoalDistance, PathOffset, FlowBearing, NeighbourCount, NeighbourDensity,
    NearestDistance, NearestBearing, VisionLeft, VisionCentre, VisionRight, FeelerLeft, FeelerCentre,
    FeelerRight, WallDistance, LightState, StopLineDistance, HeroDistance, HeroBearing, TerrainSlope, Time,
    AttrMaxSpeed, AttrRadius, AttrMass, AttrMaxForce, AttrPerception, AttrSpeedFactor,
    SoundBearing, SoundDistance, SoundStrength,
    ActionPointDistance, ActionPointBearing, ActionPointTime,
    NeighbourDistance, NeighbourBearing, NeighbourSpeed, NeighbourHeading, NeighbourTag,  // per neighbour: last
    SoundSourceBearing, SoundSourceDistance, SoundSourceStrength,                         // per source
};

// The column the World fills for a sensor a program reads; none for an unknown one
// (WorldBrainCheck.cpp).
std::optional<SensorFill> sensorFillFor(const BrainSensorUse& use);

inline bool isSoundFill(SensorFill f)
{
    return (f >= SensorFill::SoundBearing && f <= SensorFill::SoundStrength) || f >= SensorFill::SoundSourceBearing;
}

// A fixed sound source of one channel.
struct Beacon {
    float x, z, strength, radiusM;
};

// Everything heard on one channel: its beacons and the agent types that emit on it.
struct SoundChannel {
    std::string name;
    std::vector<Beacon> beacons;
    float agentReachM = 0.0f;  // the largest radius an agent type emits with on it (0 = none)
    // The agents that emit on it, by index, when they are few (kDirectEmitters at most):
    // listeners then check each instead of querying the grid over agentReachM, which in
    // a dense crowd visits every agent within that reach. Empty = use the grid.
    std::vector<std::uint32_t> emitters;
};
inline constexpr std::size_t kDirectEmitters = 64;

struct TypeBrain {
    std::shared_ptr<const BrainProgram> program;  // null: the type has no brain
    std::unique_ptr<BrainEvaluator> evaluator;
    std::vector<std::uint32_t> agents;            // World indices of this type's agents
    std::vector<SensorFill> fills;                // parallel to program->sensors
    std::vector<std::uint32_t> fillTag;           // parallel to fills: NeighbourTag's index into WorldBrains::tags
                                                  // (sound fills: the channel's index into WorldBrains::channels)
    std::vector<std::uint32_t> hears;             // channels (WorldBrains::channels) its sound sensors read
    std::vector<std::vector<std::uint8_t>> itemCounts;  // parallel to program->itemSets (sound sets only)
    std::vector<std::int32_t> itemSetChannel;     // parallel to program->itemSets: its channel, -1 = neighbours
    std::vector<std::pair<std::uint32_t, const float*>> tagOutputs;  // tag index -> last evaluate's column
    std::vector<std::vector<float>> columns;      // parallel to program->sensors
    std::vector<std::uint8_t> neighbourCount;     // per agent of the type
    std::vector<std::uint64_t> keys;              // per agent: stable random key
    float viewDeg = 360.0f;                       // the type's full view angle
    bool gathersNeighbours = false;               // the sense phase fills m_agents.nearIndex for its agents
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
    std::vector<TypeBrain> types;      // by batch: [0, types) each type's own brain, then (type, brain) pairs
    std::vector<std::int32_t> batch;   // per agent: its batch in `types` (its type's index unless it has its own brain)
    std::vector<std::int32_t> local;   // per agent: index among its batch's agents, -1 = no brain
    std::vector<std::int16_t> action;  // per agent: the chosen action index, -1 = none
    std::vector<std::string> errors;   // why a brain does not run (the type then steers without it)
    std::vector<std::string> tags;                 // every tag a brain publishes or senses
    std::vector<std::vector<float>> tagValues;     // per tag, per agent: published at the last step (0 = none)
    std::vector<SoundChannel> channels;            // every channel a brain listens to
    std::vector<std::int32_t> typeEmits;           // per type: its channel in `channels`, -1 = silent or unheard
    std::vector<float> typeEmitStrength, typeEmitRadiusM;  // per type
    std::vector<std::int32_t> vehicleOf;           // per agent: its TrafficSystem vehicle, -1 = none
    std::vector<float> vehicleSpeed;               // per vehicle: the speed its brain wants, NaN = no brain
};

}  // namespace throng::sim::detail
