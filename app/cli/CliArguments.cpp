#include "CliArguments.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <filesystem>

namespace throng::cli {

namespace {

bool parseCount(const std::string& text, std::uint64_t& out)
{
    auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && p == text.data() + text.size() && !text.empty();
}

// Why `path` names no format: "unknown format '.xyz' (known: .glb, ...)".
std::string unknownFormat(const std::string& path)
{
    const std::string suffix = std::filesystem::path(path).extension().string();
    return (suffix.empty() ? std::string("no format suffix") : "unknown format '" + suffix + "'") + " (known: " +
           exporting::knownPathForms() + ")";
}

// "                                .glb, .gltf  glTF 2.0 ...\n", a line per format --export
// reaches by its path (the Maya cache has its own option).
std::string formatLines()
{
    std::string text;
    for (const exporting::ExportFormat& f : exporting::exportFormats()) {
        if (f.writesDirectory && exporting::formatForPath("d/") != &f)
            continue;
        std::string forms = exporting::pathForms(f);
        forms.resize(std::max<std::size_t>(forms.size() + 1, 13), ' ');
        text += "                                " + forms + f.label + "\n";
    }
    return text;
}

}  // namespace

std::string usageText()
{
    return "usage: throng-cli <command> [options]\n"
           "\n"
           "commands:\n"
           "  check SCENE                 validate a scene and its brains; errors as file:line:col\n"
           "  run SCENE [options]         simulate a scene headless\n"
           "      --frames N              frames to simulate (default: the scene's duration x fps)\n"
           "      --seed S                override the scene's random seed\n"
           "      --threads T             worker threads (default: all cores)\n"
           "      --stats OUT.json        write the run's figures as JSON\n"
           "      --report OUT.html       write the run's analysis as one self-contained HTML file:\n"
           "                              trajectories, density heatmap, speed against density,\n"
           "                              flow per measurement line and exit, agents in and out\n"
           "      --report-cell M         the report's density heatmap in cells of M metres (default 1)\n"
           "      --report-trajectories N the report's plan draws at most N walkers (default 2,000)\n"
           "      --trajectories OUT.csv  write frame,agent,x,y,z,heading,speed,clip,phase rows\n"
           "                              (the same file as --export OUT.csv)\n"
           "      --export OUT            write the recorded run in the format OUT's suffix names;\n"
           "                              give it again for more outputs of the same run:\n" +
           formatLines() +
           "      --export-mode exact|compact  glTF, USD: bake every agent's joints (default), or share one\n"
           "                              cycle per look (joint data ~13x smaller; docs/export.md)\n"
           "      --export-joint-step N   glTF (exact), USD, FBX: bake joints every N-th frame (default 1)\n"
           "      --export-lod near|mid|far  glTF, USD, FBX: the built-in characters' detail (default near,\n"
           "                              about 6,600 triangles a body; mid 2,300; far 1,000)\n"
           "      --no-set                glTF, USD, FBX: the crowd alone, without the set (ground, lanes,\n"
           "                              crosswalks, walls, obstacles, traffic lights)\n"
           "      --maya-cache DIR        write the " +
           exporting::formatByKey("maya-cache")->label +
           ":\n"
           "                              for resources/maya/throngCrowd.mel (docs/export.md)\n"
           "      --maya-forward z|x      the Maya cache: the axis the rigs face at rotY 0 (default z)\n"
           "      --set KEY=VALUE         set a scene value for this run, as if the file said so\n"
           "                              (e.g. agent_types.walker.max_speed=1.2; docs/wedges.md)\n"
           "  wedge SCENE --out DIR [--set KEY=V1,V2,...]... [--seeds A..B] [--jobs N] [--frames N]\n"
           "                              run every combination of the values for every seed, each in\n"
           "                              DIR/vNNN (its stats.json and run.log), in N processes at once;\n"
           "                              then collect\n"
           "      --slurm                 submit the variants as one Slurm array job (sbatch), a task\n"
           "                              each, and return; collect when it is done\n"
           "  wedge collect DIR [--metric NAME]\n"
           "                              gather the variants' figures into DIR/wedge.csv and\n"
           "                              DIR/wedge.json, and plot NAME (default arrived) in\n"
           "                              DIR/wedge.png; a failed variant's row says why\n"
           "  bench [--agents N] [--steps S] [--scenario flock|cross|cross-brain|army|corridor] [--threads T]\n"
           "        [--window W]          run a built-in scenario and print figures as JSON; with\n"
           "                              --window, those of every W steps too (how the cost of a\n"
           "                              step changes as the crowd gathers or spreads)\n"
           "  validate [DIR] [--json]     run the RiMEA tests (docs/validation.md) on the scenes in DIR\n"
           "                              (default: the source tree's resources/validation); exit 1\n"
           "                              when one fails\n"
           "\n"
           "options for every command:\n"
           "  --quiet                     no progress on stderr\n"
           "  --help                      this text\n"
           "  --version                   the version\n"
           "\n"
           "exit status: 0 success, 1 the scene or a run failed, 2 wrong usage\n";
}

ParseOutcome parseArguments(const std::vector<std::string>& argv)
{
    ParseOutcome out;
    CliArguments& a = out.args;
    std::vector<std::string> positional;
    auto addOutput = [&](const std::string& flag, const std::string& path, const exporting::ExportFormat* format) {
        for (const ExportOutput& o : a.exports)
            if (o.path == path)
                out.error = "--" + flag + " " + path + ": already an output of this run";
        if (out.error.empty())
            a.exports.push_back({flag, path, format});
    };
    for (std::size_t i = 0; i < argv.size(); ++i) {
        const std::string& arg = argv[i];
        auto value = [&](std::string& into) {
            if (i + 1 >= argv.size() || argv[i + 1].empty()) {
                out.error = arg + " needs a value";
                return false;
            }
            into = argv[++i];
            return true;
        };
        auto count = [&](std::optional<std::uint64_t>& into, bool allowZero) {
            std::string text;
            if (!value(text))
                return;
            std::uint64_t v = 0;
            if (!parseCount(text, v) || (!allowZero && v == 0))
                out.error = arg + " needs a whole number" + (allowZero ? "" : " >= 1") + ", got '" + text + "'";
            else
                into = v;
        };
        if (arg == "--help" || arg == "-h") {
            a.command = "help";
            return out;
        }
        if (arg == "--version") {
            a.command = "version";
            return out;
        }
        if (arg == "--quiet" || arg == "-q") a.quiet = true;
        else if (arg == "--json") a.json = true;
        else if (arg == "--no-set") a.noSet = true;
        else if (arg == "--slurm") a.slurm = true;
        else if (arg == "--set") {
            std::string text;
            if (value(text))
                a.sets.push_back(text);
        } else if (arg == "--seeds") value(a.seeds);
        else if (arg == "--out") value(a.outDir);
        else if (arg == "--metric") value(a.metric);
        else if (arg == "--jobs") {
            std::optional<std::uint64_t> j;
            count(j, false);
            if (j && *j > 1024)
                out.error = "--jobs must be at most 1024";
            else if (j)
                a.jobs = int(*j);
        }
        else if (arg == "--frames") count(a.frames, true);
        else if (arg == "--seed") count(a.seed, true);
        else if (arg == "--agents") count(a.agents, false);
        else if (arg == "--steps") count(a.steps, false);
        else if (arg == "--window") count(a.window, false);
        else if (arg == "--threads") {
            std::optional<std::uint64_t> t;
            count(t, false);
            if (t && *t > 1024)
                out.error = "--threads must be at most 1024";
            else if (t)
                a.threads = int(*t);
        } else if (arg == "--stats") value(a.statsPath);
        else if (arg == "--report") value(a.reportPath);
        else if (arg == "--report-cell") {
            std::string text;
            if (value(text)) {
                char* end = nullptr;
                const double m = std::strtod(text.c_str(), &end);
                if (end != text.c_str() + text.size() || !(m >= 0.1 && m <= 100.0))
                    out.error = "--report-cell is the heatmap's cell in metres, 0.1 to 100, got '" + text + "'";
                else
                    a.reportCellM = m;
            }
        } else if (arg == "--report-trajectories") {
            count(a.reportTrajectories, false);
            if (a.reportTrajectories && *a.reportTrajectories > 1'000'000)
                out.error = "--report-trajectories must be at most 1,000,000";
        }
        else if (arg == "--trajectories") {
            std::string path;
            if (value(path))
                addOutput("trajectories", path, exporting::formatByKey("csv"));
        } else if (arg == "--export") {
            std::string path;
            if (value(path)) {
                if (const exporting::ExportFormat* format = exporting::formatForPath(path))
                    addOutput("export", path, format);
                else
                    out.error = "--export " + path + ": " + unknownFormat(path);
            }
        }
        else if (arg == "--export-mode") {
            if (value(a.exportMode) && a.exportMode != "exact" && a.exportMode != "compact")
                out.error = "--export-mode is exact or compact, got '" + a.exportMode + "'";
        } else if (arg == "--maya-cache") {
            std::string path;
            if (value(path))
                addOutput("maya-cache", path, exporting::formatByKey("maya-cache"));
        } else if (arg == "--maya-forward") {
            if (value(a.mayaForward) && a.mayaForward != "z" && a.mayaForward != "x")
                out.error = "--maya-forward is z or x, got '" + a.mayaForward + "'";
        } else if (arg == "--export-lod") {
            exporting::Lod lod{};
            if (value(a.exportLod) && !exporting::lodFromName(a.exportLod, lod))
                out.error = "--export-lod is near, mid or far, got '" + a.exportLod + "'";
        } else if (arg == "--export-joint-step") {
            count(a.exportJointStep, false);
            if (a.exportJointStep && *a.exportJointStep > 1000)
                out.error = "--export-joint-step must be at most 1000";
        }
        else if (arg == "--scenario") value(a.scenario);
        else if (arg.size() > 1 && arg[0] == '-') out.error = "unknown option '" + arg + "'";
        else positional.push_back(arg);
        if (!out.error.empty())
            return out;
    }
    if (positional.empty()) {
        out.error = "no command given";
        return out;
    }
    a.command = positional[0];
    if (a.command == "help" || a.command == "version")
        return out;
    if (a.command == "check" || a.command == "run") {
        if (positional.size() != 2) {
            out.error = a.command + " takes exactly one SCENE file";
            return out;
        }
        a.scene = positional[1];
    } else if (a.command == "bench") {
        if (positional.size() != 1)
            out.error = "bench takes no file";
    } else if (a.command == "wedge") {
        if (positional.size() == 3 && positional[1] == "collect") {
            a.command = "wedge-collect";
            a.scene = positional[2];
        } else if (positional.size() != 2) {
            out.error = "wedge takes one SCENE (or: wedge collect DIR)";
        } else {
            a.scene = positional[1];
            if (a.outDir.empty())
                out.error = "wedge needs --out DIR, the folder of its variants";
            else if (a.sets.empty() && a.seeds.empty())
                out.error = "wedge needs --set KEY=V1,V2,... or --seeds A..B: something to vary";
        }
    } else if (a.command == "validate") {
        if (positional.size() > 2)
            out.error = "validate takes at most one folder of validation scenes";
        else if (positional.size() == 2)
            a.scene = positional[1];
    } else {
        out.error = "unknown command '" + a.command + "'";
    }
    if (out.error.empty() && a.window && a.command != "bench")
        out.error = "--window belongs to 'bench'";
    const bool wedge = a.command == "wedge" || a.command == "wedge-collect";
    if (out.error.empty() && !wedge &&
        (!a.seeds.empty() || !a.outDir.empty() || a.jobs > 0 || !a.metric.empty() || a.slurm))
        out.error = "--seeds, --out, --jobs, --slurm and --metric belong to 'wedge'";
    if (out.error.empty() && a.slurm && a.jobs > 0)
        out.error = "--jobs is for a wedge on this machine; with --slurm, Slurm runs the variants";
    if (out.error.empty() && a.command != "run" && a.command != "wedge" && !a.sets.empty())
        out.error = "--set belongs to 'run' and 'wedge'";
    if (out.error.empty() && (a.reportCellM || a.reportTrajectories) && a.reportPath.empty())
        out.error = "--report-cell and --report-trajectories shape the --report: give --report OUT.html too";
    if (out.error.empty() && a.command == "wedge" && (!a.statsPath.empty() || !a.reportPath.empty() ||
                                                      !a.exports.empty()))
        out.error = "a wedge writes each variant's stats itself; --stats, --report and --export belong to 'run'";
    if (out.error.empty() && a.command != "run" && a.command != "wedge" &&
        (!a.statsPath.empty() || !a.reportPath.empty() || !a.exports.empty() || a.frames ||
         !a.exportMode.empty() || a.exportJointStep || !a.exportLod.empty() || !a.mayaForward.empty() ||
         a.noSet))
        out.error = "--frames, --stats, --report, --trajectories, --export and --maya options belong to 'run'";
    return out;
}

}  // namespace throng::cli
