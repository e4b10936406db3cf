#include "editor/viewport/DensityHeatmap.h"

#include "simcore/world/LocalDensity.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace throng::editor {

namespace {

constexpr std::array<DensityHeatmap::ScaleStop, 5> kScale{{
    {0.0f, {0.15f, 0.35f, 1.00f, 0.00f}},
    {1.0f, {0.15f, 0.35f, 1.00f, 0.50f}},
    {2.0f, {0.20f, 0.80f, 0.30f, 0.55f}},
    {4.0f, {1.00f, 0.90f, 0.20f, 0.60f}},
    {6.0f, {1.00f, 0.15f, 0.10f, 0.65f}},
}};

constexpr float kInvisibleAlpha = 0.5f / 255.0f;  // rounds to nothing in an 8-bit target

// std::floor and std::ceil are library calls without SSE4.1, four per agent. For any v
// well inside int's range.
int floorToInt(float v)
{
    const int t = int(v);
    return t - (float(t) > v ? 1 : 0);
}
int ceilToInt(float v)
{
    const int t = int(v);
    return t + (float(t) < v ? 1 : 0);
}

}  // namespace

std::span<const DensityHeatmap::ScaleStop> DensityHeatmap::scale()
{
    return kScale;
}

glm::vec4 DensityHeatmap::colourFor(float densityPerM2)
{
    if (!(densityPerM2 > kScale.front().density))
        return kScale.front().colour;
    for (std::size_t i = 1; i < kScale.size(); ++i)
        if (densityPerM2 < kScale[i].density) {
            const ScaleStop &a = kScale[i - 1], &b = kScale[i];
            // Not glm::mix (a (1 - t) + b t): it rounds a channel two stops share up and down.
            return a.colour + (b.colour - a.colour) * ((densityPerM2 - a.density) / (b.density - a.density));
        }
    return kScale.back().colour;
}

void DensityHeatmap::build(std::span<const glm::vec3> positions, glm::vec2 boundsMin, glm::vec2 boundsMax, float cellM)
{
    reset(boundsMin, boundsMax, cellM);
    for (const glm::vec3& p : positions)
        splat({p.x, p.z});
    finish();
}

void DensityHeatmap::build(std::span<const sim::AgentFrame> frame, glm::vec2 boundsMin, glm::vec2 boundsMax, float cellM)
{
    reset(boundsMin, boundsMax, cellM);
    for (const sim::AgentFrame& a : frame)
        if (a.present && !a.out)
            splat({a.position.x, a.position.z});
    finish();
}

void DensityHeatmap::reset(glm::vec2 boundsMin, glm::vec2 boundsMax, float cellM)
{
    glm::vec2 extent = boundsMax - boundsMin;
    extent = std::isfinite(extent.x) && std::isfinite(extent.y) ? glm::max(extent, glm::vec2(0.0f)) : glm::vec2(0.0f);
    double cell = cellM > 0.0f && std::isfinite(cellM) ? std::max(double(cellM), double(kMinCellM)) : double(kDefaultCellM);
    auto count = [&](double c) {
        return std::max(1.0, std::ceil(double(extent.x) / c)) * std::max(1.0, std::ceil(double(extent.y) / c));
    };
    const double maxCells = double(kMaxCells);
    if (count(cell) > maxCells)
        cell *= std::sqrt(count(cell) / maxCells);
    // ceil() can still leave a row or column too many.
    while (count(cell) > maxCells)
        cell *= 1.01;
    m_origin = boundsMin;
    m_cellM = float(cell);
    m_cols = int(std::max(1.0, std::ceil(double(extent.x) / cell)));
    m_rows = int(std::max(1.0, std::ceil(double(extent.y) / cell)));
    m_density.assign(std::size_t(m_cols) * std::size_t(m_rows), 0.0f);

    m_sigmaM = std::max(sim::kDensitySigmaM, 0.5f * m_cellM);
    m_reachM = 3.0f * m_sigmaM;
    // LocalDensity's normalisation: the kernel cut at 3 sigma still holds one person.
    m_norm = 1.0f / (std::numbers::pi_v<float> * 2.0f * m_sigmaM * m_sigmaM * (1.0f - std::exp(-4.5f)));
    m_max = 0.0f;
}

