// throng-bench-export: export time and size of skinned glTF crowds, exact and compact,
// against a naive float bake of the same data, and of skinned FBX crowds (a mesh of their
// own per agent). Prints one JSON object. Not a test.
//
// usage: throng-bench-export [OUT_DIR] [--quick] [--only NAME]
//   OUT_DIR (default: the system's temp folder) receives the .glb files, removed after.
//   --quick: 200 agents x 120 frames only, to check the program runs.
//   --only NAME: just that case (e.g. a10000_f240_compact, a10000_f240_exact_actions: half
//   the agents playing brain actions over a third of the shot; a200_f24_fbx). With it,
//   peak_rss_bytes is that case's peak memory; without, the process's so far.
#include "export/FbxExporter.h"
#include "export/GltfExporter.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <sys/resource.h>

using namespace throng;

namespace {

// A crowd on a 2 m grid, each agent on its own slowly curving path at its own pace
// (standing, strolling, walking, jogging, running), every third stopping half-way. With
// `actions`, half the agents play one of the six actions (by id) over the middle third of
// the shot, as a brain would have them: over walking, over standing, and blending in and
// out; the clips are otherwise walk, run or idle by speed.
void makeCrowd(std::size_t agents, std::size_t frames, sim::Scene& scene, sim::FrameCache& cache,
               bool actions = false)
{
    constexpr float kFps = 24.0f;
    sim::AgentType walker;
    walker.name = "walker";
    walker.variation.looks = {"man", "woman", "tall_man", "child"};
    walker.variation.tints = {{0.8f, 0.25f, 0.2f}, {0.2f, 0.45f, 0.8f}, {0.9f, 0.75f, 0.3f}, {0.3f, 0.65f, 0.35f}};
    walker.variation.heightScale = {0.92f, 1.08f};
    scene.agentTypes = {walker};
    scene.settings.fps = kFps;
    std::vector<sim::AgentInfo> infos;
    for (std::size_t i = 0; i < agents; ++i)
        infos.push_back({static_cast<sim::AgentId>(i + 1), 0});
    cache.reset(infos, kFps);
    const float paces[] = {0.0f, 0.8f, 1.3f, 1.5f, 2.4f, 3.6f};
    const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(agents))));
    std::vector<sim::AgentFrame> frame(agents);
    for (std::size_t i = 0; i < agents; ++i) {
        frame[i].position = {2.0f * static_cast<float>(i % side), 0.0f, 2.0f * static_cast<float>(i / side)};
        frame[i].headingRad = 0.37f * static_cast<float>(i);
    }
    for (std::size_t f = 0; f < frames; ++f) {
        for (std::size_t i = 0; i < agents; ++i) {
            sim::AgentFrame& a = frame[i];
            const bool stopped = i % 3 == 0 && f > frames / 2;
            a.speed = stopped ? 0.0f : paces[i % std::size(paces)];
            a.clip = a.speed < 0.1f ? sim::Clip::Idle : a.speed < 2.5f ? sim::Clip::Walk : sim::Clip::Run;
            if (actions && i % 2 == 1 && f > frames / 3 && f < 2 * frames / 3)
                a.clip = sim::Clip(int(sim::Clip::Wait) + int(i / 2 % 6));
            if (f > 0) {
                a.headingRad += (0.2f + 0.1f * static_cast<float>(i % 5)) / kFps * (i % 2 ? 1.0f : -1.0f);
                a.position += a.speed / kFps * glm::vec3(std::cos(a.headingRad), 0.0f, -std::sin(a.headingRad));
            }
        }
        cache.append(frame);
    }
}

// Every agent every frame in float32, as a straightforward exporter would: root
// translation (12) and rotation (16), 17 joint rotations (16 each), hips translation (12).
std::size_t naiveFloatAnimationBytes(std::size_t agents, std::size_t frames)
{
    return agents * frames * (12 + 16 + 17 * 16 + 12) + frames * 4;
}

std::string g_only;

