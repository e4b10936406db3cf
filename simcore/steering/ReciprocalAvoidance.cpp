#include "simcore/steering/ReciprocalAvoidance.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace throng::sim {

namespace {

constexpr std::size_t kMaxLines = 16;
constexpr float kEpsilon = 1e-5f;

// A half-plane of allowed velocities: those to the left of the directed line. Trivial
// (no initialisers), so a Lines on the stack costs nothing until lines are added; only
// the first `count` are ever read.
struct Line {
    glm::vec2 point;
    glm::vec2 direction;
};

struct Lines {
    std::array<Line, kMaxLines> line;
    std::size_t count = 0;
};

float det(glm::vec2 a, glm::vec2 b)
{
    return a.x * b.y - a.y * b.x;
}

// The best velocity on line `k` within the speed circle and the half-planes before it.
bool solveOnLine(const Lines& lines, std::size_t k, float radius, glm::vec2 optimum, bool directionOnly,
                 glm::vec2& result)
{
    const Line& l = lines.line[k];
    const float along = glm::dot(l.point, l.direction);
    const float discriminant = along * along + radius * radius - glm::dot(l.point, l.point);
    if (discriminant < 0.0f)
        return false;  // the line misses the speed circle
    const float root = std::sqrt(discriminant);
    float tLeft = -along - root, tRight = -along + root;
    for (std::size_t i = 0; i < k; ++i) {
        const float denominator = det(l.direction, lines.line[i].direction);
        const float numerator = det(lines.line[i].direction, l.point - lines.line[i].point);
        if (std::fabs(denominator) <= kEpsilon) {
            if (numerator < 0.0f)
                return false;  // parallel and outside
            continue;
        }
        const float t = numerator / denominator;
        if (denominator >= 0.0f)
            tRight = std::min(tRight, t);
        else
            tLeft = std::max(tLeft, t);
        if (tLeft > tRight)
            return false;
    }
    if (directionOnly) {
        result = l.point + (glm::dot(optimum, l.direction) > 0.0f ? tRight : tLeft) * l.direction;
    } else {
        const float t = std::clamp(glm::dot(l.direction, optimum - l.point), tLeft, tRight);
        result = l.point + t * l.direction;
    }
    return true;
}

// Incremental 2-D linear program; returns the index of the first line it could not
// satisfy, or lines.count when all hold.
std::size_t solvePlane(const Lines& lines, float radius, glm::vec2 optimum, bool directionOnly, glm::vec2& result)
{
    if (directionOnly)
        result = optimum * radius;
    else if (glm::dot(optimum, optimum) > radius * radius)
        result = glm::normalize(optimum) * radius;
    else
        result = optimum;
    for (std::size_t i = 0; i < lines.count; ++i) {
        if (det(lines.line[i].direction, lines.line[i].point - result) > 0.0f) {
            const glm::vec2 before = result;
            if (!solveOnLine(lines, i, radius, optimum, directionOnly, result)) {
                result = before;
                return i;
            }
        }
    }
    return lines.count;
}

// No velocity satisfies every half-plane: minimise the largest violation instead.
void solveLeastViolation(const Lines& lines, std::size_t first, float radius, glm::vec2& result)
{
    float distance = 0.0f;
    for (std::size_t i = first; i < lines.count; ++i) {
        const Line& li = lines.line[i];
        if (det(li.direction, li.point - result) <= distance)
            continue;
        Lines projected;
        for (std::size_t j = 0; j < i; ++j) {
            const Line& lj = lines.line[j];
            Line p;
            const float d = det(li.direction, lj.direction);
            if (std::fabs(d) <= kEpsilon) {
                if (glm::dot(li.direction, lj.direction) > 0.0f)
                    continue;  // same direction: lj adds nothing
                p.point = 0.5f * (li.point + lj.point);
            } else {
                p.point = li.point + (det(lj.direction, li.point - lj.point) / d) * li.direction;
            }
            const glm::vec2 dir = lj.direction - li.direction;
            const float len = glm::length(dir);
            if (len <= kEpsilon)
                continue;
            p.direction = dir / len;
            projected.line[projected.count++] = p;
        }
        const glm::vec2 before = result;
        if (solvePlane(projected, radius, glm::vec2(-li.direction.y, li.direction.x), true, result) < projected.count)
            result = before;  // rounding: keep the previous answer
        distance = det(li.direction, li.point - result);
    }
}

}  // namespace

glm::vec2 avoidReciprocally(const PlanarBody& self, glm::vec2 preferred, std::span<const PlanarNeighbour> neighbours,
                            float dt, const ReciprocalAvoidanceParams& params)
{
    if (self.maxSpeed <= 0.0f)
        return glm::vec2(0.0f);
    const float invHorizon = 1.0f / std::max(params.timeHorizonS, 1e-3f);
    const float invStep = 1.0f / std::max(dt, 1e-6f);
    Lines lines;
    for (const PlanarNeighbour& other : neighbours) {
        if (lines.count == kMaxLines)
            break;
        const glm::vec2 relPos = other.position - self.position;
        const glm::vec2 relVel = self.velocity - other.velocity;
        const float distSq = glm::dot(relPos, relPos);
        const float r = self.radius + other.radius;
        Line line;
        glm::vec2 u;
        if (distSq > r * r) {
            // w: from the cut-off circle's centre to the relative velocity.
            const glm::vec2 w = relVel - invHorizon * relPos;
            const float wLenSq = glm::dot(w, w);
            const float dot1 = glm::dot(w, relPos);
            if (dot1 < 0.0f && dot1 * dot1 > r * r * wLenSq) {
                // Nearest boundary point is on the cut-off circle.
                const float wLen = std::sqrt(wLenSq);
                if (wLen <= kEpsilon)
                    continue;
                const glm::vec2 unitW = w / wLen;
                line.direction = glm::vec2(unitW.y, -unitW.x);
                u = (r * invHorizon - wLen) * unitW;
            } else {
                // Nearest boundary point is on a leg of the cone.
                const float leg = std::sqrt(distSq - r * r);
                if (det(relPos, w) > 0.0f)
                    line.direction = glm::vec2(relPos.x * leg - relPos.y * r, relPos.x * r + relPos.y * leg) / distSq;
                else
                    line.direction = -glm::vec2(relPos.x * leg + relPos.y * r, -relPos.x * r + relPos.y * leg) / distSq;
                u = glm::dot(relVel, line.direction) * line.direction - relVel;
            }
        } else {
            // Already touching: part within one step.
            const glm::vec2 w = relVel - invStep * relPos;
            const float wLen = glm::length(w);
            if (wLen <= kEpsilon)
                continue;  // coincident and still: the body collision pass parts them
            const glm::vec2 unitW = w / wLen;
            line.direction = glm::vec2(unitW.y, -unitW.x);
            u = (r * invStep - wLen) * unitW;
        }
        line.point = self.velocity + other.share * u;
        lines.line[lines.count++] = line;
    }
    glm::vec2 result(0.0f);
    const std::size_t failed = solvePlane(lines, self.maxSpeed, preferred, false, result);
    if (failed < lines.count)
        solveLeastViolation(lines, failed, self.maxSpeed, result);
    if (!std::isfinite(result.x) || !std::isfinite(result.y))
        return glm::vec2(0.0f);
    return result;
}

}  // namespace throng::sim
