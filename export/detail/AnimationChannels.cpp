#include "export/detail/AnimationChannels.h"

#include "export/detail/KeyReduction.h"

namespace throng::exporting::detail {

AnimationChannels::AnimationChannels(GltfBuilder& builder, tinygltf::Animation& animation, const Clock& pair)
    : m_builder(builder), m_animation(animation), m_pair(pair)
{
}

void AnimationChannels::addSampler(int node, const char* path, int input, int output, const char* interpolation)
{
    tinygltf::AnimationSampler sampler;
    sampler.input = input;
    sampler.output = output;
    sampler.interpolation = interpolation;
    m_animation.samplers.push_back(std::move(sampler));
    tinygltf::AnimationChannel channel;
    channel.sampler = static_cast<int>(m_animation.samplers.size()) - 1;
    channel.target_node = node;
    channel.target_path = path;
    m_animation.channels.push_back(std::move(channel));
}

int AnimationChannels::inputFor(const Clock& clock, const std::vector<std::uint32_t>& kept, std::size_t valueBytes,
                                bool& subset)
{
    const std::size_t n = clock.times.size();
    subset = true;
    if (kept.size() == 2 && m_pair.times.size() == 2)
        return m_pair.accessor;
    // Own times cost 4 bytes a key: worth it only when enough keys go.
    if (kept.size() < n && kept.size() * (valueBytes + 4) < n * valueBytes) {
        auto it = m_ownTimes.find(kept);
        if (it == m_ownTimes.end()) {
            std::vector<float> times;
            times.reserve(kept.size());
            for (std::uint32_t k : kept)
                times.push_back(clock.times[k]);
            it = m_ownTimes.emplace(kept, m_builder.addTimes(times)).first;
        }
        return it->second;
    }
    subset = false;
    return clock.accessor;
}

void AnimationChannels::vec3Channel(int node, const char* path, const Clock& clock, std::span<const glm::vec3> keys,
                                    float toleranceM)
{
    vec3Channel(node, path, clock, keys, keepVec3Keys(clock.times, keys, toleranceM));
}

void AnimationChannels::rotationChannel(int node, std::span<const glm::quat> keys, const Clock& clock, float toleranceRad)
{
    rotationChannel(node, keys, clock, keepRotationKeys(clock.times, keys, toleranceRad));
}

void AnimationChannels::vec3Channel(int node, const char* path, const Clock& clock, std::span<const glm::vec3> keys,
                                    const std::vector<std::uint32_t>& kept)
{
    bool subset = false;
    const int input = inputFor(clock, kept, sizeof(glm::vec3), subset);
    if (!subset) {
        addSampler(node, path, input, m_builder.addVec3Keys(keys));
        return;
    }
    std::vector<glm::vec3> values;
    values.reserve(kept.size());
    for (std::uint32_t k : kept)
        values.push_back(keys[k]);
    addSampler(node, path, input, m_builder.addVec3Keys(values));
}

void AnimationChannels::rotationChannel(int node, std::span<const glm::quat> keys, const Clock& clock,
                                        const std::vector<std::uint32_t>& kept)
{
    bool subset = false;
    const int input = inputFor(clock, kept, 8, subset);
    if (!subset) {
        addSampler(node, "rotation", input, m_builder.addRotationKeys(keys));
        return;
    }
    std::vector<glm::quat> values;
    values.reserve(kept.size());
    for (std::uint32_t k : kept)
        values.push_back(keys[k]);
    addSampler(node, "rotation", input, m_builder.addRotationKeys(values));
}

}  // namespace throng::exporting::detail
