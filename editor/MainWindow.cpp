#include "editor/MainWindow.h"

#include "editor/AgentTypePresets.h"
#include "editor/AutosaveRecovery.h"
#include "editor/FootHeight.h"
#include "editor/HelpMenu.h"
#include "editor/Icons.h"
#include "editor/MessagesPanel.h"
#include "editor/RecentFiles.h"
#include "editor/ShortcutToolTips.h"
#include "editor/ViewportDisplayActions.h"
#include "editor/WorkspaceLayout.h"
#include "editor/brain/BrainEditorPanel.h"
#include "editor/layout/LayoutCheckWatch.h"
#include "editor/layout/LayoutEdits.h"
#include "editor/layout/LayoutPanel.h"
#include "editor/layout/LayoutRetimeDrag.h"
#include "editor/commands/DeleteItemsCommand.h"
#include "editor/panels/AgentTypeActions.h"
#include "editor/panels/AnalysisPanel.h"
#include "editor/panels/OutlinerPanel.h"
#include "editor/panels/PropertiesPanel.h"
#include "editor/panels/TimelinePanel.h"
#include "editor/simulation/SimulateToEndDialog.h"
#include "editor/simulation/SimulationController.h"
#include "editor/tools/ToolManager.h"
#include "editor/viewport/Viewport.h"

#include <QAction>
#include <QApplication>
#include <QActionGroup>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QUndoView>
#include <QVBoxLayout>

#include <algorithm>

namespace throng::editor {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent)
{
    setObjectName("mainWindow");
    setAcceptDrops(true);
    // What File > New gives: a scene a brush or the group tool can place agents in.
    m_document.reset(newSceneTemplate());
    m_viewport = new Viewport(this);
    m_viewport->setObjectName("viewport");
    m_tools = new ToolManager(m_document, *m_viewport, this);
    m_simulation = new SimulationController(this);
    m_typeActions = new AgentTypeActions(m_document, this);
    m_autosave = new AutosaveRecovery(m_document, this);
    m_editTimer = new QTimer(this);
    m_editTimer->setSingleShot(true);
    m_editTimer->setInterval(0);

    createDocks();
    createFileMenu();
    createEditMenu();
    createCreateMenu();
    createViewMenu();
    createSimulationMenu();
    createToolBars();
    createStatusBar();
    new HelpMenu(*this);
    nameShortcutsInToolTips(*this);

