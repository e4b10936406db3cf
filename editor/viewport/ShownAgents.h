#pragma once
// The agents of the shown frame as the viewport draws them (id, feet, body radius and
// whether it is drawn, by World index): which one is drawn under a pixel or inside a box,
// where one stands now, and whether the frame knows an agent at all (a frame made before
// an edit added it does not). Plain data and camera geometry; never draws or edits.

#include "editor/viewport/RenderView.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec3.hpp>

#include <QPointF>
#include <QRectF>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace throng::editor {

class ShownAgents {
public:
    static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

    void resize(std::size_t count);
    // Agent `i` of the frame; `drawn` false for one absent there or gone through an exit.
    void set(std::size_t i, sim::AgentId id, glm::vec3 feet, float radiusM, bool drawn);

    std::size_t size() const { return m_ids.size(); }
    bool empty() const { return m_ids.empty(); }
    sim::AgentId id(std::size_t i) const { return m_ids[i]; }
    glm::vec3 feet(std::size_t i) const { return m_feet[i]; }
    float radiusM(std::size_t i) const { return m_radiusM[i]; }
    bool drawn(std::size_t i) const { return m_drawn[i] != 0; }
    // The index of agent `id`, drawn or not, trying `hint` first (a placed agent's scene
    // index is usually its World index); kNone when the frame does not hold it.
    std::size_t find(sim::AgentId id, std::size_t hint = kNone) const;
    // Whether the frame holds agent `id`, drawn or not. Unlike find(), a miss costs a
    // sort of the ids once per frame, not a scan: for asking about every scene agent.
    bool holds(sim::AgentId id, std::size_t hint = kNone) const;

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
    std::vector<std::uint8_t> m_drawn;
    mutable std::vector<sim::AgentId> m_sortedIds;  // built by the first holds() that misses
};

}  // namespace throng::editor
