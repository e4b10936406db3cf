#include "simcore/nav/SketchPatches.h"

#include "simcore/base/ThreadTeam.h"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace throng::sim {

namespace {

// Up to this many constraints (2 per stroke sample, 1 per boundary sample) the field is
// one global solve, exactly the interpolant of Jin et al.: 1,600 unknowns factorise in
// a fraction of a second.
constexpr std::size_t kGlobalConstraints = 1600;
// A quadtree cell splits while its patch sees more samples than this.
constexpr std::size_t kPatchSamples = 240;
// A patch's support is this times its cell's half-diagonal, so neighbours overlap and
// every point of a cell has a weight.
constexpr double kOverlap = 1.3;
// A patch that sees fewer samples takes the nearest ones instead (open areas far from
// every stroke still get the strokes' direction, as the global interpolant gives).
constexpr std::size_t kMinPatchSamples = 24;
// Cells stop splitting at this many kernel lengths; a cell that small still seeing more
// than kMaxPatchSamples (strokes drawn over one another) keeps an even spread of them.
constexpr double kMinCellKernels = 1.0;
constexpr std::size_t kMaxPatchSamples = 720;
constexpr int kMaxDepth = 48;
constexpr int kMaxBucketsPerAxis = 512;

// Wendland's C2 function of r = distance / support: smooth, 1 at the centre, 0 from r = 1.
double wendland(double r)
{
    if (r >= 1.0)
        return 0.0;
    const double q = 1.0 - r;
    return q * q * q * q * (4.0 * r + 1.0);
}

}  // namespace

double SketchPatches::kernel(glm::vec2 a, glm::vec2 b) const
{
    const double dx = double(a.x) - double(b.x), dz = double(a.y) - double(b.y);
    return 1.0 / std::sqrt(1.0 + (dx * dx + dz * dz) * m_invLength2);
}

bool SketchPatches::solve(std::span<const VectorSample> strokes, std::span<const BoundarySample> boundary,
                          double kernelLengthM, double ridge, glm::vec2 domainMin, glm::vec2 domainMax, int threads)
{
    m_strokes.assign(strokes.begin(), strokes.end());
    m_boundary.assign(boundary.begin(), boundary.end());
    m_patches.clear();
    m_error.clear();
    const double l = kernelLengthM > 0.0 ? kernelLengthM : 1.0;
    m_invLength2 = 1.0 / (l * l);
    const std::size_t total = m_strokes.size() + m_boundary.size();
    std::vector<std::uint32_t> all(total);
    std::iota(all.begin(), all.end(), 0u);

    glm::dvec2 lo(domainMin), hi(domainMax);
    for (const VectorSample& s : m_strokes) {
        lo = glm::min(lo, glm::dvec2(s.position));
        hi = glm::max(hi, glm::dvec2(s.position));
    }
    for (const BoundarySample& b : m_boundary) {
        lo = glm::min(lo, glm::dvec2(b.position));
        hi = glm::max(hi, glm::dvec2(b.position));
    }
    const double size = std::max({hi.x - lo.x, hi.y - lo.y, 1.0});
    if (2 * m_strokes.size() + m_boundary.size() <= kGlobalConstraints)
        addPatch(lo + 0.5 * glm::dvec2(size), 0.0, all);
    else
        split(lo, size, std::move(all), 0);

    std::vector<std::string> errors(m_patches.size());
    // Each patch is its own solve, written only to its own entry: the same for any threads.
    const ThreadTeam team(threads);
    team.forEach(m_patches.size(), 1,
                 [&](std::size_t k) { solvePatch(m_patches[k], std::max(ridge, 0.0), errors[k]); });
    for (const std::string& e : errors)
        if (!e.empty()) {
            m_error = e;
            m_patches.clear();
            return false;
        }
    m_bucketMin = lo;
    double smallest = size;
    for (const Patch& p : m_patches)
        if (p.radius > 0.0)
            smallest = std::min(smallest, p.radius);
    const double bucket = std::max(smallest, size / kMaxBucketsPerAxis);
    m_bucketInv = 1.0 / bucket;
    m_bucketCols = std::clamp(int(std::ceil(size * m_bucketInv)), 1, kMaxBucketsPerAxis);
    m_bucketRows = m_bucketCols;
    index();
    return true;
}

void SketchPatches::split(glm::dvec2 lo, double size, std::vector<std::uint32_t>&& members, int depth)
{
    const glm::dvec2 centre = lo + 0.5 * glm::dvec2(size);
    const double radius = kOverlap * size * 0.5 * std::sqrt(2.0);
    // A child's support lies inside its parent's, so the parent's members are the child's
    // candidates.
    std::vector<std::uint32_t> seen;
    for (std::uint32_t i : members) {
        const glm::vec2 p = i < m_strokes.size() ? m_strokes[i].position : m_boundary[i - m_strokes.size()].position;
        if (glm::distance(glm::dvec2(p), centre) <= radius)
            seen.push_back(i);
    }
    members.clear();
    members.shrink_to_fit();
    if (seen.size() <= kPatchSamples || size <= kMinCellKernels / std::sqrt(m_invLength2) || depth >= kMaxDepth) {
        addPatch(centre, radius, seen);
        return;
    }
    const double half = 0.5 * size;
    for (int q = 0; q < 4; ++q)
        split(lo + glm::dvec2((q & 1) ? half : 0.0, (q >> 1) ? half : 0.0), half, std::vector<std::uint32_t>(seen),
              depth + 1);
}

