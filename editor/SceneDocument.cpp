#include "editor/SceneDocument.h"

#include <QFile>
#include <QFileInfo>

namespace throng::editor {

SceneDocument::SceneDocument(QObject* parent) : QObject(parent)
{
    connect(&m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
}

std::vector<sim::Diagnostic> SceneDocument::load(const QString& path)
{
    sim::LoadResult result = sim::loadScene(QFile::encodeName(path).toStdString());
    if (!result.ok())
        return std::move(result.diagnostics);
    m_scene = std::move(result.scene);
    m_undoStack.clear();
    m_filePath = QFileInfo(path).absoluteFilePath();
    emit filePathChanged(m_filePath);
    emit sceneReset();
    return std::move(result.diagnostics);
}

sim::SaveResult SceneDocument::save()
{
    if (m_filePath.isEmpty())
        return {false, "the scene has no file yet; choose one with Save As"};
    return saveAs(m_filePath);
}

sim::SaveResult SceneDocument::saveAs(const QString& path)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    sim::SaveResult result = sim::saveScene(m_scene, QFile::encodeName(absolute).toStdString());
    if (!result.ok)
        return result;
    m_undoStack.setClean();
    if (absolute != m_filePath) {
        m_filePath = absolute;
        emit filePathChanged(m_filePath);
    }
    return result;
}

}  // namespace throng::editor