    connect(&m_document, &SceneDocument::sceneReset, this, [this] {
        m_editTimer->stop();
        m_pendingChange.reset();
        const QString path = m_document.filePath();
        m_viewport->setSceneDirectory(path.isEmpty() ? QString() : QFileInfo(path).absolutePath());
        m_viewport->setScene(m_document.scene());
        m_viewport->setHighlight(m_document.scene(), m_document.selection());
        m_simulation->setScene(m_document.scene());
    });
    // A brush stroke edits many times between two paints: refresh once per burst, with
    // what the whole burst changed.
    connect(&m_document, &SceneDocument::sceneChanged, this, [this](const SceneChange& change) {
        m_pendingChange = m_pendingChange ? *m_pendingChange | change : change;
        m_editTimer->start();
    });
    connect(m_editTimer, &QTimer::timeout, this, &MainWindow::refreshAfterEdit);
    connect(&m_document, &SceneDocument::selectionChanged, this,
            [this] { m_viewport->setHighlight(m_document.scene(), m_document.selection()); });
    connect(&m_document, &SceneDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(&m_document, &SceneDocument::modifiedChanged, this, &QWidget::setWindowModified);
    connect(m_viewport, &Viewport::agentsChanged, this, &MainWindow::updateAgentStatus);
    connect(m_simulation, &SimulationController::frameChanged, this, [this](std::size_t frame) {
        // The recording through the scene's layout layer, if it has one.
        m_viewport->showFrame(m_shown.frames(m_simulation->cache(), m_document.scene()), frame);
        QStringList notes;
        for (const std::string& message : m_shown.takeNewMessages())
            notes << QString::fromStdString(message);
        if (!notes.isEmpty())
            m_messages->showNote(notes.join('\n'));
    });
    connect(m_messages, &MessagesPanel::itemRequested, this, [this](SceneItem item) {
        if (item.index < itemCount(m_document.scene(), item.kind))
            m_document.setSelection({item});
    });
    connect(m_simulation, &SimulationController::problem, this, [this](const QString& text) {
        m_messages->showNote(text);
        m_messagesDock->show();
    });

    m_viewport->setScene(m_document.scene());
    m_simulation->setScene(m_document.scene());
    for (ViewportTool* tool : m_tools->tools())
        connect(tool, &ViewportTool::agentTypeNeeded, this, &MainWindow::offerAgentType);
    m_messages->showNote(tr("New scene. Draw a spawn group (S) or paint agents with the crowd brush (B); "
                            "walls (W) and goals (G) give them a place to go. Or open a scene (Ctrl+O)."));
    updateTitle();
    restoreWindowState();
}

MainWindow::~MainWindow()
{
    // The tools refer to the viewport; let go of them before the widgets go.
    m_viewport->setTool(nullptr);
}

QDockWidget* MainWindow::addDock(const QString& title, const QString& name, QWidget* widget, Qt::DockWidgetArea area)
{
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    dock->setWidget(widget);
    addDockWidget(area, dock);
    m_docks << dock;
    return dock;
}

void MainWindow::createDocks()
{
    m_outliner = new OutlinerPanel(m_document, this);
    QDockWidget* outlinerDock = addDock(tr("Outliner"), "outlinerDock", outlinerWithActions(), Qt::LeftDockWidgetArea);
    auto* properties = new PropertiesPanel(m_document, this);
    QDockWidget* propertiesDock = addDock(tr("Properties"), "propertiesDock", properties, Qt::RightDockWidgetArea);
    auto* history = new QUndoView(m_document.undoStack(), this);
    history->setObjectName("historyView");
    history->setEmptyLabel(tr("<opened>"));
    QDockWidget* historyDock = addDock(tr("History"), "historyDock", history, Qt::RightDockWidgetArea);
    m_timeline = new TimelinePanel(*m_simulation, this);
    QDockWidget* timelineDock = addDock(tr("Timeline"), "timelineDock", m_timeline, Qt::BottomDockWidgetArea);
    m_messages = new MessagesPanel(this);
    m_messagesDock = addDock(tr("Messages"), "messagesDock", m_messages, Qt::BottomDockWidgetArea);
    // The analysis shares the bottom with the messages, behind them until asked for.
    m_analysis = new AnalysisPanel(m_document, *m_simulation, this);
    // In a scroll area: its charts and tabs would otherwise hold the whole foot of the
    // window (the timeline's and the messages') at their height, over the viewport's.
    auto* analysisScroll = new QScrollArea(this);
    analysisScroll->setObjectName("analysisScroll");
    analysisScroll->setWidget(m_analysis);
    analysisScroll->setWidgetResizable(true);
    analysisScroll->setFrameShape(QFrame::NoFrame);
    QDockWidget* analysisDock = addDock(tr("Analysis"), "analysisDock", analysisScroll, Qt::BottomDockWidgetArea);
    tabifyDockWidget(m_messagesDock, analysisDock);
    m_messagesDock->raise();
    // Brought forward, it takes the height its tabs and charts need; the messages give it back.
    new FootHeight(*this, *timelineDock, *m_messagesDock, *analysisDock, *m_analysis);
    analysisDock->toggleViewAction()->setIcon(themeIcon("action-analyse"));
    analysisDock->toggleViewAction()->setToolTip(tr("Show the Analysis panel: flows, densities and speeds of the "
                                                    "recorded run, and its HTML report"));
    connect(m_analysis, &AnalysisPanel::message, this, [this](const QString& text) {
        m_messages->showNote(text);
        statusBar()->showMessage(text, 8000);
    });
    QDockWidget* layoutDock = createLayoutDock(historyDock);
    m_brains = new BrainEditorPanel(m_document, *m_simulation, m_viewport, this);
    m_brains->setObjectName("brainEditor");
    // The brain editor shares the centre with the viewport in its own workspace (Ctrl+B),
    // where the outliner, properties and history give it their room.
    m_workspace =
        new WorkspaceLayout(*this, m_viewport, m_brains, {outlinerDock, propertiesDock, historyDock, layoutDock});
    // Room for Properties' fields at 1280 x 800 without a sideways scroll bar, and most of
    // the right column for them (History needs a few lines).
    // The timeline keeps most of the foot for its scrub bar, the messages the rest; the
    // foot is as tall as the timeline needs, not as the analysis behind the messages asks,
    // so the viewport keeps the height.
    m_workspace->setDefaultDockSizes({{"outlinerDock", QSize(220, 0)},
                                      {"propertiesDock", QSize(330, 440)},
                                      {"messagesDock", QSize(380, 0)},
                                      {"timelineDock", QSize(0, timelineDock->sizeHint().height())}});
    connect(m_brains, &BrainEditorPanel::brainMessages, m_messages, &MessagesPanel::showDiagnostics);
    connect(properties, &PropertiesPanel::problem, this, [this](const QString& text) {
        m_messages->showNote(text);
        m_messagesDock->show();
        statusBar()->showMessage(text, 8000);
    });
}

QDockWidget* MainWindow::createLayoutDock(QDockWidget* besides)
{
    m_layout = new LayoutPanel(m_document, this);
    QDockWidget* dock = addDock(tr("Layout Edits"), "layoutDock", m_layout, Qt::RightDockWidgetArea);
    // The layer shares the right column's foot with the history, behind it until asked for.
    tabifyDockWidget(besides, dock);
    besides->raise();
    dock->toggleViewAction()->setIcon(themeIcon("action-layout"));
    dock->toggleViewAction()->setToolTip(tr("Show the Layout Edits panel: edits of the recorded crowd (move, turn, "
                                            "retime, mirror, delete, spread, copy, re-dress, re-clip, resolve) "
                                            "without simulating again"));
    m_layout->setContextSource([this] {
        LayoutContext context;
        context.frame = m_simulation->currentFrame();
        context.clicked = m_viewport->focusedAgent();
        context.fps = m_simulation->fps();
        context.centreOf = [this](const sim::AgentSelector& agents) {
            return shownCentre(m_shown.frames(m_simulation->cache(), m_document.scene()), m_document.scene(), agents,
                               m_simulation->currentFrame());
        };
        return context;
    });
    connect(m_layout, &LayoutPanel::problem, this, [this](const QString& text) {
        m_messages->showNote(text);
        statusBar()->showMessage(text, 8000);
    });
    connect(m_layout, &LayoutPanel::clashRequested, this, [this](std::size_t frame, sim::AgentId agent) {
        m_simulation->seek(frame);
        m_viewport->setFocusedAgent(agent);
    });
    new LayoutRetimeDrag(m_document, *m_timeline->scrubBar(), this);
    m_layoutCheck = new LayoutCheckWatch(m_document, *m_simulation, m_shown, this);
    connect(m_layoutCheck, &LayoutCheckWatch::checked, this, [this](const sim::LayoutCheck& check) {
        m_layout->showCheck(check);
        m_viewport->setLayoutCheck(check);
    });
    connect(m_layoutCheck, &LayoutCheckWatch::skipped, this, [this](std::size_t agentFrames) {
        m_layout->showCheckSkipped(agentFrames);
        m_viewport->setLayoutCheck({});
    });
    connect(m_layout, &LayoutPanel::checkRequested, this, [this] {
        QApplication::setOverrideCursor(Qt::WaitCursor);
        m_layoutCheck->checkNow();
        QApplication::restoreOverrideCursor();
    });
    return dock;
}

void MainWindow::createEditMenu()
{
    QMenu* menu = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_document.undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName("undoAction");
    undo->setShortcut(QKeySequence::Undo);
    undo->setIcon(themeIcon("action-undo"));
    undo->setToolTip(tr("Undo the last edit"));
    QAction* redo = m_document.undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName("redoAction");
    redo->setShortcuts({QKeySequence::Redo, QKeySequence(tr("Ctrl+Y"))});
    redo->setToolTip(tr("Redo the last undone edit"));
    redo->setIcon(themeIcon("action-redo"));
    menu->addAction(undo);
    menu->addAction(redo);
    QAction* remove = menu->addAction(themeIcon("action-delete"), tr("&Delete"));
    remove->setObjectName("deleteAction");
    remove->setShortcut(QKeySequence::Delete);
    remove->setToolTip(tr("Delete the selected items (agents, paths, goals, lanes, crosswalks, vehicles, lights, brains, ...)"));
    connect(remove, &QAction::triggered, this, [this] {
        const Selection& selection = m_document.selection();
        auto* command = new DeleteItemsCommand(m_document, selection);
        const QString why = command->refusal();
        if (command->isEmpty() || !why.isEmpty()) {
            if (!why.isEmpty()) {
                m_messages->showNote(why);
                m_messagesDock->show();
                statusBar()->showMessage(why, 8000);
            }
            delete command;
            return;
        }
        m_document.setSelection({});  // the indices of what follows the deleted items shift
        m_document.undoStack()->push(command);
    });
    menu->addSeparator();
    m_outlinerBar->addAction(remove);
    if (QWidget* button = m_outlinerBar->widgetForAction(remove))
        button->setObjectName("deleteItemsButton");
    m_outliner->addAction(remove);
    QMenu* toolMenu = menu->addMenu(tr("&Tools"));
    toolMenu->addActions(m_tools->actions()->actions());
    toolMenu->setToolTipsVisible(true);
    menu->setToolTipsVisible(true);
}

void MainWindow::createViewMenu()
{
    QMenu* menu = menuBar()->addMenu(tr("&View"));
    auto* viewModes = new QActionGroup(this);
    QAction* top = menu->addAction(themeIcon("action-top-view"), tr("&Top View"), this, [this] { m_viewport->setViewMode(ViewMode::Top); });
    top->setShortcut(tr("Ctrl+1"));
    top->setToolTip(tr("Look straight down with an orthographic camera"));
    QAction* orbit = menu->addAction(themeIcon("action-3d-view"), tr("&3D View"), this, [this] { m_viewport->setViewMode(ViewMode::Orbit); });
    orbit->setShortcut(tr("Ctrl+2"));
    orbit->setToolTip(tr("Orbit the scene with a perspective camera (Alt+left or right drag)"));
    for (QAction* a : {top, orbit}) {
        a->setCheckable(true);
        viewModes->addAction(a);
    }
    top->setChecked(true);
    connect(m_viewport, &Viewport::viewModeChanged, this,
            [top, orbit](ViewMode mode) { (mode == ViewMode::Top ? top : orbit)->setChecked(true); });
    addAgentsAsMenu(*menu);
    menu->addSeparator();
    (new ViewportDisplayActions(*m_viewport, *m_simulation, this))->addTo(*menu);
    menu->addSeparator();
    QAction* frame = menu->addAction(themeIcon("action-frame-selection"), tr("&Frame Selection"), m_viewport, &Viewport::frameSelection);
    frame->setShortcut(Qt::Key_F);
    frame->setToolTip(tr("Fit the selection, its agents where they are now, into the viewport (all when nothing is selected)"));
    QAction* frameAll = menu->addAction(themeIcon("action-frame-all"), tr("Frame A&ll"), m_viewport, &Viewport::frameAll);
    frameAll->setShortcut(Qt::Key_A);
    frameAll->setToolTip(tr("Fit the whole scene into the viewport"));
    menu->addSeparator();
    menu->addAction(m_workspace->brainsAction());
    menu->addAction(m_workspace->resetAction());
    menu->addSeparator();
    for (QDockWidget* dock : m_docks)
        menu->addAction(dock->toggleViewAction());
    menu->setToolTipsVisible(true);
}

void MainWindow::addAgentsAsMenu(QMenu& viewMenu)
{
    QMenu* agentsAs = viewMenu.addMenu(tr("&Agents as"));
    agentsAs->setObjectName("agentsAsMenu");
    agentsAs->setToolTipsVisible(true);
    auto* group = new QActionGroup(this);
    QAction* characters = agentsAs->addAction(tr("&Characters"));
    characters->setObjectName("agentsAsCharactersAction");
    characters->setToolTip(tr("In 3D, near agents wear the character export gives them, walking as recorded"));
    QAction* glyphs = agentsAs->addAction(tr("&Glyphs"));
    glyphs->setObjectName("agentsAsGlyphsAction");
    glyphs->setToolTip(tr("Every agent as a simple oriented body shape (lighter to draw)"));
    for (QAction* a : {characters, glyphs}) {
        a->setCheckable(true);
        group->addAction(a);
    }
    const bool asCharacters = QSettings().value("viewport/agentsAs", "characters").toString() != "glyphs";
    (asCharacters ? characters : glyphs)->setChecked(true);
    m_viewport->setAgentsAsCharacters(asCharacters);
    connect(group, &QActionGroup::triggered, this, [this, characters](QAction* chosen) {
        const bool on = chosen == characters;
        m_viewport->setAgentsAsCharacters(on);
        QSettings().setValue("viewport/agentsAs", on ? "characters" : "glyphs");
    });
}

void MainWindow::createCreateMenu()
{
    QMenu* menu = menuBar()->addMenu(tr("&Create"));
    menu->setObjectName("createMenu");
    menu->setToolTipsVisible(true);
    menu->addAction(m_typeActions->newType());
    QMenu* presets = menu->addMenu(tr("Agent Type &Preset"));
    presets->setToolTipsVisible(true);
    presets->addActions(m_typeActions->presetMenu()->actions());
    menu->addAction(m_typeActions->duplicate());
    menu->addSeparator();
    for (const char* key : {"group", "crowdBrush", "wall", "goal", "path", "obstacle"})
        if (ViewportTool* tool = m_tools->tool(key))
            for (QAction* a : m_tools->actions()->actions())
                if (a->objectName() == tool->objectKey() + "Action")
                    menu->addAction(a);
}

QWidget* MainWindow::outlinerWithActions()
{
    auto* box = new QWidget(this);
    box->setObjectName("outlinerBox");
    auto* column = new QVBoxLayout(box);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);
    auto* bar = new QToolBar(box);
    m_outlinerBar = bar;
    bar->setObjectName("outlinerToolBar");
    bar->setIconSize(QSize(16, 16));
    bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    bar->addAction(m_typeActions->newType());
    if (auto* button = qobject_cast<QToolButton*>(bar->widgetForAction(m_typeActions->newType()))) {
        button->setObjectName("newTypeButton");
        button->setPopupMode(QToolButton::MenuButtonPopup);
        button->setText(tr("+ Type"));
    }
    bar->addAction(m_typeActions->duplicate());
    if (QWidget* button = bar->widgetForAction(m_typeActions->duplicate())) {
        button->setObjectName("duplicateTypeButton");
        static_cast<QToolButton*>(button)->setText(tr("Duplicate"));
    }
    column->addWidget(bar);
    column->addWidget(m_outliner);
    // Right click: the same, with Delete.
    m_outliner->setContextMenuPolicy(Qt::ActionsContextMenu);
    m_outliner->addAction(m_typeActions->newType());
    m_outliner->addAction(m_typeActions->duplicate());
    return box;
}

