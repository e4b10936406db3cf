#include "editor/layout/LayoutRetimeDrag.h"

#include "editor/SceneDocument.h"
#include "editor/layout/LayoutEdits.h"
#include "editor/panels/TimelineRuler.h"

#include <QUndoStack>

#include <algorithm>

namespace throng::editor {

LayoutRetimeDrag::LayoutRetimeDrag(SceneDocument& document, TimelineRuler& ruler, QObject* parent)
    : QObject(parent), m_document(document), m_ruler(ruler)
{
    connect(&m_document, &SceneDocument::selectionChanged, this, &LayoutRetimeDrag::showMark);
    connect(&m_document, &SceneDocument::sceneReset, this, &LayoutRetimeDrag::showMark);
    connect(&m_document, &SceneDocument::sceneChanged, this, [this](const SceneChange& change) {
        if (change.touches(ItemKind::LayoutOp))
            showMark();
    });
    connect(&m_ruler, &TimelineRuler::retimeDragged, this, &LayoutRetimeDrag::dragged);
}

std::optional<std::size_t> LayoutRetimeDrag::selectedRetime() const
{
    const Selection& selection = m_document.selection();
    const sim::LayoutLayer& layer = m_document.scene().layout;
    if (selection.size() != 1 || selection.front().kind != ItemKind::LayoutOp ||
        selection.front().index >= layer.ops.size() ||
        layer.ops[selection.front().index].kind != sim::LayoutKind::TimeOffset)
        return std::nullopt;
    return selection.front().index;
}

void LayoutRetimeDrag::showMark()
{
    const std::optional<std::size_t> index = selectedRetime();
    if (!index) {
        m_ruler.setRetime(std::nullopt);
        return;
    }
    const sim::LayoutOp& op = m_document.scene().layout.ops[*index];
    const int from = int(std::min<std::size_t>(op.firstFrame, std::size_t(m_ruler.maximum())));
    m_ruler.setRetime(TimelineRuler::Retime{from, op.frames});
}

void LayoutRetimeDrag::dragged(int frames, bool finished)
{
    const std::optional<std::size_t> index = selectedRetime();
    if (!index) {
        m_startFrames.reset();
        return;
    }
    if (!m_startFrames) {
        m_startFrames = m_document.scene().layout.ops[*index].frames;
        ++m_serial;
    }
    sim::LayoutLayer after = m_document.scene().layout;
    sim::LayoutOp& op = after.ops[*index];
    const int later = *m_startFrames + frames;
    if (op.frames != later) {
        op.frames = later;
        const QString text = tr("Retime %1").arg(QString::fromStdString(op.name));
        m_document.undoStack()->push(changeLayoutCommand(m_document, std::move(after), text,
                                                         QStringLiteral("layoutRetime/%1").arg(m_serial)));
    }
    if (finished)
        m_startFrames.reset();
}

}  // namespace throng::editor
