#include "simcore/nav/SketchField.h"

#include "simcore/base/ThreadTeam.h"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

double SketchField::kernel(glm::vec2 a, glm::vec2 b) const
{
    const double dx = double(a.x) - double(b.x), dz = double(a.y) - double(b.y);
    return 1.0 / std::sqrt(1.0 + (dx * dx + dz * dz) * m_invLength2);
}

bool SketchField::solve(std::span<const VectorSample> strokes, std::span<const BoundarySample> boundary,
                        const SketchParams& params)
{
    m_strokes.assign(strokes.begin(), strokes.end());
    m_boundary.assign(boundary.begin(), boundary.end());
    m_strokeWeights.clear();
    m_boundaryWeights.clear();
    m_error.clear();
    if (m_strokes.empty()) {
        m_error = "sketched field: no stroke samples (draw a flow stroke of some length)";
        return false;
    }
    const double l = params.kernelLengthM > 0.0f ? double(params.kernelLengthM) : 1.0;
    m_invLength2 = 1.0 / (l * l);
    // Generalised (Hermite-Birkhoff) interpolation: the unknowns are a vector weight per
    // stroke sample and a weight along the normal per boundary sample, so the matrix is the
    // Gram matrix of the constraints under a positive definite kernel: symmetric positive
    // definite, factorised by Cholesky. Order: x weights, z weights, boundary weights.
    const Eigen::Index s = Eigen::Index(m_strokes.size()), b = Eigen::Index(m_boundary.size()), n = 2 * s + b;
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);  // the x-z coupling blocks stay zero
    Eigen::VectorXd rhs(n);
    for (Eigen::Index i = 0; i < s; ++i) {
        for (Eigen::Index j = 0; j <= i; ++j) {
            const double k = kernel(m_strokes[std::size_t(i)].position, m_strokes[std::size_t(j)].position);
            a(i, j) = k;
            a(s + i, s + j) = k;
        }
        rhs(i) = double(m_strokes[std::size_t(i)].direction.x);
        rhs(s + i) = double(m_strokes[std::size_t(i)].direction.y);
    }
    for (Eigen::Index m = 0; m < b; ++m) {
        const BoundarySample& bm = m_boundary[std::size_t(m)];
        for (Eigen::Index i = 0; i < s; ++i) {
            const double k = kernel(bm.position, m_strokes[std::size_t(i)].position);
            a(2 * s + m, i) = double(bm.normal.x) * k;
            a(2 * s + m, s + i) = double(bm.normal.y) * k;
        }
        for (Eigen::Index j = 0; j <= m; ++j) {
            const BoundarySample& bj = m_boundary[std::size_t(j)];
            a(2 * s + m, 2 * s + j) = double(glm::dot(bm.normal, bj.normal)) * kernel(bm.position, bj.position);
        }
        rhs(2 * s + m) = 0.0;
    }
    a.diagonal().array() += double(std::max(params.ridge, 0.0f));
    const Eigen::LLT<Eigen::MatrixXd, Eigen::Lower> llt(a.selfadjointView<Eigen::Lower>());
    if (llt.info() != Eigen::Success) {
        m_error = "sketched field: the RBF system is not positive definite (repeated samples? raise ridge)";
        return false;
    }
    const Eigen::VectorXd w = llt.solve(rhs);
    m_strokeWeights.resize(std::size_t(s));
    for (Eigen::Index i = 0; i < s; ++i)
        m_strokeWeights[std::size_t(i)] = {w(i), w(s + i)};
    m_boundaryWeights.resize(std::size_t(b));
    for (Eigen::Index m = 0; m < b; ++m)
        m_boundaryWeights[std::size_t(m)] = w(2 * s + m);
    return true;
}

bool SketchField::build(const Scene& scene, const NavGrid& grid, const SketchParams& params)
{
    const std::vector<VectorSample> strokes = strokeSamples(scene.flowStrokes, params.sampleSpacingM);
    const std::vector<BoundarySample> boundary = boundarySamples(navShapes(scene), params.boundarySpacingM, strokes, params.wallReachM);
    if (!solve(strokes, boundary, params))
        return false;
    bake(grid, params.threads);
    return true;
}

glm::vec2 SketchField::evaluate(glm::vec2 p) const
{
    glm::dvec2 v(0.0);
    for (std::size_t i = 0; i < m_strokes.size(); ++i)
        v += m_strokeWeights[i] * kernel(p, m_strokes[i].position);
    for (std::size_t m = 0; m < m_boundary.size(); ++m)
        v += glm::dvec2(m_boundary[m].normal) * (m_boundaryWeights[m] * kernel(p, m_boundary[m].position));
    return glm::vec2(v);
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
            if (!grid.walkable(c) || m_strokes.empty())
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
    const glm::vec2 q = (p - m_grid.origin()) / m_grid.cellM() - 0.5f;
    const int x0 = int(std::floor(q.x)), z0 = int(std::floor(q.y));
    const float fx = q.x - float(x0), fz = q.y - float(z0);
    glm::vec2 sum(0.0f);
    for (int k = 0; k < 4; ++k) {
        const float w = ((k & 1) ? fx : 1.0f - fx) * ((k >> 1) ? fz : 1.0f - fz);
        sum += w * direction({x0 + (k & 1), z0 + (k >> 1)});
    }
    const float len = glm::length(sum);
    if (len > 1e-6f && m_grid.clearAhead(p, sum / len))
        return sum / len;
    const glm::vec2 d = direction(own);
    return glm::length(d) > 0.0f && m_grid.clearAhead(p, d) ? d : glm::vec2(0.0f);
}

}  // namespace throng::sim
