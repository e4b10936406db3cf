// Scene file throughput: saves and loads a painted crowd of N agents (table form) and
// prints one JSON object per size. Usage: throng-bench-io [AGENTS...]
#include "simcore/io/SceneIO.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace throng::sim;

namespace {

Scene paintedCrowd(std::uint32_t agents)
{
    Scene s;
    s.agentTypes.push_back(AgentType{});
    s.agentTypes[0].name = "walker";
    s.goals.push_back({"exit", {0.0f, 0.0f}, 1.0f});
    s.agents.reserve(agents);
    for (std::uint32_t i = 0; i < agents; ++i) {
        Agent a;
        a.id = i + 1;
        a.type = "walker";
        a.position = {float(i % 1000) * 0.7f + 0.013f * float(i % 7), 0.0f, float(i / 1000) * 0.7f};
        a.headingDeg = float(i % 360) + 0.25f;
        a.goal = i % 2 ? "exit" : "";
        s.agents.push_back(a);
    }
    return s;
}

double secondsSince(std::chrono::steady_clock::time_point t)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

int main(int argc, char** argv)
{
    std::vector<std::uint32_t> sizes;
    for (int i = 1; i < argc; ++i)
        sizes.push_back(std::uint32_t(std::stoul(argv[i])));
    if (sizes.empty())
        sizes = {10'000, 100'000, 1'000'000};
    const auto dir = std::filesystem::temp_directory_path() / "throng-bench-io";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "crowd.yaml").string();
    for (std::uint32_t n : sizes) {
        const Scene scene = paintedCrowd(n);
        auto t = std::chrono::steady_clock::now();
        const SaveResult saved = saveScene(scene, path);
        const double saveS = secondsSince(t);
        if (!saved.ok) {
            std::fprintf(stderr, "%s\n", saved.error.c_str());
            return 1;
        }
        const auto bytes = std::filesystem::file_size(path);
        t = std::chrono::steady_clock::now();
        const LoadResult loaded = loadScene(path);
        const double loadS = secondsSince(t);
        const bool same = loaded.ok() && loaded.scene == scene;
        std::printf("{\"bench\": \"scene_io\", \"agents\": %u, \"bytes\": %llu, \"save_seconds\": %.4f, "
                    "\"load_seconds\": %.4f, \"load_mb_per_second\": %.1f, \"round_trip_equal\": %s}\n",
                    n, static_cast<unsigned long long>(bytes), saveS, loadS, double(bytes) / 1e6 / loadS,
                    same ? "true" : "false");
    }
    std::filesystem::remove_all(dir);
    return 0;
}
