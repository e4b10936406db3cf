#include "editor/MainWindow.h"

#include "editor/MessagesPanel.h"
#include "editor/viewport/Viewport.h"

#include <QAction>
#include <QActionGroup>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

namespace throng::editor {

namespace {
constexpr int kStatusMessageMs = 5000;
const char* const kSceneFilter = "Throng scenes (*.yaml *.yml);;All files (*)";
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent)
{
    setObjectName("mainWindow");
    m_viewport = new Viewport(this);
    m_viewport->setObjectName("viewport");
    setCentralWidget(m_viewport);

    m_messages = new MessagesPanel(this);
    m_messagesDock = new QDockWidget(tr("Messages"), this);
    m_messagesDock->setObjectName("messagesDock");
    m_messagesDock->setWidget(m_messages);
    addDockWidget(Qt::BottomDockWidgetArea, m_messagesDock);

    createFileMenu();
    createEditMenu();
    createViewMenu();
    createStatusBar();

    connect(&m_document, &SceneDocument::sceneReset, this, [this] { m_viewport->setScene(m_document.scene()); });
    connect(&m_document, &SceneDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(&m_document, &SceneDocument::modifiedChanged, this, &QWidget::setWindowModified);
    connect(m_viewport, &Viewport::agentsChanged, this, &MainWindow::updateAgentStatus);

    m_viewport->setScene(m_document.scene());
    m_messages->showNote(tr("No scene open. Open one with File > Open (Ctrl+O)."));
    updateTitle();
    restoreWindowState();
}

bool MainWindow::openScene(const QString& path)
{
    const std::vector<sim::Diagnostic> diagnostics = m_document.load(path);
    const QString name = QFileInfo(path).fileName();
    if (sim::hasErrors(diagnostics)) {
        const QString failed = tr("Could not open %1; the current scene stays open.").arg(name);
        m_messages->showDiagnostics(failed, diagnostics);
        m_messagesDock->show();
        m_messagesDock->raise();
        statusBar()->showMessage(failed, kStatusMessageMs);
        return false;
    }
    m_messages->showDiagnostics(tr("Opened %1.").arg(m_document.filePath()), diagnostics);
    statusBar()->showMessage(tr("Opened %1").arg(name), kStatusMessageMs);
    return true;
}

void MainWindow::createFileMenu()
{
    QMenu* menu = menuBar()->addMenu(tr("&File"));
    QAction* open = menu->addAction(tr("&Open..."), this, &MainWindow::openWithDialog);
    open->setShortcut(QKeySequence::Open);
    open->setToolTip(tr("Open a scene file (.yaml)"));
    QAction* save = menu->addAction(tr("&Save"), this, &MainWindow::save);
    save->setShortcut(QKeySequence::Save);
    save->setToolTip(tr("Save the scene to its file"));
    QAction* saveAs = menu->addAction(tr("Save &As..."), this, &MainWindow::saveAsWithDialog);
    saveAs->setShortcut(QKeySequence::SaveAs);
    saveAs->setToolTip(tr("Save the scene to a new file"));
    menu->addSeparator();
    QAction* quit = menu->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
    quit->setToolTip(tr("Close Throng"));
    menu->setToolTipsVisible(true);
}

void MainWindow::createEditMenu()
{
    QMenu* menu = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_document.undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setToolTip(tr("Undo the last edit"));
    QAction* redo = m_document.undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    redo->setToolTip(tr("Redo the last undone edit"));
    menu->addAction(undo);
    menu->addAction(redo);
    menu->setToolTipsVisible(true);
}

void MainWindow::createViewMenu()
{
    QMenu* menu = menuBar()->addMenu(tr("&View"));
    auto* viewModes = new QActionGroup(this);
    QAction* top = menu->addAction(tr("&Top View"), this, [this] { m_viewport->setViewMode(ViewMode::Top); });
    top->setShortcut(tr("Ctrl+1"));
    top->setToolTip(tr("Look straight down with an orthographic camera"));
    QAction* orbit = menu->addAction(tr("&3D View"), this, [this] { m_viewport->setViewMode(ViewMode::Orbit); });
    orbit->setShortcut(tr("Ctrl+2"));
    orbit->setToolTip(tr("Orbit the scene with a perspective camera (right drag)"));
    for (QAction* a : {top, orbit}) {
        a->setCheckable(true);
        viewModes->addAction(a);
    }
    top->setChecked(true);
    connect(m_viewport, &Viewport::viewModeChanged, this,
            [top, orbit](ViewMode mode) { (mode == ViewMode::Top ? top : orbit)->setChecked(true); });
    menu->addSeparator();
    QAction* frame = menu->addAction(tr("&Frame All"), m_viewport, &Viewport::frameAll);
    frame->setShortcut(Qt::Key_F);
    frame->setToolTip(tr("Fit the whole scene into the viewport"));
    menu->addSeparator();
    menu->addAction(m_messagesDock->toggleViewAction());
    menu->setToolTipsVisible(true);
}

void MainWindow::createStatusBar()
{
    m_agentCountLabel = new QLabel(this);
    m_agentCountLabel->setObjectName("agentCountLabel");
    m_frameLabel = new QLabel(this);
    m_frameLabel->setObjectName("frameLabel");
    statusBar()->addPermanentWidget(m_agentCountLabel);
    statusBar()->addPermanentWidget(m_frameLabel);
    updateAgentStatus();
}

void MainWindow::openWithDialog()
{
    const QString dir = m_document.filePath().isEmpty() ? QString() : QFileInfo(m_document.filePath()).path();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Scene"), dir, tr(kSceneFilter));
    if (!path.isEmpty())
        openScene(path);
}

bool MainWindow::save()
{
    if (m_document.filePath().isEmpty())
        return saveAsWithDialog();
    return reportSave(m_document.save());
}

bool MainWindow::saveAsWithDialog()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Scene As"), m_document.filePath(),
                                                      tr(kSceneFilter));
    return !path.isEmpty() && reportSave(m_document.saveAs(path));
}

bool MainWindow::reportSave(const sim::SaveResult& result)
{
    if (!result.ok) {
        QMessageBox::warning(this, tr("Save failed"), QString::fromStdString(result.error));
        return false;
    }
    statusBar()->showMessage(tr("Saved %1").arg(m_document.filePath()), kStatusMessageMs);
    return true;
}

void MainWindow::updateTitle()
{
    const QString path = m_document.filePath();
    const QString name = path.isEmpty() ? tr("Untitled") : QFileInfo(path).fileName();
    setWindowTitle(tr("%1[*] - Throng").arg(name));
}

void MainWindow::updateAgentStatus()
{
    const std::size_t count = m_viewport->agentCount();
    m_agentCountLabel->setText(count == 1 ? tr("1 agent") : tr("%1 agents").arg(count));
    m_frameLabel->setText(tr("Frame %1").arg(m_viewport->frameIndex()));
}

void MainWindow::restoreWindowState()
{
    QSettings settings;
    if (!restoreGeometry(settings.value("mainWindow/geometry").toByteArray()))
        resize(1280, 800);
    restoreState(settings.value("mainWindow/state").toByteArray());
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    QSettings settings;
    settings.setValue("mainWindow/geometry", saveGeometry());
    settings.setValue("mainWindow/state", saveState());
    QMainWindow::closeEvent(event);
}

}  // namespace throng::editor
