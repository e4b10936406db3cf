#include "simcore/world/RunStats.h"

#include "simcore/world/FlockFigures.h"
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
// A JSON string literal (scene names may hold quotes or backslashes).
std::string quoted(const std::string& text)
{
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\')
            out += '\\';
        if (static_cast<unsigned char>(c) >= 0x20)
            out += c;
    }
    return out + "\"";
}
}  // namespace

RunStats RunStats::from(const World& world, std::uint64_t frames, double wallSeconds)
{
    RunStats s;
    s.agents = world.agentCount();
    s.frames = frames;
    s.subSteps = world.subSteps();
    s.seed = world.seed();
    s.threads = world.threads();
    s.chunksPerThread = world.team().chunksRun();
    s.simulatedSeconds = world.timeS();
    s.wallSeconds = wallSeconds;
    s.counters = world.counters();
    s.agentStepsPerSecond = wallSeconds > 0.0 ? double(s.counters.agentSteps) / wallSeconds : 0.0;
    for (std::size_t p = 0; p < kStepPhaseCount; ++p)
        s.phaseSeconds[p] = world.phaseTimes().seconds(StepPhase(p));
    for (std::size_t i = 0; i < world.agentCount(); ++i)
        if (world.hasArrived(i))
            ++s.arrived;
    s.withGoal = world.agentsWithGoal();
    s.sourceAgents = world.sourceAgents();
    s.offstage = world.offstageAgents();
    s.inScene = world.agentsInScene();
    s.heroes = world.heroTracks().size();
    const FlockFigures flock = FlockFigures::of(world);
    s.fliers = flock.fliers;
    s.flierPolarisation = flock.polarisation;
    s.flierSpreadM = flock.spreadM;
    s.flierCentreToLeaderM = flock.centreToLeaderM;
    s.nav = NavStats::from(world);
    if (const TrafficSystem* traffic = world.trafficSystem()) {
        const WorldTraffic& names = world.traffic();
        s.vehicles = traffic->vehicleCount();
        s.vehicleRedLightViolations = traffic->counters().vehicleRedLightViolations;
        s.carPedestrianCollisions = traffic->counters().carPedestrianCollisions;
        s.vehicleCollisions = traffic->counters().vehicleCollisions;
        s.counters.nonFiniteValues += traffic->counters().nonFiniteValues;
        for (const StopLineThroughput& t : traffic->throughput()) {
            StopLineFlow f;
            auto name = [](const std::vector<std::string>& list, int k) {
                return k >= 0 && std::size_t(k) < list.size() ? list[std::size_t(k)] : std::string();
            };
            f.light = name(names.lightNames, t.light);
            f.lane = name(names.laneNames, t.lane);
            f.crosswalk = name(names.crosswalkNames, t.crosswalk);
            f.crossings = t.crossings;
            f.greenPhases = t.greenPhases;
            f.perGreen = t.perGreen();
            (t.lane >= 0 ? s.vehicleCrossings : s.pedestrianCrossings) += t.crossings;
            s.throughput.push_back(std::move(f));
        }
    }
    return s;
}

void RunStats::sampleInScene(const World& world, std::vector<std::uint64_t>& series)
{
    // Whole seconds passed; the small slack keeps 24 steps of 1/24 s at 1 s.
    const auto seconds = std::size_t(std::floor(world.timeS() + 1e-6));
    while (series.size() <= seconds)
        series.push_back(world.agentsInScene());
}

