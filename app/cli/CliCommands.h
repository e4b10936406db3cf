#pragma once
// The bodies of throng-cli's commands. Each returns the exit status.

#include "CliArguments.h"

#include <iosfwd>

namespace throng::cli {

int checkCommand(const CliArguments& args, std::ostream& out, std::ostream& err);
int runCommand(const CliArguments& args, std::ostream& out, std::ostream& err);
int benchCommand(const CliArguments& args, std::ostream& out, std::ostream& err);
int validateCommand(const CliArguments& args, std::ostream& out, std::ostream& err);
int wedgeCommand(const CliArguments& args, std::ostream& out, std::ostream& err);
int wedgeCollectCommand(const CliArguments& args, std::ostream& out, std::ostream& err);

}  // namespace throng::cli
