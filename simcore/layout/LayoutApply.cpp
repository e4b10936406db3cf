#include "simcore/layout/LayoutApply.h"

#include "simcore/layout/LayoutResolve.h"
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

// The mean place of `agents` present in `frame`; false when none is.
bool centreOf(std::span<const AgentFrame> frame, const std::vector<std::size_t>& agents, glm::vec2& centre)
{
    glm::dvec2 sum(0.0);
    std::size_t n = 0;
    for (const std::size_t i : agents)
        if (frame[i].present) {
            sum += glm::dvec2(ground(frame[i].position));
            ++n;
        }
    if (n == 0)
        return false;
    centre = glm::vec2(sum / double(n));
    return true;
}

// Standing still in a held pose: no speed, the idle clip.
AgentFrame standing(AgentFrame a)
{
    a.speed = 0.0f;
    a.clip = Clip::Idle;
    return a;
}

}  // namespace

LayoutSelection selectLayoutAgents(const Scene& scene, const LayoutLayer& layer, const FrameCache& recorded)
{
    LayoutSelection selection;
    const std::size_t n = recorded.agentCount();
    std::map<std::uint32_t, std::size_t> byId;  // recorded agents and copies made so far
    AgentId nextCopy = kFirstCopyId;
    for (std::size_t i = 0; i < n; ++i) {
        byId.emplace(recorded.agents()[i].id, i);
        if (recorded.agents()[i].id >= nextCopy)
            nextCopy = recorded.agents()[i].id + 1;
    }
    std::vector<std::uint16_t> copyTypes;
    auto typeOf = [&](std::size_t i) { return i < n ? recorded.agents()[i].typeIndex : copyTypes[i - n]; };
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
                if (const auto found = byId.find(id); found != byId.end() && found->second < n)
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
            for (std::size_t i = 0; i < n + copyTypes.size(); ++i)
                if (typeOf(i) == index)
                    chosen.insert(i);
        }
        if (s.lasso.size() >= 3 && s.lassoFrame < recorded.frameCount()) {
            std::vector<glm::vec2> polygon;
            for (const glm::vec2 p : s.lasso)
                polygon.push_back(p - shift);
            for (std::size_t i = 0; i < n; ++i) {
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
        if (op.kind == LayoutKind::Resolve && s == AgentSelector{})  // a resolve of every agent
            for (std::size_t i = 0; i < n + copyTypes.size(); ++i)
                chosen.insert(i);
        if (chosen.empty() && op.enabled)
            selection.messages.push_back(label(op, k) + " selects no agent of the recording: it changes nothing");
        selection.agents.emplace_back(chosen.begin(), chosen.end());
        // An enabled duplicate's copies, which later operations may select by id or type.
        if (op.kind == LayoutKind::Duplicate && op.enabled)
            for (const std::size_t i : selection.agents.back()) {
                byId.emplace(nextCopy, n + copyTypes.size());
                selection.copies.push_back({k, i, nextCopy++});
                copyTypes.push_back(typeOf(i));
            }
    }
    return selection;
}

struct LayoutEvaluator::Memo {
    std::map<std::pair<std::size_t, std::size_t>, std::vector<AgentFrame>> frames;  // (ops, frame)
};

