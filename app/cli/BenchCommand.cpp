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

// Milliseconds per step of each phase (World::phaseTimes) over `steps` steps: what `times`
// holds beyond `before`, as a JSON object.
void writePhases(std::ostream& j, const sim::PhaseTimes& times, const sim::PhaseTimes& before, std::uint64_t steps)
{
    j << '{';
    for (std::size_t p = 0; p < sim::kStepPhaseCount; ++p) {
        const double seconds = times.seconds(sim::StepPhase(p)) - before.seconds(sim::StepPhase(p));
        j << (p ? ", " : "") << '"' << sim::kStepPhaseNames[p]
          << "\": " << (steps ? seconds * 1000.0 / double(steps) : 0.0);
    }
    j << '}';
}

// A window of the run (bench --window): the steps [first, first + steps), which took
// `seconds`; the counters and phase times as they stood before it.
struct Window {
    std::uint64_t first = 0, steps = 0;
    double seconds = 0.0;
    std::uint64_t overlapsBefore = 0;
    sim::PhaseTimes timesBefore;
};

// A window's figures as a JSON object, from the World as it ends. Its neighbours are those
// each agent listed in the window's last step, on average: a step's cost goes with them.
void writeWindow(std::ostream& j, const sim::World& world, const Window& w)
{
    std::uint64_t listed = 0;
    for (const std::uint8_t count : world.neighbourCounts())
        listed += count;
    j << "{\"first_step\": " << w.first << ", \"steps\": " << w.steps
      << ", \"ms_per_step\": " << (w.steps ? w.seconds * 1000.0 / double(w.steps) : 0.0)
      << ", \"mean_neighbours\": " << (world.agentCount() ? double(listed) / double(world.agentCount()) : 0.0)
      << ", \"overlapping_pairs_per_step\": "
      << (w.steps ? double(world.counters().overlappingPairs - w.overlapsBefore) / double(w.steps) : 0.0)
      << ", \"phase_ms_per_step\": ";
    writePhases(j, world.phaseTimes(), w.timesBefore, w.steps);
    j << '}';
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
    // With --window, the figures of each `window` steps too; the time spent on them is not
    // the run's.
    using Clock = std::chrono::steady_clock;
    const std::uint64_t window = args.window.value_or(0);
    std::ostringstream windows;
    Window current;
    Clock::duration spentOnWindows{};
    const auto start = Clock::now();
    auto windowStart = start;
    for (std::uint64_t s = 0; s < steps; ++s) {
        world.step();
        progress.update(s + 1);
        if (window > 0 && ((s + 1) % window == 0 || s + 1 == steps)) {
            const auto now = Clock::now();
            current.steps = s + 1 - current.first;
            current.seconds = std::chrono::duration<double>(now - windowStart).count();
            windows << (current.first ? ", " : "");
            writeWindow(windows, world, current);
            current = {s + 1, 0, 0.0, world.counters().overlappingPairs, world.phaseTimes()};
            windowStart = Clock::now();
            spentOnWindows += windowStart - now;
        }
    }
    progress.finish();
    const double seconds = std::chrono::duration<double>(Clock::now() - start - spentOnWindows).count();
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
    j << ", \"phase_ms_per_step\": ";
    writePhases(j, world.phaseTimes(), sim::PhaseTimes{}, steps);
    if (window > 0)
        j << ", \"windows\": [" << windows.str() << ']';
    j << "}\n";
    out << j.str();
    return 0;
}

}  // namespace throng::cli
