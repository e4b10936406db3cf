// Issue 6's figure: the time from an edit at frame F of a scene to the next frame the
// editor can show, when the run starts over from frame 0 (before) and when it resumes from
// the last checkpoint (after; as editor/simulation/SimulationRunner does: step the recorded
// scene from the checkpoint to F, adopt the state into the edited scene, step once).
// EDIT: wall (a wall across the crossroads' north-west sidewalk) or brush (a crowd-brush
// stroke: 30 placed agents on that sidewalk, ids after every id of the scene, which
// changes the agent set) or lane (a lane drawn in the north-west block, as the lane tool
// makes it: the traffic system is rebuilt and the vehicles carried over by id). Prints
// one JSON object.
// Usage: throng-bench-resume SCENE.yaml [FRAME] [INTERVAL] [wall|brush|lane]
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldState.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <map>
#include <memory>
#include <string>

using namespace throng::sim;

namespace {

double msSince(std::chrono::steady_clock::time_point t)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: throng-bench-resume SCENE.yaml [FRAME] [INTERVAL] [wall|brush|lane]\n");
        return 2;
    }
    const LoadResult loaded = loadScene(argv[1]);
    if (!loaded.ok()) {
        std::fprintf(stderr, "%s\n", loaded.diagnostics.front().format().c_str());
        return 1;
    }
    const std::size_t editFrame = argc > 2 ? std::size_t(std::atol(argv[2])) : 1000;
    const std::size_t interval = argc > 3 ? std::size_t(std::atol(argv[3])) : 24;
    const Scene& scene = loaded.scene;
    const std::string edit = argc > 4 ? argv[4] : "wall";
    Scene edited = scene;
    if (edit == "brush") {
        std::uint32_t id = 1;
        for (const Agent& a : scene.agents) id = std::max(id, a.id + 1);
        for (const Vehicle& v : scene.vehicles) id = std::max(id, v.id + 1);
        for (const Hero& h : scene.heroes) id = std::max(id, h.id + 1);
        for (int k = 0; k < 30; ++k) {
            Agent a;
            a.id = id++;
            a.type = scene.agentTypes.front().name;
            a.position = {-8.2f + 0.8f * float(k % 3), 0.0f, -38.0f + 1.0f * float(k / 3)};
            edited.agents.push_back(a);
        }
    } else if (edit == "lane") {
        edited.lanes.push_back({"drawn", {{-40.0f, -30.0f}, {-20.0f, -30.0f}, {-20.0f, -20.0f}}, 3.5f, 13.9f, true});
    } else {
        edited.walls.push_back({"", {{-8.9f, -25.0f}, {-5.2f, -25.0f}}});
    }

    // The recording, with a checkpoint every `interval` frames.
    using Clock = std::chrono::steady_clock;
    std::map<std::size_t, WorldState> checkpoints;
    double saveMs = 0.0, stepMs = 0.0;
    std::size_t bytes = 0;
    {
        World world(scene);
        checkpoints.emplace(0, world.saveState());
        for (std::size_t f = 1; f <= editFrame; ++f) {
            auto t = Clock::now();
            world.step();
            stepMs += msSince(t);
            if (f % interval == 0) {
                t = Clock::now();
                auto it = checkpoints.emplace(f, world.saveState()).first;
                saveMs += msSince(t);
                bytes += it->second.memoryBytes();
            }
        }
    }

    // Before: the edited scene from frame 0 until frame editFrame + 1 exists again.
    auto t = Clock::now();
    World restarted(edited);
    const double restartFirstMs = msSince(t);
    for (std::size_t f = 0; f <= editFrame; ++f)
        restarted.step();
    const double restartMs = msSince(t);

    // After: from the last checkpoint at or before the edit.
    t = Clock::now();
    const auto from = std::prev(checkpoints.upper_bound(editFrame));
    World recorded(scene);
    recorded.restoreState(from->second);
    for (std::size_t f = from->first; f < editFrame; ++f)
        recorded.step();
    World resumed(edited);
    const bool adopted = resumed.adoptState(recorded.saveState(), scene, edited);
    resumed.step();
    const double resumeMs = msSince(t);

    std::printf("{\"scene\": \"%s\", \"edit\": \"%s\", \"agents\": %zu, \"edit_frame\": %zu, \"checkpoint_interval\": %zu,\n"
                " \"checkpoints\": %zu, \"checkpoint_bytes_each\": %zu, \"checkpoint_save_ms_each\": %.3f,\n"
                " \"step_ms_mean\": %.3f, \"adopted\": %s,\n"
                " \"restart_first_frame_ms\": %.1f, \"restart_to_next_frame_ms\": %.1f,\n"
                " \"resume_to_next_frame_ms\": %.1f, \"speedup\": %.1f}\n",
                argv[1], edit.c_str(), resumed.agentCount(), editFrame, interval, checkpoints.size(),
                bytes / std::max<std::size_t>(1, checkpoints.size() - 1), saveMs / double(checkpoints.size() - 1),
                stepMs / double(editFrame), adopted ? "true" : "false", restartFirstMs, restartMs, resumeMs,
                restartMs / resumeMs);
    return adopted ? 0 : 1;
}
