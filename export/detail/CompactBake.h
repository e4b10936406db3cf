#pragma once
// Compact mode: each look's walk and run cycles (or the rungs of its gait ladder) are
// stored once, repeated as long as the longest agent needs, and every agent reads a
// window of one that starts at its own phase through its own time accessor, which maps
// its distance walked onto the cycle. Exact while an agent stays in one clip;
// approximates stops and changes of gait (an agent plays the gait it moves at most).
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/character/CharacterLibrary.h"
#include "export/character/Gait.h"
#include "export/detail/AgentRig.h"
#include "export/detail/AnimationChannels.h"
#include "export/detail/CompactPlanner.h"

#include <glm/vec3.hpp>

#include <map>
#include <span>
#include <vector>

namespace throng::exporting::detail {

class CompactCycles {
public:
    CompactCycles(GltfBuilder& builder, const CharacterLibrary& library)
        : m_builder(builder), m_library(library), m_planner(library)
    {
    }

    // Pass 1, agent by agent: which clip and window it reads.
    CompactPlan plan(std::size_t character, std::span<const glm::vec3> positions, const std::vector<GaitFrame>& gait,
                     const AgentVariation& variation, float fps)
    {
        return m_planner.plan(character, positions, gait, variation, fps);
    }
    // Between the passes: writes every bank the plans need.
    void writeBanks();
    // Pass 2: the agent's joint channels as windows into the banks.
    void bakeAgent(AnimationChannels& channels, const CompactPlan& plan, const AgentRig& rig, int pairTimes);

private:
    struct Bank {
        std::size_t length = 0;             // samples needed
        std::vector<std::size_t> rotation;  // region offset per joint
        std::vector<int> still;             // per joint: 2-key constant accessor when the joint never moves, else -1
        std::size_t rootTranslation = 0;
    };
    struct Still {
        std::vector<int> rotation;
        int rootTranslation = -1;
    };
    const Still& stillOf(std::size_t character);
    GltfBuilder& m_builder;
    const CharacterLibrary& m_library;
    CompactPlanner m_planner;
    std::map<std::pair<std::size_t, int>, Bank> m_banks;
    std::map<std::size_t, Still> m_still;
};

}  // namespace throng::exporting::detail
