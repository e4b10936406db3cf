#pragma once
// throng-cli's commands (check, run, bench), callable in-process so tests drive exactly
// what users run. Writes results to `out`, diagnostics and progress to `err`.

#include <iosfwd>
#include <string>
#include <vector>

namespace throng::cli {

// argv without the program name. Returns the process exit status: 0 success,
// 1 invalid scene or failed run, 2 wrong usage.
int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace throng::cli
