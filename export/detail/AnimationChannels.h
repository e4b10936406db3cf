#pragma once
// The animation's shared clocks and the writing of one channel: keys reduced within a
// tolerance, then read either through a shared time accessor (every frame, every joint
// frame, or just the first and last) or, where that is smaller, through their own times.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/detail/GltfBuilder.h"

#include <map>
#include <span>
#include <vector>

namespace throng::exporting::detail {

// One clock: key times and the accessor holding them (shared by every channel on it).
struct Clock {
    std::vector<float> times;  // s, strictly increasing
    int accessor = -1;
};

class AnimationChannels {
public:
    // `animation` must outlive this; `pair` is the clock {0, end} (or the one frame).
    AnimationChannels(GltfBuilder& builder, tinygltf::Animation& animation, const Clock& pair);

    // Keys on `clock`, reduced within the tolerance (m or rad); rotations as int16.
    void vec3Channel(int node, const char* path, const Clock& clock, std::span<const glm::vec3> keys, float toleranceM);
    void rotationChannel(int node, std::span<const glm::quat> keys, const Clock& clock, float toleranceRad);
    // The same with the keys to keep already chosen (KeyReduction), e.g. on worker threads.
    void vec3Channel(int node, const char* path, const Clock& clock, std::span<const glm::vec3> keys,
                     const std::vector<std::uint32_t>& kept);
    void rotationChannel(int node, std::span<const glm::quat> keys, const Clock& clock,
                         const std::vector<std::uint32_t>& kept);
    // A sampler of already-written input and output accessors (LINEAR or STEP).
    void addSampler(int node, const char* path, int input, int output, const char* interpolation = "LINEAR");
    // Forgets the own-times accessors kept for reuse (call between agents).
    void nextAgent() { m_ownTimes.clear(); }

private:
    int inputFor(const Clock& clock, const std::vector<std::uint32_t>& kept, std::size_t valueBytes, bool& subset);
    GltfBuilder& m_builder;
    tinygltf::Animation& m_animation;
    const Clock& m_pair;
    std::map<std::vector<std::uint32_t>, int> m_ownTimes;
};

}  // namespace throng::exporting::detail
