#include "simcore/world/Formations.h"

#include "simcore/base/Rng.h"
#include "simcore/base/detail/PlanarSegments.h"
#include "simcore/world/detail/AgentStreams.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace throng::sim {

using detail::xz;

namespace {

// A companion stands this far beside the next, m, on top of two bodies: about an
// elbow's room (Moussaid et al. 2010 measured walking groups abreast at 0.7 to 0.8 m).
constexpr float kCompanionGapM = 0.3f;
// An anchor walks at most this share of its slowest member's top speed, so members who
// fell behind can close up.
constexpr float kAnchorShare = 0.9f;
// Companions: an anchor slows from this lag of a member's, and stands at the second.
constexpr float kCompanionWaitFromM = 1.5f, kCompanionWaitToM = 4.0f;

// Where a target of the group lies: its goal, else its path's first point.
bool groupTarget(const Scene& scene, const SpawnGroup& group, glm::vec2& target)
{
    if (const Goal* g = scene.findGoal(group.goal)) {
        target = g->position;
        return true;
    }
    if (const Path* p = scene.findPath(group.path); p && !p->points.empty()) {
        target = p->points.front();
        return true;
    }
    return false;
}

// The member nearest the target (the group's front), lowest index on a tie.
std::size_t frontMember(const AgentColumns& agents, std::size_t first, std::size_t count, glm::vec2 target)
{
    std::size_t best = first;
    float bestD = std::numeric_limits<float>::max();
    for (std::size_t i = first; i < first + count; ++i)
        if (const float d = glm::length(xz(agents.pos[i]) - target); d < bestD) {
            bestD = d;
            best = i;
        }
    return best;
}

glm::vec2 rightOf(glm::vec2 forward) { return {-forward.y, forward.x}; }

// How near segment p0-p1 passes segment a-b (0 where they cross).
float segmentGap(glm::vec2 p0, glm::vec2 p1, glm::vec2 a, glm::vec2 b)
{
    if (detail::segmentsCross(p0, p1, a, b))
        return 0.0f;
    auto gap = [](glm::vec2 p, glm::vec2 s0, glm::vec2 s1) {
        return glm::length(detail::closestOnSegment(p, s0, s1) - p);
    };
    return std::min({gap(p0, a, b), gap(p1, a, b), gap(a, p0, p1), gap(b, p0, p1)});
}

}  // namespace

std::vector<glm::vec2> Formations::layout(const GroupFormation& f, std::size_t count)
{
    std::vector<glm::vec2> slots;
    slots.reserve(count);
    const float s = f.spacingM;
    switch (f.shape) {
    case FormationShape::Line:
        // Side by side with the anchor in the middle: right, left, further right, ...
        for (std::size_t k = 0; k < count; ++k)
            slots.push_back({(k % 2 == 0 ? 1.0f : -1.0f) * float(k / 2 + 1) * s, 0.0f});
        break;
    case FormationShape::Column: {
        // Rows of `width` behind the anchor, centred on its line.
        const std::size_t w = std::max<std::uint32_t>(f.width, 1);
        for (std::size_t k = 0; k < count; ++k)
            slots.push_back({(float(k % w) - 0.5f * float(w - 1)) * s, -float(k / w + 1) * s});
        break;
    }
    case FormationShape::Wedge:
        // An arrow: the anchor at the tip, row r of r + 1 walkers, rows an equilateral
        // triangle's height apart.
        for (std::size_t r = 1; slots.size() < count; ++r)
            for (std::size_t c = 0; c <= r && slots.size() < count; ++c)
                slots.push_back({(float(c) - 0.5f * float(r)) * s, -float(r) * s * 0.8660254f});
        break;
    case FormationShape::None: break;
    }
    return slots;
}

void Formations::build(const Scene& scene, const AgentColumns& agents, std::uint64_t seed)
{
    bool any = false;
    for (const SpawnGroup& g : scene.groups)
        any = any || g.formation.shape != FormationShape::None || g.companions.y >= 2;
    if (!any)
        return;
    const std::size_t n = agents.size();
    m_anchor.assign(n, -1);
    m_slot.assign(n, glm::vec2(0.0f));
    m_behind.assign(n, glm::vec2(0.0f));
    m_companion.assign(n, 0);
    m_flier.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint16_t t = agents.info[i].typeIndex;
        m_flier[i] = t < scene.agentTypes.size() && scene.agentTypes[t].kind == AgentKind::Flier ? 1 : 0;
    }
    m_isAnchor.assign(n, 0);
    m_basePace.assign(n, 1.0f);
    m_waitFromM.assign(n, 1.0f);
    m_waitToM.assign(n, 2.0f);
    m_pace.assign(n, 1.0f);
    m_lagM.assign(n, 0.0f);
    std::size_t first = scene.agents.size();
    for (std::size_t g = 0; g < scene.groups.size(); first += scene.groups[g].count, ++g) {
        const SpawnGroup& group = scene.groups[g];
        if (group.count == 0 || first + group.count > n)
            continue;
        glm::vec2 target(0.0f);
        const bool hasTarget = groupTarget(scene, group, target);
        if (group.companions.y >= 2) {
            buildCompanions(group, g, target, hasTarget, first, agents, seed);
            continue;
        }
        if (group.formation.shape == FormationShape::None)
            continue;
        std::int32_t anchor = -1;
        if (group.leader != 0)
            for (std::size_t j = 0; j < n && anchor < 0; ++j)
                if (agents.info[j].id == group.leader)
                    anchor = std::int32_t(j);
        if (anchor < 0)
            anchor = std::int32_t(hasTarget ? frontMember(agents, first, group.count, target) : first);
        buildFormation(group, anchor, first, agents);
    }
}