void DensityHeatmap::splat(glm::vec2 p)
{
    // exp(-(dx² + dz²) / 2σ²) = exp(-dx² / 2σ²) exp(-dz² / 2σ²): one exponential per
    // column and per row instead of one per cell.
    const float reachCells = m_reachM / m_cellM;
    const float fx = (p.x - m_origin.x) / m_cellM - 0.5f, fz = (p.y - m_origin.y) / m_cellM - 0.5f;
    if (!(fx + reachCells >= 0.0f && fx - reachCells <= float(m_cols - 1) && fz + reachCells >= 0.0f &&
          fz - reachCells <= float(m_rows - 1)))
        return;  // also every NaN
    const int x0 = std::max(0, ceilToInt(fx - reachCells)), x1 = std::min(m_cols - 1, floorToInt(fx + reachCells));
    const int z0 = std::max(0, ceilToInt(fz - reachCells)), z1 = std::min(m_rows - 1, floorToInt(fz + reachCells));
    // At kMinCellM an agent reaches 13 cells per axis (floor(2 * 6) + 1).
    std::array<float, 16> dx2, wx, dz2, wz;
    const float inv2s2 = 1.0f / (2.0f * m_sigmaM * m_sigmaM), reach2 = m_reachM * m_reachM;
    for (int x = x0; x <= x1; ++x) {
        const float d = (float(x) - fx) * m_cellM;
        dx2[std::size_t(x - x0)] = d * d;
        wx[std::size_t(x - x0)] = std::exp(-d * d * inv2s2);
    }
    for (int z = z0; z <= z1; ++z) {
        const float d = (float(z) - fz) * m_cellM;
        dz2[std::size_t(z - z0)] = d * d;
        wz[std::size_t(z - z0)] = std::exp(-d * d * inv2s2);
    }
    for (int z = z0; z <= z1; ++z) {
        const float rowDz2 = dz2[std::size_t(z - z0)], rowWz = wz[std::size_t(z - z0)];
        float* row = &m_density[std::size_t(z) * std::size_t(m_cols)];
        for (int x = x0; x <= x1; ++x)
            if (dx2[std::size_t(x - x0)] + rowDz2 < reach2)
                row[x] += wx[std::size_t(x - x0)] * rowWz;
    }
}

void DensityHeatmap::finish()
{
    m_max = 0.0f;
    for (float& d : m_density) {
        d *= m_norm;
        m_max = std::max(m_max, d);
    }
}

float DensityHeatmap::densityAt(glm::vec2 p) const
{
    const float fx = std::floor((p.x - m_origin.x) / m_cellM), fz = std::floor((p.y - m_origin.y) / m_cellM);
    if (!(fx >= 0.0f && fz >= 0.0f && fx < float(m_cols) && fz < float(m_rows)))
        return 0.0f;
    return m_density[std::size_t(fz) * std::size_t(m_cols) + std::size_t(fx)];
}

void DensityHeatmap::addCells(ShapeMesh& mesh) const
{
    for (int z = 0; z < m_rows; ++z)
        for (int x = 0; x < m_cols; ++x) {
            const glm::vec4 colour = colourFor(m_density[std::size_t(z) * std::size_t(m_cols) + std::size_t(x)]);
            if (colour.a < kInvisibleAlpha)
                continue;
            const glm::vec2 lo = m_origin + glm::vec2(float(x), float(z)) * m_cellM, hi = lo + m_cellM;
            const std::array<glm::vec2, 4> quad{lo, glm::vec2(hi.x, lo.y), hi, glm::vec2(lo.x, hi.y)};
            mesh.addConvexPolygon(quad, colour);
        }
}

}  // namespace throng::editor
