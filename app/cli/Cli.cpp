#include "Cli.h"

#include "CliArguments.h"
#include "CliCommands.h"
#include "Interrupt.h"

#include <ostream>

namespace throng::cli {

int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
{
    const ParseOutcome parsed = parseArguments(args);
    if (!parsed.error.empty()) {
        // The whole usage only for a bare `throng-cli`; after a mistake in a command line, the
        // one line that says what is wrong stays in view.
        err << "throng-cli: " << parsed.error << '\n';
        if (args.empty())
            err << '\n' << usageText();
        else
            err << "throng-cli: 'throng-cli --help' lists the commands and their options\n";
        return 2;
    }
    const CliArguments& a = parsed.args;
    if (a.command == "help") {
        out << "throng-cli: run Throng crowd scenes headless\n\n" << usageText();
        return 0;
    }
    if (a.command == "version") {
        out << "throng-cli " << THRONG_VERSION << " (scene format 1)\n";
        return 0;
    }
    if (a.command == "check")
        return checkCommand(a, out, err);
    if (a.command == "run") {
        const InterruptWatch watch;  // Ctrl-C stops the run and its exports cleanly
        return runCommand(a, out, err);
    }
    if (a.command == "validate")
        return validateCommand(a, out, err);
    if (a.command == "wedge") {
        const InterruptWatch watch;  // Ctrl-C stops the variants running and starts no more
        return wedgeCommand(a, out, err);
    }
    if (a.command == "wedge-collect")
        return wedgeCollectCommand(a, out, err);
    return benchCommand(a, out, err);
}

}  // namespace throng::cli