void MainWindow::offerAgentType()
{
    const QString question = tr("This scene has no agent type yet, so there is nothing to place.\n\n"
                                "Create a pedestrian type? (Create > New Agent Type offers others.)");
    QMessageBox box(QMessageBox::Question, tr("No agent type"), question, QMessageBox::Yes | QMessageBox::No, this);
    box.setObjectName("createTypePrompt");
    box.setDefaultButton(QMessageBox::Yes);
    if (box.exec() != QMessageBox::Yes)
        return;
    const std::size_t index = m_typeActions->create(TypePreset::Pedestrian);
    statusBar()->showMessage(
        tr("Created agent type %1: now draw or paint.").arg(QString::fromStdString(m_document.scene().agentTypes[index].name)),
        8000);
}

void MainWindow::createSimulationMenu()
{
    QMenu* menu = menuBar()->addMenu(tr("&Simulation"));
    auto add = [&](const QString& text, const char* icon, const QKeySequence& key, const QString& tip, auto slot) {
        QAction* a = menu->addAction(themeIcon(icon), text, m_simulation, slot);
        a->setShortcut(key);
        a->setToolTip(tip);
        return a;
    };
    add(tr("&Play / Pause"), "action-play", QKeySequence(Qt::Key_Space), tr("Play or pause the simulation"),
        &SimulationController::togglePlay);
    add(tr("&Step"), "action-step-forward", QKeySequence(Qt::Key_Period), tr("Advance one frame"), &SimulationController::stepForward);
    add(tr("&Restart"), "action-first-frame", QKeySequence(Qt::Key_Home), tr("Back to frame 0"), &SimulationController::restart);
    add(tr("&Last Computed Frame"), "action-last-frame", QKeySequence(Qt::Key_End), tr("Pause at the last frame computed so far"),
        &SimulationController::showLastRecorded);
    // The arrows move frames only from the viewport or the timeline: trees, tables and
    // text fields keep their own.
    for (QAction* a : {add(tr("Pre&vious Frame"), "action-step-back", QKeySequence(Qt::Key_Left), tr("Back one frame"),
                           &SimulationController::stepBackward),
                       add(tr("&Next Frame"), "action-step-forward", QKeySequence(Qt::Key_Right), tr("Advance one frame, computing it if needed"),
                           &SimulationController::stepForward)}) {
        a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        m_viewport->addAction(a);
        m_timeline->addAction(a);
    }
    QAction* toEnd = menu->addAction(themeIcon("action-simulate-to-end"), tr("Simulate to &End"), this, [this] { new SimulateToEndDialog(*m_simulation, this); });
    toEnd->setObjectName("simulateToEndAction");
    toEnd->setShortcut(QKeySequence(tr("Ctrl+E")));
    toEnd->setToolTip(tr("Record every frame, with progress and Cancel"));
    menu->setToolTipsVisible(true);
}

