#include "simcore/nav/SketchField.h"

#include "simcore/base/ThreadTeam.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

bool SketchField::solve(std::span<const VectorSample> strokes, std::span<const BoundarySample> boundary,
                        const SketchParams& params, glm::vec2 domainMin, glm::vec2 domainMax)
{
    m_strokeCount = strokes.size();
    m_boundaryCount = boundary.size();
    m_error.clear();
    if (strokes.empty()) {
        m_solution = {};
        m_error = "sketched field: no stroke samples (draw a flow stroke of some length)";
        return false;
    }
    if (!m_solution.solve(strokes, boundary, double(params.kernelLengthM), double(params.ridge), domainMin, domainMax,
                          params.threads)) {
        m_error = m_solution.error();
        return false;
    }
    return true;
}

bool SketchField::build(const Scene& scene, const NavGrid& grid, const SketchParams& params)
{
    const std::vector<VectorSample> strokes = strokeSamples(scene.flowStrokes, params.sampleSpacingM);
    const std::vector<BoundarySample> boundary =
        boundarySamples(navShapes(scene), params.boundarySpacingM, strokes, params.wallReachM);
    if (!solve(strokes, boundary, params, grid.origin(),
               grid.origin() + grid.cellM() * glm::vec2(float(grid.cols()), float(grid.rows()))))
        return false;
    bake(grid, params.threads);
    return true;
}

glm::vec2 SketchField::evaluate(glm::vec2 p) const
{
    return m_solution.evaluate(p);
}

void SketchField::bake(const NavGrid& grid, int threads)
{
    m_grid = grid;
    const int cols = grid.cols(), rows = grid.rows();
    m_dir.assign(std::size_t(grid.cellCount()), glm::vec2(0.0f));
    m_strength.assign(std::size_t(grid.cellCount()), 0.0f);
    const ThreadTeam team(threads);
    team.forEach(std::size_t(rows), 1, [&](std::size_t row) {
        const int z = int(row);
        for (int x = 0; x < cols; ++x) {
            const NavCell c{x, z};
            if (!grid.walkable(c) || m_strokeCount == 0)
                continue;
            const glm::vec2 centre = grid.centre(c);
            const glm::vec2 v = evaluate(centre);
            const float len = glm::length(v);
            const std::size_t i = std::size_t(grid.index(c));
            m_strength[i] = len;
            if (len <= 1e-6f)
                continue;
            glm::vec2 d = v / len;
            if (!grid.clearAhead(centre, d)) {
                // Near a wall the interpolant can still lean into it between boundary samples:
                // of the directions that stay clear, keep the one nearest to the field's.
                glm::vec2 away(0.0f);
                for (int dz = -1; dz <= 1; ++dz)
                    for (int dx = -1; dx <= 1; ++dx)
                        if ((dx != 0 || dz != 0) && !grid.walkable({x + dx, z + dz}))
                            away -= glm::normalize(glm::vec2(float(dx), float(dz)));
                glm::vec2 best(0.0f);
                float bestDot = 0.0f;
                auto consider = [&](glm::vec2 cand) {
                    const float l = glm::length(cand);
                    if (l <= 1e-6f)
                        return;
                    cand /= l;
                    if (glm::dot(cand, d) > bestDot && grid.clearAhead(centre, cand)) {
                        best = cand;
                        bestDot = glm::dot(cand, d);
                    }
                };
                if (glm::length(away) > 1e-6f) {
                    const glm::vec2 n = glm::normalize(away);
                    consider(d - n * std::min(glm::dot(d, n), 0.0f));
                }
                for (int k = 0; k < 16; ++k) {
                    const float a = 6.2831853f * float(k) / 16.0f;
                    consider({std::cos(a), std::sin(a)});
                }
                d = best;
            }
            m_dir[i] = d;
        }
    });
}

glm::vec2 SketchField::direction(NavCell c) const
{
    return m_grid.inside(c) ? m_dir[std::size_t(m_grid.index(c))] : glm::vec2(0.0f);
}

float SketchField::strength(NavCell c) const
{
    return m_grid.inside(c) ? m_strength[std::size_t(m_grid.index(c))] : 0.0f;
}

glm::vec2 SketchField::sample(glm::vec2 p) const
{
    const NavCell own = m_grid.cellOf(p);
    if (!m_grid.walkable(own))
        return glm::vec2(0.0f);
    const glm::vec2 sum = m_grid.blendAtCentres(p, [&](NavCell c) { return direction(c); });
    const float len = glm::length(sum);
    if (len > 1e-6f && m_grid.clearAhead(p, sum / len))
        return sum / len;
    const glm::vec2 d = direction(own);
    return glm::length(d) > 0.0f && m_grid.clearAhead(p, d) ? d : glm::vec2(0.0f);
}

}  // namespace throng::sim
