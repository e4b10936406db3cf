#include "editor/WorkspaceLayout.h"

#include "editor/Icons.h"

#include <QAction>
#include <QDockWidget>
#include <QGuiApplication>
#include <QMainWindow>
#include <QScreen>
#include <QSettings>
#include <QSignalBlocker>
#include <QSplitter>
#include <QTabBar>

namespace throng::editor {

namespace {
// Raised whenever the docks or the central widget change: a layout saved by an older
// build is then not applied (restoreState would place docks the window no longer has
// where they no longer fit).
constexpr int kLayoutVersion = 3;
constexpr int kViewportMinWidth = 360, kViewportMinHeight = 260;
constexpr int kBrainEditorMinWidth = 420;
const char* const kKeys[] = {"layout", "brains"};

QString key(Workspace w, const char* what)
{
    return QStringLiteral("workspace/%1/%2").arg(kKeys[int(w)], what);
}
}  // namespace

WorkspaceLayout::WorkspaceLayout(QMainWindow& window, QWidget* viewport, QWidget* brains,
                                 QList<QDockWidget*> brainsHides)
    : QObject(&window), m_window(window), m_brainEditor(brains), m_brainsHides(brainsHides)
{
    m_splitter = new QSplitter(Qt::Horizontal, &window);
    m_splitter->setObjectName("workspaceSplitter");
    m_splitter->setChildrenCollapsible(false);
    m_splitter->addWidget(viewport);
    m_splitter->addWidget(brains);
    m_splitter->setStretchFactor(0, 2);
    m_splitter->setStretchFactor(1, 3);
    viewport->setMinimumSize(kViewportMinWidth, kViewportMinHeight);
    brains->setMinimumWidth(kBrainEditorMinWidth);
    brains->hide();
    window.setCentralWidget(m_splitter);

    m_brains = new QAction(tr("&Brains Workspace"), this);
    m_brains->setObjectName("brainsWorkspaceAction");
    m_brains->setCheckable(true);
    m_brains->setIcon(themeIcon("action-brains-workspace"));
    m_brains->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    m_brains->setToolTip(tr("Edit brains beside the viewport, or go back to the layout docks (Ctrl+B)"));
    connect(m_brains, &QAction::toggled, this,
            [this](bool on) { switchTo(on ? Workspace::Brains : Workspace::Layout); });
    m_reset = new QAction(tr("&Reset Layout"), this);
    m_reset->setObjectName("resetLayoutAction");
    m_reset->setIcon(themeIcon("action-reset-layout"));
    m_reset->setToolTip(tr("Put every dock and tool bar of this workspace back where it started"));
    connect(m_reset, &QAction::triggered, this, &WorkspaceLayout::reset);
    m_tabs = new QTabBar(&window);
    m_tabs->setObjectName("workspaceTabs");
    m_tabs->addTab(themeIcon("action-layout-workspace"), tr("Layout"));
    m_tabs->addTab(themeIcon("action-brains-workspace"), tr("Brains"));
    m_tabs->setTabToolTip(0, tr("Set, crowd and properties (Ctrl+B switches)"));
    m_tabs->setTabToolTip(1, tr("The brain editor beside the viewport (Ctrl+B)"));
    m_tabs->setDrawBase(false);
    connect(m_tabs, &QTabBar::currentChanged, this, [this](int i) { switchTo(Workspace(i)); });
}

WorkspaceLayout::Arrangement WorkspaceLayout::capture() const
{
    Arrangement a{m_window.saveState(kLayoutVersion), m_splitter->saveState(), {}};
    for (QDockWidget* dock : m_window.findChildren<QDockWidget*>())
        if (dock->isVisible() && !dock->isFloating())
            a.dockSizes.insert(dock->objectName(), dock->size());
    return a;
}

void WorkspaceLayout::apply(const Arrangement& arrangement)
{
    m_window.restoreState(arrangement.window, kLayoutVersion);
    // Docks that were hidden when the state is applied come back at their size hint, not
    // at the size they had: give them that size again.
    QList<QDockWidget*> across, down;
    QList<int> widths, heights;
    for (QDockWidget* dock : m_window.findChildren<QDockWidget*>()) {
        const auto size = arrangement.dockSizes.find(dock->objectName());
        if (size == arrangement.dockSizes.end() || !dock->isVisibleTo(&m_window) || dock->isFloating())
            continue;
        if (size->width() > 0) {
            across << dock;
            widths << size->width();
        }
        if (size->height() > 0) {
            down << dock;
            heights << size->height();
        }
    }
    m_window.resizeDocks(across, widths, Qt::Horizontal);
    m_window.resizeDocks(down, heights, Qt::Vertical);
    m_splitter->restoreState(arrangement.splitter);
}

void WorkspaceLayout::applyDefault(Workspace workspace)
{
    apply({m_defaultWindow, {}, m_defaultDockSizes});
    if (workspace == Workspace::Brains) {
        for (QDockWidget* dock : m_brainsHides)
            dock->hide();
        const int width = std::max(m_splitter->width(), kViewportMinWidth + kBrainEditorMinWidth);
        m_splitter->setSizes({width * 2 / 5, width - width * 2 / 5});
    }
}

void WorkspaceLayout::showWorkspace(Workspace workspace)
{
    m_brainEditor->setVisible(workspace == Workspace::Brains);
    const QSignalBlocker blockAction(m_brains), blockTabs(m_tabs);
    m_brains->setChecked(workspace == Workspace::Brains);
    m_tabs->setCurrentIndex(int(workspace));
}

void WorkspaceLayout::switchTo(Workspace workspace)
{
    if (workspace == m_current)
        return;
    m_saved[int(m_current)] = capture();
    m_current = workspace;
    showWorkspace(workspace);
    if (m_saved[int(workspace)].window.isEmpty())
        applyDefault(workspace);
    else
        apply(m_saved[int(workspace)]);
    emit workspaceChanged(workspace);
}

void WorkspaceLayout::reset()
{
    m_saved = {};
    showWorkspace(m_current);
    applyDefault(m_current);
}

// Sound: every shown floating dock lies on a screen (the docked ones and the central
// widgets keep their minimum sizes by themselves).
bool WorkspaceLayout::sound() const
{
    for (QDockWidget* dock : m_window.findChildren<QDockWidget*>()) {
        if (!dock->isVisibleTo(&m_window) || !dock->isFloating())
            continue;
        bool onScreen = false;
        for (QScreen* screen : QGuiApplication::screens())
            onScreen = onScreen || screen->availableGeometry().intersects(dock->frameGeometry());
        if (!onScreen)
            return false;
    }
    return true;
}

void WorkspaceLayout::restore()
{
    m_defaultWindow = m_window.saveState(kLayoutVersion);
    QSettings settings;
    if (settings.value("workspace/version").toInt() != kLayoutVersion) {
        m_window.resize(1280, 800);
        applyDefault(Workspace::Layout);
        return;
    }
    if (!m_window.restoreGeometry(settings.value("workspace/geometry").toByteArray()))
        m_window.resize(1280, 800);
    for (Workspace w : {Workspace::Layout, Workspace::Brains})
        m_saved[int(w)] = {settings.value(key(w, "window")).toByteArray(), settings.value(key(w, "splitter")).toByteArray(), {}};
    const Workspace current = settings.value("workspace/current").toString() == kKeys[1] ? Workspace::Brains
                                                                                          : Workspace::Layout;
    m_current = current;
    showWorkspace(current);
    const Arrangement& saved = m_saved[int(current)];
    const bool restored = !saved.window.isEmpty() && m_window.restoreState(saved.window, kLayoutVersion) &&
                          m_splitter->restoreState(saved.splitter);
    if (!restored || !sound()) {
        m_saved = {};
        applyDefault(current);
    }
}

void WorkspaceLayout::save() const
{
    QSettings settings;
    settings.setValue("workspace/version", kLayoutVersion);
    settings.setValue("workspace/geometry", m_window.saveGeometry());
    settings.setValue("workspace/current", kKeys[int(m_current)]);
    std::array<Arrangement, 2> all = m_saved;
    all[int(m_current)] = capture();
    for (Workspace w : {Workspace::Layout, Workspace::Brains}) {
        settings.setValue(key(w, "window"), all[int(w)].window);
        settings.setValue(key(w, "splitter"), all[int(w)].splitter);
    }
}

}  // namespace throng::editor