void Formations::buildFormation(const SpawnGroup& group, std::int32_t anchor, std::size_t first,
                                const AgentColumns& agents)
{
    std::vector<std::size_t> members;
    for (std::size_t i = first; i < first + group.count; ++i)
        if (std::int32_t(i) != anchor)
            members.push_back(i);
    const std::vector<glm::vec2> slots = layout(group.formation, members.size());
    // Slots by rows from the front, and members by how far ahead they start in the anchor's
    // frame: each row takes the members furthest ahead that are left, left to right.
    const auto a = std::size_t(anchor);
    const glm::vec2 fwd = glm::length(xz(agents.fwd[a])) > 0.0f ? glm::normalize(xz(agents.fwd[a])) : glm::vec2(1, 0);
    const glm::vec2 right = rightOf(fwd), origin = xz(agents.pos[a]);
    auto local = [&](std::size_t i) {
        const glm::vec2 d = xz(agents.pos[i]) - origin;
        return glm::vec2(glm::dot(d, right), glm::dot(d, fwd));
    };
    std::stable_sort(members.begin(), members.end(),
                     [&](std::size_t p, std::size_t q) { return local(p).y > local(q).y; });
    std::vector<std::size_t> order(slots.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) { return slots[p].y > slots[q].y; });
    float slowest = agents.maxSpeed[a];
    for (std::size_t k = 0; k < order.size();) {
        std::size_t end = k;
        while (end < order.size() && std::abs(slots[order[end]].y - slots[order[k]].y) < 1e-4f)
            ++end;
        std::vector<std::size_t> row(members.begin() + std::ptrdiff_t(k), members.begin() + std::ptrdiff_t(end));
        std::vector<std::size_t> rowSlots(order.begin() + std::ptrdiff_t(k), order.begin() + std::ptrdiff_t(end));
        std::stable_sort(row.begin(), row.end(), [&](std::size_t p, std::size_t q) { return local(p).x < local(q).x; });
        std::stable_sort(rowSlots.begin(), rowSlots.end(),
                         [&](std::size_t p, std::size_t q) { return slots[p].x < slots[q].x; });
        for (std::size_t r = 0; r < row.size(); ++r) {
            m_anchor[row[r]] = anchor;
            m_slot[row[r]] = slots[rowSlots[r]];
            slowest = std::min(slowest, agents.maxSpeed[row[r]]);
        }
        k = end;
    }
    const float s = group.formation.spacingM;
    setPaceRange(a, s, 3.0f * s, slowest, agents);
}

void Formations::buildCompanions(const SpawnGroup& group, std::size_t groupIndex, glm::vec2 target, bool hasTarget,
                                 std::size_t first, const AgentColumns& agents, std::uint64_t seed)
{
    const std::uint32_t lo = std::max(1u, group.companions.x), hi = std::max(lo, group.companions.y);
    std::size_t k = first;
    const std::size_t end = first + group.count;
    // Members are numbered by where they start (World::spawnGroup), so consecutive members
    // stand near each other: each small group is the next few.
    for (std::uint64_t small = 0; k < end; ++small) {
        const float u = rngUniform(seed, (std::uint64_t(groupIndex + 1) << 32) | small, 0, detail::kCompanions);
        const std::uint32_t drawn = lo + std::min<std::uint32_t>(hi - lo, std::uint32_t(u * float(hi - lo + 1)));
        const std::size_t size = std::min<std::size_t>(end - k, drawn);
        const std::size_t anchor = hasTarget ? frontMember(agents, k, size, target) : k;
        const float spacing = 2.0f * agents.radius[anchor] + kCompanionGapM;
        float slowest = agents.maxSpeed[anchor];
        // Right, left, further right, ... and one behind the other where there is no room.
        std::size_t rank = 0;
        for (std::size_t i = k; i < k + size; ++i) {
            if (i == anchor)
                continue;
            ++rank;
            m_anchor[i] = std::int32_t(anchor);
            m_companion[i] = 1;
            m_slot[i] = {((rank % 2 == 1) ? 1.0f : -1.0f) * float((rank + 1) / 2) * spacing, 0.0f};
            m_behind[i] = {0.0f, -float(rank) * spacing};
            slowest = std::min(slowest, agents.maxSpeed[i]);
        }
        if (size > 1)
            setPaceRange(anchor, kCompanionWaitFromM, kCompanionWaitToM, slowest, agents);
        k += size;
    }
}

