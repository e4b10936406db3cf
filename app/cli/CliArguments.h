#pragma once
// Parses throng-cli's command line into a plain struct; reports usage errors as text.
// Knows nothing of scenes or simulation.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace throng::cli {

struct CliArguments {
    std::string command;  // check | run | bench | help | version
    std::string scene;
    std::optional<std::uint64_t> frames, seed, agents, steps;
    int threads = 0;
    std::string statsPath, trajectoriesPath, exportPath, scenario;
    std::string exportMode;                        // exact | compact; empty = exact
    std::optional<std::uint64_t> exportJointStep;  // >= 1
    bool quiet = false;
    bool json = false;  // check: diagnostics as JSON lines
};

struct ParseOutcome {
    CliArguments args;
    std::string error;  // non-empty = usage error
};

ParseOutcome parseArguments(const std::vector<std::string>& argv);
std::string usageText();

}  // namespace throng::cli
