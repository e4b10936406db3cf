#include "simcore/hero/HeroTrack.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {
constexpr float kMovingSpeed = 1e-4f;  // m/s: slower counts as standing for the heading
constexpr double kSnapS = 1e-5;        // s: this close to a keyframe's time is that keyframe
glm::vec2 ground(glm::vec3 v) { return {v.x, v.z}; }
}  // namespace

HeroTrack::HeroTrack(const Hero& hero, HeroInterpolation mode) : HeroTrack(hero.keyframes, hero.clearanceM, mode) {}

HeroTrack::HeroTrack(std::vector<Keyframe> keys, float clearanceM, HeroInterpolation mode)
    : m_keys(std::move(keys)), m_clearanceM(clearanceM), m_mode(mode)
{
}

std::vector<Keyframe> HeroTrack::fromFrames(const std::vector<glm::vec3>& positions, float fps)
{
    std::vector<Keyframe> keys;
    keys.reserve(positions.size());
    for (std::size_t n = 0; n < positions.size(); ++n)
        keys.push_back({float(double(n) / double(fps)), positions[n]});  // as the scene loader keys them
    return keys;
}

std::size_t HeroTrack::segmentAt(double t) const
{
    const auto it = std::upper_bound(m_keys.begin(), m_keys.end(), t,
                                     [](double x, const Keyframe& k) { return x < double(k.timeS); });
    const std::size_t k = std::size_t(it - m_keys.begin());
    return std::min(k == 0 ? 0 : k - 1, m_keys.size() - 2);
}

glm::vec3 HeroTrack::tangent(std::size_t k) const
{
    const std::size_t a = k == 0 ? 0 : k - 1, b = std::min(k + 1, m_keys.size() - 1);
    const float dt = m_keys[b].timeS - m_keys[a].timeS;
    return dt > 0.0f ? (m_keys[b].position - m_keys[a].position) / dt : glm::vec3(0.0f);
}

glm::vec3 HeroTrack::positionAt(double t) const
{
    if (m_keys.empty())
        return glm::vec3(0.0f);
    if (m_keys.size() == 1 || t <= double(m_keys.front().timeS))
        return m_keys.front().position;
    if (t >= double(m_keys.back().timeS))
        return m_keys.back().position;
    const std::size_t k = segmentAt(t);
    const Keyframe &k0 = m_keys[k], &k1 = m_keys[k + 1];
    // Exactly the keyframe near its time, whether the caller computed frame / fps in
    // float or in double.
    if (t - double(k0.timeS) <= kSnapS)
        return k0.position;
    if (double(k1.timeS) - t <= kSnapS)
        return k1.position;
    const double h = double(k1.timeS) - double(k0.timeS);
    const float u = float((t - double(k0.timeS)) / h);
    if (m_mode == HeroInterpolation::Linear)
        return k0.position + (k1.position - k0.position) * u;
    // Cubic Hermite basis with Catmull-Rom tangents scaled to the segment's duration.
    const float u2 = u * u, u3 = u2 * u, hf = float(h);
    const float h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    return k0.position * h00 + tangent(k) * (h10 * hf) + k1.position * h01 + tangent(k + 1) * (h11 * hf);
}

glm::vec3 HeroTrack::velocityAt(double t) const
{
    if (m_keys.size() < 2 || t < double(m_keys.front().timeS) || t >= double(m_keys.back().timeS))
        return glm::vec3(0.0f);
    const std::size_t k = segmentAt(t);
    const Keyframe &k0 = m_keys[k], &k1 = m_keys[k + 1];
    const float hf = k1.timeS - k0.timeS;
    if (m_mode == HeroInterpolation::Linear)
        return (k1.position - k0.position) / hf;
    const float u = float((t - double(k0.timeS)) / double(hf)), u2 = u * u;
    const float d00 = 6 * u2 - 6 * u, d10 = 3 * u2 - 4 * u + 1, d01 = -6 * u2 + 6 * u, d11 = 3 * u2 - 2 * u;
    return (k0.position * d00 + k1.position * d01) / hf + tangent(k) * d10 + tangent(k + 1) * d11;
}

glm::vec2 HeroTrack::forwardAt(double t) const
{
    const glm::vec2 v = ground(velocityAt(t));
    if (glm::length(v) > kMovingSpeed)
        return glm::normalize(v);
    if (m_keys.size() < 2)
        return {1.0f, 0.0f};
    // Standing: the direction of the last segment that moved before t, else the first after.
    const std::size_t k = t >= double(m_keys.back().timeS) ? m_keys.size() - 2 : segmentAt(t);
    for (std::size_t j = k + 1; j-- > 0;) {
        const glm::vec2 d = ground(m_keys[j + 1].position - m_keys[j].position);
        if (glm::length(d) > 1e-6f)
            return glm::normalize(d);
    }
    for (std::size_t j = k + 1; j + 1 < m_keys.size(); ++j) {
        const glm::vec2 d = ground(m_keys[j + 1].position - m_keys[j].position);
        if (glm::length(d) > 1e-6f)
            return glm::normalize(d);
    }
    return {1.0f, 0.0f};
}

float HeroTrack::headingDegAt(double t) const
{
    // Heading 90 faces -z (north): the angle of (x, -z).
    const glm::vec2 f = forwardAt(t);
    return float(std::atan2(-double(f.y), double(f.x)) * 180.0 / 3.14159265358979323846);
}

HeroPush heroPush(glm::vec2 heroPos, glm::vec2 heroVelocity, float clearanceM, glm::vec2 walkerPos,
                  float walkerRadiusM, std::uint32_t walkerId)
{
    HeroPush push;
    const float need = clearanceM + walkerRadiusM;
    const glm::vec2 away = walkerPos - heroPos;
    const float d = glm::length(away);
    if (!(d < need))
        return push;
    push.inside = true;
    const float heroSpeed = glm::length(heroVelocity);
    const glm::vec2 heroDir = heroSpeed > kMovingSpeed ? heroVelocity / heroSpeed : glm::vec2(1.0f, 0.0f);
    const glm::vec2 left{heroDir.y, -heroDir.x};
    glm::vec2 n;
    if (d > 1e-6f)
        n = away / d;
    else
        n = (walkerId & 1u) ? left : -left;
    // Slightly beyond the rim, so rounding never leaves the walker a hair inside.
    push.displacement = n * (need - d) * (1.0f + 1e-5f) + n * 1e-5f;
    // Make room sideways off a moving hero's line; straight away from a standing one.
    if (heroSpeed > kMovingSpeed) {
        const float side = glm::dot(n, left) >= 0.0f ? 1.0f : -1.0f;  // the walker's side of the hero's line
        push.velocity = left * side * std::max(heroSpeed, 1.0f);
        if (glm::dot(away, heroDir) > 0.0f)
            push.velocity += heroDir * heroSpeed;  // keep ahead of it meanwhile
    } else {
        push.velocity = n;
    }
    return push;
}

}  // namespace throng::sim
