#pragma once
// The editor window: assembles the viewport, the tools, the outliner, properties,
// history, timeline and messages docks, the menus and the status bar around one
// SceneDocument and one SimulationController. Wires them together; it computes nothing
// and never edits the scene itself (tools and panels push commands).

#include "editor/SceneChange.h"
#include "editor/SceneDocument.h"
#include "editor/simulation/ShownRecording.h"

#include <QMainWindow>
#include <QMessageBox>

#include <functional>
#include <optional>

class QDockWidget;
class QLabel;
class QMenu;
class QTimer;
class QToolBar;

namespace throng::editor {

class AgentTypeActions;
class AnalysisPanel;
class AutosaveRecovery;
class BrainEditorPanel;
class ExportDialog;
class LayoutCheckWatch;
class LayoutPanel;
class MessagesPanel;
class OutlinerPanel;
class RecentFiles;
class SimulationController;
class TimelinePanel;
class ToolManager;
class Viewport;
class WorkspaceLayout;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens a scene file. On errors they are listed in the Messages dock, the current
    // scene stays, and false is returned. Does not ask about unsaved changes.
    bool openScene(const QString& path);
    // Asks (Save, Discard, Cancel) when the scene has unsaved changes; true when the
    // caller may go on and drop the scene.
    bool maybeKeepChanges();
    // Replaces the question maybeKeepChanges() asks (tests answer it without a dialog).
    void setUnsavedChangesPrompt(std::function<QMessageBox::StandardButton()> prompt);
    // When the last session left unsaved changes behind (a crash), asks whether to
    // recover them (`ask` replaces the dialog) and loads them. True when recovered.
    bool offerRecovery(std::function<bool()> ask = {});
    AutosaveRecovery& autosave() { return *m_autosave; }

    SceneDocument& document() { return m_document; }
    Viewport& viewport() { return *m_viewport; }
    MessagesPanel& messages() { return *m_messages; }
    ToolManager& tools() { return *m_tools; }
    SimulationController& simulation() { return *m_simulation; }
    AnalysisPanel& analysis() { return *m_analysis; }
    OutlinerPanel& outliner() { return *m_outliner; }
    TimelinePanel& timeline() { return *m_timeline; }
    WorkspaceLayout& workspace() { return *m_workspace; }
    BrainEditorPanel& brainEditor() { return *m_brains; }
    LayoutPanel& layoutPanel() { return *m_layout; }
    LayoutCheckWatch& layoutCheck() { return *m_layoutCheck; }
    // Opens File > Export (window-modal, not blocking) and returns it.
    ExportDialog* showExportDialog();

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    QDockWidget* addDock(const QString& title, const QString& name, QWidget* widget, Qt::DockWidgetArea area);
    void createDocks();
    QDockWidget* createLayoutDock(QDockWidget* besides);
    void createFileMenu();
    void createEditMenu();
    void createViewMenu();
    void addAgentsAsMenu(QMenu& viewMenu);
    void createCreateMenu();
    QWidget* outlinerWithActions();
    void offerAgentType();
    void createSimulationMenu();
    void createToolBars();
    void createStatusBar();
    void newScene();
    void openWithDialog();
    void openAfterAsking(const QString& path);
    void revert();
    bool save();
    bool saveAsWithDialog();
    bool reportSave(const sim::SaveResult& result);
    void sceneEdited();
    void refreshAfterEdit();
    void updateTitle();
    void updateAgentStatus();
    void restoreWindowState();

    SceneDocument m_document;
    ShownRecording m_shown;  // the frames the viewport shows: the recording through the layout layer
    Viewport* m_viewport = nullptr;
    ToolManager* m_tools = nullptr;
    SimulationController* m_simulation = nullptr;
    MessagesPanel* m_messages = nullptr;
    AnalysisPanel* m_analysis = nullptr;
    OutlinerPanel* m_outliner = nullptr;
    TimelinePanel* m_timeline = nullptr;
    RecentFiles* m_recent = nullptr;
    AutosaveRecovery* m_autosave = nullptr;
    AgentTypeActions* m_typeActions = nullptr;
    BrainEditorPanel* m_brains = nullptr;
    LayoutPanel* m_layout = nullptr;
    LayoutCheckWatch* m_layoutCheck = nullptr;
    WorkspaceLayout* m_workspace = nullptr;
    QToolBar* m_outlinerBar = nullptr;
    QDockWidget* m_messagesDock = nullptr;
    QList<QDockWidget*> m_docks;
    QLabel* m_agentCountLabel = nullptr;
    QLabel* m_frameLabel = nullptr;
    QLabel* m_speedLabel = nullptr;
    QTimer* m_editTimer = nullptr;
    // The union of the changes since the last refresh (a brush stroke edits many times
    // between two paints).
    std::optional<SceneChange> m_pendingChange;
    std::function<QMessageBox::StandardButton()> m_prompt;
};

}  // namespace throng::editor
