#include "RunOutputs.h"

#include "export/GltfExporter.h"
#include "export/TrajectoryCsv.h"
#include "simcore/io/SceneIO.h"

#include <filesystem>
#include <ostream>

namespace throng::cli {

bool writeRunOutputs(const CliArguments& args, const sim::Scene& scene, const sim::FrameCache& cache,
                     const sim::RunStats& stats, std::ostream& out, std::ostream& err)
{
    bool ok = true;
    auto report = [&](const char* what, bool success, const std::string& path, const std::string& error) {
        if (success)
            out << what << ": " << path << '\n';
        else {
            err << "throng-cli: " << error << '\n';
            ok = false;
        }
    };
    if (!args.trajectoriesPath.empty()) {
        const exporting::ExportResult r = exporting::writeTrajectoryCsv(cache, args.trajectoriesPath);
        report("trajectories", r.ok(), args.trajectoriesPath, r.error);
    }
    if (!args.exportPath.empty()) {
        exporting::GltfOptions options;
        options.path = args.exportPath;
        options.mode = args.exportMode == "compact" ? exporting::GltfMode::Compact : exporting::GltfMode::Exact;
        options.sceneDirectory = std::filesystem::path(args.scene).parent_path().string();
        options.threads = args.threads;
        options.seed = args.seed;
        if (args.exportJointStep)
            options.jointFrameStep = static_cast<int>(*args.exportJointStep);
        const exporting::ExportResult r = exporting::exportGltf(scene, cache, options);
        std::string written;
        for (const std::string& p : r.writtenPaths)
            written += (written.empty() ? "" : ", ") + p;
        report("export", r.ok(), written, r.error);
    }
    // Stats last, so a pipeline that sees the stats file knows the other outputs are done.
    if (!args.statsPath.empty()) {
        const sim::SaveResult r = sim::writeFileAtomically(args.statsPath, stats.toJson());
        report("stats", r.ok, args.statsPath, r.error);
    }
    return ok;
}

}  // namespace throng::cli
