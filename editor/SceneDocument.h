#pragma once
// The open scene: owns the sim::Scene, its undo stack and its file path, and tells views
// when the scene is replaced or edited. Loading never half-loads; it never draws.

#include "editor/SceneChange.h"
#include "editor/SceneItem.h"
#include "simcore/base/Diagnostic.h"
#include "simcore/io/SceneIO.h"
#include "simcore/scene/Scene.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <functional>
#include <vector>

namespace throng::editor {

class SceneDocument : public QObject {
    Q_OBJECT

public:
    explicit SceneDocument(QObject* parent = nullptr);

    const sim::Scene& scene() const { return m_scene; }
    QUndoStack* undoStack() { return &m_undoStack; }
    // Absolute path of the scene file; empty for a scene never saved.
    QString filePath() const { return m_filePath; }
    bool isModified() const { return !m_undoStack.isClean(); }

    // Reads and validates `path`. Returns every diagnostic (warnings included). With an
    // error the current scene, path and undo history stay as they were; otherwise the
    // file replaces them and sceneReset() is emitted.
    std::vector<sim::Diagnostic> load(const QString& path);
    // The same, but the file names inside (brain and keyframe files) are relative to the
    // folder of `relativeTo` instead of the file's own: for a recovery copy, which lives
    // elsewhere than the scene it was made from.
    std::vector<sim::Diagnostic> load(const QString& path, const QString& relativeTo);
    // Writes the scene to its file (fails when it has none) or to `path`, atomically;
    // on success the document takes that path and is no longer modified.
    sim::SaveResult save();
    sim::SaveResult saveAs(const QString& path);
    // After loading a recovery copy: the scene belongs to `path` (empty = untitled) and
    // counts as unsaved.
    void adoptRecovered(const QString& path);
    // Replaces the scene with `initial` (File > New passes a starting template) without a
    // file; clears the history.
    void reset(sim::Scene initial = {});

    // The one mutator commands use: applies `edit` to the scene, then emits
    // sceneChanged(change). `change` says what `edit` changes; a command's undo passes
    // the same description as its redo. Only QUndoCommands call it, so every edit is
    // undoable.
    void modify(const SceneChange& change, const std::function<void(sim::Scene&)>& edit);
    // A stable id not yet used by any placed agent, vehicle or hero (> 0), nor by a
    // group member of a World of the scene.
    std::uint32_t nextAgentId() const;

    // What the user picked (outliner, select tool); the properties panel edits it.
    const Selection& selection() const { return m_selection; }
    void setSelection(Selection selection);

signals:
    // The whole scene was replaced (opened); views rebuild everything.
    void sceneReset();
    // Part of the scene was edited through a command: `change` says which.
    void sceneChanged(const throng::editor::SceneChange& change);
    void filePathChanged(const QString& path);
    void modifiedChanged(bool modified);
    void selectionChanged();

private:
    std::vector<sim::Diagnostic> adoptLoaded(sim::LoadResult result, const QString& path);
    sim::Scene m_scene;
    QUndoStack m_undoStack;
    QString m_filePath;
    Selection m_selection;
};

}  // namespace throng::editor