LayoutEvaluator::LayoutEvaluator(const Scene& scene, const FrameCache& recorded)
    : m_layer(scene.layout), m_recorded(recorded), m_selection(selectLayoutAgents(scene, scene.layout, recorded)),
      m_shift(float(recorded.origin().x), float(recorded.origin().z))
{
    const std::size_t frames = recorded.frameCount(), n = recorded.agentCount();
    // The laid-out agents: the recording's, then the copies (each of its source's type), and
    // what the swaps show instead, operation after operation.
    m_agents = recorded.agents();
    m_copiesOf.assign(m_layer.ops.size(), {});
    for (std::size_t c = 0; c < m_selection.copies.size(); ++c) {
        const LayoutCopy& copy = m_selection.copies[c];
        AgentInfo info = m_agents[copy.source];
        info.id = copy.id;
        m_agents.push_back(info);
        m_copiesOf[copy.op].emplace_back(copy.source, n + c);
    }
    for (std::size_t k = 0; k < m_layer.ops.size(); ++k) {
        const LayoutOp& op = m_layer.ops[k];
        if (op.kind != LayoutKind::Swap || !op.enabled)
            continue;
        const auto type = std::find_if(scene.agentTypes.begin(), scene.agentTypes.end(),
                                       [&](const AgentType& t) { return !op.type.empty() && t.name == op.type; });
        for (const std::size_t i : m_selection.agents[k]) {
            if (type != scene.agentTypes.end())
                m_agents[i].typeIndex = std::uint16_t(type - scene.agentTypes.begin());
            if (op.look >= 0 && op.look < AgentInfo::kDrawnLook)
                m_agents[i].look = std::uint8_t(op.look);
            if (op.tint != LayoutOp::kKeepTint && op.tint >= -1 && op.tint < 128)
                m_agents[i].tint = std::int8_t(op.tint);
        }
    }
    // Only a time offset asks where an agent's recording starts: a scan of every frame,
    // which a layer without one (the editor extends those frame by frame) never pays for.
    const bool retimes = std::any_of(m_layer.ops.begin(), m_layer.ops.end(),
                                     [](const LayoutOp& op) { return op.kind == LayoutKind::TimeOffset; });
    if (retimes) {
        m_firstPresent.assign(m_agents.size(), frames);
        for (std::size_t f = frames; f-- > 0;)
            for (std::size_t i = 0; i < n; ++i)
                if (recorded.at(f, i).present)
                    m_firstPresent[i] = f;
        // A copy is there from its source's start or its duplicate's first frame, the later.
        for (std::size_t c = 0; c < m_selection.copies.size(); ++c) {
            const LayoutCopy& copy = m_selection.copies[c];
            m_firstPresent[n + c] = std::max(m_firstPresent[copy.source], m_layer.ops[copy.op].firstFrame);
        }
    }
    // What a resolve keeps apart: the bodies (of the types shown) and the walls.
    for (const AgentInfo& a : m_agents)
        m_radius.push_back(a.typeIndex < scene.agentTypes.size() ? scene.agentTypes[a.typeIndex].radiusM : 0.3f);
    for (const Wall& w : scene.walls)
        for (std::size_t p = 0; p + 1 < w.points.size(); ++p)
            m_walls.push_back({w.points[p] - m_shift, w.points[p + 1] - m_shift});
    // A rotation without a pivot turns about its agents' centre on its first frame, as the
    // operations before it left them.
    m_pivots.assign(m_layer.ops.size(), glm::vec2(0.0f));
    for (std::size_t k = 0; k < m_layer.ops.size(); ++k) {
        const LayoutOp& op = m_layer.ops[k];
        if (op.kind != LayoutKind::Rotate)
            continue;
        if (op.pivot) {
            m_pivots[k] = *op.pivot - m_shift;
        } else if (op.firstFrame < frames) {
            Memo memo;
            centreOf(evaluate(k, op.firstFrame, memo), m_selection.agents[k], m_pivots[k]);
        }
    }
}

LayoutEvaluator::Shown LayoutEvaluator::shown(std::size_t k, std::size_t f, std::size_t i) const
{
    // Frame f shows what frame f - later showed before this operation; before the agent's
    // first recorded frame it holds that frame's pose (or is absent), past the recording's
    // end the last frame's.
    const std::size_t frames = m_recorded.frameCount();
    const long long source = static_cast<long long>(f) - m_layer.ops[k].frames;
    if (source >= static_cast<long long>(frames))
        return {frames - 1, true, false};
    if (m_firstPresent[i] >= frames)
        return {f, false, false};  // never recorded: nothing to move
    if (source < static_cast<long long>(m_firstPresent[i]))
        return {m_firstPresent[i], true, true};
    return {std::size_t(source), false, false};
}

