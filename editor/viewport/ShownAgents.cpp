#include "editor/viewport/ShownAgents.h"
#include "editor/SegmentDistance.h"

#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace throng::editor {

namespace {

struct Projected {
    QPointF pixel;
    float w = 1.0f;  // clip w: the depth that scales a metre into pixels
};

// Empty behind the camera, where a projected point would mirror onto the screen.
std::optional<Projected> project(const RenderView& view, glm::vec3 p)
{
    const glm::vec4 clip = view.viewProjection * glm::vec4(p, 1.0f);
    if (!(clip.w > 1e-6f))
        return std::nullopt;
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return Projected{{(0.5 + 0.5 * double(ndc.x)) * double(view.sizePx.x), (0.5 - 0.5 * double(ndc.y)) * double(view.sizePx.y)},
                     clip.w};
}

}  // namespace

void ShownAgents::resize(std::size_t count)
{
    m_ids.resize(count);
    m_feet.resize(count);
    m_radiusM.resize(count);
    m_drawn.resize(count);
    m_sortedIds.clear();
}

void ShownAgents::set(std::size_t i, sim::AgentId id, glm::vec3 feet, float radiusM, bool drawn)
{
    m_ids[i] = id;
    m_feet[i] = feet;
    m_radiusM[i] = radiusM;
    m_drawn[i] = drawn ? 1 : 0;
    m_sortedIds.clear();
}

bool ShownAgents::holds(sim::AgentId id, std::size_t hint) const
{
    if (hint < m_ids.size() && m_ids[hint] == id)
        return true;
    if (m_sortedIds.size() != m_ids.size()) {
        m_sortedIds = m_ids;
        std::sort(m_sortedIds.begin(), m_sortedIds.end());
    }
    return std::binary_search(m_sortedIds.begin(), m_sortedIds.end(), id);
}

std::size_t ShownAgents::find(sim::AgentId id, std::size_t hint) const
{
    if (id == 0)
        return kNone;
    if (hint < m_ids.size() && m_ids[hint] == id)
        return hint;
    const auto it = std::find(m_ids.begin(), m_ids.end(), id);
    return it == m_ids.end() ? kNone : std::size_t(it - m_ids.begin());
}

float ShownAgents::bodyHeightM(const RenderView& view, float radiusM)
{
    return view.perspective ? std::clamp(5.5f * radiusM, 0.5f, 1.8f) : 0.0f;
}

ShownAgents::Nearest ShownAgents::nearest(const RenderView& view, QPointF pixel, double maxPx) const
{
    Nearest best;
    for (std::size_t i = 0; i < m_ids.size(); ++i) {
        if (!m_drawn[i])
            continue;
        const float r = m_radiusM[i];
        const std::optional<Projected> feet = project(view, m_feet[i]);
        const std::optional<Projected> head = project(view, m_feet[i] + glm::vec3(0.0f, bodyHeightM(view, r), 0.0f));
        if (!feet || !head)
            continue;
        const double radiusPx = double(r) / (double(view.metresPerPixel) * double(feet->w));
        const double d = segmentDistancePx(pixel, feet->pixel, head->pixel);
        if (d <= std::max(maxPx, radiusPx) && (best.index == kNone || d < best.distancePx))
            best = {i, d};
    }
    return best;
}

std::vector<std::size_t> ShownAgents::inside(const RenderView& view, const QRectF& box) const
{
    std::vector<std::size_t> found;
    for (std::size_t i = 0; i < m_ids.size(); ++i) {
        if (!m_drawn[i])
            continue;
        const glm::vec3 middle = m_feet[i] + glm::vec3(0.0f, 0.5f * bodyHeightM(view, m_radiusM[i]), 0.0f);
        if (const std::optional<Projected> p = project(view, middle); p && box.contains(p->pixel))
            found.push_back(i);
    }
    return found;
}

}  // namespace throng::editor