void run(const char* name, std::size_t agents, std::size_t frames, exporting::GltfMode mode, int jointStep,
         const std::filesystem::path& dir, bool& first, bool actions = false)
{
    if (!g_only.empty() && g_only != name)
        return;
    sim::Scene scene;
    sim::FrameCache cache;
    makeCrowd(agents, frames, scene, cache, actions);
    exporting::GltfOptions options;
    options.path = (dir / (std::string("throng-bench-") + name + ".glb")).string();
    options.mode = mode;
    options.jointFrameStep = jointStep;
    exporting::GltfExportStats stats;
    const auto start = std::chrono::steady_clock::now();
    const exporting::ExportResult result = exporting::exportGltf(scene, cache, options, {}, &stats);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::error_code ec;
    std::filesystem::remove(options.path, ec);
    const double agentFrames = static_cast<double>(agents * frames);
    const std::size_t animation = stats.rootMotionBytes + stats.jointBytes + stats.clockBytes;
    const std::size_t naive = naiveFloatAnimationBytes(agents, frames);
    std::printf("%s\n    \"%s\": {\"ok\": %s, \"error\": \"%s\", \"agents\": %zu, \"frames\": %zu, \"mode\": \"%s\", "
                "\"joint_frame_step\": %d, \"export_seconds\": %.3f, \"file_bytes\": %zu, \"bytes_per_agent_frame\": %.2f, "
                "\"json_bytes\": %zu, \"geometry_bytes\": %zu, \"root_motion_bytes\": %zu, \"joint_animation_bytes\": %zu, "
                "\"clock_bytes\": %zu, \"joint_share_of_file\": %.4f, \"joint_share_of_animation\": %.4f, "
                "\"naive_float_animation_bytes\": %zu, \"animation_bytes_vs_naive\": %.4f, \"file_bytes_vs_naive_animation\": %.4f}",
                first ? "" : ",", name, result.ok() ? "true" : "false", result.error.c_str(), agents, frames,
                mode == exporting::GltfMode::Exact ? "exact" : "compact", jointStep, seconds, stats.fileBytes,
                static_cast<double>(stats.fileBytes) / agentFrames,
                stats.fileBytes - std::min(stats.fileBytes, stats.geometryBytes + animation), stats.geometryBytes,
                stats.rootMotionBytes, stats.jointBytes, stats.clockBytes,
                static_cast<double>(stats.jointBytes) / static_cast<double>(std::max<std::size_t>(1, stats.fileBytes)),
                static_cast<double>(stats.jointBytes) / static_cast<double>(std::max<std::size_t>(1, animation)), naive,
                static_cast<double>(animation) / static_cast<double>(naive),
                static_cast<double>(stats.fileBytes) / static_cast<double>(naive));
    std::fflush(stdout);
    first = false;
}

// The process's peak resident memory so far.
std::size_t peakRssBytes()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return std::size_t(usage.ru_maxrss) * 1024;
}

void runFbx(const char* name, std::size_t agents, std::size_t frames, const std::filesystem::path& dir, bool& first)
{
    if (!g_only.empty() && g_only != name)
        return;
    sim::Scene scene;
    sim::FrameCache cache;
    makeCrowd(agents, frames, scene, cache);
    exporting::FbxOptions options;
    options.path = (dir / (std::string("throng-bench-") + name + ".fbx")).string();
    const auto start = std::chrono::steady_clock::now();
    const exporting::ExportResult result = exporting::exportFbx(scene, cache, options, {});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::error_code ec;
    const std::uintmax_t bytes = std::filesystem::file_size(options.path, ec);
    std::filesystem::remove(options.path, ec);
    std::printf("%s\n    \"%s\": {\"ok\": %s, \"error\": \"%s\", \"agents\": %zu, \"frames\": %zu, "
                "\"format\": \"fbx\", \"export_seconds\": %.3f, \"file_bytes\": %ju, \"bytes_per_agent\": %.0f, "
                "\"peak_rss_bytes\": %zu}",
                first ? "" : ",", name, result.ok() ? "true" : "false", result.error.c_str(), agents, frames, seconds,
                bytes, static_cast<double>(bytes) / static_cast<double>(agents), peakRssBytes());
    std::fflush(stdout);
    first = false;
}

}  // namespace

int main(int argc, char** argv)
{
    std::filesystem::path dir = std::filesystem::temp_directory_path();
    bool quick = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--quick")
            quick = true;
        else if (arg == "--only" && i + 1 < argc)
            g_only = argv[++i];
        else if (arg == "--help" || arg == "-h") {
            std::printf("usage: throng-bench-export [OUT_DIR] [--quick] [--only NAME]\n");
            return 0;
        } else
            dir = arg;
    }
    using exporting::GltfMode;
    bool first = true;
    std::printf("{\"benchmark\": \"throng-bench-export\", \"results\": {");
    if (quick) {
        run("quick_exact", 200, 120, GltfMode::Exact, 1, dir, first);
        run("quick_compact", 200, 120, GltfMode::Compact, 1, dir, first);
        runFbx("quick_fbx", 10, 24, dir, first);
    } else {
        run("a1000_f600_exact", 1000, 600, GltfMode::Exact, 1, dir, first);
        run("a1000_f600_exact_joints_every_2", 1000, 600, GltfMode::Exact, 2, dir, first);
        run("a1000_f600_compact", 1000, 600, GltfMode::Compact, 1, dir, first);
        run("a10000_f240_exact", 10000, 240, GltfMode::Exact, 1, dir, first);
        run("a10000_f240_exact_actions", 10000, 240, GltfMode::Exact, 1, dir, first, true);
        run("a10000_f240_compact", 10000, 240, GltfMode::Compact, 1, dir, first);
        runFbx("a200_f24_fbx", 200, 24, dir, first);
    }
    std::printf("\n}}\n");
    return 0;
}