AgentFrame LayoutEvaluator::showing(std::size_t k, const Shown& s, const AgentFrame& there) const
{
    AgentFrame a = s.standing ? standing(there) : there;
    if (s.beforeStart)
        a.present = m_layer.ops[k].holdFirst && there.present;
    return a;
}

void LayoutEvaluator::applyInFrame(std::size_t k, std::size_t f, std::span<AgentFrame> out) const
{
    const LayoutOp& op = m_layer.ops[k];
    const std::vector<std::size_t>& agents = m_selection.agents[k];
    switch (op.kind) {
    case LayoutKind::Translate:
        for (const std::size_t i : agents)
            if (out[i].present)
                place(out[i], ground(out[i].position) + op.offset);
        break;
    case LayoutKind::Rotate: {
        const float rad = op.angleDeg * kDegToRad;
        for (const std::size_t i : agents) {
            AgentFrame& a = out[i];
            if (!a.present)
                continue;
            place(a, m_pivots[k] + turned(ground(a.position) - m_pivots[k], rad));
            a.headingRad += rad;
        }
        break;
    }
    case LayoutKind::Mirror: {
        const glm::vec2 a0 = op.axis[0] - m_shift;
        const glm::vec2 d = glm::normalize(op.axis[1] - op.axis[0]);
        auto reflect = [&](glm::vec2 v) { return 2.0f * glm::dot(v, d) * d - v; };
        for (const std::size_t i : agents) {
            AgentFrame& a = out[i];
            if (!a.present)
                continue;
            place(a, a0 + reflect(ground(a.position) - a0));
            const glm::vec2 facing = reflect({std::cos(a.headingRad), -std::sin(a.headingRad)});
            a.headingRad = std::atan2(-facing.y, facing.x);
        }
        break;
    }
    case LayoutKind::Delete:
        for (const std::size_t i : agents)
            out[i].present = false;
        break;
    case LayoutKind::Expand: {
        glm::vec2 centre;
        if (!centreOf(out, agents, centre))
            break;
        for (const std::size_t i : agents)
            if (out[i].present)
                place(out[i], centre + op.factor * (ground(out[i].position) - centre));
        break;
    }
    case LayoutKind::Duplicate:
        for (const auto& [source, copy] : m_copiesOf[k]) {
            out[copy] = out[source];
            if (out[copy].present)
                place(out[copy], ground(out[copy].position) + op.offset);
        }
        break;
    case LayoutKind::ReplaceClip:
        for (const std::size_t i : agents)
            if (out[i].present)
                out[i].clip = op.clip;
        break;
    case LayoutKind::TimeOffset:
        break;  // across frames: evaluate() and allFrames() do it
    case LayoutKind::Swap:
        break;  // not frames: the agents' descriptions (agents())
    case LayoutKind::Resolve:
        resolveInFrame(k, f, out);
        break;
    }
}

void LayoutEvaluator::resolveInFrame(std::size_t k, std::size_t f, std::span<AgentFrame> out) const
{
    // It may move the agents it selects that the operations before it changed on this frame
    // (a copy always): what the simulation placed stays where it is.
    const std::span<const AgentFrame> recorded = m_recorded.frame(f);
    std::vector<std::uint8_t> movable(out.size(), 0);
    for (const std::size_t i : m_selection.agents[k]) {
        const bool copy = i >= recorded.size();
        movable[i] = copy || out[i].position != recorded[i].position ? 1 : 0;
    }
    resolveFrame({out, recorded, m_radius, movable, m_walls});
}