void MainWindow::createToolBars()
{
    auto* workspaces = new QToolBar(tr("Workspaces"), this);
    workspaces->setObjectName("workspaceToolBar");
    workspaces->addWidget(m_workspace->tabBar());
    addToolBar(Qt::TopToolBarArea, workspaces);
    // Down the left side: a column has room for every tool, a row would hide some.
    auto* tools = new QToolBar(tr("Tools"), this);
    addToolBar(Qt::LeftToolBarArea, tools);
    tools->setObjectName("toolsToolBar");
    tools->setToolButtonStyle(Qt::ToolButtonIconOnly);
    tools->setIconSize(QSize(24, 24));
    QToolBar* options = addToolBar(tr("Tool Options"));
    options->setObjectName("toolOptionsToolBar");
    m_tools->populate(tools, options);
}

void MainWindow::createStatusBar()
{
    m_agentCountLabel = new QLabel(this);
    m_agentCountLabel->setObjectName("agentCountLabel");
    m_frameLabel = new QLabel(this);
    m_frameLabel->setObjectName("frameLabel");
    m_speedLabel = new QLabel(this);
    m_speedLabel->setObjectName("speedLabel");
    m_speedLabel->setToolTip(tr("Simulation speed: steps computed per second"));
    statusBar()->addPermanentWidget(m_agentCountLabel);
    statusBar()->addPermanentWidget(m_frameLabel);
    statusBar()->addPermanentWidget(m_speedLabel);
    auto* speedTimer = new QTimer(this);
    connect(speedTimer, &QTimer::timeout, this, [this] {
        m_speedLabel->setText(tr("%1 steps/s").arg(m_simulation->stepsPerSecond(), 0, 'f', 0));
    });
    speedTimer->start(500);
    m_speedLabel->setText(tr("0 steps/s"));
    updateAgentStatus();
}

