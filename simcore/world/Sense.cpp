// The sense phase's queries (Sense.h): an agent as the steering functions see it, and
// whom it perceives. They read only the previous state.
#include "simcore/world/Sense.h"

#include "simcore/world/NearestList.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

constexpr float kHeadingLookaheadM = 2.0f;  // m along its path: where a walker "wants to go"

}  // namespace

SteeringAgent steeringAgent(const AgentColumns& agents, const AgentTypes& types, std::size_t i)
{
    const TypeParams& t = types.params[agents.info[i].typeIndex];
    SteeringAgent a;
    a.position = agents.pos[i];
    a.velocity = agents.vel[i];
    a.forward = agents.fwd[i];
    a.side = agents.side[i];
    a.up = agents.up[i];
    a.radius = agents.radius[i];
    a.maxSpeed = agents.maxSpeed[i];
    a.maxForce = t.maxForce;
    a.mass = t.mass;
    a.id = agents.info[i].id;
    return a;
}

float lastNearestBound(const AgentColumns& agents, std::size_t i, glm::vec3 p, float perception2)
{
    constexpr std::size_t k = kMaxNeighbours;
    if (agents.nearCount[i] != k)
        return perception2;
    const std::uint32_t* last = &agents.nearIndex[i * k];
    float far2 = 0.0f;
    for (std::size_t n = 0; n < k; ++n) {
        const std::uint32_t j = last[n];
        const glm::vec3 d = j < agents.pos.size() ? agents.pos[j] - p : glm::vec3(INFINITY);
        far2 = std::max(far2, glm::dot(d, d));
    }
    return std::min(perception2, far2);
}

std::size_t gatherNeighbours(const StepView& v, std::size_t i, Neighbour* out, std::uint32_t* indices)
{
    const TypeParams& t = v.types.params[v.agents.info[i].typeIndex];
    const glm::vec3 p = v.agents.pos[i], fwd = v.agents.fwd[i];
    const float r2 = t.perception * t.perception;
    // The k nearest, ties by id (TieOrder.h), kept sorted by insertion; once k are known
    // the search radius shrinks to the k-th distance, so farther candidates and cells are
    // skipped. A candidate is one 64-bit key: the bits of d2 (>= 0, so they order like the
    // floats) above the index (or rank), so a comparison is one integer compare. A
    // neighbour of higher priority ranks before every other (its top bit is clear), so a
    // dense crowd never loses sight of the ambulance among its nearest neighbours; with
    // priorities in the scene the radius therefore does not shrink.
    const TypeCollision& mine = v.collision(i);
    NearestList<kMaxNeighbours> best;
    float bound = r2;
    const float c = t.cosHalfView;
    // Where ids do not rise with the index, watch for ties, and should one come, search
    // again with ranks for indices (TieOrder.h).
    const bool watch = !v.ties.byIndex();
    auto consider = [&](std::uint32_t j, const glm::vec3& q) {
        if (v.types.makingWay && !collide(mine, v.collision(j)))
            return;  // agents on layers that do not collide do not perceive each other
        const glm::vec3 d = q - p;
        const float d2 = glm::dot(d, d);
        if (d2 > bound || j == i)
            return;
        // Outside the view cone (but a touching neighbour is always felt).
        const float contact = v.agents.radius[i] + v.agents.radius[j];
        if (outsideViewCone(d, d2, fwd, c) && d2 > contact * contact)
            return;
        const bool urgent = v.types.makingWay && v.collision(j).priority > mine.priority;
        const std::uint64_t key = nearestKey(d2, best.byRank ? v.ties.rank(j) : j, !urgent);
        if ((watch ? best.insertWatchingTies(key) : best.insert(key)) && best.full() && !v.types.makingWay)
            bound = best.worstDistance2();
    };
    // Nearest rows first: once the k best are found, farther cells are skipped. As the
    // kernels do, start from last step's k nearest (lastNearestBound) and search in full
    // only when fewer than k lie within them: the result is the same either way. (Not when
    // types make way: the bound then never shrinks.)
    const float guess2 = v.warmSearch && !v.types.makingWay ? lastNearestBound(v.agents, i, p, r2) : r2;
    auto search = [&](float start, bool ranked) {
        best.clear();
        best.byRank = ranked;
        bound = start;
        v.grid.forEachNearest(p, t.perception, [&] { return bound; }, consider);
    };
    search(guess2, false);
    finishNearest(best, guess2, r2, watch, search);
    for (std::size_t n = 0; n < best.count; ++n) {
        const auto j = best.index(n, v.ties);
        if (out)
            out[n] = {v.agents.pos[j], v.agents.vel[j], v.agents.fwd[j], v.agents.radius[j], v.agents.info[j].id};
        indices[n] = j;
    }
    return best.count;
}

glm::vec3 flowDirection(const StepView& v, glm::vec3 p)
{
    // The strokes' sketched field where it solved (WorldNav.cpp).
    if (glm::vec3 sketched; v.nav.sketchedFlow(p, sketched))
        return sketched;
    // The nearest stroke segment whose band holds p gives the direction.
    const glm::vec2 q = xz(p);
    float bestD = INFINITY;
    glm::vec2 dir(0.0f);
    for (const FlowSegment& s : v.set.flow) {
        const float d = glm::distance(q, closestOnSegment(q, s.a, s.b));
        if (d <= s.halfWidth && d < bestD && s.a != s.b) {
            bestD = d;
            dir = glm::normalize(s.b - s.a);
        }
    }
    return {dir.x, 0.0f, dir.y};
}

glm::vec2 wantedHeading(const StepView& v, std::size_t i)
{
    const glm::vec2 p = xz(v.agents.pos[i]);
    if (v.agents.path[i] >= 0) {
        // The point a little ahead of the nearest point of its path: where it is heading
        // even while it stands still or rounds a corner.
        const Path& path = v.set.paths[std::size_t(v.agents.path[i])];
        const std::size_t count = path.points.size(), segments = path.closed ? count : count - 1;
        float best = 1e30f;
        std::size_t seg = 0;
        float along = 0.0f;
        for (std::size_t k = 0; k < segments; ++k) {
            const glm::vec2 a = path.points[k], b = path.points[(k + 1) % count];
            const glm::vec2 c = closestOnSegment(p, a, b);
            const float d = glm::distance(p, c);
            if (d < best) {
                best = d;
                seg = k;
                along = glm::distance(a, c);
            }
        }
        float ahead = kHeadingLookaheadM;
        for (std::size_t step = 0; step < segments; ++step) {
            const glm::vec2 a = path.points[seg], b = path.points[(seg + 1) % count];
            const float len = glm::distance(a, b);
            if (along + ahead <= len || (!path.closed && seg + 1 == segments))
                return a + (b - a) * (std::min(along + ahead, len) / std::max(len, 1e-6f)) - p;
            ahead -= len - along;
            along = 0.0f;
            seg = (seg + 1) % segments;
        }
    }
    if (v.agents.goal[i] >= 0)
        return xz(v.nav.goal(i, glm::vec3(v.agents.goalSpot[i].x, 0.0f, v.agents.goalSpot[i].y))) - p;
    const glm::vec2 vel = xz(v.agents.vel[i]);
    return glm::dot(vel, vel) > 1e-4f ? vel : xz(v.agents.fwd[i]);
}

}  // namespace throng::sim
