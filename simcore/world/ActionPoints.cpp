// The action point phase (ActionPoints.h).
#include "simcore/world/ActionPoints.h"

#include "simcore/base/Rng.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/StepView.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace throng::sim {

using detail::xz;

namespace {

// The random stream of the draw whether an agent stops at a point it entered (keyed by
// the agent's id and the step it entered on, so each visit draws anew).
constexpr std::uint64_t kStopDraw = 0x4163'7450;  // "AcPt"

// Turns agent i towards `to` (unit, on the ground) by at most `maxRad`.
void turnTowards(AgentColumns& agents, std::size_t i, glm::vec3 to, float maxRad)
{
    const glm::vec3 f = agents.fwd[i];
    const float now = std::atan2(-f.z, f.x), want = std::atan2(-to.z, to.x);
    const float by = std::remainder(want - now, 6.28318531f);
    if (std::fabs(by) < 1e-6f)
        return;
    const float h = now + std::clamp(by, -maxRad, maxRad);
    agents.fwd[i] = glm::vec3(std::cos(h), 0.0f, -std::sin(h));
    agents.side[i] = glm::normalize(glm::cross(agents.fwd[i], agents.up[i]));
}

void playAgent(const StepView& v, AgentColumns& agents, std::size_t i)
{
    const std::vector<ActionPlace>& places = v.set.actionPoints;
    if (agents.out[i] || v.traffic.isDriven(i) || v.type(i).kind != AgentKind::Pedestrian)
        return;
    const glm::vec2 p = xz(agents.pos[i]);
    if (const std::int32_t at = agents.pointAt[i]; at >= 0) {
        const ActionPlace& place = places[std::size_t(at)];
        if (place.faces)
            turnTowards(agents, i, place.facing, glm::radians(kActionTurnDegPerS) * v.clock.dt);
        agents.pointLeftS[i] -= v.clock.dt;
        // Done (within half a step, so that whole steps of a duration play it out exactly):
        // on to its goal or path.
        if (agents.pointLeftS[i] <= 0.5f * v.clock.dt) {
            agents.pointAt[i] = -1;
            agents.pointLeftS[i] = 0.0f;
            agents.stopped[i] = 0;
        }
        return;
    }
    if (agents.stopped[i] || agents.escaping[i])
        return;
    if (const std::int32_t last = agents.pointLast[i]; last >= 0) {
        const ActionPlace& place = places[std::size_t(last)];
        if (glm::distance(p, place.position) >= place.radiusM)
            agents.pointLast[i] = -1;  // it left the disk: it may stop there on a later visit
    }
    // The nearest point whose disk holds its centre.
    std::int32_t entered = -1;
    float nearest = 0.0f;
    const std::uint16_t type = agents.info[i].typeIndex;
    for (std::size_t k = 0; k < places.size(); ++k) {
        const ActionPlace& place = places[k];
        const glm::vec2 d = p - place.position;
        const float d2 = glm::dot(d, d);
        if (d2 < place.radiusM * place.radiusM && place.forType[type] && (entered < 0 || d2 < nearest)) {
            entered = std::int32_t(k);
            nearest = d2;
        }
    }
    if (entered < 0 || entered == agents.pointLast[i])
        return;
    const ActionPlace& place = places[std::size_t(entered)];
    agents.pointLast[i] = entered;
    if (place.chance < 1.0f && !(rngUniform(v.seed, agents.info[i].id, v.clock.step, kStopDraw) < place.chance))
        return;  // passes by this time
    agents.pointAt[i] = entered;
    agents.pointLeftS[i] = place.durationS;
    agents.stopped[i] = 1;
    agents.vel[i] = glm::vec3(0.0f);
}

}  // namespace

std::vector<ActionPlace> actionPlaces(const Scene& scene)
{
    std::vector<ActionPlace> out;
    for (const ActionPoint& a : scene.actionPoints) {
        ActionPlace p;
        p.position = a.position;
        p.radiusM = a.radiusM;
        p.clip = clipFromName(a.action).value_or(Clip::LookAround);
        p.durationS = a.durationS;
        p.faces = a.faces;
        const float h = glm::radians(a.facingDeg);
        p.facing = glm::vec3(std::cos(h), 0.0f, -std::sin(h));
        p.chance = a.chance;
        p.forType.assign(scene.agentTypes.size(), a.types.empty() ? 1 : 0);
        for (const std::string& name : a.types)
            for (std::size_t t = 0; t < scene.agentTypes.size(); ++t)
                if (scene.agentTypes[t].name == name)
                    p.forType[t] = 1;
        out.push_back(std::move(p));
    }
    return out;
}

void playActionPoints(const StepView& v, AgentColumns& agents)
{
    if (v.set.actionPoints.empty())
        return;
    v.team.forChunks(agents.size(), 1024, [&](std::size_t begin, std::size_t end, int) {
        for (std::size_t i = begin; i < end; ++i)
            playAgent(v, agents, i);
    });
}

}  // namespace throng::sim
