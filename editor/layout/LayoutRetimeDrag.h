#pragma once
// The retime drag on the timeline: while one layout time offset is selected, the scrub bar
// marks it (TimelineRuler::setRetime: from its first frame, its frames later), and a
// Shift+drag on the bar shifts its agents by the frames dragged, as the mouse goes; the
// whole drag is one undoable step. Edits the scene only through changeLayoutCommand.

#include <QObject>

#include <optional>

namespace throng::editor {

class SceneDocument;
class TimelineRuler;

class LayoutRetimeDrag : public QObject {
    Q_OBJECT

public:
    LayoutRetimeDrag(SceneDocument& document, TimelineRuler& ruler, QObject* parent = nullptr);

private:
    // The selected time offset's index, if exactly one is selected.
    std::optional<std::size_t> selectedRetime() const;
    void showMark();
    void dragged(int frames, bool finished);

    SceneDocument& m_document;
    TimelineRuler& m_ruler;
    std::optional<int> m_startFrames;  // the operation's frames when the drag began
    int m_serial = 0;                  // one merge key per drag
};

}  // namespace throng::editor
