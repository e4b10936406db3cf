#pragma once
// The navigation figures of a run: agents out through exits and the flow per metre of door
// width, the shortest-path (A*) walkers' arrivals, plan sharing and re-plans. Computed from
// a World after the run; never changes it.

#include <cstdint>
#include <string>
#include <vector>

namespace throng::sim {

class World;

struct ExitFlow {
    std::string goal;
    double doorWidthM = 0.0;            // the goal's diameter: its size across the flow
    std::uint64_t agentsOut = 0;
    double flowPerMetrePerSecond = -1;  // persons/m/s over the steady part; < 0 = not measured
};

struct NavStats {
    std::uint64_t exitAgents = 0;   // agents whose goal is an exit, or whose path ends in one
    std::uint64_t agentsOut = 0;
    double timeTo99PercentOutS = -1;  // < 0: not reached
    std::vector<ExitFlow> exits;
    std::uint64_t shortestPathAgents = 0, shortestPathArrived = 0;  // walkers navigating by A*
    double shortestPathLastArrivalS = -1;  // the latest arrival among them; < 0 = none arrived
    std::uint64_t planCacheHits = 0, planCacheMisses = 0, replans = 0, sideSteps = 0;
    std::uint64_t lostReplans = 0;  // A* walkers pushed out of sight of their way that planned afresh

    static NavStats from(const World& world);
    // The JSON fields (each line "  \"key\": value,\n"), to sit inside RunStats' object.
    std::string jsonFields() const;
};

// Persons per second over the steady part of one exit's outflow: between the 10th and the
// 90th percentile of its exit times (the first arrivals and the last stragglers left out).
// times must be sorted; < 0 when fewer than 10 agents left or they all left at once.
double steadyOutflowPerSecond(const std::vector<float>& sortedTimesS);

}  // namespace throng::sim
