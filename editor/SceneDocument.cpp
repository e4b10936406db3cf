#include "editor/SceneDocument.h"

#include <QFile>
#include <QFileInfo>

#include <algorithm>

namespace throng::editor {

SceneDocument::SceneDocument(QObject* parent) : QObject(parent)
{
    connect(&m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
}

std::vector<sim::Diagnostic> SceneDocument::load(const QString& path)
{
    return adoptLoaded(sim::loadScene(QFile::encodeName(path).toStdString()), path);
}

std::vector<sim::Diagnostic> SceneDocument::load(const QString& path, const QString& relativeTo)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return load(path);  // says why it cannot be read
    const std::string folder = QFile::encodeName(QFileInfo(relativeTo).absolutePath()).toStdString();
    return adoptLoaded(sim::parseScene(file.readAll().toStdString(), QFile::encodeName(path).toStdString(), folder),
                       path);
}

std::vector<sim::Diagnostic> SceneDocument::adoptLoaded(sim::LoadResult result, const QString& path)
{
    if (!result.ok())
        return std::move(result.diagnostics);
    m_scene = std::move(result.scene);
    m_undoStack.clear();
    setSelection({});
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

void SceneDocument::adoptRecovered(const QString& path)
{
    m_filePath = path.isEmpty() ? QString() : QFileInfo(path).absoluteFilePath();
    emit filePathChanged(m_filePath);
    m_undoStack.resetClean();
}

void SceneDocument::reset(sim::Scene initial)
{
    m_scene = std::move(initial);
    m_undoStack.clear();
    setSelection({});
    m_filePath.clear();
    emit filePathChanged(m_filePath);
    emit sceneReset();
}

void SceneDocument::setSelection(Selection selection)
{
    if (selection == m_selection)
        return;
    m_selection = std::move(selection);
    emit selectionChanged();
}

void SceneDocument::modify(const SceneChange& change, const std::function<void(sim::Scene&)>& edit)
{
    edit(m_scene);
    // Undoing an addition may remove a selected item.
    Selection kept;
    for (const SceneItem& item : m_selection)
        if (item.index < itemCount(m_scene, item.kind))
            kept.push_back(item);
    emit sceneChanged(change);
    setSelection(std::move(kept));
}

std::uint32_t SceneDocument::nextAgentId() const
{
    // Past the ids the groups' members have in a World: an agent painted during a run
    // never gets the id of a member that keeps its id through the resumed run (issue 6;
    // WorldState.h).
    std::uint32_t members = 0;
    for (const sim::SpawnGroup& g : m_scene.groups)
        members += g.count;
    return sim::firstSpawnedId(m_scene) + members;
}

}  // namespace throng::editor
