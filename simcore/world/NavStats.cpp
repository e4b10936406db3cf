#include "simcore/world/NavStats.h"

#include "simcore/world/World.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace throng::sim {

namespace {
// A JSON number; null for a figure that is unknown (negative) or not finite.
std::string numberOrNull(double v)
{
    if (!std::isfinite(v) || v < 0.0)
        return "null";
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : "null";
}
}  // namespace

double steadyOutflowPerSecond(const std::vector<float>& t)
{
    const std::size_t n = t.size();
    if (n < 10)
        return -1.0;
    const std::size_t a = n / 10, b = n - 1 - n / 10;
    const double span = double(t[b]) - double(t[a]);
    return span > 0.0 ? double(b - a) / span : -1.0;
}

NavStats NavStats::from(const World& world)
{
    NavStats s;
    const std::vector<Goal>& goals = world.goals();
    std::vector<std::vector<float>> outTimes(goals.size());
    std::vector<float> allOut;
    for (std::size_t i = 0; i < world.agentCount(); ++i) {
        const std::int32_t g = world.goalIndex(i);
        if (world.isOffstage(i))  // never came in
            continue;
        const std::int32_t p = world.pathIndex(i);
        if (p >= 0 && world.paths()[std::size_t(p)].exit) {  // leaves at its path's end
            ++s.exitAgents;
            if (world.isOut(i))
                allOut.push_back(world.arrivalTimeS(i));
        } else if (g >= 0 && goals[std::size_t(g)].exit) {
            ++s.exitAgents;
            if (world.isOut(i)) {
                outTimes[std::size_t(g)].push_back(world.arrivalTimeS(i));
                allOut.push_back(world.arrivalTimeS(i));
            }
        }
    }
    s.agentsOut = allOut.size();
    std::sort(allOut.begin(), allOut.end());
    if (s.exitAgents > 0) {
        const auto need = std::size_t(std::ceil(0.99 * double(s.exitAgents)));
        if (need > 0 && allOut.size() >= need)
            s.timeTo99PercentOutS = allOut[need - 1];
    }
    for (std::size_t g = 0; g < goals.size(); ++g) {
        if (!goals[g].exit)
            continue;
        std::sort(outTimes[g].begin(), outTimes[g].end());
        ExitFlow f;
        f.goal = goals[g].name;
        f.doorWidthM = 2.0 * double(goals[g].radiusM);
        f.agentsOut = outTimes[g].size();
        const double perSecond = steadyOutflowPerSecond(outTimes[g]);
        f.flowPerMetrePerSecond = perSecond < 0.0 ? -1.0 : perSecond / f.doorWidthM;
        s.exits.push_back(std::move(f));
    }
    const WorldNav& nav = world.navigation();
    if (nav.active) {
        for (std::size_t i = 0; i < world.agentCount(); ++i) {
            if (nav.mode[i] != Navigation::AStar || world.goalIndex(i) < 0)
                continue;
            ++s.shortestPathAgents;
            if (world.hasArrived(i)) {
                ++s.shortestPathArrived;
                s.shortestPathLastArrivalS = std::max(s.shortestPathLastArrivalS, double(world.arrivalTimeS(i)));
            }
        }
        s.planCacheHits = nav.cache.hits();
        s.planCacheMisses = nav.cache.misses();
        s.replans = nav.counters.replans;
        s.sideSteps = nav.counters.sideSteps;
        s.lostReplans = nav.counters.lostPlans;
    }
    return s;
}

std::string NavStats::jsonFields() const
{
    std::string j;
    auto field = [&](const char* key, const std::string& value) {
        j += std::string("  \"") + key + "\": " + value + ",\n";
    };
    field("agents_out", std::to_string(agentsOut));
    field("exit_agents", std::to_string(exitAgents));
    field("fraction_out", exitAgents > 0 ? numberOrNull(double(agentsOut) / double(exitAgents)) : "null");
    field("time_to_99_percent_out", numberOrNull(timeTo99PercentOutS));
    std::string list = "[";
    for (std::size_t k = 0; k < exits.size(); ++k) {
        const ExitFlow& f = exits[k];
        std::string name;
        for (char c : f.goal)
            if (c != '"' && c != '\\' && static_cast<unsigned char>(c) >= 0x20)
                name += c;
        list += std::string(k ? "," : "") + "\n    {\"goal\": \"" + name + "\", \"door_width_m\": " +
                numberOrNull(f.doorWidthM) + ", \"agents_out\": " + std::to_string(f.agentsOut) +
                ", \"flow_per_metre_per_second\": " + numberOrNull(f.flowPerMetrePerSecond) + "}";
    }
    field("exits", list + (exits.empty() ? "]" : "\n  ]"));
    field("shortest_path_agents", std::to_string(shortestPathAgents));
    field("shortest_path_arrived", std::to_string(shortestPathArrived));
    field("shortest_path_last_arrival_s", numberOrNull(shortestPathLastArrivalS));
    field("plan_cache_hits", std::to_string(planCacheHits));
    field("plan_cache_misses", std::to_string(planCacheMisses));
    field("nav_replans", std::to_string(replans));
    field("nav_side_steps", std::to_string(sideSteps));
    field("nav_lost_replans", std::to_string(lostReplans));
    return j;
}

}  // namespace throng::sim
