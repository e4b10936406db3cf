#include "CliCommands.h"

#include "validation/Rimea.h"

#include <cstdio>
#include <ostream>

namespace throng::cli {

namespace {

// A JSON string (the texts here are plain; quotes and backslashes escaped).
std::string quoted(const std::string& text)
{
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\')
            out += '\\';
        out += c;
    }
    return out + '"';
}

}  // namespace

// Runs the RiMEA tests that apply (validation/Rimea.h) on the scenes in the folder given,
// or in the source tree's resources/validation; a line per test, and the tests that cannot
// run yet with their reason. Exit status 1 when a test fails or its scene does not load.
int validateCommand(const CliArguments& args, std::ostream& out, std::ostream& err)
{
    const std::string directory = args.scene.empty() ? std::string(THRONG_VALIDATION_DIR) : args.scene;
    int passed = 0, failed = 0, notRun = 0;
    for (const validation::RimeaTest& test : validation::rimeaTests()) {
        if (!args.quiet && test.run)
            err << "throng-cli: RiMEA " << test.number << " (" << test.title << ")...\n";
        const validation::Outcome o = validation::runRimeaTest(test, directory);
        const char* verdict = !test.run ? "not run" : (o.error.empty() && o.pass ? "pass" : "FAIL");
        (test.run ? (o.error.empty() && o.pass ? passed : failed) : notRun) += 1;
        if (args.json) {
            out << "{\"test\": " << test.number << ", \"title\": " << quoted(test.title)
                << ", \"criterion\": " << quoted(test.criterion) << ", \"measured\": " << quoted(o.measured)
                << ", \"result\": " << quoted(verdict) << ", \"reason\": " << quoted(o.error) << "}\n";
            continue;
        }
        out << "RiMEA " << test.number << ": " << test.title << ": " << verdict;
        if (!test.run)
            out << " (" << test.notRunBecause << ")\n";
        else if (!o.error.empty())
            out << " (" << o.error << ")\n";
        else
            out << "\n  criterion: " << test.criterion << "\n  measured:  " << o.measured << '\n';
    }
    if (!args.json)
        out << passed << " passed, " << failed << " failed, " << notRun << " not run\n";
    return failed > 0 ? 1 : 0;
}

}  // namespace throng::cli
