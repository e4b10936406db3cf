#include "export/detail/CompactPlanner.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::exporting::detail {

const CycleClip& CompactPlanner::clipOf(std::size_t character, int clip) const
{
    const Character& c = m_library.character(character);
    if (!c.ladder.empty())
        return c.ladder[static_cast<std::size_t>(clip)];
    return clip == 1 ? c.run : c.walk;
}

CompactPlan CompactPlanner::plan(std::size_t character, std::span<const glm::vec3> positions,
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
    std::size_t& length = m_lengths[{character, clip}];
    length = std::max(length, p.first + p.times.size());
    return p;
}

const Pose& CompactPlanner::stillPose(std::size_t character) const
{
    const Character& c = m_library.character(character);
    return c.hasIdle ? c.idle.samples[0] : c.walk.samples[0];
}

}  // namespace throng::exporting::detail
