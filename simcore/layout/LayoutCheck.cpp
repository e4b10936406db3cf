#include "simcore/layout/LayoutCheck.h"

#include "simcore/layout/LayoutGrid.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <limits>

namespace throng::sim {

namespace {

bool unchangedFrame(const AgentFrame& a, const AgentFrame& b)
{
    return a.position == b.position && a.headingRad == b.headingRad && a.present == b.present && a.out == b.out &&
           a.speed == b.speed && a.clip == b.clip;
}

bool inShot(const AgentFrame& a) { return a.present && !a.out; }

glm::vec2 placeOf(const AgentFrame& a) { return {a.position.x, a.position.z}; }

// Whether the step p0-p1 crosses the wall q0-q1: it ends on it or beyond (a step that only
// starts on it was counted as the one before, which ended there).
bool crosses(glm::vec2 p0, glm::vec2 p1, glm::vec2 q0, glm::vec2 q1)
{
    auto cross = [](glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; };
    const glm::vec2 r = p1 - p0, s = q1 - q0;
    const float denominator = cross(r, s);
    if (std::abs(denominator) < 1e-12f)
        return false;  // parallel: a step along a wall does not go through it
    const float t = cross(q0 - p0, s) / denominator, u = cross(q0 - p0, r) / denominator;
    return t > 0.0f && t <= 1.0f && u >= 0.0f && u <= 1.0f;
}

struct WallPiece {
    glm::vec2 a, b;
    std::string wall;
};

// The wall a step crosses, or nullptr.
const WallPiece* crossedWall(const std::vector<WallPiece>& walls, glm::vec2 from, glm::vec2 to)
{
    if (from == to)
        return nullptr;
    for (const WallPiece& w : walls)
        if (crosses(from, to, w.a, w.b))
            return &w;
    return nullptr;
}

// Pairs of shown agents closer than their radii allow less `tolerance` on frame f of
// `laid`, at least one of them `wanted`, that the recording did not have so: (i, j) with
// i < j, and how deep, in pair order. Only the bodies near a wanted one are gridded.
struct Overlap {
    std::size_t i = 0, j = 0;
    float depth = 0.0f;
};
void newOverlapsOn(const FrameCache& laid, const FrameCache& recorded, std::size_t f, const std::vector<float>& radius,
                   const std::vector<std::uint8_t>& wanted, float tolerance, std::vector<Overlap>& out)
{
    out.clear();
    const std::size_t n = laid.agentCount(), recordedCount = recorded.agentCount();
    const std::span<const AgentFrame> now = laid.frame(f);
    std::vector<std::uint32_t> checked;
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (std::size_t i = 0; i < n; ++i)
        if (wanted[i] && inShot(now[i])) {
            checked.push_back(std::uint32_t(i));
            lo = glm::min(lo, placeOf(now[i]));
            hi = glm::max(hi, placeOf(now[i]));
        }
    if (checked.empty())
        return;
    float largest = 0.0f;
    for (const float r : radius)
        largest = std::max(largest, r);
    const float cell = std::max(2.0f * largest, 0.1f);
    lo -= glm::vec2(cell);
    hi += glm::vec2(cell);
    std::vector<std::uint32_t> near;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec2 p = placeOf(now[i]);
        if (inShot(now[i]) && p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y)
            near.push_back(std::uint32_t(i));
    }
    layout::CellGrid grid = layout::CellGrid::fitting(lo, hi, cell, near.size());
    grid.build(now, near);
    const std::span<const AgentFrame> then = recorded.frame(f);
    for (const std::uint32_t i : checked) {
        const glm::vec2 p = placeOf(now[i]);
        grid.forNear(p, [&](std::size_t j) {
            if (j == i || (wanted[j] && j < i))  // a pair of wanted agents once, from its lower index
                return;
            const float depth = radius[i] + radius[j] - glm::length(p - placeOf(now[j]));
            if (!(depth > tolerance))
                return;
            // The recording's own overlap is the simulation's, not the edits'.
            if (i < recordedCount && j < recordedCount && inShot(then[i]) && inShot(then[j]) &&
                radius[i] + radius[j] - glm::length(placeOf(then[i]) - placeOf(then[j])) > tolerance)
                return;
            out.push_back({std::min<std::size_t>(i, j), std::max<std::size_t>(i, j), depth});
        });
    }
    std::sort(out.begin(), out.end(),
              [](const Overlap& a, const Overlap& b) { return std::tie(a.i, a.j) < std::tie(b.i, b.j); });
}

}  // namespace

