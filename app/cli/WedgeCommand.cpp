// throng-cli wedge: every variant of a scene run in parallel processes, and the table of
// their figures (wedge collect). See WedgePlan.h for the variants, docs/wedges.md for use.
#include "CliCommands.h"
#include "Interrupt.h"
#include "WedgePlan.h"

#include "simcore/io/SceneIO.h"
#include "simcore/io/SceneOverrides.h"

#ifdef THRONG_HAS_REPORT
#include "report/WedgeChart.h"
#endif

#include <yaml-cpp/yaml.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <thread>

extern char** environ;

namespace throng::cli {

namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string jsonString(const std::string& text)
{
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\')
            out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
            continue;
        }
        out += c;
    }
    return out + "\"";
}

std::string csvField(const std::string& text)
{
    if (text.find_first_of(",\"\n") == std::string::npos)
        return text;
    std::string out = "\"";
    for (const char c : text)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

bool looksNumeric(const std::string& text)
{
    if (text.empty())
        return false;
    char* end = nullptr;
    std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size();
}

// The command line a variant runs, throng-cli's own arguments after the program.
std::vector<std::string> variantArguments(const WedgePlan& plan, const WedgeVariant& v, const fs::path& folder,
                                          const CliArguments& args, int threads)
{
    std::vector<std::string> a{"run", plan.scene};
    for (const sim::SceneOverride& o : v.overrides) {
        a.push_back("--set");
        a.push_back(o.key + "=" + o.value);
    }
    if (v.seed) {
        a.push_back("--seed");
        a.push_back(std::to_string(*v.seed));
    }
    if (args.frames) {
        a.push_back("--frames");
        a.push_back(std::to_string(*args.frames));
    }
    a.insert(a.end(), {"--stats", (folder / "stats.json").string(), "--quiet"});
    if (threads > 0) {  // else the run's own default, every core
        a.push_back("--threads");
        a.push_back(std::to_string(threads));
    }
    return a;
}

// Starts `program` with `arguments`, its output into `log`; the child's pid, or -1.
pid_t spawn(const std::string& program, const std::vector<std::string>& arguments, const fs::path& log)
{
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    std::vector<std::string> all{program};
    all.insert(all.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& s : all)
        argv.push_back(s.data());
    argv.push_back(nullptr);
    pid_t pid = -1;
    const int rc = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    return rc == 0 ? pid : -1;
}

// `text` quoted for bash, as one word.
std::string shellWord(const std::string& text)
{
    std::string out = "'";
    for (const char c : text)
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// The array job: task k runs variant k (its own folder's log and status), one CPU each.
std::string sbatchScript(const WedgePlan& plan, const fs::path& dir, const CliArguments& args, const std::string& self)
{
    std::ostringstream s;
    s << "#!/bin/bash\n"
      << "# A Throng wedge of " << plan.variants.size() << " variants of " << plan.scene << " (throng-cli wedge --slurm):\n"
      << "# task k runs variant k into its folder; collect with: throng-cli wedge collect " << dir.string() << "\n"
      << "#SBATCH --job-name=throng-wedge\n"
      << "#SBATCH --array=0-" << plan.variants.size() - 1 << "\n"
      << "#SBATCH --cpus-per-task=1\n"
      << "#SBATCH --output=" << (dir / "slurm-%a.log").string() << "\n"
      << "case \"$SLURM_ARRAY_TASK_ID\" in\n";
    for (const WedgeVariant& v : plan.variants) {
        s << v.index << ") folder=" << shellWord((dir / v.folder).string()) << "; args=(";
        for (const std::string& a : variantArguments(plan, v, dir / v.folder, args, 1))
            s << ' ' << shellWord(a);
        s << " ) ;;\n";
    }
    s << "*) echo \"no variant $SLURM_ARRAY_TASK_ID in this wedge\" >&2; exit 2 ;;\n"
      << "esac\n"
      << shellWord(self) << " \"${args[@]}\" > \"$folder/run.log\" 2>&1\n"
      << "status=$?\n"
      << "echo \"$status\" > \"$folder/status\"\n"
      << "exit \"$status\"\n";
    return s.str();
}

std::string selfPath()
{
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    return ec ? std::string() : self.string();
}

struct Row {
    const WedgeVariant* variant = nullptr;
    std::string status;  // ok, failed or not run
    std::string reason;  // why it failed
    std::vector<std::pair<std::string, std::string>> stats;  // name, scalar text ("" for null)
};

std::vector<Row> readRows(const WedgePlan& plan, const fs::path& dir)
{
    std::vector<Row> rows;
    for (const WedgeVariant& v : plan.variants) {
        Row row{&v, "not run", "", {}};
        const fs::path folder = dir / v.folder;
        const std::string status = readText(folder / "status");
        std::string log = readText(folder / "run.log");
        while (!log.empty() && (log.back() == '\n' || log.back() == '\r'))
            log.pop_back();
        const std::string lastLine = log.substr(log.find_last_of('\n') == std::string::npos ? 0 : log.find_last_of('\n') + 1);
        if (!status.empty()) {
            const int code = std::atoi(status.c_str());
            row.status = code == 0 ? "ok" : "failed";
            if (code != 0)
                row.reason = lastLine.empty() ? "exit status " + std::to_string(code) : lastLine;
        }
        if (row.status == "ok") {
            try {
                const YAML::Node stats = YAML::LoadFile((folder / "stats.json").string());
                for (const auto& entry : stats)
                    if (entry.second.IsScalar() || entry.second.IsNull())
                        row.stats.emplace_back(entry.first.as<std::string>(),
                                               entry.second.IsNull() ? std::string() : entry.second.Scalar());
            } catch (const YAML::Exception& e) {
                row.status = "failed";
                row.reason = "its stats.json does not read: " + std::string(e.what());
            }
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

}  // namespace

int wedgeCollectCommand(const CliArguments& args, std::ostream& out, std::ostream& err)
{
    const fs::path dir = args.scene;
    std::string error;
    const std::string planText = readText(dir / "wedge.yaml");
    const std::optional<WedgePlan> plan = planText.empty() ? std::nullopt : planFromYaml(planText, error);
    if (!plan) {
        err << "throng-cli: " << (dir / "wedge.yaml").string() << ": "
            << (planText.empty() ? "no wedge here (no such file)" : error) << '\n';
        return 1;
    }
    const std::vector<Row> rows = readRows(*plan, dir);
    // The figures' columns in the order the first variant that ran gives them (its seed is
    // the row's own seed column already).
    std::vector<std::string> columns;
    for (const Row& r : rows)
        for (const auto& [name, value] : r.stats)
            if (name != "seed" && std::find(columns.begin(), columns.end(), name) == columns.end())
                columns.push_back(name);
    std::ostringstream csv, json;
    csv << "variant,seed";
    for (const WedgeAxis& a : plan->axes)
        csv << ',' << csvField(a.key);
    csv << ",status,reason";
    for (const std::string& c : columns)
        csv << ',' << csvField(c);
    csv << '\n';
    json << "{\n  \"scene\": " << jsonString(plan->scene) << ",\n  \"variants\": [\n";
    std::size_t failed = 0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const Row& r = rows[k];
        const WedgeVariant& v = *r.variant;
        failed += r.status == "ok" ? 0 : 1;
        std::map<std::string, std::string> byName(r.stats.begin(), r.stats.end());
        // Without --seeds a variant runs with the scene's seed, which its stats name.
        const std::string seed = v.seed ? std::to_string(*v.seed) : byName["seed"];
        csv << v.folder << ',' << seed;
        json << "    {\"variant\": " << jsonString(v.folder) << ", \"seed\": " << (seed.empty() ? "null" : seed)
             << ", \"set\": {";
        for (std::size_t a = 0; a < v.overrides.size(); ++a) {
            csv << ',' << csvField(v.overrides[a].value);
            json << (a ? ", " : "") << jsonString(v.overrides[a].key) << ": " << jsonString(v.overrides[a].value);
        }
        csv << ',' << r.status << ',' << csvField(r.reason);
        json << "}, \"status\": " << jsonString(r.status) << ", \"reason\": " << jsonString(r.reason)
             << ", \"stats\": {";
        for (std::size_t c = 0; c < columns.size(); ++c) {
            const auto it = byName.find(columns[c]);
            const std::string value = it == byName.end() ? std::string() : it->second;
            csv << ',' << csvField(value);
            json << (c ? ", " : "") << jsonString(columns[c]) << ": "
                 << (value.empty() ? std::string("null") : looksNumeric(value) ? value : jsonString(value));
        }
        csv << '\n';
        json << "}}" << (k + 1 < rows.size() ? "," : "") << '\n';
    }
    json << "  ]\n}\n";
    for (const auto& [name, text] : {std::pair{"wedge.csv", csv.str()}, {"wedge.json", json.str()}}) {
        const sim::SaveResult saved = sim::writeFileAtomically((dir / name).string(), text);
        if (!saved.ok) {
            err << "throng-cli: " << saved.error << '\n';
            return 1;
        }
        out << "wedge: " << (dir / name).string() << '\n';
    }
#ifdef THRONG_HAS_REPORT
    const std::string metric = args.metric.empty() ? "arrived" : args.metric;
    std::vector<report::WedgeBar> bars;
    for (const Row& r : rows) {
        std::string label = r.variant->folder;
        for (const sim::SceneOverride& o : r.variant->overrides)
            label += " " + o.value;
        if (r.variant->seed)
            label += " s" + std::to_string(*r.variant->seed);
        std::optional<double> value;
        for (const auto& [name, text] : r.stats)
            if (name == metric && looksNumeric(text))
                value = std::strtod(text.c_str(), nullptr);
        bars.push_back({label, value});
    }
    if (std::none_of(bars.begin(), bars.end(), [](const report::WedgeBar& b) { return b.value.has_value(); })) {
        err << "throng-cli: no variant has a figure '" << metric << "' to plot (the columns of wedge.csv are)\n";
    } else if (const std::string plotError = report::writeWedgeChart((dir / "wedge.png").string(), metric, bars);
               !plotError.empty()) {
        err << "throng-cli: " << plotError << '\n';
        return 1;
    } else {
        out << "wedge: " << (dir / "wedge.png").string() << '\n';
    }
#endif
    out << "wedge: " << rows.size() - failed << " of " << rows.size() << " variants ran";
    if (failed > 0) {
        out << "; failed:";
        for (const Row& r : rows)
            if (r.status != "ok")
                out << ' ' << r.variant->folder << " (" << (r.reason.empty() ? r.status : r.reason) << ")";
    }
    out << '\n';
    return failed > 0 ? 1 : 0;
}

int wedgeCommand(const CliArguments& args, std::ostream& out, std::ostream& err)
{
    WedgePlan plan;
    std::error_code ec;
    plan.scene = fs::absolute(args.scene, ec).lexically_normal().string();
    std::string error;
    for (const std::string& text : args.sets) {
        const std::optional<WedgeAxis> axis = parseAxis(text, error);
        if (!axis) {
            err << "throng-cli: " << error << '\n';
            return 2;
        }
        plan.axes.push_back(*axis);
    }
    if (!args.seeds.empty()) {
        const auto seeds = parseSeeds(args.seeds, error);
        if (!seeds) {
            err << "throng-cli: " << error << '\n';
            return 2;
        }
        plan.seeds = *seeds;
    }
    plan.variants = expandVariants(plan.axes, plan.seeds);
    const fs::path dir = args.outDir;
    if (fs::exists(dir / "wedge.yaml", ec)) {
        err << "throng-cli: " << dir.string() << " already holds a wedge (wedge.yaml); give another --out\n";
        return 1;
    }
    // Every variant's scene reads before anything runs: a bad key or value stops the wedge.
    for (const WedgeVariant& v : plan.variants) {
        const sim::LoadResult loaded = sim::loadScene(plan.scene, v.overrides);
        if (!loaded.ok()) {
            for (const sim::Diagnostic& d : loaded.diagnostics)
                if (d.severity == sim::Severity::Error)
                    err << d.format() << '\n';
            err << "throng-cli: variant " << v.folder << " of " << args.scene << " is not a valid scene; nothing was run\n";
            return 1;
        }
    }
    fs::create_directories(dir, ec);
    for (const WedgeVariant& v : plan.variants)
        fs::create_directories(dir / v.folder, ec);
    if (ec) {
        err << "throng-cli: cannot create " << dir.string() << ": " << ec.message() << '\n';
        return 1;
    }
    if (const sim::SaveResult saved = sim::writeFileAtomically((dir / "wedge.yaml").string(), planToYaml(plan));
        !saved.ok) {
        err << "throng-cli: " << saved.error << '\n';
        return 1;
    }
    const std::string self = selfPath();
    if (args.slurm) {
        // One array job; the throng-cli that wrote it must be at the same path on the nodes.
        const fs::path script = dir / "wedge.sbatch";
        if (const sim::SaveResult saved = sim::writeFileAtomically(script.string(), sbatchScript(plan, dir, args, self));
            !saved.ok) {
            err << "throng-cli: " << saved.error << '\n';
            return 1;
        }
        const fs::path submitted = dir / "sbatch.out";
        const pid_t pid = spawn("/usr/bin/env", {"sbatch", "--parsable", script.string()}, submitted);
        int status = 0;
        pid_t waited = pid;
        while (pid >= 0 && (waited = waitpid(pid, &status, 0)) < 0 && errno == EINTR) {
        }  // a signal (InterruptWatch) does not stop the submission half-way
        if (pid < 0 || waited < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            err << "throng-cli: sbatch did not take " << script.string() << ": "
                << (pid < 0 ? std::string("it could not be started") : readText(submitted)) << '\n';
            return 1;
        }
        std::string job = readText(submitted);
        job = job.substr(0, job.find_first_of(";\n"));
        out << "wedge: submitted Slurm job " << job << ", " << plan.variants.size() << " tasks; when it is done: "
            << "throng-cli wedge collect " << dir.string() << '\n';
        return 0;
    }
    const int jobs = args.jobs > 0 ? args.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
    const int threads = jobs > 1 ? 1 : args.threads;
    std::map<pid_t, const WedgeVariant*> running;
    std::size_t next = 0, done = 0, failed = 0;
    auto finish = [&](const WedgeVariant& v, int code) {
        std::ofstream(dir / v.folder / "status") << code << '\n';
        ++done;
        failed += code == 0 ? 0 : 1;
        if (!args.quiet)
            err << "wedge: " << done << " of " << plan.variants.size() << " variants done"
                << (failed ? " (" + std::to_string(failed) + " failed)" : std::string()) << '\n';
    };
    bool forwarded = false;
    while (done < plan.variants.size()) {
        // Stopped (Ctrl-C, SIGTERM): start no more, and stop those running. SIGTERM, not the
        // signal itself: after a Ctrl-C from the terminal, which the variants got too, the
        // same signal again would end them at once, their outputs half-written.
        if (InterruptWatch::requested()) {
            if (!forwarded)
                for (const auto& [pid, variant] : running)
                    kill(pid, SIGTERM);
            forwarded = true;
            if (running.empty())
                break;
        }
        while (!InterruptWatch::requested() && next < plan.variants.size() && int(running.size()) < jobs) {
            const WedgeVariant& v = plan.variants[next++];
            const pid_t pid =
                spawn(self, variantArguments(plan, v, dir / v.folder, args, threads), dir / v.folder / "run.log");
            if (pid < 0) {
                std::ofstream(dir / v.folder / "run.log") << "throng-cli: could not start " << self << '\n';
                finish(v, 127);
            } else {
                running.emplace(pid, &v);
            }
        }
        if (running.empty())
            continue;
        int status = 0;
        const pid_t pid = waitpid(-1, &status, 0);
        if (pid < 0) {
            if (errno == EINTR)
                continue;
            break;
        }
        if (const auto it = running.find(pid); it != running.end()) {
            finish(*it->second, WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status));
            running.erase(it);
        }
    }
    if (InterruptWatch::requested()) {
        err << "throng-cli: stopped by " << InterruptWatch::signalName() << "; " << done << " of "
            << plan.variants.size() << " variants ended (a stopped one's status is 128 + its signal), the rest "
            << "were not started; nothing was collected\n";
        return InterruptWatch::exitStatus();
    }
    CliArguments collect = args;
    collect.scene = dir.string();
    return wedgeCollectCommand(collect, out, err);
}

}  // namespace throng::cli
