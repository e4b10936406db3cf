#include "CliCommands.h"
#include "Interrupt.h"
#include "Progress.h"
#include "RunOutputs.h"

#include "simcore/io/SceneIO.h"
#include "simcore/io/SceneOverrides.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/GridOrder.h"
#include "simcore/world/RunStats.h"
#include "simcore/world/World.h"

#include <chrono>
#include <cmath>
#include <ostream>

namespace throng::cli {

int runCommand(const CliArguments& args, std::ostream& out, std::ostream& err)
{
    std::vector<sim::SceneOverride> overrides;
    for (const std::string& text : args.sets) {
        std::string why;
        const std::optional<sim::SceneOverride> o = sim::parseOverride(text, why);
        if (!o) {
            err << "throng-cli: --set " << why << '\n';
            return 2;
        }
        overrides.push_back(*o);
    }
    // Before loading (a million agents take seconds) and long before the last frame.
    if (!outputsWritable(args, err)) {
        err << "throng-cli: nothing was run\n";
        return 1;
    }
    sim::LoadResult loaded = sim::loadScene(args.scene, overrides);
    for (const sim::Diagnostic& d : loaded.diagnostics)
        err << d.format() << '\n';
    if (!loaded.ok()) {
        err << "throng-cli: " << args.scene << " is not a valid scene; nothing was run\n";
        return 1;
    }
    // A big crowd of fliers is stored in the order the World steps it in: every agent keeps
    // its id and does the same, but the steps read and write memory in order (GridOrder.h).
    sim::orderPlacedForGrid(loaded.scene);
    const sim::Scene& scene = loaded.scene;
    const std::uint64_t frames =
        args.frames ? *args.frames
                    : std::max<std::uint64_t>(1, std::uint64_t(std::llround(double(scene.settings.durationS) *
                                                                             double(scene.settings.fps))));
    if (frames == 0) {
        err << "throng-cli: --frames must be at least 1 (frame 0 is the initial state)\n";
        return 2;
    }
    sim::WorldOptions options;
    options.threads = args.threads;
    if (args.seed) {
        options.overrideSeed = true;
        options.seed = *args.seed;
    }
    sim::World world(scene, options);
    if (!world.brainErrors().empty()) {
        for (const std::string& e : world.brainErrors())
            err << e << '\n';
        err << "throng-cli: a brain of " << args.scene << " cannot run; nothing was run\n";
        return 1;
    }

    const bool record = !args.exports.empty() || !args.reportPath.empty();
    sim::FrameCache cache;
    if (record)
        world.startRecording(cache);
    std::vector<sim::AgentFrame> frame;

    Progress progress(err, "simulating", frames - 1, !args.quiet && world.agentCount() * frames > 2'000'000);
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::uint64_t> inScene;
    sim::RunStats::sampleInScene(world, inScene);
    for (std::uint64_t f = 1; f < frames; ++f) {
        if (InterruptWatch::requested()) {
            progress.stop();
            err << "throng-cli: stopped by " << InterruptWatch::signalName() << " at frame " << f << " of " << frames
                << "; nothing was written\n";
            return InterruptWatch::exitStatus();
        }
        world.step();
        sim::RunStats::sampleInScene(world, inScene);
        if (record) {
            world.snapshot(frame);
            cache.append(frame);
        }
        progress.update(f);
    }
    progress.finish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    sim::RunStats stats = sim::RunStats::from(world, frames, seconds);
    stats.inSceneEachSecond = std::move(inScene);

    out << "simulated " << stats.agents << " agents for " << frames << " frames (" << world.timeS()
        << " s at " << scene.settings.fps << " fps) in " << seconds << " s: " << stats.agentStepsPerSecond
        << " agent-steps/s\n";
    return writeRunOutputs(args, scene, cache, stats, out, err);
}

}  // namespace throng::cli