void Formations::setPaceRange(std::size_t anchor, float waitFromM, float waitToM, float slowestMember,
                              const AgentColumns& agents)
{
    m_isAnchor[anchor] = 1;
    m_waitFromM[anchor] = waitFromM;
    m_waitToM[anchor] = std::max(waitToM, waitFromM + 0.5f);
    const float own = agents.maxSpeed[anchor];
    m_basePace[anchor] = own > 0.0f ? std::min(1.0f, kAnchorShare * slowestMember / own) : 1.0f;
    m_pace[anchor] = m_basePace[anchor];
}

std::int32_t Formations::anchorOf(std::size_t i, const AgentColumns& agents) const
{
    if (!active())
        return -1;
    const std::int32_t a = m_anchor[i];
    if (a < 0)
        return -1;
    const auto j = std::size_t(a);
    return agents.out[j] || agents.offstage[j] || agents.arrived[j] ? -1 : a;
}

Formations::SlotTarget Formations::target(std::size_t i, const AgentColumns& agents, const StaticSet& set) const
{
    const std::int32_t anchor = anchorOf(i, agents);
    if (anchor < 0)
        return {};
    const auto a = std::size_t(anchor);
    const glm::vec2 from = xz(agents.pos[a]), self = xz(agents.pos[i]);
    const glm::vec2 fwd =
        glm::length(xz(agents.fwd[a])) > 0.0f ? glm::normalize(xz(agents.fwd[a])) : glm::vec2(1.0f, 0.0f);
    auto place = [&](glm::vec2 slot) { return from + rightOf(fwd) * slot.x + fwd * slot.y; };
    // fn(segment) for the walls near `at` within reach of `at`, the anchor and member i.
    auto eachWall = [&](glm::vec2 at, float room, auto&& fn) {
        const float reach = room + std::max(glm::length(at - from), glm::length(at - self));
        set.walls.forEachNear(at, reach, [&](std::uint32_t k) { fn(set.walls.segment(k)); });
    };
    glm::vec2 slot = m_slot[i], at = place(slot);
    if (m_flier[i])
        return {anchor, glm::vec3(slot.x, 0.0f, slot.y)};  // over walls, in the anchor's frame
    const float room = agents.radius[i] + 0.05f;
    if (m_companion[i]) {
        // Abreast only where the slot and the way to it from the anchor are clear of walls.
        bool blocked = false;
        eachWall(at, room, [&](const Segment& seg) {
            blocked = blocked || glm::length(detail::closestOnSegment(at, seg.a, seg.b) - at) < room ||
                      detail::segmentsCross(from, at, seg.a, seg.b);
        });
        if (blocked) {
            slot = m_behind[i];
            at = place(slot);
        }
    }
    // A wall between the member and its slot, or too near the way for its body: it finds
    // its own way (its navigation, as without the formation) until the way is clear.
    bool cut = false;
    eachWall(at, room, [&](const Segment& seg) { cut = cut || segmentGap(self, at, seg.a, seg.b) < agents.radius[i]; });
    if (cut)
        return {};
    return {anchor, glm::vec3(slot.x, 0.0f, slot.y)};
}

OffsetPursuitParams Formations::slotParams(const SlotTarget& target)
{
    OffsetPursuitParams p;
    p.offsetM = target.offsetM;
    p.slowingDistanceM = 1.5f;
    return p;
}

void Formations::pace(const AgentColumns& agents, const StaticSet& set)
{
    if (!active())
        return;
    const std::size_t n = m_anchor.size();
    std::fill(m_lagM.begin(), m_lagM.end(), 0.0f);
    for (std::size_t i = 0; i < n; ++i) {
        if (m_anchor[i] < 0 || agents.out[i] || agents.offstage[i] || agents.arrived[i])
            continue;
        // A member cut off from its slot by a wall finds its own way: its anchor walks on
        // (standing where it is, in the gap it came through, it would block that way), and
        // waits once the member is in sight again.
        const SlotTarget t = target(i, agents, set);
        if (t.anchor < 0)
            continue;
        const auto a = std::size_t(t.anchor);
        const Neighbour anchor{agents.pos[a], agents.vel[a], agents.fwd[a], agents.radius[a], agents.info[a].id};
        const float lag = glm::length(xz(agents.pos[i]) - xz(pointInFrameOf(anchor, t.offsetM)));
        m_lagM[a] = std::max(m_lagM[a], lag);
    }
    for (std::size_t a = 0; a < n; ++a)
        if (m_isAnchor[a]) {
            const float t = (m_waitToM[a] - m_lagM[a]) / (m_waitToM[a] - m_waitFromM[a]);
            m_pace[a] = m_basePace[a] * std::clamp(t, 0.0f, 1.0f);
        }
}

}  // namespace throng::sim
