#include "export/detail/CompactBake.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::exporting::detail {

const CycleClip& CompactCycles::clipOf(std::size_t character, int clip) const
{
    const Character& c = m_library.character(character);
    if (!c.ladder.empty())
        return c.ladder[static_cast<std::size_t>(clip)];
    return clip == 1 ? c.run : c.walk;
}

CompactPlan CompactCycles::plan(std::size_t character, std::span<const glm::vec3> positions,
                                const std::vector<GaitFrame>& gait, const AgentVariation& v, float fps)
{
    CompactPlan p;
    p.character = character;
    std::size_t moving = 0;
    double running = 0.0;
    for (const GaitFrame& g : gait)
        if (g.moveWeight > 0.5f) {
            ++moving;
            running += g.runWeight;
        }
    if (moving == 0)
        return p;
    // Walk or run, whichever it moves at most; with a gait ladder, the rung nearest its
    // mean place along it.
    const std::size_t rungs = m_library.character(character).ladder.size();
    const int clip = rungs > 0 ? static_cast<int>(std::lround(running / static_cast<double>(moving) *
                                                              static_cast<double>(rungs - 1)))
                               : (running > 0.5 * static_cast<double>(moving) ? 1 : 0);
    const CycleClip& cycle = clipOf(character, clip);
    const double samples = static_cast<double>(cycle.samples.size());
    // The phase as this one clip's stride measures it, in samples of the cycle.
    std::vector<double> at(positions.size());
    at[0] = static_cast<double>(v.phaseOffset) * samples;
    const double perMetre = samples / (static_cast<double>(cycle.strideM) * static_cast<double>(v.heightScale));
    for (std::size_t f = 1; f < positions.size(); ++f)
        at[f] = at[f - 1] + glm::length(glm::dvec3(positions[f]) - glm::dvec3(positions[f - 1])) * perMetre;
    // The window reaches one sample past each end of the agent's phase range, keyed at
    // the first and last frame: between them and their neighbours the cycle runs a little
    // fast, where holding the pose would let a planted foot slide with the body.
    const auto first = static_cast<std::size_t>(std::floor(at.front() + 1e-9));
    const auto last = static_cast<std::size_t>(std::ceil(at.back() - 1e-9));
    if (last < first + 2)
        return p;
    p.clip = clip;
    p.first = first;
    std::size_t f = 0;
    for (std::size_t s = first; s <= last; ++s) {
        const double target = static_cast<double>(s);
        while (f + 1 < at.size() && at[f + 1] < target)
            ++f;
        double frame = static_cast<double>(f);
        if (f + 1 < at.size() && at[f + 1] > at[f])
            frame += std::clamp((target - at[f]) / (at[f + 1] - at[f]), 0.0, 1.0);
        float t = static_cast<float>(frame / static_cast<double>(fps));
        if (!p.times.empty() && !(t > p.times.back()))
            t = std::nextafter(p.times.back(), 1e30f);
        p.times.push_back(t);
    }
    Bank& bank = m_banks[{character, clip}];
    bank.length = std::max(bank.length, p.first + p.times.size());
    return p;
}

void CompactCycles::writeBanks()
{
    for (auto& [key, bank] : m_banks) {
        const Character& c = m_library.character(key.first);
        const CycleClip& cycle = clipOf(key.first, key.second);
        const std::size_t k = cycle.samples.size();
        bank.rotation.resize(c.joints.size());
        bank.still.assign(c.joints.size(), -1);
        std::vector<glm::quat> keys(bank.length);
        for (std::size_t j = 0; j < c.joints.size(); ++j) {
            bool constant = true;
            for (std::size_t s = 0; s < bank.length; ++s) {
                glm::quat q = cycle.samples[s % k].rotations[j];
                if (s > 0 && glm::dot(q, keys[s - 1]) < 0.0f)
                    q = -q;
                keys[s] = q;
                constant = constant && std::abs(glm::dot(q, keys[0])) > 0.9999999f;
            }
            if (constant) {
                const glm::quat two[2] = {keys[0], keys[0]};
                bank.still[j] = m_builder.addRotationKeys(two);
                continue;
            }
            std::vector<std::int16_t> packed(4 * bank.length);
            GltfBuilder::quantise(keys, packed.data());
            bank.rotation[j] = m_builder.appendAnimationBytes(packed.data(), packed.size() * 2);
        }
        std::vector<glm::vec3> roots(bank.length);
        for (std::size_t s = 0; s < bank.length; ++s)
            roots[s] = cycle.samples[s % k].rootTranslation;
        bank.rootTranslation = m_builder.appendAnimationBytes(roots.data(), roots.size() * sizeof(glm::vec3));
    }
}

const CompactCycles::Still& CompactCycles::stillOf(std::size_t character)
{
    auto it = m_still.find(character);
    if (it != m_still.end())
        return it->second;
    const Character& c = m_library.character(character);
    const Pose& pose = c.hasIdle ? c.idle.samples[0] : c.walk.samples[0];
    Still still;
    for (const glm::quat& q : pose.rotations) {
        const glm::quat two[2] = {q, q};
        still.rotation.push_back(m_builder.addRotationKeys(two));
    }
    const glm::vec3 two[2] = {pose.rootTranslation, pose.rootTranslation};
    still.rootTranslation = m_builder.addVec3Keys(two);
    return m_still.emplace(character, std::move(still)).first->second;
}

void CompactCycles::bakeAgent(AnimationChannels& channels, const CompactPlan& p, const AgentRig& rig, int pairTimes)
{
    const std::size_t joints = m_library.character(p.character).joints.size();
    if (p.clip < 0) {
        const Still& still = stillOf(p.character);
        channels.addSampler(rig.firstJoint, "translation", pairTimes, still.rootTranslation);
        for (std::size_t j = 0; j < joints; ++j)
            channels.addSampler(rig.firstJoint + static_cast<int>(j), "rotation", pairTimes, still.rotation[j]);
        return;
    }
    const Bank& bank = m_banks.at({p.character, p.clip});
    const int input = m_builder.addTimes(p.times);
    const std::size_t n = p.times.size();
    channels.addSampler(rig.firstJoint, "translation", input,
                        m_builder.addWindow(bank.rootTranslation, p.first, sizeof(glm::vec3), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                            n, TINYGLTF_TYPE_VEC3, false));
    for (std::size_t j = 0; j < joints; ++j) {
        const int node = rig.firstJoint + static_cast<int>(j);
        if (bank.still[j] >= 0)
            channels.addSampler(node, "rotation", pairTimes, bank.still[j]);
        else
            channels.addSampler(node, "rotation", input,
                                m_builder.addWindow(bank.rotation[j], p.first, 8, TINYGLTF_COMPONENT_TYPE_SHORT, n,
                                                    TINYGLTF_TYPE_VEC4, true));
    }
}

}  // namespace throng::exporting::detail