const std::vector<AgentFrame>& LayoutEvaluator::evaluate(std::size_t ops, std::size_t f, Memo& memo) const
{
    const auto key = std::make_pair(ops, f);
    if (const auto it = memo.frames.find(key); it != memo.frames.end())
        return it->second;
    std::vector<AgentFrame> out;
    if (ops == 0) {
        const std::span<const AgentFrame> recorded = m_recorded.frame(f);
        out.assign(recorded.begin(), recorded.end());
        AgentFrame absent;
        absent.present = false;
        out.resize(m_agents.size(), absent);  // the copies, until their duplicate makes them
    } else {
        out = evaluate(ops - 1, f, memo);
        const std::size_t k = ops - 1;
        const LayoutOp& op = m_layer.ops[k];
        if (op.enabled && !m_selection.agents[k].empty() && f >= op.firstFrame && f <= op.lastFrame) {
            if (op.kind == LayoutKind::TimeOffset) {
                for (const std::size_t i : m_selection.agents[k]) {
                    const Shown s = shown(k, f, i);
                    out[i] = showing(k, s, evaluate(k, s.frame, memo)[i]);
                }
            } else {
                applyInFrame(k, f, out);
            }
        }
    }
    return memo.frames.emplace(key, std::move(out)).first->second;
}

void LayoutEvaluator::frame(std::size_t f, std::vector<AgentFrame>& out) const
{
    Memo memo;
    out = evaluate(m_layer.ops.size(), f, memo);
}

FrameCache LayoutEvaluator::allFrames() const
{
    const std::size_t frames = m_recorded.frameCount(), width = m_agents.size(), n = m_recorded.agentCount();
    FrameCache laid;
    if (width == n) {
        laid = m_recorded;
    } else {
        // Wider by the copies: one agent set, the copies absent until their duplicate.
        laid.reset(m_agents, m_recorded.fps(), m_recorded.origin());
        std::vector<AgentFrame> frame(width);
        AgentFrame absent;
        absent.present = false;
        for (std::size_t f = 0; f < frames; ++f) {
            const std::span<const AgentFrame> recorded = m_recorded.frame(f);
            std::copy(recorded.begin(), recorded.end(), frame.begin());
            std::fill(frame.begin() + std::ptrdiff_t(n), frame.end(), absent);
            laid.append(frame);
        }
    }
    const std::vector<AgentInfo>& before = m_recorded.agents();
    for (std::size_t i = 0; i < n; ++i) {
        const AgentInfo& a = m_agents[i];
        if (a.look != before[i].look || a.tint != before[i].tint || a.typeIndex != before[i].typeIndex)
            laid.swapAgent(i, a.typeIndex != before[i].typeIndex ? std::optional<std::uint16_t>(a.typeIndex)
                                                                 : std::nullopt,
                           a.look, a.tint);
    }
    for (std::size_t k = 0; k < m_layer.ops.size(); ++k) {
        const LayoutOp& op = m_layer.ops[k];
        const std::vector<std::size_t>& agents = m_selection.agents[k];
        if (!op.enabled || agents.empty() || op.firstFrame >= frames || op.kind == LayoutKind::Swap)
            continue;
        const std::size_t last = std::min(op.lastFrame, frames - 1);
        if (op.kind == LayoutKind::TimeOffset) {
            std::vector<AgentFrame> column(frames);
            for (const std::size_t i : agents) {
                for (std::size_t f = 0; f < frames; ++f)
                    column[f] = laid.at(f, i);
                for (std::size_t f = op.firstFrame; f <= last; ++f) {
                    const Shown s = shown(k, f, i);
                    laid.edit(f, i) = showing(k, s, column[s.frame]);
                }
            }
        } else {
            for (std::size_t f = op.firstFrame; f <= last; ++f)
                applyInFrame(k, f, std::span<AgentFrame>(&laid.edit(f, 0), width));
        }
    }
    return laid;
}

FrameCache applyLayout(const Scene& scene, const FrameCache& recorded, std::vector<std::string>* messages)
{
    if (scene.layout.ops.empty())
        return recorded;
    const LayoutEvaluator evaluator(scene, recorded);
    if (messages)
        *messages = evaluator.messages();
    return evaluator.allFrames();
}

}  // namespace throng::sim
