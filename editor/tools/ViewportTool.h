#pragma once
// One interaction mode of the viewport (brush, wall, select, ...): turns the left mouse
// button and keys into undo commands pushed on the document's stack, and draws its own
// preview. A tool never edits the scene directly and owns no GL.

#include <glm/vec3.hpp>

#include <QKeySequence>
#include <QObject>
#include <QPointF>
#include <QString>

#include <optional>

class QKeyEvent;
class QPainter;
class QWidget;

namespace throng::editor {

class SceneDocument;
class Viewport;

// A mouse event as tools see it: the widget pixel and the ground point under it (found by
// ray casting onto the terrain or the ground plane; empty when the ray misses).
struct ToolMouse {
    QPointF pixel;
    std::optional<glm::vec3> ground;
    Qt::KeyboardModifiers modifiers;
};

class ViewportTool : public QObject {
    Q_OBJECT

public:
    enum class State { Idle, Hover, Dragging };

    ViewportTool(SceneDocument& document, Viewport& viewport, QObject* parent = nullptr);

    virtual QString name() const = 0;        // menu and button text ("Crowd Brush")
    virtual QString toolTip() const = 0;     // what it does and how
    virtual QKeySequence shortcut() const = 0;
    virtual QString objectKey() const = 0;   // stable id ("crowdBrush") for tests and settings
    // The key of its icon in the editor's set (Icons.h): "tool-" and the object key in
    // kebab case ("tool-crowd-brush").
    virtual QString iconKey() const;

    virtual void activate() {}
    // Drops any preview (Escape does the same); the document is untouched.
    virtual void deactivate() { cancel(); }
    // By default: back to Idle and the overlay redrawn. Tools with a preview drop it first.
    virtual void cancel();

    virtual void mousePressed(const ToolMouse&) {}
    virtual void mouseMoved(const ToolMouse&) {}
    virtual void mouseReleased(const ToolMouse&) {}
    virtual void mouseDoubleClicked(const ToolMouse&) {}
    // True when the tool used the key. By default Escape during a drag takes the drag back
    // (revertDrag, then cancel) and is used; other keys are not.
    virtual bool keyPressed(QKeyEvent* event);

    // Draws the preview in widget pixels over the viewport.
    virtual void drawOverlay(QPainter&) const {}
    virtual QString statusText() const { return toolTip(); }
    // The tool's option widgets for the tool options bar; null when it has none.
    virtual QWidget* createOptionsWidget(QWidget*) { return nullptr; }

    State state() const { return m_state; }

signals:
    // The preview or status text changed: the viewport repaints its overlay.
    void overlayChanged();
    // The user tried to place agents in a scene without agent types: the main window
    // offers to create one.
    void agentTypeNeeded();

protected:
    // Entering Dragging remembers the undo stack's index, for revertDrag.
    void setState(State state);
    // Takes back every step the current drag pushed (a tool that pushes as it goes) and
    // drops them from the redo list too, so a cancelled drag leaves no trace in the
    // history. Does nothing outside a drag or when the drag pushed nothing.
    void revertDrag();
    SceneDocument& document() { return m_document; }
    const SceneDocument& document() const { return m_document; }
    Viewport& viewport() { return m_viewport; }
    const Viewport& viewport() const { return m_viewport; }

private:
    SceneDocument& m_document;
    Viewport& m_viewport;
    State m_state = State::Idle;
    int m_dragStartIndex = -1;  // the undo stack's index when the drag began
};

}  // namespace throng::editor
