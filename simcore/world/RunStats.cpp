#include "simcore/world/RunStats.h"

#include "simcore/world/World.h"

#include <charconv>
#include <cmath>

namespace throng::sim {

namespace {
std::string number(double v)
{
    if (!std::isfinite(v))
        return "null";
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : "null";
}
}  // namespace

RunStats RunStats::from(const World& world, std::uint64_t frames, double wallSeconds)
{
    RunStats s;
    s.agents = world.agentCount();
    s.frames = frames;
    s.seed = world.seed();
    s.threads = world.threads();
    s.simulatedSeconds = world.timeS();
    s.wallSeconds = wallSeconds;
    s.counters = world.counters();
    s.agentStepsPerSecond = wallSeconds > 0.0 ? double(s.counters.agentSteps) / wallSeconds : 0.0;
    for (std::size_t i = 0; i < world.agentCount(); ++i)
        if (world.hasArrived(i))
            ++s.arrived;
    s.withGoal = world.agentsWithGoal();
    return s;
}

std::string RunStats::toJson() const
{
    std::string j = "{\n";
    auto field = [&](const char* key, const std::string& value, bool last = false) {
        j += std::string("  \"") + key + "\": " + value + (last ? "\n" : ",\n");
    };
    field("agents", std::to_string(agents));
    field("frames", std::to_string(frames));
    field("steps", std::to_string(frames > 0 ? frames - 1 : 0));
    field("seed", std::to_string(seed));
    field("threads", std::to_string(threads));
    field("simulated_seconds", number(simulatedSeconds));
    field("wall_seconds", number(wallSeconds));
    field("agent_steps_per_second", number(agentStepsPerSecond));
    field("arrived", std::to_string(arrived));
    field("agents_with_goal", std::to_string(withGoal));
    field("wall_penetrations", std::to_string(counters.wallPenetrations));
    field("obstacle_penetrations", std::to_string(counters.obstaclePenetrations));
    field("overlapping_pairs", std::to_string(counters.overlappingPairs));
    field("overlapping_pairs_per_step",
          number(frames > 1 ? double(counters.overlappingPairs) / double(frames - 1) : 0.0));
    field("red_light_violations", std::to_string(counters.redLightViolations));
    field("non_finite_values", std::to_string(counters.nonFiniteValues), true);
    return j + "}\n";
}

}  // namespace throng::sim
