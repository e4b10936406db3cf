#include "simcore/world/TypeSteering.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

namespace throng::sim {

namespace {

enum class Kind { Number, AngleDeg, Flag, Vector3, Response };

struct ParamSlot {
    Behaviour behaviour;
    const char* key;
    const char* meaning;
    Kind kind;
    float lo, hi;  // accepted range (degrees for angles)
    float& (*number)(TypeSteering&);
};

constexpr float kBig = 1e6f;

// One row per parameter the scene file may set. The lambdas pick the field; capture-less,
// so they are plain function pointers.
const std::vector<ParamSlot>& slots()
{
    using B = Behaviour;
    static const std::vector<ParamSlot> table{
        {B::Seek, "response_time", "s, > 0: time to reach the desired velocity", Kind::Number, 1e-3f, kBig,
         [](TypeSteering& t) -> float& { return t.seek.responseTimeS; }},
        {B::Flee, "panic_distance", "m, >= 0: flee only nearer than this; 0 = always", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.flee.panicDistanceM; }},
        {B::Flee, "response_time", "s, > 0", Kind::Number, 1e-3f, kBig,
         [](TypeSteering& t) -> float& { return t.flee.responseTimeS; }},
        {B::Pursuit, "max_prediction", "s, >= 0: the prediction interval's cap", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.pursuit.maxPredictionS; }},
        {B::Pursuit, "response_time", "s, > 0", Kind::Number, 1e-3f, kBig,
         [](TypeSteering& t) -> float& { return t.pursuit.responseTimeS; }},
        {B::Evasion, "max_prediction", "s, >= 0", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.evasion.maxPredictionS; }},
        {B::Evasion, "panic_distance", "m, >= 0: evade only nearer than this; 0 = always", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.evasion.panicDistanceM; }},
        {B::Evasion, "response_time", "s, > 0", Kind::Number, 1e-3f, kBig,
         [](TypeSteering& t) -> float& { return t.evasion.responseTimeS; }},
        {B::OffsetPursuit, "offset", "[x, y, z] m in the leader's frame: x right, y up, z forward", Kind::Vector3,
         -kBig, kBig, nullptr},
        {B::OffsetPursuit, "slowing_distance", "m, > 0", Kind::Number, 1e-3f, kBig,
         [](TypeSteering& t) -> float& { return t.offsetPursuit.slowingDistanceM; }},
        {B::OffsetPursuit, "response_time", "s, > 0", Kind::Number, 1e-3f, kBig,
         [](TypeSteering& t) -> float& { return t.offsetPursuit.responseTimeS; }},
        {B::Arrival, "slowing_distance", "m, > 0: the speed ramps down inside it", Kind::Number, 1e-3f, kBig,
         [](TypeSteering& t) -> float& { return t.arrival.slowingDistanceM; }},
        {B::Arrival, "tolerance", "m, >= 0: stopped this near the target", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.arrival.toleranceM; }},
        {B::Arrival, "response_time", "s, > 0", Kind::Number, 1e-3f, kBig,
         [](TypeSteering& t) -> float& { return t.arrival.responseTimeS; }},
        {B::ObstacleAvoidance, "min_length", "m, >= 0: look-ahead cylinder when standing", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.obstacles.minLengthM; }},
        {B::ObstacleAvoidance, "lookahead", "s, >= 0: extra cylinder length per m/s", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.obstacles.lookaheadS; }},
        {B::ObstacleAvoidance, "margin", "m, >= 0: clearance beyond the body", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.obstacles.marginM; }},
        {B::ObstacleAvoidance, "whisker_angle", "degrees, 0..90: side feelers' angle", Kind::AngleDeg, 0, 90,
         [](TypeSteering& t) -> float& { return t.obstacles.whiskerAngleRad; }},
        {B::ObstacleAvoidance, "response", "lateral or repulsive", Kind::Response, 0, 0, nullptr},
        {B::Wander, "distance", "m, >= 0: circle centre ahead of the agent", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.wander.distanceM; }},
        {B::Wander, "strength", "m, >= 0: circle radius", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.wander.radiusM; }},
        {B::Wander, "rate", "m per step, >= 0: how far the target may jitter", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.wander.jitterM; }},
        {B::PathFollowing, "prediction", "s, >= 0: look-ahead of the future position", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.path.predictionS; }},
        {B::PathFollowing, "ahead", "m, >= 0: how far along the spine to aim", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.path.aheadM; }},
        {B::PathFollowing, "response_time", "s, > 0", Kind::Number, 1e-3f, kBig,
         [](TypeSteering& t) -> float& { return t.path.responseTimeS; }},
        {B::WallFollowing, "feeler_length", "m, >= 0: feeler when standing", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.walls.feelerMinM; }},
        {B::WallFollowing, "lookahead", "s, >= 0: extra feeler per m/s", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.walls.feelerLookaheadS; }},
        {B::WallFollowing, "feeler_angle", "degrees, 0..90: side feelers' angle", Kind::AngleDeg, 0, 90,
         [](TypeSteering& t) -> float& { return t.walls.sideFeelerAngleRad; }},
        {B::WallFollowing, "standoff", "m, > 0: gap below which a wall pushes back", Kind::Number, 1e-3f, kBig,
         [](TypeSteering& t) -> float& { return t.walls.standoffM; }},
        {B::Containment, "probe_length", "m, >= 0: probe when standing", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.containment.probeMinM; }},
        {B::Containment, "lookahead", "s, >= 0: extra probe per m/s", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.containment.probeLookaheadS; }},
        {B::FlowFieldFollowing, "prediction", "s, >= 0: where the field is sampled", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.flow.predictionS; }},
        {B::FlowFieldFollowing, "response_time", "s, > 0", Kind::Number, 1e-3f, kBig,
         [](TypeSteering& t) -> float& { return t.flow.responseTimeS; }},
        {B::Separation, "range", "m, >= 0: body gap below which neighbours push", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.separation.rangeM; }},
        {B::Separation, "keep_right",
         "0..1: share of max force a walker steps right with, an oncoming walker in its way", Kind::Number, 0, 1,
         [](TypeSteering& t) -> float& { return t.separation.keepRight; }},
        {B::Alignment, "match_speed", "true: match speed too, not only heading", Kind::Flag, 0, 1, nullptr},
        {B::Alignment, "response_time", "s, > 0", Kind::Number, 1e-3f, kBig,
         [](TypeSteering& t) -> float& { return t.alignment.responseTimeS; }},
        {B::Cohesion, "slowing_distance", "m, > 0", Kind::Number, 1e-3f, kBig,
         [](TypeSteering& t) -> float& { return t.cohesion.slowingDistanceM; }},
        {B::LeaderFollowing, "behind", "m, >= 0: follow point behind the leader", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.leader.behindM; }},
        {B::LeaderFollowing, "corridor_length", "m, >= 0: kept clear ahead of the leader", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.leader.corridorLengthM; }},
        {B::LeaderFollowing, "corridor_half_width", "m, >= 0", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.leader.corridorHalfWidthM; }},
        {B::UnalignedCollisionAvoidance, "horizon", "s, > 0: approaches later than this are ignored", Kind::Number,
         1e-3f, kBig, [](TypeSteering& t) -> float& { return t.unaligned.horizonS; }},
        {B::UnalignedCollisionAvoidance, "margin", "m, >= 0: clearance beyond the two bodies", Kind::Number, 0, kBig,
         [](TypeSteering& t) -> float& { return t.unaligned.marginM; }},
        {B::UnalignedCollisionAvoidance, "brake_fraction", "0..1: share of force spent braking head-on", Kind::Number,
         0, 1, [](TypeSteering& t) -> float& { return t.unaligned.brakeFraction; }},
        {B::ReciprocalAvoidance, "time_horizon", "s, > 0: collisions further ahead are ignored", Kind::Number, 1e-3f,
         kBig, [](TypeSteering& t) -> float& { return t.reciprocal.timeHorizonS; }},
        {B::ReciprocalAvoidance, "keep_right", "degrees, 0..90: turn right of the way while walkers come the other way",
         Kind::AngleDeg, 0, 90, [](TypeSteering& t) -> float& { return t.reciprocal.keepRightRad; }},
    };
    return table;
}

