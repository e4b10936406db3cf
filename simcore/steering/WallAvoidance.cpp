// Wall avoidance / wall following (Reynolds 1999, "Wall Following"; feelers after Buckland 2005).
#include "simcore/steering/WallAvoidance.h"

#include "simcore/steering/detail/PlanarGeometry.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

// The braking term's gap never counts as less than this, so it stays finite at contact.
constexpr float kMinBrakingGapM = 0.01f;

// The unit normal of wall a-b on the side of p; for p on the wall's line, the side the heading
// h comes from (and the left normal when h runs along the wall).
glm::vec2 wallNormalToward(glm::vec2 p, glm::vec2 a, glm::vec2 b, glm::vec2 h)
{
    const glm::vec2 along = normalizeOr(b - a, glm::vec2(1.0f, 0.0f));
    const glm::vec2 n = -rightOf(along);
    const float side = glm::dot(p - a, n);
    if (std::abs(side) > kTiny)
        return side > 0.0f ? n : -n;
    return glm::dot(h, n) > 0.0f ? -n : n;
}

// Whether the end point e of a wall, nearest to p, is a corner that juts out towards p: a
// door post (an end no other wall of the list shares), or a joint of walls that p lies past
// every one of (the corner of a passage's mouth, where the room's wall meets the passage's).
// A joint p lies in front of a wall of (a room's corner, seen from inside) is not.
bool juttingEnd(std::span<const WallSegment> walls, glm::vec2 e, glm::vec2 p)
{
    for (const WallSegment& w : walls) {
        const glm::vec2 a = xz(finiteOrZero(w.a)), b = xz(finiteOrZero(w.b));
        if ((a == e && glm::dot(p - e, b - e) > 0.0f) || (b == e && glm::dot(p - e, a - e) > 0.0f))
            return false;
    }
    return true;
}

// Whether the wall through segment (o, e) goes on at its end e, by a segment that p lies in
// front of, turning by less than 30 degrees.
bool bendsOnGently(std::span<const WallSegment> walls, glm::vec2 e, glm::vec2 o, glm::vec2 p)
{
    constexpr float kCosGentleBend = 0.866f;
    const glm::vec2 on = normalizeOr(e - o, glm::vec2(0.0f));
    for (const WallSegment& w : walls) {
        const glm::vec2 a = xz(finiteOrZero(w.a)), b = xz(finiteOrZero(w.b));
        if (a != e && b != e)
            continue;
        const glm::vec2 q = a == e ? b : a;
        const bool inFront = glm::dot(p - e, q - e) > 0.0f;
        if (q != o && inFront && glm::dot(normalizeOr(q - e, glm::vec2(0.0f)), on) >= kCosGentleBend)
            return true;
    }
    return false;
}

}  // namespace

glm::vec3 avoidWalls(const SteeringAgent& agent, std::span<const WallSegment> walls, const WallAvoidanceParams& params,
                     const glm::vec3* target)
{
    const glm::vec2 p = xz(finiteOrZero(agent.position));
    const glm::vec2 v = xz(finiteOrZero(agent.velocity));
    const float r = nonNegative(agent.radius);
    const float mass = effectiveMass(agent.mass);
    const glm::vec2 h = planarHeading(agent);
    const float standoff = std::max(nonNegative(params.standoffM), kTiny);
    const float standoffForce = nonNegative(params.standoffGain) * nonNegative(agent.maxForce);
    const float damping = std::max(nonNegative(params.dampingTimeS), kMinResponseTimeS);

    const float length = nonNegative(params.feelerMinM) + glm::length(v) * nonNegative(params.feelerLookaheadS);
    const float angle = finiteOr(params.sideFeelerAngleRad, 0.0f);
    const glm::vec2 feelers[3] = {h, h * std::cos(angle) + rightOf(h) * std::sin(angle),
                                  h * std::cos(angle) - rightOf(h) * std::sin(angle)};
    const float lengths[3] = {length, 0.5f * length, 0.5f * length};

    // The way the standoff of a door post never pushes back along (the header).
    glm::vec2 way = h;
    if (target) {
        const glm::vec2 toTarget = xz(finiteOrZero(*target)) - p;
        const float len = glm::length(toTarget);
        if (len > kTiny)
            way = toTarget / len;
    }
    glm::vec2 force(0.0f);
    for (const WallSegment& w : walls) {
        const glm::vec2 a = xz(finiteOrZero(w.a)), b = xz(finiteOrZero(w.b));
        // The nearest point, exactly an end where it lies past one (closestOnSegment's
        // a + 1 * (b - a) need not be b to the bit, and a door post is told by its end).
        const bool pastA = glm::dot(p - a, b - a) <= 0.0f, pastB = glm::dot(p - b, a - b) <= 0.0f;
        const glm::vec2 c = pastA ? a : pastB ? b : closestOnSegment(p, a, b);
        const bool post = (pastA || pastB) && juttingEnd(walls, c, p);
        // A joint where the wall bends on gently, into a segment that p lies in front of (an
        // arc drawn as segments), is that segment's to push from: its face is nearer. Pushed
        // from and braked for along the line to the joint as well, a walker entering the bend
        // of a corridor 0.8 m wide came to a stand at its start.
        if ((pastA || pastB) && !post && bendsOnGently(walls, c, pastA ? b : a, p))
            continue;
        const float dist = glm::length(p - c);
        const glm::vec2 n = dist > kTiny ? (p - c) / dist : wallNormalToward(p, a, b, h);
        const float gap = dist - r;
        // Standoff term: push in proportion to how far inside the standoff the body is.
        // Inside it the motion along the normal is also damped, so a pushed agent settles instead of bouncing.
        if (gap < standoff) {
            const float depth = (standoff - gap) / standoff;
            glm::vec2 push = n * (standoffForce * depth - glm::dot(v, n) * mass / damping * std::min(depth, 1.0f));
            // At a corner that juts out towards the agent (a door post, or the corner of a
            // passage's mouth: juttingEnd) the standoff only pushes sideways to the agent's
            // way, never back: the two posts of a narrow door pushed a walker back out of the
            // doorway harder than its goal drew it in, and it stood in front of the door for
            // good (issue 23); the two corners where a room's wall meets a passage 1 m wide
            // did the same to walkers in front of the passage (RiMEA test 12). The way is
            // toward the target where one is given: sideways to the heading of a walker that
            // came at a 0.8 m door aslant still pushed it back into the room, round and round
            // in front of the door. The feelers still brake an approach at contact; a room's
            // corners push as before.
            if (post) {
                const float back = glm::dot(push, way);
                if (back < 0.0f)
                    push -= way * back;
            }
            force += push;
        }
        // Feeler term: a wall a feeler meets and the agent closes on gets the braking force that
        // stops the approach at contact.
        const float approach = -glm::dot(v, n);
        if (!(approach > 0.0f) || h == glm::vec2(0.0f))
            continue;
        bool seen = false;
        for (int f = 0; f < 3 && !seen; ++f)
            seen = lengths[f] > kTiny && raySegment(p, feelers[f], lengths[f], a, b) >= 0.0f;
        if (seen)
            force += n * (mass * approach * approach / (2.0f * std::max(gap, kMinBrakingGapM)));
    }
    return fromXz(force);
}

}  // namespace throng::sim
