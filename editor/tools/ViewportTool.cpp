#include "editor/tools/ViewportTool.h"

#include "editor/SceneDocument.h"

#include <QKeyEvent>
#include <QUndoCommand>

namespace throng::editor {

ViewportTool::ViewportTool(SceneDocument& document, Viewport& viewport, QObject* parent)
    : QObject(parent), m_document(document), m_viewport(viewport)
{
}

QString ViewportTool::iconKey() const
{
    QString key = QStringLiteral("tool-");
    for (QChar c : objectKey())
        key += c.isUpper() ? QStringLiteral("-") + c.toLower() : QString(c);
    return key;
}

void ViewportTool::cancel()
{
    setState(State::Idle);
    emit overlayChanged();
}

bool ViewportTool::keyPressed(QKeyEvent* event)
{
    if (event->key() != Qt::Key_Escape || m_state != State::Dragging)
        return false;
    revertDrag();
    cancel();
    return true;
}

void ViewportTool::setState(State state)
{
    if (state == State::Dragging && m_state != State::Dragging)
        m_dragStartIndex = m_document.undoStack()->index();
    m_state = state;
}

void ViewportTool::revertDrag()
{
    QUndoStack* stack = m_document.undoStack();
    if (m_state != State::Dragging || m_dragStartIndex < 0 || stack->index() <= m_dragStartIndex)
        return;
    stack->setIndex(m_dragStartIndex);
    // Pushing an obsolete command clears the redo list and adds nothing (QUndoStack::push).
    auto* nothing = new QUndoCommand;
    nothing->setObsolete(true);
    stack->push(nothing);
}

}  // namespace throng::editor