const ParamSlot* findSlot(Behaviour b, const std::string& key)
{
    for (const ParamSlot& s : slots())
        if (s.behaviour == b && key == s.key)
            return &s;
    return nullptr;
}

// Applies a checked parameter; returns an error message or "".
std::string apply(TypeSteering& t, Behaviour b, const BrainParam& p)
{
    const ParamSlot* slot = findSlot(b, p.key);
    if (!slot) {
        std::string known;
        for (const ParamSlot& s : slots())
            if (s.behaviour == b)
                known += std::string(known.empty() ? "" : ", ") + s.key;
        return "unknown parameter '" + p.key + "' for " + behaviourName(b) +
               (known.empty() ? " (it has none)" : " (known: weight, " + known + ")");
    }
    switch (slot->kind) {
    case Kind::Response:
        if (p.text == "lateral") t.obstacles.response = AvoidanceResponse::Lateral;
        else if (p.text == "repulsive") t.obstacles.response = AvoidanceResponse::Repulsive;
        else return "response must be lateral or repulsive";
        return {};
    case Kind::Flag: {
        std::string v = p.text;
        std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        const bool yes = v == "true" || v == "yes" || v == "on", no = v == "false" || v == "no" || v == "off";
        if (!yes && !no)
            return std::string(slot->key) + " must be true or false";
        t.alignment.matchSpeed = yes;
        return {};
    }
    case Kind::Vector3:
        if (!p.text.empty() || p.numbers.size() != 3) return std::string(slot->key) + " must be [x, y, z]";
        t.offsetPursuit.offsetM = {p.numbers[0], p.numbers[1], p.numbers[2]};
        return {};
    case Kind::Number:
    case Kind::AngleDeg:
        if (!p.text.empty() || p.numbers.size() != 1) return std::string(slot->key) + " must be a number";
        if (p.numbers[0] < slot->lo || p.numbers[0] > slot->hi)
            return "must be within [" + std::to_string(slot->lo) + ", " + std::to_string(slot->hi) + "] (" +
                   slot->meaning + ")";
        slot->number(t) = slot->kind == Kind::AngleDeg ? p.numbers[0] * 0.017453292f : p.numbers[0];
        return {};
    }
    return {};
}

}  // namespace

