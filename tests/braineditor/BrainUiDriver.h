#pragma once
// Drives the brain editor of the real main window as a user does in the UI tests: opens
// a scene written into a temporary folder, makes the Brains dock roomy, adds nodes by
// typing in the Tab palette, drags links from port to port, edits inline parameters.

#include "editor/MainWindow.h"
#include "editor/brain/BrainEditorPanel.h"
#include "simcore/scene/BrainGraph.h"

#include <QByteArray>
#include <QPoint>
#include <QTemporaryDir>

namespace throng::editor::test {

class BrainUi {
public:
    explicit BrainUi(MainWindow& window);

    // Shows the window and opens `yaml` (written as dir/scene.yaml). False on failure.
    bool open(const QTemporaryDir& dir, const QByteArray& yaml);
    // Shows the window and opens the scene file at `path` (the demos in resources/).
    bool openPath(const QString& path);
    BrainEditorPanel& panel() { return *m_panel; }

    // The view pixel of a scene point.
    QPoint pixel(QPointF scenePos) const;
    // Moves the mouse over `scenePos`, presses Tab, types `text` and presses Enter.
    // Returns the new node's id (0 when none was added).
    sim::NodeId addByTyping(QPointF scenePos, const QString& text);
    // A left drag from output `fromPort` of `from` to input `toPort` of `to`.
    void dragLink(sim::NodeId from, int fromPort, sim::NodeId to, int toPort);
    // A left drag in the view between two scene points (with moves between).
    void drag(QPointF fromScene, QPointF toScene, Qt::KeyboardModifiers mods = Qt::NoModifier);
    // Double-clicks parameter `key` of node `node`, types `text` and presses Enter.
    bool editParam(sim::NodeId node, const QString& key, const QString& text);
    void click(QPointF scenePos, Qt::KeyboardModifiers mods = Qt::NoModifier);
    void key(int key, Qt::KeyboardModifiers mods = Qt::NoModifier);
    int nodeCount() const;
    int linkCount() const;

private:
    MainWindow& m_window;
    BrainEditorPanel* m_panel;
};

}  // namespace throng::editor::test
