#pragma once
// The agents of the shown frame as the viewport draws them (id, feet, body radius, by
// World index): which one is drawn under a pixel or inside a box, and where one stands
// now. Plain data and camera geometry; never draws and never edits the scene.

#include "editor/viewport/RenderView.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec3.hpp>

#include <QPointF>
#include <QRectF>

#include <cstddef>
#include <limits>
#include <vector>

namespace throng::editor {

class ShownAgents {
public:
    static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

    void resize(std::size_t count);
    // Agent `i` of the frame; id 0 marks one that is not drawn (absent, or left the shot).
    void set(std::size_t i, sim::AgentId id, glm::vec3 feet, float radiusM);

    std::size_t size() const { return m_ids.size(); }
    bool empty() const { return m_ids.empty(); }
    sim::AgentId id(std::size_t i) const { return m_ids[i]; }
    glm::vec3 feet(std::size_t i) const { return m_feet[i]; }
    float radiusM(std::size_t i) const { return m_radiusM[i]; }
    // The index of drawn agent `id`, trying `hint` first (a placed agent's scene index is
    // usually its World index); kNone when it is not drawn.
    std::size_t find(sim::AgentId id, std::size_t hint = kNone) const;

    struct Nearest {
        std::size_t index = kNone;
        double distancePx = 0.0;  // from the pixel to the body's axis
    };
    // The drawn agent whose body (an upright prism in perspective, a disc from above)
    // passes nearest `pixel`, within `maxPx` or its own drawn radius; index kNone for none.
    Nearest nearest(const RenderView& view, QPointF pixel, double maxPx) const;
    // The drawn agents whose body's middle appears inside `box` (widget pixels).
    std::vector<std::size_t> inside(const RenderView& view, const QRectF& box) const;

    // The height the viewport draws a body of `radiusM` at (AgentShaders: 5.5 radii,
    // 0.5 to 1.8 m); 0 from above, where bodies are flat.
    static float bodyHeightM(const RenderView& view, float radiusM);

private:
    std::vector<sim::AgentId> m_ids;
    std::vector<glm::vec3> m_feet;
    std::vector<float> m_radiusM;
};

}  // namespace throng::editor
