#include "RunOutputs.h"

#include "Interrupt.h"
#include "Progress.h"

#include "export/ExportFormats.h"
#include "simcore/io/SceneIO.h"
#include "simcore/layout/LayoutApply.h"
#include "simcore/layout/LayoutCheck.h"
#ifdef THRONG_HAS_REPORT
#include "report/HtmlReport.h"
#include "simcore/analysis/RunAnalysis.h"
#endif

#include <algorithm>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

#include <unistd.h>

namespace throng::cli {

namespace {

constexpr std::size_t kProgressAgentFrames = 500'000;

// Why `path` cannot be written, or empty when it can (as far as can be told before writing).
std::string unwritable(const std::string& path, bool directory)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path p(path);
    if (directory) {
        if (fs::exists(p, ec) && !fs::is_directory(p, ec))
            return "it is a file, not a folder";
    } else if (fs::is_directory(p, ec)) {
        return "it is a folder";
    }
    // The folder it goes in (the nearest that exists, for a directory the writer makes).
    fs::path folder = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    if (directory)
        while (!fs::exists(folder, ec)) {
            const fs::path up = folder.parent_path();
            if (up == folder)
                break;  // a root that does not exist
            folder = up.empty() ? fs::path(".") : up;  // a relative path's first folder lies in "."
        }
    if (!fs::exists(folder, ec))
        return "the folder '" + folder.string() + "' does not exist";
    if (!fs::is_directory(folder, ec))
        return "'" + folder.string() + "' is not a folder";
    if (::access(folder.c_str(), W_OK) != 0)
        return "the folder '" + folder.string() + "' is not writable";
    return {};
}

}  // namespace

bool outputsWritable(const CliArguments& args, std::ostream& err)
{
    bool ok = true;
    auto check = [&](const std::string& flag, const std::string& path, bool directory) {
        if (const std::string why = unwritable(path, directory); !why.empty()) {
            err << "throng-cli: --" << flag << ' ' << path << ": cannot be written: " << why << '\n';
            ok = false;
        }
    };
    for (const ExportOutput& output : args.exports)
        check(output.flag, output.path, output.format->writesDirectory);
    if (!args.reportPath.empty())
        check("report", args.reportPath, false);
    if (!args.statsPath.empty())
        check("stats", args.statsPath, false);
    return ok;
}

int writeRunOutputs(const CliArguments& args, const sim::Scene& scene, const sim::FrameCache& cache,
                    const sim::RunStats& stats, std::ostream& out, std::ostream& err)
{
    bool ok = true;
    // Stopped by a signal before `what`: say what was not written.
    auto stopped = [&](const std::string& what) {
        if (!InterruptWatch::requested())
            return false;
        err << "throng-cli: stopped by " << InterruptWatch::signalName() << "; " << what
            << " and the outputs after it were not written\n";
        return true;
    };
    auto report = [&](const char* what, bool success, const std::string& path, const std::string& error) {
        if (success)
            out << what << ": " << path << '\n';
        else {
            err << "throng-cli: " << error << '\n';
            ok = false;
        }
    };
    exporting::ExportRequest request;
    request.sceneDirectory = std::filesystem::path(args.scene).parent_path().string();
    request.seed = args.seed;
    request.threads = args.threads;
    request.jointBake = args.exportMode == "compact" ? exporting::JointBake::Compact : exporting::JointBake::Exact;
    if (args.exportJointStep)
        request.jointFrameStep = static_cast<int>(*args.exportJointStep);
    if (!args.exportLod.empty())
        exporting::lodFromName(args.exportLod, request.lod);
    request.mayaForward = args.mayaForward == "x" ? exporting::ForwardAxis::PlusX : exporting::ForwardAxis::PlusZ;
    request.includeSet = !args.noSet;
    // The scene's layout layer edits what the exports write, never the run itself: stats
    // and the report stay the simulation's. An operation that selects nobody is named.
    std::optional<sim::FrameCache> laidOut;
    if (!scene.layout.ops.empty() && !args.exports.empty()) {
        std::vector<std::string> messages;
        laidOut = sim::applyLayout(scene, cache, &messages);
        for (const std::string& m : messages)
            err << "throng-cli: warning: " << m << '\n';
        // What the edits broke that the simulation had kept: bodies overlapping, walls walked through.
        if (const std::string clashes = sim::describe(sim::checkLayout(scene, cache, *laidOut)); !clashes.empty())
            err << "throng-cli: warning: the layout layer makes " << clashes << '\n';
    }
    const sim::FrameCache& frames = laidOut ? *laidOut : cache;
    for (const ExportOutput& output : args.exports) {
        if (stopped(output.path))
            return InterruptWatch::exitStatus();
        request.path = output.path;
        // Progress on stderr, as the run's own, for an export of half a million agent-frames or more.
        Progress progress(err, "exporting " + output.path, 1000,
                          !args.quiet && frames.agentCount() * frames.frameCount() >= kProgressAgentFrames);
        const exporting::ExportResult r = output.format->write(scene, frames, request, [&](float done) {
            progress.update(std::uint64_t(std::clamp(done, 0.0f, 1.0f) * 1000.0f));
            return !InterruptWatch::requested();  // the writer stops and leaves nothing
        });
        if (r.ok())
            progress.finish();
        else
            progress.stop();
        if (r.cancelled && stopped(output.path))
            return InterruptWatch::exitStatus();
        // A directory holds a file per agent: name the directory, not thousands of files.
        std::string written;
        if (output.format->writesDirectory)
            written = output.path + " (" + std::to_string(r.writtenPaths.size()) + " files)";
        else
            for (const std::string& p : r.writtenPaths)
                written += (written.empty() ? "" : ", ") + p;
        report(output.flag.c_str(), r.ok(), written, r.error);
    }
    if (!args.reportPath.empty()) {
        if (stopped(args.reportPath))
            return InterruptWatch::exitStatus();
#ifdef THRONG_HAS_REPORT
        sim::AnalysisOptions options;
        options.densityCellM = args.reportCellM.value_or(options.densityCellM);
        options.maxTrajectories = std::size_t(args.reportTrajectories.value_or(options.maxTrajectories));
        const sim::RunAnalysis analysis = sim::analyseRun(scene, cache, options);
        const report::ReportHeading heading{std::filesystem::path(args.scene).filename().string(), stats.seed};
        const sim::SaveResult r = report::writeReport(args.reportPath, scene, analysis, heading);
        report("report", r.ok, args.reportPath, r.error);
#else
        report("report", false, args.reportPath,
               "--report " + args.reportPath + ": this throng-cli was built without Qt Charts, which the report needs");
#endif
    }
    // Stats last, so a pipeline that sees the stats file knows the other outputs are done.
    if (!args.statsPath.empty()) {
        if (stopped(args.statsPath))
            return InterruptWatch::exitStatus();
        const sim::SaveResult r = sim::writeFileAtomically(args.statsPath, stats.toJson());
        report("stats", r.ok, args.statsPath, r.error);
    }
    return ok ? 0 : 1;
}

}  // namespace throng::cli
