#include "export/character/FootPlanter.h"
#include "export/character/PoseMaths.h"

#include "export/character/LegIk.h"
#include "simcore/scene/TerrainHeight.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>

namespace throng::exporting {

namespace {

float smoothstep01(float t)
{
    t = std::clamp(t, 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

glm::vec2 ground(const glm::vec3& p) { return {p.x, p.z}; }

// Heading about +Y of a yaw-only turn, radians.
float headingOf(const glm::quat& q) { return 2.0f * std::atan2(q.y, q.w); }

float angleBetween(float a, float b)
{
    const float d = std::remainder(a - b, 2.0f * kPi);
    return std::abs(d);
}

}  // namespace

FootPlanter::FootPlanter(const Character& c, std::span<const GaitFrame> gait, const RootMotion& motion,
                         const sim::Terrain& terrain)
    : m_character(c), m_gait(gait), m_motion(motion), m_terrain(terrain), m_feet(c.legs.size()),
      m_legJoints(c.joints.size(), 0), m_targets(c.legs.size()), m_stance(c.legs.size())
{
    for (const Leg& leg : c.legs)
        for (int j = leg.foot; j >= 0; j = c.joints[static_cast<std::size_t>(j)].parent)
            m_legJoints[static_cast<std::size_t>(j)] = 1;
}

float FootPlanter::groundAt(glm::vec2 p, const glm::vec3& root) const
{
    // Relative to the root: an agent the recording holds off the terrain keeps its feet
    // where its root is, and a walker (root on the terrain) stands on it.
    return root.y + sim::terrainHeight(m_terrain, p.x, p.y) - sim::terrainHeight(m_terrain, root.x, root.z);
}

glm::vec3 FootPlanter::groundNormalAt(glm::vec2 p) const
{
    constexpr float h = 0.1f;
    const float dx = sim::terrainHeight(m_terrain, p.x + h, p.y) - sim::terrainHeight(m_terrain, p.x - h, p.y);
    const float dz = sim::terrainHeight(m_terrain, p.x, p.y + h) - sim::terrainHeight(m_terrain, p.x, p.y - h);
    return glm::normalize(glm::vec3(-dx / (2.0f * h), 1.0f, -dz / (2.0f * h)));
}

Pose FootPlanter::next()
{
    const std::size_t f = m_frame++;
    if (f >= m_gait.size())
        return gaitPose(m_character, m_gait.empty() ? GaitFrame{} : m_gait.back());
    Pose pose = gaitPose(m_character, m_gait[f]);
    const Character& c = m_character;
    if (c.legs.empty() || f >= m_motion.positions.size() || f >= m_motion.yaw.size())
        return pose;
    const float s = m_motion.heightScale > 0.0f ? m_motion.heightScale : 1.0f;
    const float dt = m_motion.fps > 0.0f ? 1.0f / m_motion.fps : 0.0f;
    const glm::vec3 root = m_motion.positions[f];
    const glm::quat yaw = m_motion.yaw[f], unyaw = glm::inverse(yaw);
    const float heading = headingOf(yaw);
    const auto toWorld = [&](const glm::vec3& p) { return root + yaw * (s * p); };
    const auto toCharacter = [&](const glm::vec3& w) { return unyaw * (w - root) / s; };

    // Only the legs' chains: the arms and head are the clip's and never read here.
    jointGlobalTransforms(c, pose, m_legJoints, m_globals);
    std::vector<glm::mat4>& g = m_globals;
    const std::size_t legs = c.legs.size();
    std::vector<glm::vec3>& target = m_targets;
    std::vector<float>& stance = m_stance;
    // A one-shot (fall, get_up) moves the feet as its clip does: the planting gives way to
    // it as it blends in, and no foot locks until it has blended out.
    float oneShot = 0.0f;
    for (const ActionLayer* layer : {&m_gait[f].fading, &m_gait[f].action})
        if (layer->action >= 0 && c.actions[static_cast<std::size_t>(layer->action)].oneShot)
            oneShot = std::max(oneShot, std::clamp(layer->weight, 0.0f, 1.0f));
    bool anyStepping = false;
    for (const Foot& foot : m_feet)
        anyStepping = anyStepping || (foot.stepping && foot.sinceReleaseS < kReleaseS);
    for (std::size_t i = 0; i < legs; ++i) {
        const Leg& leg = c.legs[i];
        Foot& foot = m_feet[i];
        const glm::vec3 ankleC(g[static_cast<std::size_t>(leg.foot)][3]);
        const glm::vec3 ankle = toWorld(ankleC);
        const float lift = (ankleC.y - leg.plantedAnkle.y) * s;  // above where it would be down, m
        const bool down = lift < kDownM * s;
        const auto release = [&](bool step) {
            foot.locked = false;
            foot.stepping = step;
            foot.offset = foot.lock - ground(ankle);
            foot.sinceReleaseS = 0.0f;
        };
        // While one foot steps, the others hold: an agent always has a foot on the ground.
        bool othersLocked = true;
        for (std::size_t k = 0; k < legs; ++k)
            othersLocked = othersLocked && (k == i || m_feet[k].locked);
        if (foot.locked && oneShot > 0.0f) {
            release(false);
        } else if (foot.locked) {
            const bool drifted = glm::length(foot.lock - ground(ankle)) > kMaxDriftM * s ||
                                 angleBetween(heading, foot.lockHeadingRad) > kMaxTwistRad;
            if (!down && !anyStepping)
                release(false);
            else if (down && drifted && othersLocked && m_gait[f].moveWeight < 0.5f) {
                release(true);
                anyStepping = true;
            }
        } else if (f > 0) {
            foot.sinceReleaseS += dt;
        }
        const float eased = smoothstep01(foot.sinceReleaseS / kReleaseS);
        glm::vec2 at = foot.locked ? foot.lock : ground(ankle) + foot.offset * (1.0f - eased);
        // A foot the clip puts down locks where it is now; a re-stepping one once it has
        // landed where the clip wants it.
        if (!foot.locked && down && oneShot == 0.0f && (!foot.stepping || foot.sinceReleaseS >= kReleaseS)) {
            foot.locked = true;
            foot.stepping = false;
            foot.lock = at;
            foot.lockHeadingRad = heading;
        }
        // A held foot (the clip would lift it while the other steps) stays on the ground.
        float raise = foot.locked ? std::clamp(lift, 0.0f, kDownM * s) : std::max(lift, 0.0f);
        if (foot.stepping && foot.sinceReleaseS < kReleaseS)
            raise += kStepLiftM * s * std::sin(kPi * foot.sinceReleaseS / kReleaseS);
        target[i] = glm::vec3(at.x, groundAt(at, root) + leg.plantedAnkle.y * s + raise, at.y);
        stance[i] = foot.locked ? 1.0f : 1.0f - eased;
    }

    // The hips drop as far as the leg that reaches furthest down needs, so it can.
    float drop = 0.0f;
    for (std::size_t i = 0; i < legs; ++i) {
        const Leg& leg = c.legs[i];
        const auto upper = static_cast<std::size_t>(leg.upper), lower = static_cast<std::size_t>(leg.lower),
                   footJoint = static_cast<std::size_t>(leg.foot);
        const glm::vec3 hip = toWorld(glm::vec3(g[upper][3]));
        const float reach = 0.999f * s *
                            (glm::length(glm::vec3(g[lower][3]) - glm::vec3(g[upper][3])) +
                             glm::length(glm::vec3(g[footJoint][3]) - glm::vec3(g[lower][3])));
        const float across = glm::length(ground(target[i]) - ground(hip)), below = hip.y - target[i].y;
        const float need = across < reach ? below - std::sqrt(reach * reach - across * across) : below;
        drop = std::max(drop, need);
    }
    drop = std::min(drop, kMaxDropM * s) * (1.0f - oneShot);
    if (drop > kKeepM * s) {
        pose.rootTranslation.y -= drop / s;
        for (std::size_t j = 0; j < g.size(); ++j)
            if (m_legJoints[j])
                g[j][3].y -= drop / s;
    }

    for (std::size_t i = 0; i < legs; ++i) {
        // A planted sole lies on the slope; a lifted one eases back to the clip's.
        const glm::vec3 normal = unyaw * groundNormalAt(ground(target[i]));
        const glm::quat tilt = glm::slerp(glm::quat(1.0f, 0.0f, 0.0f, 0.0f),
                                          turnBetween(glm::vec3(0.0f, 1.0f, 0.0f), normal),
                                          stance[i] * (1.0f - oneShot));
        // A foot already where it should be, level, keeps the clip's own joints (the
        // export's key reduction then keeps as few keys as without planting).
        const glm::vec3 now(g[static_cast<std::size_t>(c.legs[i].foot)][3]);
        const glm::vec3 want = now + (toCharacter(target[i]) - now) * (1.0f - oneShot);
        if (glm::length(want - now) < kKeepM && std::abs(tilt.w) > 1.0f - 5e-7f)
            continue;
        reachWithLeg(c, c.legs[i], g, want, tilt, pose);
    }
    return pose;
}

}  // namespace throng::exporting
