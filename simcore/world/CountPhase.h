#pragma once
// The count phase: the run's quality figures (StepCounters.h) on the positions a step
// ended at: overlapping pairs and their depths, bodies in obstacles, walkers stepping onto
// the road on red, the peak local density and followers ahead of their leaders. Each
// chunk of agents counts its own; the totals are the same for any thread count.

#include "simcore/world/StepCounters.h"
#include "simcore/world/StepView.h"

#include <cstdint>
#include <vector>

namespace throng::sim {

class CountPhase {
public:
    // Counts the step that just ended (the grid indexes its positions). Writes
    // onCrosswalk (per agent: its centre is on a crosswalk's road part), which the next
    // step's count reads; nonFinite: the values that are not numbers the commit saw.
    void count(const StepView& v, std::vector<std::uint8_t>& onCrosswalk, std::uint64_t nonFinite);
    // Moves across walls the commit saw in this step.
    void addWallCrossings(std::uint64_t crossings) { m_counters.wallPenetrations += crossings; }

    const StepCounters& counters() const { return m_counters; }
    StepCounters& counters() { return m_counters; }  // checkpoints put them back

private:
    std::uint64_t overlappingPairs(const StepView& v, std::uint64_t nonFinite);
    // Whether i at p and j at q overlap by more than the tolerance; if so, their overlap
    // goes into `depths` as a fraction of r1 + r2. Only a body within i's radius plus the
    // largest one can overlap i.
    static bool overlapping(const StepView& v, std::size_t i, glm::vec3 p, std::uint32_t j, glm::vec3 q,
                            OverlapDepths& depths);
    // Those of i with the agents of higher index; those of the k-th of the grid's order,
    // k in [begin, end), with the agents after it.
    static std::uint64_t overlapsAfter(const StepView& v, std::size_t i, OverlapDepths& depths);
    static std::uint64_t laterOverlaps(const StepView& v, std::size_t begin, std::size_t end, OverlapDepths& depths);
    // Bodies in obstacles and steps onto the road on red.
    void countGround(const StepView& v, std::vector<std::uint8_t>& onCrosswalk);
    // The peak local density (LocalDensity.h) in this step's positions, kept if the highest.
    void samplePeakDensity(const StepView& v);
    // Followers ahead of their leader this step (CountLeaders.cpp).
    void countLeaderOvertakes(const StepView& v);

    StepCounters m_counters;
};

}  // namespace throng::sim
