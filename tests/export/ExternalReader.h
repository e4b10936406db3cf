#pragma once
// Runs one of the external readers of our exports (Khronos validator, three.js, assimp,
// tinyusdz) on a file and hands back its exit status and its one-line JSON summary.
// Test-only; never installs anything itself (the tools do that on first use).

#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace throng::test {

struct ExternalReaderRun {
    bool started = false;   // false: the tool is missing or did not finish in time
    int exitCode = -1;      // 0 passed, 1 the file failed, 2 usage or install problem
    QString output;         // stdout and stderr, for failure messages
    QJsonObject summary;    // the last output line parsed as JSON; empty if it is not JSON
};

// `tool`: a file name in tests/tools (usd-check), else in ../shared/tools (gltf-validate).
QString externalReaderPath(const QString& tool);
ExternalReaderRun runExternalReader(const QString& tool, const QStringList& arguments);

}  // namespace throng::test
