#include "simcore/layout/LayoutApply.h"

#include "simcore/scene/GroundPolygon.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace throng::sim {

namespace {

constexpr float kDegToRad = 3.14159265358979f / 180.0f;

std::string label(const LayoutOp& op, std::size_t index)
{
    return "layout operation " + std::to_string(index + 1) + " (" + toString(op.kind) +
           (op.name.empty() ? "" : " '" + op.name + "'") + ")";
}

// The ids of each group name: spawn groups' members, and placed agents carrying the name.
std::map<std::string, std::vector<std::uint32_t>> groupMembers(const Scene& scene)
{
    std::map<std::string, std::vector<std::uint32_t>> members;
    std::uint32_t next = firstSpawnedId(scene);
    for (const SpawnGroup& g : scene.groups) {
        std::vector<std::uint32_t>& ids = members[g.name];
        for (std::uint32_t k = 0; k < g.count; ++k)
            ids.push_back(next++);
    }
    for (const Agent& a : scene.agents)
        if (!a.group.empty())
            members[a.group].push_back(a.id);
    return members;
}

// Turns (x, z) by `rad` counter-clockwise seen from above (+y up): as a heading turns.
glm::vec2 turned(glm::vec2 v, float rad)
{
    const float c = std::cos(rad), s = std::sin(rad);
    return {v.x * c + v.y * s, -v.x * s + v.y * c};
}

glm::vec2 ground(const glm::vec3& p) { return {p.x, p.z}; }

void place(AgentFrame& a, glm::vec2 xz)
{
    a.position.x = xz.x;
    a.position.z = xz.y;
}

// The mean place of `agents` present on frame f; false when none is.
bool centreOf(const FrameCache& cache, const std::vector<std::size_t>& agents, std::size_t f, glm::vec2& centre)
{
    glm::dvec2 sum(0.0);
    std::size_t n = 0;
    for (const std::size_t i : agents)
        if (cache.at(f, i).present) {
            sum += glm::dvec2(ground(cache.at(f, i).position));
            ++n;
        }
    if (n == 0)
        return false;
    centre = glm::vec2(sum / double(n));
    return true;
}

void timeOffset(FrameCache& cache, std::size_t agent, const LayoutOp& op, std::size_t first, std::size_t last)
{
    const std::size_t frames = cache.frameCount();
    std::vector<AgentFrame> column(frames);
    for (std::size_t f = 0; f < frames; ++f)
        column[f] = cache.at(f, agent);
    const auto firstPresent = std::find_if(column.begin(), column.end(), [](const AgentFrame& a) { return a.present; });
    if (firstPresent == column.end())
        return;
    for (std::size_t f = first; f <= last; ++f) {
        const long long source = static_cast<long long>(f) - op.frames;
        const std::size_t firstFrame = std::size_t(firstPresent - column.begin());
        AgentFrame a;
        if (source >= static_cast<long long>(frames)) {
            a = column[frames - 1];  // after the recording: its last pose, standing
            a.speed = 0.0f;
            a.clip = Clip::Idle;
        } else if (source < static_cast<long long>(firstFrame)) {
            // Before its (shifted) start: standing in its first pose, or not there yet.
            a = *firstPresent;
            a.present = op.holdFirst;
            a.speed = 0.0f;
            a.clip = Clip::Idle;
        } else {
            a = column[std::size_t(source)];
        }
        cache.edit(f, agent) = a;
    }
}

void applyOp(FrameCache& cache, const LayoutOp& op, const std::vector<std::size_t>& agents, glm::dvec3 origin)
{
    const std::size_t frames = cache.frameCount();
    if (frames == 0 || agents.empty() || op.firstFrame >= frames)
        return;
    const std::size_t first = op.firstFrame, last = std::min(op.lastFrame, frames - 1);
    if (last < first)
        return;
    const glm::vec2 shift(float(origin.x), float(origin.z));  // scene coordinates -> the cache's
    switch (op.kind) {
    case LayoutKind::Translate:
        for (std::size_t f = first; f <= last; ++f)
            for (const std::size_t i : agents) {
                AgentFrame& a = cache.edit(f, i);
                if (a.present)
                    place(a, ground(a.position) + op.offset);
            }
        break;
    case LayoutKind::Rotate: {
        glm::vec2 pivot;
        if (op.pivot)
            pivot = *op.pivot - shift;
        else if (!centreOf(cache, agents, first, pivot))
            return;
        const float rad = op.angleDeg * kDegToRad;
        for (std::size_t f = first; f <= last; ++f)
            for (const std::size_t i : agents) {
                AgentFrame& a = cache.edit(f, i);
                if (!a.present)
                    continue;
                place(a, pivot + turned(ground(a.position) - pivot, rad));
                a.headingRad += rad;
            }
        break;
    }
    case LayoutKind::TimeOffset:
        for (const std::size_t i : agents)
            timeOffset(cache, i, op, first, last);
        break;
    case LayoutKind::Mirror: {
        const glm::vec2 a0 = op.axis[0] - shift;
        const glm::vec2 d = glm::normalize(op.axis[1] - op.axis[0]);
        auto reflect = [&](glm::vec2 v) { return 2.0f * glm::dot(v, d) * d - v; };
        for (std::size_t f = first; f <= last; ++f)
            for (const std::size_t i : agents) {
                AgentFrame& a = cache.edit(f, i);
                if (!a.present)
                    continue;
                place(a, a0 + reflect(ground(a.position) - a0));
                const glm::vec2 facing = reflect({std::cos(a.headingRad), -std::sin(a.headingRad)});
                a.headingRad = std::atan2(-facing.y, facing.x);
            }
        break;
    }
    case LayoutKind::Delete:
        for (std::size_t f = first; f <= last; ++f)
            for (const std::size_t i : agents)
                cache.edit(f, i).present = false;
        break;
    case LayoutKind::Expand:
        for (std::size_t f = first; f <= last; ++f) {
            glm::vec2 centre;
            if (!centreOf(cache, agents, f, centre))
                continue;
            for (const std::size_t i : agents) {
                AgentFrame& a = cache.edit(f, i);
                if (a.present)
                    place(a, centre + op.factor * (ground(a.position) - centre));
            }
        }
        break;
    }
}

}  // namespace

