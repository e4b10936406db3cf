// Wall following's slide along the wall in the way (Reynolds 1999, "Wall Following"). It
// uses the step's planar helpers (base/detail/PlanarSegments.h), the ones it was written
// with, so a wall follower's path stays exactly as it was.
#include "simcore/steering/WallAvoidance.h"

#include "simcore/base/detail/PlanarSegments.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

// Head-on to a wall, a walker sliding along it faster than this keeps its way.
constexpr float kSlideOnMps = 0.1f;

}  // namespace

glm::vec3 slideAlongWall(const SteeringAgent& self, std::span<const WallSegment> walls, glm::vec3 target,
                         const WallAvoidanceParams& params)
{
    const glm::vec2 p(self.position.x, self.position.z);
    glm::vec2 way(target.x - p.x, target.z - p.y);
    if (glm::dot(way, way) < 1e-8f)
        way = glm::vec2(self.forward.x, self.forward.z);
    if (glm::dot(way, way) < 1e-8f)
        return glm::vec3(0.0f);
    way = glm::normalize(way);
    const float reach = self.radius + params.standoffM + 0.5f;
    float nearest = reach;
    glm::vec2 tangent(0.0f);
    for (const WallSegment& w : walls) {
        const glm::vec2 a(w.a.x, w.a.z), b(w.b.x, w.b.z);
        const glm::vec2 c = closestOnSegment(p, a, b);
        const float d = glm::distance(p, c);
        const glm::vec2 along = b - a;
        if (d >= nearest || glm::dot(along, along) < 1e-8f || d < 1e-6f)
            continue;
        // Only a wall that the way actually runs into (a ray from the body's centre
        // widened by its radius) counts; door jambs beside the way do not.
        const glm::vec2 sideways(-way.y, way.x);
        bool blocked = false;
        for (float offset : {-self.radius, 0.0f, self.radius})
            blocked = blocked || segmentsCross(p + sideways * offset, p + sideways * offset + way * reach, a, b);
        if (!blocked)
            continue;
        glm::vec2 t = glm::normalize(along);
        float side = glm::dot(way, t);
        if (std::fabs(side) < 0.2f) {
            // Nearly head-on: keep on the way it already slides, so a walker near the middle
            // of a face does not turn back each time the nearer end changes; from a stand,
            // go round the nearer end.
            const float sliding = glm::dot(glm::vec2(self.velocity.x, self.velocity.z), t);
            if (std::fabs(sliding) > kSlideOnMps)
                side = sliding;
            else
                side = glm::distance(c, a) < glm::distance(c, b) ? -1.0f : 1.0f;
        }
        tangent = side < 0.0f ? -t : t;
        nearest = d;
    }
    return glm::vec3(tangent.x, 0.0f, tangent.y) * self.maxForce;
}

}  // namespace throng::sim
