#pragma once
// Base of the brushes that edit the placed agents under a disk dragged over the ground
// (orient, variation, assign): each dab edits copies of the agents inside the disk and
// pushes one ChangeAgentsCommand; the dabs of one stroke merge into one undo step.
// Never edits the scene directly.

#include "editor/tools/BrushTool.h"
#include "simcore/scene/Scene.h"

#include <vector>

namespace throng::editor {

class AgentBrushTool : public BrushTool {
    Q_OBJECT

public:
    AgentBrushTool(SceneDocument& document, Viewport& viewport, QObject* parent = nullptr);

protected:
    // Edits `agent` for a dab at `centre`; `direction` is the stroke's unit direction over
    // the last radius of its length (zero for the first dab of a stroke). `strokeId` keys
    // the brush's random draws. Returns true when the agent changed.
    virtual bool editAgent(sim::Agent& agent, glm::vec2 centre, glm::vec2 direction, int strokeId) const = 0;
    // The history's verb ("Comb").
    virtual QString verb() const = 0;

    void strokeBegan(glm::vec2 point) override;
    void strokeMoved(glm::vec2 point) override;
    void strokeEnded() override;

private:
    void dab(glm::vec2 centre, glm::vec2 direction);

    void dabAt(glm::vec2 point);

    glm::vec2 m_lastDab{0.0f};
    glm::vec2 m_lastPoint{0.0f};  // the stroke's newest mouse point
    std::vector<glm::vec2> m_dabs;  // of the stroke in progress, for its direction
    int m_strokeId = 0;
};

}  // namespace throng::editor
