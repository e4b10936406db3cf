#include "CliCommands.h"
#include "Progress.h"

#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/world/GridOrder.h"
#include "simcore/world/RunStats.h"
#include "simcore/world/World.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <ostream>
#include <sstream>

namespace throng::cli {

namespace {
std::uint64_t peakResidentBytes()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return std::uint64_t(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}
}  // namespace

int benchCommand(const CliArguments& args, std::ostream& out, std::ostream& err)
{
    const std::string name = args.scenario.empty() ? "cross" : args.scenario;
    const std::uint32_t agents = std::uint32_t(std::min<std::uint64_t>(args.agents.value_or(10'000), 50'000'000));
    sim::Scene scene;
    if (!sim::makeBenchScenario(name, agents, scene)) {
        err << "throng-cli: unknown scenario '" << name << "'; known:";
        for (const std::string& n : sim::benchScenarioNames())
            err << ' ' << n;
        err << '\n';
        return 2;
    }
    const std::uint64_t memoryBefore = peakResidentBytes();
    // As `run` does: a big crowd of fliers stored in the order the World steps it in.
    const bool ordered = sim::orderPlacedForGrid(scene);
    sim::WorldOptions options;
    options.threads = args.threads;
    sim::World world(scene, options);
    if (!world.brainErrors().empty()) {
        err << "throng-cli: the scenario's brain does not run: " << world.brainErrors()[0] << '\n';
        return 1;
    }
    std::size_t withBrain = 0;
    for (std::size_t i = 0; i < world.agentCount(); ++i)
        withBrain += world.agentBrainEvaluator(i) != nullptr;
    const std::uint64_t steps = args.steps.value_or(200);
    Progress progress(err, "bench " + name, steps, !args.quiet);
    const auto start = std::chrono::steady_clock::now();
    for (std::uint64_t s = 0; s < steps; ++s) {
        world.step();
        progress.update(s + 1);
    }
    progress.finish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const sim::RunStats stats = sim::RunStats::from(world, steps + 1, seconds);
    const std::uint64_t memory = peakResidentBytes();

    std::ostringstream j;
    j << "{\"scenario\": \"" << name << "\", ";
    if (name == "cross" || name == "cross-brain")
        j << "\"layout\": \"" << sim::crossLayoutDescription() << "\", ";
    j << "\"agents\": " << world.agentCount() << ", \"steps\": " << steps
      << ", \"threads\": " << world.threads() << ", \"placed_in_grid_order\": " << (ordered ? "true" : "false")
      << ", \"seconds\": " << seconds
      << ", \"agent_steps_per_second\": " << stats.agentStepsPerSecond
      << ", \"ms_per_step\": " << (steps ? seconds * 1000.0 / double(steps) : 0.0)
      << ", \"steps_per_second\": " << (seconds > 0.0 ? double(steps) / seconds : 0.0)
      << ", \"agents_with_brain\": " << withBrain
      << ", \"peak_memory_bytes_per_agent\": "
      << (world.agentCount() ? double(memory - std::min(memory, memoryBefore)) / double(world.agentCount()) : 0.0)
      << ", \"overlapping_pairs_per_step\": " << (steps ? double(stats.counters.overlappingPairs) / double(steps) : 0.0)
      << ", \"fraction_arrived\": " << (stats.withGoal ? double(stats.arrived) / double(stats.withGoal) : 0.0)
      << ", \"wall_penetrations\": " << stats.counters.wallPenetrations
      << ", \"non_finite_values\": " << stats.counters.nonFiniteValues;
    // Of the agents the contact rounds went through, the share they passed by (Collide.h).
    const sim::ContactRounds& rounds = world.contactRounds();
    j << ", \"contact_rounds_passed_by\": "
      << (rounds.agents ? double(rounds.passedBy) / double(rounds.agents) : 0.0);
    // Where the steps' time went, phase by phase (World::phaseTimes): ms per step.
    const sim::PhaseTimes& times = world.phaseTimes();
    j << ", \"phase_ms_per_step\": {";
    for (std::size_t p = 0; p < sim::kStepPhaseCount; ++p)
        j << (p ? ", " : "") << '"' << sim::kStepPhaseNames[p] << "\": "
          << (steps ? times.seconds(sim::StepPhase(p)) * 1000.0 / double(steps) : 0.0);
    j << "}}\n";
    out << j.str();
    return 0;
}

}  // namespace throng::cli
