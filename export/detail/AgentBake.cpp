#include "export/detail/AgentBake.h"

#include "export/character/FootPlanter.h"
#include "export/detail/KeyReduction.h"

#include <cmath>

namespace throng::exporting::detail {

namespace {

// Rotation about +Y by the heading: the character's +X nose turns to (cos h, 0, -sin h).
glm::quat yawOf(float headingRad)
{
    const double half = 0.5 * static_cast<double>(headingRad);
    return {static_cast<float>(std::cos(half)), 0.0f, static_cast<float>(std::sin(half)), 0.0f};
}

}  // namespace

AgentBaker::AgentBaker(const sim::Scene& scene, const sim::FrameCache& cache, const CharacterLibrary& library,
                       std::uint64_t seed, const std::vector<float>& frameTimes, const JointClock& jointClock,
                       BakeSettings settings)
    : m_scene(scene), m_cache(cache), m_library(library), m_seed(seed), m_frameTimes(frameTimes),
      m_jointClock(jointClock), m_settings(settings)
{
    for (const sim::Agent& a : scene.agents)
        if (a.look >= 0 || a.tint >= 0 || a.heightScale > 0.0f)
            m_placed.emplace(a.id, &a);
}

AgentVariation AgentBaker::variationOf(std::size_t i) const
{
    const sim::AgentInfo& info = m_cache.agents()[i];
    const sim::AgentType& type = m_scene.agentTypes[info.typeIndex];
    const std::size_t looks = m_library.looksOf(info.typeIndex).size();
    AgentVariation v = drawVariation(type.variation, m_seed, info.id, looks);
    if (const auto it = m_placed.find(info.id); it != m_placed.end())
        applyHandSetVariation(v, *it->second, looks, type.variation.tints.size());
    applySwappedLook(v, info, looks, type.variation.tints.size());
    return v;
}

void AgentBaker::prepare(std::size_t i, AgentWork& w, bool withKeys) const
{
    const std::size_t frames = m_cache.frameCount();
    w.positions.resize(frames);
    w.yaw.resize(frames);
    std::vector<float> speeds(frames), phases(frames, 0.0f);
    std::vector<sim::Clip> clips(frames, sim::Clip::Idle);
    w.hidden.assign(frames, 0);
    std::size_t firstPresent = frames;
    for (std::size_t f = 0; f < frames; ++f) {
        const sim::AgentFrame& a = m_cache.at(f, i);
        w.hidden[f] = a.out || !a.present ? 1 : 0;
        if (!a.present) {
            // Nothing recorded: stand still where it was last (or will first be).
            w.positions[f] = f > 0 ? w.positions[f - 1] : glm::vec3(0.0f);
            w.yaw[f] = f > 0 ? w.yaw[f - 1] : glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
            speeds[f] = 0.0f;
            continue;
        }
        if (firstPresent == frames) {
            firstPresent = f;
            for (std::size_t g = 0; g < f; ++g) {
                w.positions[g] = a.position;
                w.yaw[g] = yawOf(a.headingRad);
            }
        }
        w.positions[f] = a.position;
        speeds[f] = a.speed;
        clips[f] = a.clip;
        phases[f] = sim::actionPhase(a.clip, static_cast<double>(f) / static_cast<double>(m_cache.fps()),
                                     m_cache.agents()[i].id);
        w.yaw[f] = yawOf(a.headingRad);
        if (f > 0 && glm::dot(w.yaw[f], w.yaw[f - 1]) < 0.0f)
            w.yaw[f] = -w.yaw[f];
    }
    w.variation = variationOf(i);
    const std::size_t typeIndex = m_cache.agents()[i].typeIndex;
    w.character = m_library.looksOf(typeIndex)[w.variation.look];
    const Character& character = m_library.character(w.character);
    const float blendS = m_scene.agentTypes[typeIndex].actionBlendS;
    w.gait = computeGait(character, w.positions, speeds, w.variation, {clips, phases, m_cache.fps(), blendS});
    const RootMotion motion{w.positions, w.yaw, w.variation.heightScale, m_cache.fps()};
    w.firstPose = m_settings.compact ? gaitPose(character, w.gait[0])
                                     : FootPlanter(character, w.gait, motion, m_scene.terrain).next();
    if (!withKeys)
        return;
    w.positionKept = keepVec3Keys(m_frameTimes, w.positions, m_settings.positionToleranceM);
    w.yawKept = keepRotationKeys(m_frameTimes, w.yaw, m_settings.rootRotationToleranceRad);
    if (!m_settings.compact)
        w.joints = bakeJoints(m_jointClock, character, w.gait, motion, m_scene.terrain,
                              m_settings.positionToleranceM, m_settings.rotationToleranceRad);
}

}  // namespace throng::exporting::detail