std::string RunStats::toJson() const
{
    std::string j = "{\n";
    auto field = [&](const char* key, const std::string& value, bool last = false) {
        j += std::string("  \"") + key + "\": " + value + (last ? "\n" : ",\n");
    };
    field("agents", std::to_string(agents));
    field("frames", std::to_string(frames));
    const std::uint64_t steps = frames > 0 ? (frames - 1) * std::uint64_t(subSteps) : 0;
    field("steps", std::to_string(steps));
    field("sub_steps", std::to_string(subSteps));
    field("seed", std::to_string(seed));
    field("threads", std::to_string(threads));
    std::string chunks;
    for (const std::uint64_t c : chunksPerThread)
        chunks += (chunks.empty() ? "" : ", ") + std::to_string(c);
    field("chunks_per_thread", "[" + chunks + "]");
    field("simulated_seconds", number(simulatedSeconds));
    field("wall_seconds", number(wallSeconds));
    field("agent_steps_per_second", number(agentStepsPerSecond));
    std::string phases;
    for (std::size_t p = 0; p < kStepPhaseCount; ++p)
        phases += (p ? ", \"" : "\"") + std::string(kStepPhaseNames[p]) + "\": " + number(phaseSeconds[p]);
    field("phase_seconds", "{" + phases + "}");
    field("arrived", std::to_string(arrived));
    field("agents_with_goal", std::to_string(withGoal));
    field("agents_in_scene", std::to_string(inScene));
    field("source_agents", std::to_string(sourceAgents));
    field("source_agents_entered", std::to_string(sourceAgents - offstage));
    field("source_agents_offstage", std::to_string(offstage));
    std::string series;
    for (const std::uint64_t n : inSceneEachSecond)
        series += (series.empty() ? "" : ", ") + std::to_string(n);
    field("agents_in_scene_each_second", "[" + series + "]");
    field("wall_penetrations", std::to_string(counters.wallPenetrations));
    field("obstacle_penetrations", std::to_string(counters.obstaclePenetrations));
    field("overlapping_pairs", std::to_string(counters.overlappingPairs));
    field("overlapping_pairs_per_step",
          number(steps > 0 ? double(counters.overlappingPairs) / double(steps) : 0.0));
    field("overlap_depth_p95", number(counters.overlapDepths.quantile(0.95)));
    field("overlap_depth_max", number(double(counters.overlapDepths.deepest)));
    field("peak_density_per_m2", number(double(counters.peakDensity)));
    field("peak_density_time_s", counters.peakDensityTimeS < 0.0 ? "null" : number(counters.peakDensityTimeS));
    field("red_light_violations", std::to_string(counters.redLightViolations + vehicleRedLightViolations));
    field("pedestrian_red_light_violations", std::to_string(counters.redLightViolations));
    field("vehicle_red_light_violations", std::to_string(vehicleRedLightViolations));
    field("car_pedestrian_collisions", std::to_string(carPedestrianCollisions));
    field("vehicle_collisions", std::to_string(vehicleCollisions));
    field("vehicles", std::to_string(vehicles));
    field("heroes", std::to_string(heroes));
    field("vehicle_crossings", std::to_string(vehicleCrossings));
    field("pedestrian_crossings", std::to_string(pedestrianCrossings));
    std::string flows = "[";
    for (std::size_t k = 0; k < throughput.size(); ++k) {
        const StopLineFlow& f = throughput[k];
        flows += std::string(k ? "," : "") + "\n    {\"light\": " + quoted(f.light) + ", " +
                 (f.lane.empty() ? "\"crosswalk\": " + quoted(f.crosswalk) : "\"lane\": " + quoted(f.lane)) +
                 ", \"crossings\": " + std::to_string(f.crossings) +
                 ", \"green_phases\": " + std::to_string(f.greenPhases) + ", \"per_green\": " + number(f.perGreen) +
                 "}";
    }
    field("throughput_per_green", flows + (throughput.empty() ? "]" : "\n  ]"));
    field("leader_overtaken", std::to_string(counters.leaderOvertaken));
    field("fliers", std::to_string(fliers));
    field("flier_polarisation", number(flierPolarisation));
    field("flier_spread_m", number(flierSpreadM));
    field("flier_centre_to_leader_m", number(flierCentreToLeaderM));
    j += nav.jsonFields();
    field("non_finite_values", std::to_string(counters.nonFiniteValues), true);
    return j + "}\n";
}

}  // namespace throng::sim
