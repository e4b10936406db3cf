#include "export/detail/CompactBake.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::exporting::detail {

void CompactCycles::writeBanks()
{
    for (const auto& [key, length] : m_planner.bankLengths()) {
        Bank& bank = m_banks[key];
        bank.length = length;
        const Character& c = m_library.character(key.first);
        const CycleClip& cycle = m_planner.clipOf(key.first, key.second);
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
    const Pose& pose = m_planner.stillPose(character);
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