LayoutSelection selectLayoutAgents(const Scene& scene, const LayoutLayer& layer, const FrameCache& recorded)
{
    LayoutSelection selection;
    std::map<std::uint32_t, std::size_t> byId;
    for (std::size_t i = 0; i < recorded.agentCount(); ++i)
        byId.emplace(recorded.agents()[i].id, i);
    const auto members = groupMembers(scene);
    const glm::vec2 shift(float(recorded.origin().x), float(recorded.origin().z));
    for (std::size_t k = 0; k < layer.ops.size(); ++k) {
        const LayoutOp& op = layer.ops[k];
        const AgentSelector& s = op.agents;
        std::set<std::size_t> chosen;
        std::vector<std::uint32_t> missing;
        auto take = [&](std::uint32_t id) {
            if (const auto it = byId.find(id); it != byId.end())
                chosen.insert(it->second);
            else
                missing.push_back(id);
        };
        for (const std::uint32_t id : s.ids)
            take(id);
        for (const std::string& g : s.groups) {
            const auto it = members.find(g);
            if (it == members.end()) {
                selection.messages.push_back(label(op, k) + ": no group named '" + g + "'");
                continue;
            }
            for (const std::uint32_t id : it->second)
                if (const auto found = byId.find(id); found != byId.end())
                    chosen.insert(found->second);
        }
        for (const std::string& t : s.types) {
            const auto type = std::find_if(scene.agentTypes.begin(), scene.agentTypes.end(),
                                           [&](const AgentType& a) { return a.name == t; });
            if (type == scene.agentTypes.end()) {
                selection.messages.push_back(label(op, k) + ": no agent type named '" + t + "'");
                continue;
            }
            const auto index = std::size_t(type - scene.agentTypes.begin());
            for (std::size_t i = 0; i < recorded.agentCount(); ++i)
                if (recorded.agents()[i].typeIndex == index)
                    chosen.insert(i);
        }
        if (s.lasso.size() >= 3 && s.lassoFrame < recorded.frameCount()) {
            std::vector<glm::vec2> polygon;
            for (const glm::vec2 p : s.lasso)
                polygon.push_back(p - shift);
            for (std::size_t i = 0; i < recorded.agentCount(); ++i) {
                const AgentFrame& a = recorded.at(s.lassoFrame, i);
                if (a.present && polygonContains(polygon, ground(a.position)))
                    chosen.insert(i);
            }
        }
        if (!missing.empty()) {
            std::string ids;
            for (std::size_t m = 0; m < missing.size() && m < 8; ++m)
                ids += (m ? ", " : "") + std::to_string(missing[m]);
            selection.messages.push_back(label(op, k) + ": " + std::to_string(missing.size()) +
                                         (missing.size() == 1 ? " agent is" : " agents are") +
                                         " not in the recording (id " + ids + (missing.size() > 8 ? ", ..." : "") +
                                         ")");
        }
        if (chosen.empty() && op.enabled)
            selection.messages.push_back(label(op, k) + " selects no agent of the recording: it changes nothing");
        selection.agents.emplace_back(chosen.begin(), chosen.end());
    }
    return selection;
}

FrameCache applyLayout(const Scene& scene, const FrameCache& recorded, std::vector<std::string>* messages)
{
    FrameCache laid = recorded;
    if (scene.layout.ops.empty())
        return laid;
    const LayoutSelection selection = selectLayoutAgents(scene, scene.layout, recorded);
    for (std::size_t k = 0; k < scene.layout.ops.size(); ++k)
        if (scene.layout.ops[k].enabled)
            applyOp(laid, scene.layout.ops[k], selection.agents[k], recorded.origin());
    if (messages)
        *messages = selection.messages;
    return laid;
}

}  // namespace throng::sim