TypeSteering compileTypeSteering(const AgentType& type)
{
    TypeSteering t;
    const bool flying = type.kind == AgentKind::Flier;
    t.vehicle.flying = flying;
    t.vehicle.minSpeed = type.minSpeed;
    t.vehicle.bankingGainS2PerM = type.banking;
    t.wander.flying = flying;
    t.priority = type.priorityCombination;
    if (type.behaviours.empty()) {
        using B = Behaviour;
        auto set = [&](std::initializer_list<std::pair<B, float>> weights) {
            for (auto [b, w] : weights)
                t.weight[std::size_t(b)] = w;
        };
        if (type.kind == AgentKind::Flier) {
            // Boids (Reynolds 1987), kept inside the world, heading for a goal or path if given.
            set({{B::Separation, 2.0f}, {B::Alignment, 1.0f}, {B::Cohesion, 1.0f}, {B::Containment, 4.0f},
                 {B::Arrival, 0.5f}, {B::PathFollowing, 0.5f}, {B::Wander, 0.2f}});
        } else if (type.kind == AgentKind::Vehicle) {
            set({{B::Arrival, 1.0f}, {B::PathFollowing, 1.0f}, {B::Separation, 1.0f}, {B::ObstacleAvoidance, 2.0f},
                 {B::WallFollowing, 2.0f}, {B::Containment, 2.0f}});
        } else {
            set({{B::Arrival, 1.0f}, {B::PathFollowing, 1.0f}, {B::Separation, 1.0f},
                 {B::UnalignedCollisionAvoidance, 1.0f}, {B::ObstacleAvoidance, 2.0f}, {B::WallFollowing, 2.0f},
                 {B::Containment, 2.0f}, {B::ReciprocalAvoidance, 1.0f}});
            // A short separation range keeps a crowd moving; the world's body collision pass
            // removes what overlap remains (measured on a 300-agent crossing: 0.3 % overlap).
            t.separation.rangeM = 0.2f;
            // Walkers brake over about a metre (from 1.4 m/s: about 1 m/s^2), not two.
            t.arrival.slowingDistanceM = 1.0f;
        }
    }
    for (const BehaviourWeight& bw : type.behaviours) {
        const std::optional<Behaviour> b = behaviourFromName(bw.behaviour);
        if (!b)
            continue;  // the reader rejected it already
        t.weight[std::size_t(*b)] = bw.weight;
        for (const BrainParam& p : bw.params)
            apply(t, *b, p);
    }
    for (std::size_t n = 0; n < t.keepRightTurn.size(); ++n) {
        const float angle = t.reciprocal.keepRightRad * float(n + 1) / 3.0f;
        t.keepRightTurn[n] = {std::cos(angle), std::sin(angle)};
    }
    return t;
}

const std::vector<BehaviourParamInfo>& behaviourParams()
{
    static const std::vector<BehaviourParamInfo> info = [] {
        std::vector<BehaviourParamInfo> v;
        for (const ParamSlot& s : slots())
            v.push_back({behaviourName(s.behaviour), s.key, s.meaning});
        return v;
    }();
    return info;
}

std::string checkBehaviourParam(const std::string& behaviour, const BrainParam& param)
{
    const std::optional<Behaviour> b = behaviourFromName(behaviour);
    if (!b)
        return "unknown steering behaviour '" + behaviour + "'";
    TypeSteering scratch;
    return apply(scratch, *b, param);
}

}  // namespace throng::sim
