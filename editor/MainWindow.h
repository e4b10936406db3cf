#pragma once
// The editor window: assembles the viewport, the Messages dock, the menus and the status
// bar around one SceneDocument. Wires them together; it computes nothing and never edits
// the scene itself.

#include "editor/SceneDocument.h"

#include <QMainWindow>

class QDockWidget;
class QLabel;

namespace throng::editor {

class MessagesPanel;
class Viewport;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);

    // Opens a scene file. On errors they are listed in the Messages dock, the current
    // scene stays, and false is returned.
    bool openScene(const QString& path);

    SceneDocument& document() { return m_document; }
    Viewport& viewport() { return *m_viewport; }
    MessagesPanel& messages() { return *m_messages; }

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createFileMenu();
    void createEditMenu();
    void createViewMenu();
    void createStatusBar();
    void openWithDialog();
    bool save();
    bool saveAsWithDialog();
    bool reportSave(const sim::SaveResult& result);
    void updateTitle();
    void updateAgentStatus();
    void restoreWindowState();

    SceneDocument m_document;
    Viewport* m_viewport = nullptr;
    MessagesPanel* m_messages = nullptr;
    QDockWidget* m_messagesDock = nullptr;
    QLabel* m_agentCountLabel = nullptr;
    QLabel* m_frameLabel = nullptr;
};

}  // namespace throng::editor