void SketchPatches::addPatch(glm::dvec2 centre, double radius, const std::vector<std::uint32_t>& members)
{
    const auto position = [&](std::uint32_t i) {
        return glm::dvec2(i < m_strokes.size() ? m_strokes[i].position : m_boundary[i - m_strokes.size()].position);
    };
    std::vector<std::uint32_t> chosen = members;
    if (chosen.size() > kMaxPatchSamples) {
        std::vector<std::uint32_t> even;
        for (std::size_t k = 0; k < kMaxPatchSamples; ++k)
            even.push_back(chosen[k * chosen.size() / kMaxPatchSamples]);
        chosen = std::move(even);
    }
    std::size_t strokeCount = 0;
    for (std::uint32_t i : chosen)
        strokeCount += i < m_strokes.size();
    if (strokeCount == 0 || chosen.size() < kMinPatchSamples) {
        // Nearest samples (ties by index), so the patch carries the strokes' direction.
        std::vector<std::uint32_t> byDistance(m_strokes.size() + m_boundary.size());
        std::iota(byDistance.begin(), byDistance.end(), 0u);
        const std::size_t k = std::min(kMinPatchSamples, byDistance.size());
        const auto closer = [&](std::uint32_t a, std::uint32_t b) {
            const double da = glm::distance(position(a), centre), db = glm::distance(position(b), centre);
            return da < db || (da == db && a < b);
        };
        std::partial_sort(byDistance.begin(), byDistance.begin() + std::ptrdiff_t(k), byDistance.end(), closer);
        chosen.assign(byDistance.begin(), byDistance.begin() + std::ptrdiff_t(k));
        std::sort(chosen.begin(), chosen.end());
        if (std::none_of(chosen.begin(), chosen.end(), [&](std::uint32_t i) { return i < m_strokes.size(); })) {
            // Only walls near: the nearest stroke sample too, or the patch would be all zero.
            std::uint32_t best = 0;
            for (std::uint32_t i = 1; i < m_strokes.size(); ++i)
                if (closer(i, best))
                    best = i;
            chosen.insert(chosen.begin(), best);
        }
    }
    Patch p;
    p.centre = centre;
    p.radius = radius;
    for (std::uint32_t i : chosen)
        (i < m_strokes.size() ? p.strokes : p.boundary)
            .push_back(i < m_strokes.size() ? i : i - std::uint32_t(m_strokes.size()));
    m_patches.push_back(std::move(p));
}

bool SketchPatches::solvePatch(Patch& patch, double ridge, std::string& error) const
{
    // Generalised (Hermite-Birkhoff) interpolation: the unknowns are a vector weight per
    // stroke sample and a weight along the normal per boundary sample, so the matrix is the
    // Gram matrix of the constraints under a positive definite kernel: symmetric positive
    // definite, factorised by Cholesky. Order: x weights, z weights, boundary weights.
    const Eigen::Index s = Eigen::Index(patch.strokes.size()), b = Eigen::Index(patch.boundary.size()), n = 2 * s + b;
    const auto stroke = [&](Eigen::Index i) -> const VectorSample& { return m_strokes[patch.strokes[std::size_t(i)]]; };
    const auto wall = [&](Eigen::Index i) -> const BoundarySample& {
        return m_boundary[patch.boundary[std::size_t(i)]];
    };
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);  // the x-z coupling blocks stay zero
    Eigen::VectorXd rhs(n);
    for (Eigen::Index i = 0; i < s; ++i) {
        for (Eigen::Index j = 0; j <= i; ++j) {
            const double k = kernel(stroke(i).position, stroke(j).position);
            a(i, j) = k;
            a(s + i, s + j) = k;
        }
        rhs(i) = double(stroke(i).direction.x);
        rhs(s + i) = double(stroke(i).direction.y);
    }
    for (Eigen::Index m = 0; m < b; ++m) {
        const BoundarySample& bm = wall(m);
        for (Eigen::Index i = 0; i < s; ++i) {
            const double k = kernel(bm.position, stroke(i).position);
            a(2 * s + m, i) = double(bm.normal.x) * k;
            a(2 * s + m, s + i) = double(bm.normal.y) * k;
        }
        for (Eigen::Index j = 0; j <= m; ++j) {
            const BoundarySample& bj = wall(j);
            a(2 * s + m, 2 * s + j) = double(glm::dot(bm.normal, bj.normal)) * kernel(bm.position, bj.position);
        }
        rhs(2 * s + m) = 0.0;
    }
    a.diagonal().array() += ridge;
    const Eigen::LLT<Eigen::MatrixXd, Eigen::Lower> llt(a.selfadjointView<Eigen::Lower>());
    if (llt.info() != Eigen::Success) {
        error = "sketched field: the RBF system is not positive definite (repeated samples? raise ridge)";
        return false;
    }
    const Eigen::VectorXd w = llt.solve(rhs);
    if (!w.allFinite()) {
        error = "sketched field: the RBF system has no finite solution (samples at extreme coordinates?)";
        return false;
    }
    patch.strokeWeights.resize(std::size_t(s));
    for (Eigen::Index i = 0; i < s; ++i)
        patch.strokeWeights[std::size_t(i)] = {w(i), w(s + i)};
    patch.boundaryWeights.resize(std::size_t(b));
    for (Eigen::Index m = 0; m < b; ++m)
        patch.boundaryWeights[std::size_t(m)] = w(2 * s + m);
    return true;
}

