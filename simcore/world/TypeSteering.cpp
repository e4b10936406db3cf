#include "simcore/world/TypeSteering.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

namespace throng::sim {

namespace {

// Calls fn(Row{}) for behaviour b's row of the behaviour list.
template <class Fn, class... Rows>
void withRow(Behaviour b, Fn&& fn, BehaviourRows<Rows...>)
{
    ((Rows::kBehaviour == b ? (fn(Rows{}), true) : false) || ...);
}

// Applies a checked parameter to one behaviour's parameters; returns an error message or "".
template <class P, std::size_t N>
std::string applyKey(P& params, const std::array<ParamKey<P>, N>& keys, Behaviour b, const BrainParam& p)
{
    const ParamKey<P>* slot = nullptr;
    for (const ParamKey<P>& k : keys)
        if (p.key == k.key) {
            slot = &k;
            break;
        }
    if (!slot) {
        std::string known;
        for (const ParamKey<P>& k : keys)
            known += std::string(known.empty() ? "" : ", ") + k.key;
        return "unknown parameter '" + p.key + "' for " + behaviourName(b) +
               (known.empty() ? " (it has none)" : " (known: weight, " + known + ")");
    }
    switch (slot->kind) {
    case ParamKind::Choice:
        if (!slot->choose(params, p.text))
            return std::string(slot->key) + " must be " + slot->meaning;
        return {};
    case ParamKind::Flag: {
        std::string v = p.text;
        std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        const bool yes = v == "true" || v == "yes" || v == "on", no = v == "false" || v == "no" || v == "off";
        if (!yes && !no)
            return std::string(slot->key) + " must be true or false";
        params.*slot->flag = yes;
        return {};
    }
    case ParamKind::Vector3:
        if (!p.text.empty() || p.numbers.size() != 3) return std::string(slot->key) + " must be [x, y, z]";
        params.*slot->vector = {p.numbers[0], p.numbers[1], p.numbers[2]};
        return {};
    case ParamKind::Number:
    case ParamKind::AngleDeg:
        if (!p.text.empty() || p.numbers.size() != 1) return std::string(slot->key) + " must be a number";
        if (p.numbers[0] < slot->lo || p.numbers[0] > slot->hi)
            return "must be within [" + std::to_string(slot->lo) + ", " + std::to_string(slot->hi) + "] (" +
                   slot->meaning + ")";
        params.*slot->number = slot->kind == ParamKind::AngleDeg ? p.numbers[0] * 0.017453292f : p.numbers[0];
        return {};
    }
    return {};
}

// Applies a checked parameter of behaviour b; returns an error message or "".
std::string apply(TypeSteering& t, Behaviour b, const BrainParam& p)
{
    std::string message;
    withRow(b, [&]<class Row>(Row) {
        using D = typename Row::Type;
        message = applyKey(t.*D::kParams, D::kKeys, b, p);
    }, BehaviourList{});
    return message;
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
        [&]<class... Rows>(BehaviourRows<Rows...>) {
            auto add = [&]<class Row>(Row) {
                for (const auto& k : Row::Type::kKeys)
                    v.push_back({behaviourName(Row::kBehaviour), k.key, k.meaning});
            };
            (add(Rows{}), ...);
        }(BehaviourList{});
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
