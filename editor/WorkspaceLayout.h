#pragma once
// The window's two workspaces and their layouts: Layout (the viewport with the outliner,
// properties and history docks) and Brains (the viewport beside the brain editor, with
// the room those docks took). Switches between them, keeps each one's arrangement,
// resets it (View > Reset Layout) and saves it for the next launch, where a layout that
// does not fit any more is replaced by the default. Arranges widgets; edits nothing.

#include <QByteArray>
#include <QHash>
#include <QSize>
#include <QObject>
#include <QString>

#include <array>

class QAction;
class QActionGroup;
class QDockWidget;
class QMainWindow;
class QSplitter;
class QTabBar;
class QWidget;

namespace throng::editor {

enum class Workspace { Layout, Brains };

class WorkspaceLayout : public QObject {
    Q_OBJECT

public:
    // `viewport` and `brains` go into the central splitter this object makes and sets on
    // `window`; the docks named in `brainsHides` are hidden in the Brains workspace.
    WorkspaceLayout(QMainWindow& window, QWidget* viewport, QWidget* brains, QList<QDockWidget*> brainsHides);

    Workspace current() const { return m_current; }
    void switchTo(Workspace workspace);
    // Back to the arrangement of a first launch, for the shown workspace.
    void reset();
    // Call once every dock and tool bar exists: it records the defaults, then applies
    // the saved layout when it is sound.
    void restore();
    void save() const;
    // The docks' sizes in the default arrangement, by object name (0 = as laid out). Set
    // before restore().
    void setDefaultDockSizes(QHash<QString, QSize> sizes) { m_defaultDockSizes = std::move(sizes); }

    QSplitter* splitter() const { return m_splitter; }
    QAction* brainsAction() const { return m_brains; }   // Ctrl+B: Brains and back
    QAction* resetAction() const { return m_reset; }
    QTabBar* tabBar() const { return m_tabs; }            // workspace tabs for a tool bar

signals:
    void workspaceChanged(Workspace workspace);

private:
    struct Arrangement {
        QByteArray window;    // QMainWindow::saveState
        QByteArray splitter;  // QSplitter::saveState
        QHash<QString, QSize> dockSizes;  // by object name, the docks shown
    };
    Arrangement capture() const;
    void apply(const Arrangement& arrangement);
    void applyDefault(Workspace workspace);
    bool sound() const;
    void showWorkspace(Workspace workspace);

    QMainWindow& m_window;
    QSplitter* m_splitter = nullptr;
    QWidget* m_brainEditor = nullptr;
    QList<QDockWidget*> m_brainsHides;
    QAction* m_brains = nullptr;
    QAction* m_reset = nullptr;
    QTabBar* m_tabs = nullptr;
    Workspace m_current = Workspace::Layout;
    QByteArray m_defaultWindow;
    QHash<QString, QSize> m_defaultDockSizes;
    std::array<Arrangement, 2> m_saved;  // by Workspace; empty = the default
};

}  // namespace throng::editor
