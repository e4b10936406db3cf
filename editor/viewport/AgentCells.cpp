#include "editor/viewport/AgentCells.h"

#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {

// A cell is kept when it reaches this far past the view's edges (a fraction of the half
// view): glyphs are never drawn smaller than a few pixels, so an agent just outside may
// still touch the edge.
constexpr float kEdgeMargin = 0.05f;

void addRange(std::vector<InstanceRange>& ranges, int first, int count)
{
    if (!ranges.empty() && ranges.back().first + ranges.back().count == first)
        ranges.back().count += count;
    else
        ranges.push_back({first, count});
}

}  // namespace

float AgentCells::bodyHeightM(float radiusM)
{
    return std::clamp(5.5f * radiusM, 0.5f, 1.8f);
}

void AgentCells::build(std::span<const AgentGlyph> glyphs)
{
    m_cells.clear();
    m_sorted.resize(glyphs.size());
    m_order.resize(glyphs.size());
    if (glyphs.empty())
        return;
    glm::vec2 lo{glyphs[0].position.x, glyphs[0].position.z}, hi = lo;
    for (const AgentGlyph& g : glyphs) {
        lo = glm::min(lo, glm::vec2(g.position.x, g.position.z));
        hi = glm::max(hi, glm::vec2(g.position.x, g.position.z));
    }
    const glm::vec2 extent = hi - lo;
    const float cellM = std::max(kMinCellM, std::max(extent.x, extent.y) / float(kMaxCellsPerSide));
    const int nx = std::min(kMaxCellsPerSide, int(extent.x / cellM) + 1);
    const int nz = std::min(kMaxCellsPerSide, int(extent.y / cellM) + 1);

    // Counting sort by cell, row after row: stable, so equal input gives equal order.
    m_cellOf.resize(glyphs.size());
    std::vector<int> start(std::size_t(nx * nz) + 1, 0);
    for (std::size_t i = 0; i < glyphs.size(); ++i) {
        const int cx = std::min(nx - 1, int((glyphs[i].position.x - lo.x) / cellM));
        const int cz = std::min(nz - 1, int((glyphs[i].position.z - lo.y) / cellM));
        m_cellOf[i] = cz * nx + cx;
        ++start[std::size_t(m_cellOf[i]) + 1];
    }
    for (std::size_t c = 1; c < start.size(); ++c)
        start[c] += start[c - 1];
    std::vector<int> next(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < glyphs.size(); ++i) {
        const std::size_t at = std::size_t(next[std::size_t(m_cellOf[i])]++);
        m_sorted[at] = glyphs[i];
        m_order[at] = int(i);
    }

    for (std::size_t c = 0; c + 1 < start.size(); ++c) {
        const int first = start[c], count = start[c + 1] - start[c];
        if (count == 0)
            continue;
        Cell cell;
        cell.first = first;
        cell.count = count;
        const AgentGlyph& g0 = m_sorted[std::size_t(first)];
        cell.min = cell.max = {g0.position.x, g0.position.z};
        cell.minY = cell.maxY = g0.position.y;
        for (int i = first; i < first + count; ++i) {
            const AgentGlyph& g = m_sorted[std::size_t(i)];
            cell.min = glm::min(cell.min, glm::vec2(g.position.x, g.position.z));
            cell.max = glm::max(cell.max, glm::vec2(g.position.x, g.position.z));
            cell.minY = std::min(cell.minY, g.position.y);
            cell.maxY = std::max(cell.maxY, g.position.y);
            cell.maxRadiusM = std::max(cell.maxRadiusM, g.radiusM);
        }
        m_cells.push_back(cell);
    }
}

void AgentCells::plan(const RenderView& view, const DetailThresholds& thresholds, AgentDrawPlan& plan) const
{
    for (std::vector<InstanceRange>& r : plan.ranges)
        r.clear();
    plan.agents = {};
    plan.culledAgents = 0;
    const float edge = 1.0f + kEdgeMargin;
    for (const Cell& cell : m_cells) {
        // The cell's box with its agents' bodies: radius around, height above.
        const float r = cell.maxRadiusM;
        const float top = cell.maxY + (view.perspective ? bodyHeightM(r) : 0.0f);
        const glm::vec3 lo{cell.min.x - r, cell.minY, cell.min.y - r};
        const glm::vec3 hi{cell.max.x + r, top, cell.max.y + r};
        // Outside when all eight corners lie beyond one clip plane (homogeneous tests,
        // right for corners behind the eye too).
        int outLeft = 0, outRight = 0, outDown = 0, outUp = 0, outNear = 0, outFar = 0;
        float minW = 1e30f;
        for (int k = 0; k < 8; ++k) {
            const glm::vec4 p{(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z, 1.0f};
            const glm::vec4 c = view.viewProjection * p;
            outLeft += c.x < -edge * c.w;
            outRight += c.x > edge * c.w;
            outDown += c.y < -edge * c.w;
            outUp += c.y > edge * c.w;
            outNear += c.z < -c.w;
            outFar += c.z > c.w;
            minW = std::min(minW, c.w);
        }
        if (outLeft == 8 || outRight == 8 || outDown == 8 || outUp == 8 || outNear == 8 || outFar == 8) {
            plan.culledAgents += cell.count;
            continue;
        }
        // The largest agent of the cell at the cell's nearest corner, in pixels.
        AgentDetail detail = AgentDetail::Detailed;
        if (minW > 0.0f && view.metresPerPixel > 0.0f) {
            const float radiusPx = r / (minW * view.metresPerPixel);
            detail = radiusPx < thresholds.coarseFromPx     ? AgentDetail::Impostor
                     : radiusPx < thresholds.detailedFromPx ? AgentDetail::Coarse
                                                            : AgentDetail::Detailed;
        }
        addRange(plan.ranges[std::size_t(detail)], cell.first, cell.count);
        plan.agents[std::size_t(detail)] += cell.count;
    }
}

}  // namespace throng::editor
