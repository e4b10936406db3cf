#pragma once
// Compact joints, planned: which cycle each agent plays (walk or run, whichever it moves at
// most; with a gait ladder, the rung nearest its mean place on it) and the window of that
// cycle, repeated into a bank, that it reads, sample by sample, at the times its distance
// walked reaches each sample. The glTF (CompactCycles) and USD writers store each bank
// once and map every agent onto it. Pure planning; writes nothing.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/character/CharacterLibrary.h"
#include "export/character/Gait.h"

#include <glm/vec3.hpp>

#include <map>
#include <span>
#include <vector>

namespace throng::exporting::detail {

struct CompactPlan {
    std::size_t character = 0;
    int clip = -1;           // -1: holds the still pose; 0: walk; 1: run; with a gait ladder, its rung
    std::size_t first = 0;   // window start in the cycle bank, samples
    std::vector<float> times;  // one per window sample, s, strictly increasing
};

class CompactPlanner {
public:
    explicit CompactPlanner(const CharacterLibrary& library) : m_library(library) {}

    // One agent's plan; the bank it reads grows to hold its window.
    CompactPlan plan(std::size_t character, std::span<const glm::vec3> positions, const std::vector<GaitFrame>& gait,
                     const AgentVariation& variation, float fps);
    // Samples each (character, clip) bank needs, for the plans made so far.
    const std::map<std::pair<std::size_t, int>, std::size_t>& bankLengths() const { return m_lengths; }
    // The cycle a bank repeats.
    const CycleClip& clipOf(std::size_t character, int clip) const;
    // The pose of a plan without a clip (-1): idle, or the moving clip's first for
    // characters without one.
    const Pose& stillPose(std::size_t character) const;

private:
    const CharacterLibrary& m_library;
    std::map<std::pair<std::size_t, int>, std::size_t> m_lengths;
};

}  // namespace throng::exporting::detail
