#pragma once
// Runs throng-cli's commands in-process and keeps what they printed. Test-only.

#include "Cli.h"

#include <QFile>
#include <QString>

#include <sstream>
#include <string>
#include <vector>

namespace throng::test {

struct CliOutput {
    int status = -1;
    std::string out, err;
};

inline CliOutput runCli(const std::vector<std::string>& args)
{
    std::ostringstream out, err;
    CliOutput r;
    r.status = throng::cli::runCli(args, out, err);
    r.out = out.str();
    r.err = err.str();
    return r;
}

inline QString writeText(const QString& path, const char* text)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        qFatal("cannot write %s", qPrintable(path));
    f.write(text);
    return path;
}

}  // namespace throng::test
