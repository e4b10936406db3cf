// throng-bench-layout: the layout layer on a big recording (issue 29's figures): 10,000
// walkers over 2,400 frames and a layer of 20 operations, each kind twice (translate,
// rotate, time offset, mirror, delete, expand, duplicate, swap, replace clip, resolve;
// selections by ids, types and a lasso). Times, medians of 3:
// setting the layer up, showing one edited frame (the viewport's cost after an edit;
// median over 24 frames across the shot), applying it to every frame (and the same without
// its two resolves, the costly kind), and writing the trajectories CSV of the laid-out
// frames against the recording's. Prints one JSON object.
// Not a test.
//
// usage: throng-bench-layout [--agents N] [--frames F]
#include "export/TrajectoryCsv.h"
#include "simcore/layout/LayoutApply.h"
#include "simcore/layout/LayoutCheck.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <vector>

using namespace throng;

namespace {

void makeRun(std::size_t agents, std::size_t frames, sim::Scene& scene, sim::FrameCache& cache)
{
    constexpr float kFps = 24.0f;
    sim::AgentType walker, runner;
    walker.name = "walker";
    runner.name = "runner";
    scene.agentTypes = {walker, runner};
    scene.settings.fps = kFps;
    std::vector<sim::AgentInfo> infos;
    for (std::size_t i = 0; i < agents; ++i)
        infos.push_back({static_cast<sim::AgentId>(i + 1), static_cast<std::uint16_t>(i % 5 == 0 ? 1 : 0)});
    cache.reset(infos, kFps);
    const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(agents))));
    std::vector<sim::AgentFrame> frame(agents);
    for (std::size_t i = 0; i < agents; ++i)
        frame[i].position = {0.5f * static_cast<float>(i % side), 0.0f, -25.0f + 0.5f * static_cast<float>(i / side)};
    for (std::size_t f = 0; f < frames; ++f) {
        for (std::size_t i = 0; i < agents; ++i) {
            sim::AgentFrame& a = frame[i];
            a.speed = 0.8f + 0.1f * static_cast<float>(i % 7);
            a.clip = sim::Clip::Walk;
            if (f > 0)
                a.position.x += a.speed / kFps;
        }
        cache.append(frame);
    }
}

// Twenty operations, each on a few hundred to a few thousand agents.
sim::LayoutLayer makeLayer(std::size_t agents, std::size_t frames)
{
    sim::LayoutLayer layer;
    auto ids = [&](std::size_t from, std::size_t count) {
        std::vector<std::uint32_t> list;
        for (std::size_t i = from; i < std::min(agents, from + count); ++i)
            list.push_back(static_cast<std::uint32_t>(i + 1));
        return list;
    };
    for (int k = 0; k < 20; ++k) {
        sim::LayoutOp op;
        op.kind = static_cast<sim::LayoutKind>(k % sim::kLayoutKindCount);
        op.agents.ids = ids(std::size_t(k) * agents / 25, agents / 10);
        if (k % 4 == 1)
            op.agents.types = {"runner"};
        if (k == 7)
            op.agents.lasso = {{0, -25}, {20, -25}, {20, 0}, {0, 0}};
        op.offset = {1.0f, -0.5f};
        op.angleDeg = 10.0f;
        op.frames = 12 * (k % 3 + 1);
        op.axis[0] = {10, -30};
        op.axis[1] = {10, 30};
        op.factor = 1.1f;
        op.look = 1;
        op.clip = sim::Clip::Wave;
        if (op.kind == sim::LayoutKind::Delete)
            op.firstFrame = frames / 2;
        layer.ops.push_back(op);
    }
    return layer;
}

double seconds(const std::function<void()>& work)
{
    const auto t0 = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv)
{
    std::size_t agents = 10'000, frames = 2'400;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--agents"))
            agents = std::strtoul(argv[i + 1], nullptr, 10);
        else if (!std::strcmp(argv[i], "--frames"))
            frames = std::strtoul(argv[i + 1], nullptr, 10);
    }
    sim::Scene scene;
    sim::FrameCache cache;
    makeRun(agents, frames, scene, cache);
    scene.layout = makeLayer(agents, frames);

    sim::Scene unresolved = scene;
    std::erase_if(unresolved.layout.ops, [](const sim::LayoutOp& op) { return op.kind == sim::LayoutKind::Resolve; });
    std::vector<double> setup, frame, apply, applyUnresolved, check, csvLaid, csvRaw;
    const std::string path = (std::filesystem::temp_directory_path() / "throng-bench-layout.csv").string();
    for (int run = 0; run < 3; ++run) {
        std::unique_ptr<sim::LayoutEvaluator> evaluator;
        setup.push_back(seconds([&] { evaluator = std::make_unique<sim::LayoutEvaluator>(scene, cache); }));
        std::vector<double> each;
        std::vector<sim::AgentFrame> out;
        for (std::size_t f = 0; f < frames; f += frames / 24)
            each.push_back(seconds([&] { evaluator->frame(f, out); }));
        frame.push_back(median(each));
        sim::FrameCache laid;
        apply.push_back(seconds([&] { laid = sim::applyLayout(scene, cache); }));
        applyUnresolved.push_back(seconds([&] { sim::applyLayout(unresolved, cache); }));
        check.push_back(seconds([&] { sim::checkLayout(scene, cache, laid); }));
        csvLaid.push_back(seconds([&] { exporting::writeTrajectoryCsv(laid, path); }));
        csvRaw.push_back(seconds([&] { exporting::writeTrajectoryCsv(cache, path); }));
    }
    std::filesystem::remove(path);
    std::printf("{\"bench\": \"layout\", \"agents\": %zu, \"frames\": %zu, \"operations\": %zu, "
                "\"setup_ms\": %.1f, \"edited_frame_ms\": %.2f, \"apply_all_frames_s\": %.2f, "
                "\"apply_without_resolves_s\": %.2f, \"check_s\": %.2f, \"csv_laid_out_s\": %.2f, "
                "\"csv_recording_s\": %.2f, "
                "\"csv_ratio\": %.3f, \"laid_out_agents\": %zu}\n",
                agents, frames, scene.layout.ops.size(), 1e3 * median(setup), 1e3 * median(frame), median(apply),
                median(applyUnresolved), median(check), median(csvLaid), median(csvRaw),
                median(csvLaid) / median(csvRaw),
                sim::LayoutEvaluator(scene, cache).agents().size());
    return 0;
}