void MainWindow::refreshAfterEdit()
{
    if (!m_pendingChange)
        return;
    const SceneChange change = std::move(*m_pendingChange);
    m_pendingChange.reset();
    // The set at once, and the shown frame as the edited scene colours it; the simulation
    // brings the frame to show when the edit changes it (the edit frame again, or frame 0
    // of a run that starts over). Nothing here builds a World.
    m_viewport->updateScene(m_document.scene());
    m_viewport->setHighlight(m_document.scene(), m_document.selection());
    m_simulation->applyEdit(m_document.scene(), change);
    // The layout layer edits the recorded frames, not the simulation: show the shown
    // frame through the edited layer now.
    const std::size_t frame = m_simulation->currentFrame();
    if (change.touches(ItemKind::LayoutOp) && frame < m_simulation->cache().frameCount())
        m_viewport->showFrame(m_shown.frames(m_simulation->cache(), m_document.scene()), frame);
}

void MainWindow::updateAgentStatus()
{
    const std::size_t count = m_viewport->agentCount();
    m_agentCountLabel->setText(count == 1 ? tr("1 agent") : tr("%1 agents").arg(count));
    m_frameLabel->setText(tr("Frame %1").arg(m_viewport->frameIndex()));
}

void MainWindow::restoreWindowState()
{
    m_workspace->restore();
}

}  // namespace throng::editor
