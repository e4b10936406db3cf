#pragma once
// Crash protection: every minute a modified scene is written to a recovery file (never
// over the user's own file); a clean close or a save removes it, so a recovery file
// found at start-up means the last session ended without saving. Asks nothing itself.

#include <QObject>
#include <QString>
#include <QTimer>

namespace throng::editor {

class SceneDocument;

class AutosaveRecovery : public QObject {
    Q_OBJECT

public:
    static constexpr int kIntervalMs = 60 * 1000;

    explicit AutosaveRecovery(SceneDocument& document, QObject* parent = nullptr);

    // Where the recovery copy goes (the application's data folder).
    static QString recoveryPath();
    // Writes the scene to the recovery file when it has unsaved changes; true on success
    // or when there was nothing to write.
    bool saveNow();
    // Removes the recovery file (after a save or a clean close).
    void discard();
    bool hasRecovery() const;
    // The scene file the recovered changes belong to; empty for an untitled scene.
    QString recoveredFor() const;
    // Loads the recovery copy into the document as unsaved changes to recoveredFor().
    bool restore();

private:
    SceneDocument& m_document;
    QTimer m_timer;
};

}  // namespace throng::editor
