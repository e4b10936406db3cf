#pragma once
// The "Brains" dock: the scene's brains (new, rename, duplicate, delete, import/export a
// .brain.yaml, assign to an agent type), the node graph of the shown one, the node
// palette, compiler errors on the graph and in the message log, and the live values of
// an agent picked in the viewport while the simulation plays (recorded by the playback's
// own World with each frame). Edits go through BrainGraphModel and EditBrainsCommand on
// the document's stack; it never runs a World of its own.

#include "editor/SceneDocument.h"
#include "editor/brain/BrainCommands.h"
#include "simcore/brain/BrainCompiler.h"
#include "simcore/base/Diagnostic.h"

#include <QWidget>

#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QToolButton;

namespace throng::editor {

class BrainGraphModel;
class BrainScene;
class BrainView;
class NodePalette;
class SimulationController;
class Viewport;

class BrainEditorPanel : public QWidget {
    Q_OBJECT

public:
    // `viewport` (may be null) is where an agent is picked for the live view.
    BrainEditorPanel(SceneDocument& document, SimulationController& simulation, Viewport* viewport,
                     QWidget* parent = nullptr);
    ~BrainEditorPanel() override;

    BrainGraphModel& model() { return *m_model; }
    BrainScene& scene() { return *m_scene; }
    BrainView& view() { return *m_view; }
    NodePalette& palette() { return *m_palette; }
    // The last compile of the shown brain.
    const std::vector<sim::BrainError>& errors() const { return m_errors; }
    // What the panel last said (a refused link, an import error...).
    QString statusText() const;

    void showBrain(int index);
    bool renameBrain(const QString& name);
    void duplicateBrain();
    void newBrain();
    void deleteBrain();
    bool importBrain(const QString& path);
    bool exportBrain(const QString& path);
    // Agent type `type` runs the shown brain from now on.
    void assignToType(int type);
    // Follows World agent `agent` (dense index) in the live view; -1 stops.
    void pickAgent(std::ptrdiff_t agent);
    std::ptrdiff_t pickedAgent() const { return m_picked; }
    // Arms the viewport: its next left click picks the nearest agent.
    void armViewportPick();

    void copySelection();
    void paste();
    void duplicateSelection();
    bool collapseSelection();
    bool expandSelection();

signals:
    // The compiler's verdict on the shown brain changed: for the message log.
    void brainMessages(const QString& headline, const std::vector<sim::Diagnostic>& diagnostics);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QWidget* createBar();
    void refreshList();
    // The empty graph's hint: how to start a brain, or its first node.
    void updateHint();
    void recompile();
    void reportErrors();
    void updateLive();
    // The brain World agent `agent` runs: its own (Agent::brain) or its type's; empty = none.
    std::string brainOf(std::ptrdiff_t agent) const;
    void setStatus(const QString& text, bool problem);
    void addFromPalette(const QString& type);
    void pushLibrary(const EditBrainsCommand::State& after, const QString& text);

    SceneDocument& m_document;
    SimulationController& m_simulation;
    Viewport* m_viewport;
    BrainGraphModel* m_model;
    BrainScene* m_scene;
    BrainView* m_view;
    NodePalette* m_palette;
    QComboBox* m_brains = nullptr;
    QComboBox* m_types = nullptr;
    QSpinBox* m_agent = nullptr;
    QToolButton* m_pick = nullptr;
    QLabel* m_status = nullptr;
    std::vector<sim::BrainError> m_errors;
    std::ptrdiff_t m_picked = -1;  // World agent (dense index) in the live view, -1 = nobody
    sim::BrainGraph m_clipboard;
    QPointF m_paletteScenePos;
    // A link dropped on empty space waits for the node the palette adds.
    struct PendingLink { sim::NodeId node = 0; int port = 0; bool fromInput = false; };
    std::optional<PendingLink> m_pending;
};

}  // namespace throng::editor