LayoutCheck checkLayout(const Scene& scene, const FrameCache& recorded, const FrameCache& laid, float toleranceM)
{
    LayoutCheck check;
    const std::size_t frames = std::min(recorded.frameCount(), laid.frameCount());
    const std::size_t n = laid.agentCount(), recordedCount = recorded.agentCount();
    if (recordedCount > n || frames == 0)
        return check;
    // The laid-out agents past the recording's are copies a duplicate made: edited.
    std::vector<std::uint8_t> edited(n, 0);
    std::fill(edited.begin() + std::ptrdiff_t(recordedCount), edited.end(), 1);
    for (std::size_t f = 0; f < frames; ++f)
        for (std::size_t i = 0; i < recordedCount; ++i)
            if (!edited[i] && !unchangedFrame(recorded.at(f, i), laid.at(f, i)))
                edited[i] = 1;
    if (std::find(edited.begin(), edited.end(), 1) == edited.end())
        return check;
    std::vector<float> radius(n, 0.3f);
    for (std::size_t i = 0; i < n; ++i)
        if (laid.agents()[i].typeIndex < scene.agentTypes.size())
            radius[i] = scene.agentTypes[laid.agents()[i].typeIndex].radiusM;
    std::vector<WallPiece> walls;
    const glm::vec2 shift(float(laid.origin().x), float(laid.origin().z));
    for (std::size_t w = 0; w < scene.walls.size(); ++w)
        for (std::size_t k = 0; k + 1 < scene.walls[w].points.size(); ++k)
            walls.push_back({scene.walls[w].points[k] - shift, scene.walls[w].points[k + 1] - shift,
                             scene.walls[w].name.empty() ? "wall " + std::to_string(w + 1) : scene.walls[w].name});

    std::set<std::size_t> clashFrames;
    std::vector<Overlap> overlaps;
    for (std::size_t f = 0; f < frames; ++f) {
        newOverlapsOn(laid, recorded, f, radius, edited, toleranceM, overlaps);
        for (const Overlap& o : overlaps) {
            const std::size_t a = edited[o.i] ? o.i : o.j;
            const std::size_t b = a == o.i ? o.j : o.i;
            check.overlaps.push_back({f, laid.agents()[a].id, laid.agents()[b].id, {}, o.depth});
            clashFrames.insert(f);
        }
        if (f == 0 || walls.empty())
            continue;
        for (std::size_t i = 0; i < n; ++i) {
            if (!edited[i] || !inShot(laid.at(f, i)) || !inShot(laid.at(f - 1, i)))
                continue;
            const WallPiece* wall = crossedWall(walls, placeOf(laid.at(f - 1, i)), placeOf(laid.at(f, i)));
            if (!wall)
                continue;
            const bool recordedToo = i < recordedCount && inShot(recorded.at(f, i)) && inShot(recorded.at(f - 1, i)) &&
                                     crossedWall(walls, placeOf(recorded.at(f - 1, i)), placeOf(recorded.at(f, i)));
            if (recordedToo)
                continue;
            check.wallCrossings.push_back({f, laid.agents()[i].id, 0, wall->wall, 0.0f});
            clashFrames.insert(f);
        }
    }
    check.frames = clashFrames.size();
    return check;
}

std::vector<LayoutClashSpan> clashSpans(const LayoutCheck& check, std::size_t max)
{
    // Open runs by what clashes: (agent, other, wall).
    std::map<std::tuple<AgentId, AgentId, std::string>, LayoutClashSpan> open;
    std::vector<LayoutClashSpan> spans;
    auto take = [&](const LayoutClash& c) {
        const auto key = std::make_tuple(c.agent, c.other, c.wall);
        const auto it = open.find(key);
        if (it != open.end() && it->second.last + 1 >= c.frame) {
            it->second.last = c.frame;
            it->second.deepestM = std::max(it->second.deepestM, c.depthM);
            return;
        }
        if (it != open.end())
            spans.push_back(it->second);
        open[key] = {c.frame, c.frame, c.agent, c.other, c.wall, c.depthM};
    };
    for (const LayoutClash& c : check.overlaps)
        take(c);
    for (const LayoutClash& c : check.wallCrossings)
        take(c);
    for (const auto& [key, span] : open)
        spans.push_back(span);
    std::sort(spans.begin(), spans.end(), [](const LayoutClashSpan& a, const LayoutClashSpan& b) {
        return std::tie(a.first, a.agent, a.other, a.wall) < std::tie(b.first, b.agent, b.other, b.wall);
    });
    if (spans.size() > max)
        spans.resize(max);
    return spans;
}

std::string describe(const LayoutCheck& check)
{
    if (check.overlaps.empty() && check.wallCrossings.empty())
        return {};
    auto count = [](std::size_t n, const char* one, const char* many) {
        return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    std::string text = count(check.overlaps.size(), "overlap", "overlaps") + " and " +
                       count(check.wallCrossings.size(), "wall crossing", "wall crossings") + " on " +
                       count(check.frames, "frame", "frames");
    const bool overlapFirst = !check.overlaps.empty() &&
                              (check.wallCrossings.empty() || check.overlaps[0].frame <= check.wallCrossings[0].frame);
    const LayoutClash& first = overlapFirst ? check.overlaps[0] : check.wallCrossings[0];
    text += " (first: frame " + std::to_string(first.frame) + ", agent " + std::to_string(first.agent) +
            (first.other ? " and agent " + std::to_string(first.other) : " through " + first.wall) + ")";
    return text;
}

}  // namespace throng::sim
