// Sound for brains: beacons and emitting agent types by channel, and what a listener
// hears. A source of strength s and radius r is heard at distance d < r with strength
// s (1 - d / r): full at the source, silent at its radius (docs/brains.md).
#include "simcore/world/detail/WorldSound.h"

#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim::detail {

namespace {

// Strictly louder, or as loud and nearer; `rank` orders the rest (beacons before agents).
// The bearing is worked out only for the sources kept, from `offset`.
struct Candidate {
    float strength, distanceM;
    glm::vec2 offset;  // source - listener
    std::uint64_t rank;
};

bool before(const Candidate& a, const Candidate& b)
{
    if (a.strength != b.strength)
        return a.strength > b.strength;
    if (a.distanceM != b.distanceM)
        return a.distanceM < b.distanceM;
    return a.rank < b.rank;
}

// Keeps the best kMaxHeard in order (insertion into a short sorted list).
void offer(std::array<Candidate, kMaxHeard>& best, std::size_t& count, const Candidate& c)
{
    if (count == kMaxHeard && !before(c, best[count - 1]))
        return;
    std::size_t k = count < kMaxHeard ? count++ : count - 1;
    while (k > 0 && before(c, best[k - 1])) {
        best[k] = best[k - 1];
        --k;
    }
    best[k] = c;
}

}  // namespace

std::uint32_t channelIndex(WorldBrains& wb, const std::string& name)
{
    for (std::size_t c = 0; c < wb.channels.size(); ++c)
        if (wb.channels[c].name == name)
            return std::uint32_t(c);
    wb.channels.push_back({name, {}, 0.0f, {}});
    return std::uint32_t(wb.channels.size() - 1);
}

void buildSoundChannels(WorldBrains& wb, const Scene& scene, std::span<const AgentInfo> info)
{
    for (SoundChannel& c : wb.channels) {
        c.beacons.clear();
        c.agentReachM = 0.0f;
        for (const SoundSource& s : scene.soundSources)
            if (s.channel == c.name)
                c.beacons.push_back({s.position.x, s.position.y, s.strength, s.radiusM});
    }
    const std::size_t types = scene.agentTypes.size();
    wb.typeEmits.assign(types, -1);
    wb.typeEmitStrength.assign(types, 0.0f);
    wb.typeEmitRadiusM.assign(types, 0.0f);
    for (std::size_t t = 0; t < types; ++t) {
        const SoundEmission& e = scene.agentTypes[t].emits;
        for (std::size_t c = 0; c < wb.channels.size() && !e.channel.empty(); ++c) {
            if (wb.channels[c].name != e.channel)
                continue;
            wb.typeEmits[t] = std::int32_t(c);
            wb.typeEmitStrength[t] = e.strength;
            wb.typeEmitRadiusM[t] = e.radiusM;
            wb.channels[c].agentReachM = std::max(wb.channels[c].agentReachM, e.radiusM);
        }
    }
    for (std::size_t c = 0; c < wb.channels.size(); ++c) {
        std::vector<std::uint32_t>& list = wb.channels[c].emitters;
        list.clear();
        for (std::size_t j = 0; j < info.size() && list.size() <= kDirectEmitters; ++j)
            if (wb.typeEmits[info[j].typeIndex] == std::int32_t(c))
                list.push_back(std::uint32_t(j));
        if (list.size() > kDirectEmitters)
            list.clear();
    }
}

std::size_t hearChannel(const WorldBrains& wb, std::uint32_t c, const NeighbourGrid& grid,
                        std::span<const AgentInfo> info, std::span<const glm::vec3> positions,
                        std::span<const std::uint8_t> gone, std::size_t self, glm::vec2 p, glm::vec2 f,
                        HeardList& out)
{
    const SoundChannel& channel = wb.channels[c];
    std::array<Candidate, kMaxHeard> best;
    std::size_t count = 0;
    auto consider = [&](glm::vec2 q, float strength, float radiusM, std::uint64_t rank) {
        const glm::vec2 d = q - p;
        const float d2 = glm::dot(d, d);
        if (d2 >= radiusM * radiusM)
            return;
        const float dist = std::sqrt(d2);
        const float heard = std::min(1.0f, strength * (1.0f - dist / radiusM));
        if (heard > 0.0f)
            offer(best, count, {heard, dist, d, rank});
    };
    for (std::size_t b = 0; b < channel.beacons.size(); ++b) {
        const Beacon& s = channel.beacons[b];
        consider({s.x, s.z}, s.strength, s.radiusM, b);
    }
    // A few emitters are checked one by one; many through the grid. Either way the same
    // sources are offered, and offer() orders them fully, so the answer is the same.
    auto emitter = [&](std::uint32_t j, const glm::vec3& q) {
        const std::uint16_t t = info[j].typeIndex;
        if (j == self || wb.typeEmits[t] != std::int32_t(c))
            return;
        consider({q.x, q.z}, wb.typeEmitStrength[t], wb.typeEmitRadiusM[t], (std::uint64_t(1) << 32) + j);
    };
    if (!channel.emitters.empty()) {
        for (const std::uint32_t j : channel.emitters)
            if (gone.empty() || !gone[j])
                emitter(j, positions[j]);
    } else if (channel.agentReachM > 0.0f) {
        grid.forEachNear(p, channel.agentReachM, emitter);
    }
    for (std::size_t k = 0; k < count; ++k) {
        const float bearing = best[k].distanceM > 0.0f ? bearingDeg(f, best[k].offset) : 0.0f;
        out[k] = {best[k].strength, best[k].distanceM, bearing};
    }
    return count;
}

}  // namespace throng::sim::detail
