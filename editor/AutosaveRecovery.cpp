#include "editor/AutosaveRecovery.h"

#include "editor/SceneDocument.h"
#include "simcore/io/SceneIO.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace throng::editor {

namespace {
const char* const kForKey = "recovery/sceneFile";
}

AutosaveRecovery::AutosaveRecovery(SceneDocument& document, QObject* parent) : QObject(parent), m_document(document)
{
    m_timer.setInterval(kIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &AutosaveRecovery::saveNow);
    m_timer.start();
}

QString AutosaveRecovery::recoveryPath()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/recovery.yaml";
}

bool AutosaveRecovery::saveNow()
{
    if (!m_document.isModified())
        return true;
    const QString path = recoveryPath();
    QDir().mkpath(QFileInfo(path).path());
    const sim::SaveResult result =
        sim::writeFileAtomically(QFile::encodeName(path).toStdString(), sim::sceneToYaml(m_document.scene()));
    if (result.ok)
        QSettings().setValue(kForKey, m_document.filePath());
    return result.ok;
}

void AutosaveRecovery::discard()
{
    QFile::remove(recoveryPath());
    QSettings().remove(kForKey);
}

bool AutosaveRecovery::hasRecovery() const
{
    return QFile::exists(recoveryPath());
}

QString AutosaveRecovery::recoveredFor() const
{
    return QSettings().value(kForKey).toString();
}

bool AutosaveRecovery::restore()
{
    // Brain and keyframe files the scene names are relative to the scene's own folder.
    const QString forFile = recoveredFor();
    if (!hasRecovery() ||
        sim::hasErrors(forFile.isEmpty() ? m_document.load(recoveryPath()) : m_document.load(recoveryPath(), forFile)))
        return false;
    m_document.adoptRecovered(recoveredFor());
    return true;
}

}  // namespace throng::editor
