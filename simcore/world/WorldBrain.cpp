// Brains in the World: compiling each type's brain once, checking that the World can
// fill every sensor it reads, and running it each step before steering. The sensors
// themselves are gathered in WorldBrainSense.cpp.
#include "simcore/world/WorldBrain.h"

#include "simcore/brain/BrainCompiler.h"
#include "simcore/base/Rng.h"
#include "simcore/world/World.h"
#include "simcore/world/BrainPhase.h"
#include "simcore/world/StepView.h"

#include "simcore/world/Sense.h"
#include "simcore/world/detail/StepGeometry.h"
#include "simcore/world/detail/WorldBrains.h"
#include "simcore/world/detail/WorldSound.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <optional>
#include <cmath>
#include <map>
#include <optional>

namespace throng::sim {

using detail::SensorFill;

namespace {

// Random streams of their own (see World.cpp's list), so brains shift no other draw.
enum BrainStream : std::uint64_t { kBrainKey = 301, kGoalSpotR, kGoalSpotA };

// m/s: how fast a walker its brain slows or stops may still step sideways or back to make
// way (a shuffle, well under a walk).
constexpr float kYieldSpeedMps = 0.5f;

std::uint32_t tagIndex(std::vector<std::string>& tags, const std::string& name)
{
    const auto it = std::find(tags.begin(), tags.end(), name);
    if (it != tags.end())
        return std::uint32_t(it - tags.begin());
    tags.push_back(name);
    return std::uint32_t(tags.size() - 1);
}

}  // namespace

void BrainPhase::build(const Scene& scene, const StepView& v)
{
    // Placed agents may run a brain of their own in place of their type's.
    std::map<AgentId, const std::string*> ownBrain;
    for (const Agent& a : scene.agents)
        if (!a.brain.empty())
            ownBrain.emplace(a.id, &a.brain);
    bool any = !ownBrain.empty();
    for (const AgentType& t : scene.agentTypes)
        any = any || !t.brain.empty();
    if (!any)
        return;
    m_brains = std::make_shared<detail::WorldBrains>();
    detail::WorldBrains& wb = *m_brains;
    // One batch per (type, brain): batch t is type t's own brain, then one batch per other
    // (type, brain) pair that placed agents ask for, in (type, brain name) order, so the
    // batches do not depend on the agents' order.
    const std::size_t typeCount = scene.agentTypes.size();
    wb.batch.resize(v.agents.pos.size());
    std::map<std::pair<std::size_t, std::string>, std::int32_t> extra;
    for (std::size_t i = 0; i < v.agents.pos.size(); ++i) {
        const std::size_t t = v.agents.info[i].typeIndex;
        wb.batch[i] = std::int32_t(t);
        const auto own = ownBrain.find(v.agents.info[i].id);
        if (own != ownBrain.end() && *own->second != scene.agentTypes[t].brain)
            extra.emplace(std::pair(t, *own->second), 0);
    }
    std::vector<std::pair<std::size_t, std::string>> batches;
    for (std::size_t t = 0; t < typeCount; ++t)
        batches.emplace_back(t, scene.agentTypes[t].brain);
    for (auto& [key, index] : extra) {
        index = std::int32_t(batches.size());
        batches.push_back(key);
    }
    for (std::size_t i = 0; i < v.agents.pos.size(); ++i)
        if (const auto own = ownBrain.find(v.agents.info[i].id); own != ownBrain.end())
            if (const auto it = extra.find({v.agents.info[i].typeIndex, *own->second}); it != extra.end())
                wb.batch[i] = it->second;
    wb.types.resize(batches.size());
    wb.local.assign(v.agents.pos.size(), -1);
    wb.action.assign(v.agents.pos.size(), -1);
    std::map<std::string, std::int32_t> goalByName;
    for (std::size_t g = 0; g < v.set.goals.size(); ++g)
        goalByName.emplace(v.set.goals[g].name, std::int32_t(g));
    for (std::size_t b = 0; b < batches.size(); ++b) {
        const AgentType& type = scene.agentTypes[batches[b].first];
        const std::string& brainName = batches[b].second;
        const BrainGraph* graph = brainName.empty() ? nullptr : scene.findBrain(brainName);
        if (!graph)
            continue;
        const BrainCompileResult r = compileBrain(*graph, scene.brains);
        if (!r.ok()) {
            for (const BrainError& e : r.errors)
                wb.errors.push_back(e.format());
            continue;
        }
        detail::TypeBrain& tb = wb.types[b];
        bool usable = true;
        for (const BrainSensorUse& use : r.program->sensors) {
            const std::string why = worldSensorProblem(use, scene);
            if (!why.empty()) {
                wb.errors.push_back("brain '" + graph->name + "': " + why);
                usable = false;
            }
            const SensorFill fill = detail::sensorFillFor(use).value_or(SensorFill::Time);
            tb.fills.push_back(fill);
            tb.fillTag.push_back(use.sensor == "neighbour_tag" ? tagIndex(wb.tags, use.argument)
                                 : detail::isSoundFill(fill) ? detail::channelIndex(wb, use.argument)
                                                             : 0);
            if (detail::isSoundFill(fill) &&
                std::find(tb.hears.begin(), tb.hears.end(), tb.fillTag.back()) == tb.hears.end())
                tb.hears.push_back(tb.fillTag.back());
        }
        if (!usable) {
            tb.fills.clear();
            tb.fillTag.clear();
            tb.hears.clear();
            continue;
        }
        for (const BrainOutputSlot& o : r.program->outputs)
            if (o.channel == "tag")
                tagIndex(wb.tags, o.name);
        tb.program = r.program;
        tb.viewDeg = std::min(type.viewAngleDeg, 360.0f);
        for (const std::string& name : r.program->goal.names) {
            const auto it = goalByName.find(name);
            tb.goalIndex.push_back(it == goalByName.end() ? -1 : it->second);
        }
        // An action named as a clip plays it (Clip.h); any other name keeps the clip the
        // agent's speed gives.
        for (const std::string& name : r.program->action.names) {
            const std::optional<Clip> clip = clipFromName(name);
            tb.actionClip.push_back(clip ? std::int8_t(*clip) : std::int8_t(-1));
        }
    }
    for (std::size_t i = 0; i < v.agents.pos.size(); ++i) {
        detail::TypeBrain& tb = wb.types[std::size_t(wb.batch[i])];
        if (!tb.program)
            continue;
        wb.local[i] = std::int32_t(tb.agents.size());
        tb.agents.push_back(std::uint32_t(i));
        tb.keys.push_back(rng(v.seed, v.agents.info[i].id, 0, kBrainKey));
    }
    wb.tagValues.assign(wb.tags.size(), std::vector<float>(v.agents.pos.size(), 0.0f));
    wb.vehicleOf.assign(v.agents.pos.size(), -1);
    for (std::size_t vehicle = 0; vehicle < v.traffic.vehicleAgent.size(); ++vehicle)
        wb.vehicleOf[v.traffic.vehicleAgent[vehicle]] = std::int32_t(vehicle);
    wb.vehicleSpeed.assign(v.traffic.vehicleAgent.size(), std::nanf(""));
    for (detail::TypeBrain& tb : wb.types) {
        if (!tb.program)
            continue;
        const std::size_t n = tb.agents.size();
        tb.evaluator = std::make_unique<BrainEvaluator>(tb.program);
        tb.evaluator->keepOnlyOutputs();  // the World reads outputs(), probes and pickedValues
        tb.evaluator->resize(n);
        for (const BrainSensorUse& use : tb.program->sensors)
            tb.columns.emplace_back(use.perNeighbour ? n * kBrainNeighbours : n, 0.0f);
        tb.neighbourCount.assign(n, 0);
        for (const std::string& set : tb.program->itemSets) {
            const bool sound = set.starts_with("sound:");
            tb.itemCounts.emplace_back(sound ? n : 0, std::uint8_t(0));
            tb.itemSetChannel.push_back(sound ? std::int32_t(detail::channelIndex(wb, set.substr(6))) : -1);
        }
    }
    detail::buildSoundChannels(wb, scene, v.agents.info);
}

// Brain: sense from the previous state, evaluate each type's program for all its agents,
// then take up the choices (goal, action) that are the agent's own state.
void BrainPhase::run(const StepView& v, AgentColumns& agents, WorldTraffic& traffic)
{
    detail::WorldBrains& wb = *m_brains;
    for (detail::TypeBrain& tb : wb.types) {
        if (!tb.program)
            continue;
        sense(v, agents, tb);
        BrainInputs in;
        for (const std::vector<float>& c : tb.columns)
            in.sensors.push_back(c.data());
        for (std::size_t s = 0; s < tb.program->itemSets.size(); ++s)
            in.itemCounts.push_back(tb.program->itemSets[s] == "neighbours" ? tb.neighbourCount.data()
                                                                            : tb.itemCounts[s].data());
        in.agentKey = tb.keys.data();
        in.timeS = float(v.clock.timeS());
        in.dtS = v.clock.dt;
        std::string error;
        if (!tb.evaluator->evaluate(in, &error, &v.team)) {
            wb.errors.push_back(error);
            tb.program.reset();
            continue;
        }
        const BrainOutputs out = tb.evaluator->outputs();
        tb.speed = out.speed;
        tb.turn = out.turn;
        tb.action = out.action;
        tb.goal = out.goal;
        tb.tagOutputs.clear();
        for (const auto& [name, column] : out.tags)
            tb.tagOutputs.emplace_back(std::uint32_t(std::find(wb.tags.begin(), wb.tags.end(), name) - wb.tags.begin()),
                                       column);
        tb.weight.fill(nullptr);
        for (const auto& [name, column] : out.weights)
            if (const std::optional<Behaviour> b = behaviourFromName(name))
                tb.weight[std::size_t(*b)] = column;
        const std::size_t n = tb.agents.size();
        v.team.forEach(n, 1024, [&](std::size_t k) {
            const std::size_t i = tb.agents[k];
            if (tb.action)
                wb.action[i] = std::int16_t(tb.action[k]);
            if (!tb.goal || v.agents.stopped[i])
                return;
            const auto choice = std::size_t(std::max(0.0f, tb.goal[k]));
            const std::int32_t g = choice < tb.goalIndex.size() ? tb.goalIndex[choice] : -1;
            if (g < 0 || g == v.agents.goal[i])
                return;
            // A new goal: the agent heads for its own spot in it, drawn as at the start.
            agents.goal[i] = g;
            const Goal& goal = v.set.goals[std::size_t(g)];
            const AgentId id = v.agents.info[i].id;
            agents.goalSpot[i] = detail::goalSpot(goal.position, goal.radiusM, goal.exit, v.agents.radius[i],
                                                  rngUniform(v.seed, id, std::uint64_t(g) + 1, kGoalSpotR),
                                                  rngUniform(v.seed, id, std::uint64_t(g) + 1, kGoalSpotA));
        });
    }
    // Vehicles with a speed output are driven by it along their lanes (this step's traffic
    // step comes after the brains).
    if (v.traffic.system && !wb.vehicleSpeed.empty()) {
        for (std::size_t vehicle = 0; vehicle < wb.vehicleSpeed.size(); ++vehicle) {
            const std::size_t i = v.traffic.vehicleAgent[vehicle];
            const detail::TypeBrain& tb = wb.types[std::size_t(wb.batch[i])];
            wb.vehicleSpeed[vehicle] = tb.program && tb.speed ? tb.speed[wb.local[i]] : std::nanf("");
        }
        traffic.system->setBrainSpeeds(wb.vehicleSpeed);
    }
    // Tags are published only once every type has sensed, so all read last step's values.
    for (detail::TypeBrain& tb : wb.types) {
        if (!tb.program)
            continue;
        for (const auto& [tag, column] : tb.tagOutputs) {
            std::vector<float>& values = wb.tagValues[tag];
            for (std::size_t k = 0; k < tb.agents.size(); ++k)
                values[tb.agents[k]] = column[k];
        }
    }
}

bool BrainPhase::gatheredNeighbours(std::size_t i) const
{
    return row(i).gathered();
}

BrainPhase::Row BrainPhase::row(std::size_t i) const
{
    if (!m_brains || m_brains->local[i] < 0)
        return {};
    const detail::TypeBrain& tb = m_brains->types[std::size_t(m_brains->batch[i])];
    return {tb.weight.data(), tb.turn, tb.speed, m_brains->local[i], tb.gathersNeighbours};
}

float BrainPhase::speedCap(const StepView& v, std::size_t i) const
{
    return speedCap(v, row(i), i);
}

float BrainPhase::speedCap(const StepView& v, const Row& row, std::size_t i) const
{
    // A driven vehicle's brain speed went to the TrafficSystem, which moves it.
    if (row.local < 0 || !row.speed || v.traffic.isDriven(i))
        return v.agents.maxSpeed[i];
    return std::clamp(row.speed[row.local], 0.0f, v.agents.maxSpeed[i]);
}

// The brain's speed is a cap applied after steering, not a lower max speed for the
// behaviours: arrival already slows by distance, and slowing twice (arrival's ramp on a
// brain-lowered max speed) would make an agent creep toward its goal and never stop.
// For a walker it caps progress (the velocity along the way it wants to go), not making
// way: sideways and back it may still move at kYieldSpeedMps, so one its brain holds (at
// a light, for a hero) steps aside for those who pass instead of standing as a post.
void BrainPhase::capToSpeed(const StepView& v, std::size_t i, glm::vec3 from, glm::vec3& position,
                            glm::vec3& velocity) const
{
    capToSpeed(v, row(i), i, from, position, velocity);
}

void BrainPhase::capToSpeed(const StepView& v, const Row& row, std::size_t i, glm::vec3 from, glm::vec3& position,
                            glm::vec3& velocity) const
{
    if (row.local < 0)
        return;
    const float cap = speedCap(v, row, i);
    if (glm::length(velocity) <= cap)
        return;
    velocity = limited(v, i, velocity, std::max(cap, std::min(kYieldSpeedMps, v.agents.maxSpeed[i])), 1.0f);
    position = from + velocity * v.clock.dt;
}

// Agent i's move v over `seconds` (a velocity for 1) within its brain's speed: along the
// way a walker wants to go at most the brain's speed, sideways and back at most `aside`
// (m/s); for other agents (or a walker with no path or goal) at most the brain's speed in
// all. v itself when it is within them or the agent runs no brain.
glm::vec3 BrainPhase::limited(const StepView& view, std::size_t i, glm::vec3 v, float aside, float seconds) const
{
    if (!m_brains || m_brains->local[i] < 0 || view.traffic.isDriven(i))
        return v;
    const float cap = speedCap(view, i) * seconds, speed = glm::length(v);
    aside *= seconds;
    if (speed <= cap)
        return v;
    // The way it wants to go: only a walker with a path or a goal has one (for the rest,
    // wantedHeading is where it happens to be heading).
    glm::vec2 h(0.0f);
    if (view.types.params[view.agents.info[i].typeIndex].kind == AgentKind::Pedestrian &&
        !view.types.steering[view.agents.info[i].typeIndex].vehicle.flying &&
        (view.agents.path[i] >= 0 || view.agents.goal[i] >= 0))
        h = wantedHeading(view, i);
    if (!(glm::dot(h, h) > 1e-12f))
        return v * (cap / speed);
    h = glm::normalize(h);
    const glm::vec3 w(h.x, 0.0f, h.y);
    const float along = glm::dot(v, w);
    glm::vec3 side = v - w * along;
    side.y = 0.0f;
    if (const float s = glm::length(side); s > aside)
        side *= aside / s;
    return w * std::clamp(along, -aside, cap) + side + glm::vec3(0.0f, v.y, 0.0f);
}

float BrainPhase::weight(std::size_t i, Behaviour b) const
{
    return row(i).weight(b);
}

glm::vec3 BrainPhase::turnForce(std::size_t i, glm::vec3 forward, glm::vec3 velocity, float mass) const
{
    return row(i).turnForce(forward, velocity, mass);
}

Clip BrainPhase::clip(std::size_t i, Clip bySpeed) const
{
    if (!m_brains || m_brains->action[i] < 0)
        return bySpeed;
    const detail::TypeBrain& tb = m_brains->types[std::size_t(m_brains->batch[i])];
    const auto a = std::size_t(m_brains->action[i]);
    return a < tb.actionClip.size() && tb.actionClip[a] >= 0 ? Clip(tb.actionClip[a]) : bySpeed;
}

int BrainPhase::action(std::size_t i) const
{
    return m_brains ? m_brains->action[i] : -1;
}

std::string BrainPhase::actionName(std::size_t i) const
{
    if (!m_brains || m_brains->action[i] < 0 || !m_brains->types[std::size_t(m_brains->batch[i])].program)
        return {};
    const auto& names = m_brains->types[std::size_t(m_brains->batch[i])].program->action.names;
    const auto a = std::size_t(m_brains->action[i]);
    return a < names.size() ? names[a] : std::string();
}

const std::vector<std::string>& BrainPhase::errors() const
{
    static const std::vector<std::string> none;
    return m_brains ? m_brains->errors : none;
}

const BrainEvaluator* BrainPhase::evaluator(std::size_t typeIndex) const
{
    if (!m_brains || typeIndex >= m_brains->types.size())
        return nullptr;
    return m_brains->types[typeIndex].evaluator.get();
}

const BrainEvaluator* BrainPhase::agentEvaluator(std::size_t i) const
{
    if (!m_brains || i >= m_brains->batch.size())
        return nullptr;
    return m_brains->types[std::size_t(m_brains->batch[i])].evaluator.get();
}

void BrainPhase::pickAgent(std::ptrdiff_t i, std::size_t agentCount)
{
    if (!m_brains)
        return;
    for (detail::TypeBrain& tb : m_brains->types)
        if (tb.evaluator)
            tb.evaluator->setPickedAgent(-1);
    if (i < 0 || std::size_t(i) >= agentCount || m_brains->local[std::size_t(i)] < 0)
        return;
    m_brains->types[std::size_t(m_brains->batch[std::size_t(i)])].evaluator->setPickedAgent(
        m_brains->local[std::size_t(i)]);
}

}  // namespace throng::sim
