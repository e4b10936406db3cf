#pragma once
// The Layout Edits panel: the scene's layout layer (issue 29), one row per operation in the
// order they apply, each with its switch. Adds an operation of any kind for the selected
// agents, groups or types (or only the agent last clicked), turns operations on and off,
// moves them up and down and removes them: each one undoable edit (LayoutEdits.h).
// Selecting a row selects the operation, which Properties then edits. Below, what the
// last layout check found (LayoutCheckWatch.h): the overlaps and wall crossings the edits
// made, by agent and frames; activating one asks to see it.

#include "editor/SceneChange.h"
#include "editor/SceneDocument.h"
#include "simcore/layout/LayoutCheck.h"

#include <QWidget>

#include <functional>

class QAction;
class QCheckBox;
class QLabel;
class QPushButton;
class QListWidget;
class QListWidgetItem;
class QTreeWidget;

namespace throng::editor {

// What a new operation needs from the rest of the editor.
struct LayoutContext {
    std::size_t frame = 0;       // the shown frame
    sim::AgentId clicked = 0;    // the agent last clicked in the viewport (0 = none)
    double fps = 24.0;
    // The centre of the agents a selector names on the shown frame (the scene's x, z).
    std::function<glm::vec2(const sim::AgentSelector&)> centreOf;
};

class LayoutPanel : public QWidget {
    Q_OBJECT

public:
    LayoutPanel(SceneDocument& document, QWidget* parent = nullptr);
    // The lists are deleted after this part of the panel (and maybe after the document):
    // what they say while they go is not heard.
    ~LayoutPanel() override;
    void setContextSource(std::function<LayoutContext()> source) { m_context = std::move(source); }

    // Appends an operation of `kind` for the selection (see LayoutEdits.h); false, with a
    // problem(), when the selection names no agent.
    bool addOperation(sim::LayoutKind kind);
    // Moves the selected operation one place earlier (-1) or later (+1).
    void moveSelected(int by);
    void removeSelected();
    // Shows what the layout check found; an empty check clears the list.
    void showCheck(const sim::LayoutCheck& check);
    // The shot was too large to check by itself (`agentFrames` laid-out agent-frames): the
    // panel says so and offers Check.
    void showCheckSkipped(std::size_t agentFrames);

    // As narrow as the right column's docks start (Properties' 330 px): it shares that column.
    QSize sizeHint() const override { return {300, 240}; }

    QListWidget* list() const { return m_list; }
    QTreeWidget* clashes() const { return m_clashes; }
    QAction* addMenuAction(sim::LayoutKind kind) const { return m_add[int(kind)]; }

signals:
    // The user asked to see a clash: frame `frame`, agent `agent`.
    void clashRequested(std::size_t frame, sim::AgentId agent);
    // The user asked for the check (Check).
    void checkRequested();
    void problem(const QString& text);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void rebuild();
    void showSelection();
    void takeSelection();
    void rowChanged(QListWidgetItem* row);
    void updateActions();
    int selectedRow() const;

    SceneDocument& m_document;
    std::function<LayoutContext()> m_context;
    QListWidget* m_list = nullptr;
    QTreeWidget* m_clashes = nullptr;
    QLabel* m_checkLabel = nullptr;
    QPushButton* m_checkButton = nullptr;
    QCheckBox* m_clickedOnly = nullptr;
    QAction* m_add[sim::kLayoutKindCount] = {};
    QAction* m_up = nullptr;
    QAction* m_down = nullptr;
    QAction* m_remove = nullptr;
    bool m_updating = false;
};

}  // namespace throng::editor