void SketchPatches::index()
{
    const std::size_t buckets = std::size_t(m_bucketCols) * std::size_t(m_bucketRows);
    std::vector<std::uint32_t> count(buckets + 1, 0);
    const auto visit = [&](const Patch& p, auto&& f) {
        if (p.radius <= 0.0) {
            for (std::size_t c = 0; c < buckets; ++c)
                f(c);
            return;
        }
        const auto cell = [&](double v, double origin, int n) {
            return std::clamp(int(std::floor((v - origin) * m_bucketInv)), 0, n - 1);
        };
        const int x0 = cell(p.centre.x - p.radius, m_bucketMin.x, m_bucketCols),
                  x1 = cell(p.centre.x + p.radius, m_bucketMin.x, m_bucketCols);
        const int z0 = cell(p.centre.y - p.radius, m_bucketMin.y, m_bucketRows),
                  z1 = cell(p.centre.y + p.radius, m_bucketMin.y, m_bucketRows);
        for (int z = z0; z <= z1; ++z)
            for (int x = x0; x <= x1; ++x)
                f(std::size_t(z) * std::size_t(m_bucketCols) + std::size_t(x));
    };
    for (const Patch& p : m_patches)
        visit(p, [&](std::size_t c) { ++count[c + 1]; });
    for (std::size_t c = 1; c < count.size(); ++c)
        count[c] += count[c - 1];
    m_bucketStart = count;
    m_bucketItems.resize(count.back());
    for (std::uint32_t k = 0; k < m_patches.size(); ++k)
        visit(m_patches[k], [&](std::size_t c) { m_bucketItems[count[c]++] = k; });
}

glm::dvec2 SketchPatches::evaluatePatch(const Patch& patch, glm::vec2 p) const
{
    glm::dvec2 v(0.0);
    for (std::size_t i = 0; i < patch.strokes.size(); ++i)
        v += patch.strokeWeights[i] * kernel(p, m_strokes[patch.strokes[i]].position);
    for (std::size_t m = 0; m < patch.boundary.size(); ++m) {
        const BoundarySample& b = m_boundary[patch.boundary[m]];
        v += glm::dvec2(b.normal) * (patch.boundaryWeights[m] * kernel(p, b.position));
    }
    return v;
}

glm::vec2 SketchPatches::evaluate(glm::vec2 p) const
{
    if (m_patches.empty())
        return glm::vec2(0.0f);
    if (m_patches.size() == 1)
        return glm::vec2(evaluatePatch(m_patches[0], p));
    const glm::dvec2 q(p);
    const auto cell = [&](double v, double origin, int n) {
        const double c = std::floor((v - origin) * m_bucketInv);
        return c != c ? 0 : int(std::clamp(c, 0.0, double(n - 1)));
    };
    const std::size_t c = std::size_t(cell(q.y, m_bucketMin.y, m_bucketRows)) * std::size_t(m_bucketCols) +
                          std::size_t(cell(q.x, m_bucketMin.x, m_bucketCols));
    glm::dvec2 sum(0.0);
    double weights = 0.0, nearest = INFINITY;
    std::uint32_t fallback = 0;
    const auto consider = [&](std::uint32_t k) {
        const Patch& patch = m_patches[k];
        const double r = glm::distance(q, patch.centre) / patch.radius;
        if (r < nearest) {
            nearest = r;
            fallback = k;
        }
        const double w = wendland(r);
        if (w > 0.0) {
            sum += w * evaluatePatch(patch, p);
            weights += w;
        }
    };
    for (std::uint32_t k = m_bucketStart[c]; k < m_bucketStart[c + 1]; ++k)
        consider(m_bucketItems[k]);
    if (weights > 0.0)
        return glm::vec2(sum / weights);
    // Outside every support (far outside the domain): the nearest patch's own fit.
    if (m_bucketStart[c] == m_bucketStart[c + 1])
        for (std::uint32_t k = 0; k < m_patches.size(); ++k) {
            const double r = glm::distance(q, m_patches[k].centre) / m_patches[k].radius;
            if (r < nearest) {
                nearest = r;
                fallback = k;
            }
        }
    return glm::vec2(evaluatePatch(m_patches[fallback], p));
}

}  // namespace throng::sim
