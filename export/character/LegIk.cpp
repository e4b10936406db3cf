#include "export/character/LegIk.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>

namespace throng::exporting {

glm::quat turnBetween(const glm::vec3& from, const glm::vec3& to)
{
    const glm::vec3 u = glm::normalize(from), v = glm::normalize(to);
    const float c = glm::dot(u, v);
    if (c < -0.999999f) {
        // Opposite: half a turn about any axis square to u.
        glm::vec3 axis = glm::cross(u, glm::vec3(1.0f, 0.0f, 0.0f));
        if (glm::length(axis) < 1e-3f)
            axis = glm::cross(u, glm::vec3(0.0f, 1.0f, 0.0f));
        return glm::angleAxis(3.14159265f, glm::normalize(axis));
    }
    const glm::vec3 axis = glm::cross(u, v);
    return glm::normalize(glm::quat(1.0f + c, axis.x, axis.y, axis.z));
}

namespace {

glm::quat rotationOf(const glm::mat4& m) { return glm::normalize(glm::quat_cast(glm::mat3(m))); }

}  // namespace

void reachWithLeg(const Character& c, const Leg& leg, const glm::vec3& target, Pose& pose)
{
    const std::vector<glm::mat4> g = jointGlobalTransforms(c, pose);
    reachWithLeg(c, leg, g, target, glm::quat(1.0f, 0.0f, 0.0f, 0.0f), pose);
}

void reachWithLeg(const Character& c, const Leg& leg, std::span<const glm::mat4> g, const glm::vec3& target,
                  const glm::quat& footTurn, Pose& pose)
{
    const auto upper = static_cast<std::size_t>(leg.upper), lower = static_cast<std::size_t>(leg.lower),
               foot = static_cast<std::size_t>(leg.foot);
    const glm::vec3 hip(g[upper][3]), knee(g[lower][3]), ankle(g[foot][3]);
    const float a = glm::length(knee - hip), b = glm::length(ankle - knee);
    const bool turnsFoot = std::abs(footTurn.w) < 1.0f - 1e-7f;
    if (a <= 0.0f || b <= 0.0f || (glm::length(target - ankle) < 1e-6f && !turnsFoot))
        return;
    // Hip to target, as far as the leg reaches; the knee in the plane of its bend now.
    glm::vec3 toTarget = target - hip;
    if (glm::length(toTarget) < 1e-6f)
        return;
    const glm::vec3 dir = glm::normalize(toTarget);
    const float d = std::clamp(glm::length(toTarget), std::abs(a - b) + 1e-4f, a + b - 1e-4f);
    glm::vec3 bend = (knee - hip) - glm::dot(knee - hip, dir) * dir;
    if (glm::length(bend) < 1e-6f) {
        // A straight leg: bend the knee the way the thigh's own +X points (forward).
        const glm::vec3 forward(g[upper] * glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
        bend = forward - glm::dot(forward, dir) * dir;
        if (glm::length(bend) < 1e-6f)
            return;
    }
    bend = glm::normalize(bend);
    const float along = (a * a - b * b + d * d) / (2.0f * d);
    const glm::vec3 newKnee = hip + along * dir + std::sqrt(std::max(0.0f, a * a - along * along)) * bend;
    const glm::vec3 newAnkle = hip + d * dir;

    const std::size_t hips = static_cast<std::size_t>(c.joints[upper].parent);
    const glm::quat parentRot = rotationOf(g[hips]), upperRot = rotationOf(g[upper]), lowerRot = rotationOf(g[lower]),
                    footRot = rotationOf(g[foot]);
    const glm::quat turnThigh = turnBetween(knee - hip, newKnee - hip);
    const glm::vec3 shinAfter = turnThigh * (ankle - knee);
    const glm::quat turnShin = turnBetween(shinAfter, newAnkle - newKnee);
    const glm::quat newUpper = turnThigh * upperRot, newLower = turnShin * turnThigh * lowerRot;
    pose.rotations[upper] = glm::normalize(glm::inverse(parentRot) * newUpper);
    pose.rotations[lower] = glm::normalize(glm::inverse(newUpper) * newLower);
    pose.rotations[foot] = glm::normalize(glm::inverse(newLower) * (footTurn * footRot));
}

void plantFeet(const Character& c, Pose& pose, float share)
{
    if (c.legs.empty() || share <= 0.0f)
        return;
    // One leg's reach leaves the other's joint transforms as they were.
    const std::vector<glm::mat4> g = jointGlobalTransforms(c, pose);
    const glm::quat keep(1.0f, 0.0f, 0.0f, 0.0f);
    for (const Leg& leg : c.legs) {
        const glm::vec3 ankle(g[static_cast<std::size_t>(leg.foot)][3]);
        reachWithLeg(c, leg, g, ankle + std::min(share, 1.0f) * (leg.plantedAnkle - ankle), keep, pose);
    }
}

}  // namespace throng::exporting
