#include "ExternalReader.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QProcess>

namespace throng::test {

QString externalReaderPath(const QString& tool)
{
    // Our own readers (tests/tools) first, then the shared ones beside the repository.
    const QString own = QDir::cleanPath(QStringLiteral(THRONG_SOURCE_DIR "/tests/tools/") + tool);
    if (QFile::exists(own))
        return own;
    return QDir::cleanPath(QStringLiteral(THRONG_SOURCE_DIR "/../shared/tools/") + tool);
}

ExternalReaderRun runExternalReader(const QString& tool, const QStringList& arguments)
{
    ExternalReaderRun run;
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(externalReaderPath(tool), arguments);
    // First use may npm-install the reader: allow for it.
    if (!process.waitForStarted(10'000) || !process.waitForFinished(300'000)) {
        process.kill();
        process.waitForFinished(5'000);
        run.output = QString::fromUtf8(process.readAll()) + process.errorString();
        return run;
    }
    run.started = process.exitStatus() == QProcess::NormalExit;
    run.exitCode = process.exitCode();
    run.output = QString::fromUtf8(process.readAll());
    const QStringList lines = run.output.trimmed().split('\n');
    run.summary = QJsonDocument::fromJson(lines.last().toUtf8()).object();
    return run;
}

}  // namespace throng::test
