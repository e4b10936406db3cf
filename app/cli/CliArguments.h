#pragma once
// Parses throng-cli's command line into a plain struct; reports usage errors as text.
// Knows the export formats' table, but nothing of scenes or simulation.

#include "export/ExportFormats.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace throng::cli {

// One recorded output of `run`: --export PATH, --trajectories PATH (the CSV format) or
// --maya-cache DIR (the Maya cache).
struct ExportOutput {
    std::string flag;                                // "export" or "trajectories": says where it went
    std::string path;
    const exporting::ExportFormat* format = nullptr;  // a row of exporting::exportFormats()
};

struct CliArguments {
    std::string command;  // check | run | bench | validate | wedge | wedge-collect | help | version
    std::string scene;    // check, run, wedge: the scene; validate: the folder of validation scenes;
                          // wedge-collect: the wedge's folder
    std::optional<std::uint64_t> frames, seed, agents, steps;
    std::optional<std::uint64_t> window;  // bench: the figures of every `window` steps as well
    int threads = 0;
    std::string statsPath, scenario;
    std::string reportPath;  // run: the analysis as one HTML file (report/HtmlReport.h)
    std::optional<double> reportCellM;                 // its heatmap's cells, m; default 1
    std::optional<std::uint64_t> reportTrajectories;   // the walkers its plan draws at most; default 2,000
    std::vector<ExportOutput> exports;             // in the order given; the run records frames for them
    std::string exportMode;                        // exact | compact; empty = exact
    std::optional<std::uint64_t> exportJointStep;  // >= 1
    std::string exportLod;                         // near | mid | far; empty = near
    std::string mayaForward;                       // z | x; empty = z (the Maya cache's rigs)
    bool noSet = false;                            // glTF: leave the set out
    std::vector<std::string> sets;                 // --set: run KEY=VALUE; wedge KEY=V1,V2,...
    std::string seeds;                             // wedge: A..B or A,B,C
    std::string outDir;                            // wedge: the folder of its variants
    int jobs = 0;                                  // wedge: variants at once; 0 = one per core
    std::string metric;                            // wedge collect: the figure plotted
    bool slurm = false;                            // wedge: submit one Slurm array job instead
    bool quiet = false;
    bool json = false;  // check: diagnostics as JSON lines; validate: a JSON line per test
};

struct ParseOutcome {
    CliArguments args;
    std::string error;  // non-empty = usage error
};

ParseOutcome parseArguments(const std::vector<std::string>& argv);
std::string usageText();

}  // namespace throng::cli
