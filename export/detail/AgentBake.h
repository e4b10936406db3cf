#pragma once
// One agent's share of a skinned-crowd export, prepared from the recorded frames: its root
// motion (positions and yaw per frame, with the keys that reduction keeps), the frames it
// is out of the shot, its variation and look, its gait, its first pose and, for an exact
// bake, its joints. Pure: agents may be prepared on any thread, in any order; the glTF, USD
// and FBX writers then write them in agent order.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/character/AgentVariation.h"
#include "export/character/CharacterLibrary.h"
#include "export/character/Gait.h"
#include "export/detail/ExactBake.h"
#include "export/detail/ExportCancel.h"
#include "simcore/base/ThreadTeam.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <vector>

namespace throng::exporting::detail {

struct AgentWork {
    std::vector<glm::vec3> positions;  // per frame, m, relative to the cache's origin
    std::vector<glm::quat> yaw;        // per frame, about +Y by the heading; neighbours in one hemisphere
    AgentVariation variation;
    std::size_t character = 0;         // in the library
    std::vector<GaitFrame> gait;
    Pose firstPose;
    std::vector<std::uint32_t> positionKept, yawKept;
    // Per frame: 1 = not in the shot (left through an exit, or not present: an edit added
    // it later or removed it earlier); the character scales to nothing there.
    std::vector<std::uint8_t> hidden;
    BakedJoints joints;  // an exact bake's
};

struct BakeSettings {
    bool compact = false;                // joints come from shared cycles: no exact bake, first pose unplanted
    float positionToleranceM = 0.0005f;  // key reduction (KeyReduction.h)
    float rotationToleranceRad = 0.0035f;
    float rootRotationToleranceRad = 0.00087f;
};

class AgentBaker {
public:
    // `frameTimes`: every frame's time, s; `jointClock`: the frames an exact bake keys.
    AgentBaker(const sim::Scene& scene, const sim::FrameCache& cache, const CharacterLibrary& library,
               std::uint64_t seed, const std::vector<float>& frameTimes, const JointClock& jointClock,
               BakeSettings settings);

    // Agent i of the cache (dense order). withKeys: also the reduced keys and, unless
    // compact, the exact bake of its joints.
    void prepare(std::size_t i, AgentWork& work, bool withKeys) const;
    // Its drawn variation, with what the variation brush set by hand.
    AgentVariation variationOf(std::size_t i) const;

private:
    const sim::Scene& m_scene;
    const sim::FrameCache& m_cache;
    const CharacterLibrary& m_library;
    std::uint64_t m_seed;
    const std::vector<float>& m_frameTimes;
    const JointClock& m_jointClock;
    BakeSettings m_settings;
    std::map<std::uint32_t, const sim::Agent*> m_placed;  // agents with a hand-set look, tint or height
};

// Prepares the cache's first `agents` agents on `team`, a block of 256 at a time, and hands
// each to take(i, work) in agent order, on the calling thread. Before each block it tells
// `progress` how far it is, from `from` to `to` of the whole export; false, having
// stopped, when progress asks it to cancel.
template <class Take>
bool bakeInOrder(const AgentBaker& baker, std::size_t agents, bool withKeys, const sim::ThreadTeam& team,
                 const ProgressFn& progress, float from, float to, Take&& take)
{
    constexpr std::size_t kBlock = 256;
    std::vector<AgentWork> work(std::min(kBlock, agents));
    for (std::size_t begin = 0; begin < agents; begin += kBlock) {
        if (cancelledAt(progress, from + (to - from) * static_cast<float>(begin) / static_cast<float>(agents)))
            return false;
        const std::size_t count = std::min(kBlock, agents - begin);
        team.forEach(count, 4, [&](std::size_t k) { baker.prepare(begin + k, work[k], withKeys); });
        for (std::size_t k = 0; k < count; ++k)
            take(begin + k, work[k]);
    }
    return true;
}

}  // namespace throng::exporting::detail
