// The kerbs of the lane network as wall segments (LaneNetwork::pedestrianBarriers):
// carriageway edges with openings at crosswalks, and crosswalk sides over the road.
#include "simcore/traffic/LaneNetwork.h"
#include "simcore/traffic/detail/LaneMaths.h"
#include "simcore/traffic/detail/StripClip.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <utility>

namespace throng::sim {

using detail::leftOf;

namespace {
constexpr float kEdgeEps = 1e-3f;  // m: a shared edge between two lanes counts as inside both

// An oriented strip: from o along unit u for len metres, halfWidth either side.
struct Box {
    glm::vec2 o, u;
    float len, halfWidth;
};
using Interval = std::pair<float, float>;

// The part of p0 -> p1 (parameter in [0, 1]) inside the box.
bool clip(glm::vec2 p0, glm::vec2 p1, const Box& box, Interval& out)
{
    float t0 = 0.0f, t1 = 1.0f;
    if (!detail::clipToStrip(p0, p1, box.o, box.u, box.len, box.halfWidth, t0, t1))
        return false;
    out = {t0, t1};
    return t1 > t0;
}

// Sorted, merged union of intervals.
std::vector<Interval> merged(std::vector<Interval> v)
{
    std::sort(v.begin(), v.end());
    std::vector<Interval> out;
    for (const Interval& i : v) {
        if (!out.empty() && i.first <= out.back().second)
            out.back().second = std::max(out.back().second, i.second);
        else
            out.push_back(i);
    }
    return out;
}

void emit(glm::vec2 p0, glm::vec2 p1, const std::vector<Interval>& keep, std::vector<BarrierSegment>& out)
{
    for (const Interval& i : keep)
        if ((i.second - i.first) * glm::distance(p0, p1) > 1e-4f)
            out.push_back({p0 + (p1 - p0) * i.first, p0 + (p1 - p0) * i.second});
}
}  // namespace

std::vector<BarrierSegment> LaneNetwork::pedestrianBarriers() const
{
    struct LaneBox {
        std::size_t lane;
        Box box;
    };
    std::vector<LaneBox> laneBoxes;
    for (std::size_t l = 0; l < m_lanes.size(); ++l) {
        const LaneGeometry& g = m_lanes[l];
        for (std::size_t k = 0; k + 1 < g.points.size(); ++k) {
            const float len = g.cumulative[k + 1] - g.cumulative[k];
            laneBoxes.push_back({l, {g.points[k], (g.points[k + 1] - g.points[k]) / len, len, 0.5f * g.widthM}});
        }
    }
    std::vector<Box> strips;
    for (const CrosswalkStrip& c : m_crosswalks)
        strips.push_back({c.a, c.dir, c.lengthM, c.halfWidthM});

    std::vector<BarrierSegment> out;
    // Carriageway edges, minus crosswalk openings and what other carriageways cover.
    for (std::size_t b = 0; b < laneBoxes.size(); ++b) {
        const Box& own = laneBoxes[b].box;
        for (float side : {1.0f, -1.0f}) {
            const glm::vec2 shift = leftOf(own.u) * (own.halfWidth * side);
            const glm::vec2 p0 = own.o + shift, p1 = own.o + own.u * own.len + shift;
            std::vector<Interval> removed;
            Interval i;
            for (const Box& s : strips)
                if (clip(p0, p1, s, i))
                    removed.push_back(i);
            for (std::size_t o = 0; o < laneBoxes.size(); ++o) {
                if (o == b)
                    continue;
                Box other = laneBoxes[o].box;
                // Another lane's edge on ours is shared road; our own next segment
                // covers only what lies strictly inside it (the inner side of a bend).
                other.halfWidth += laneBoxes[o].lane == laneBoxes[b].lane ? -kEdgeEps : kEdgeEps;
                if (clip(p0, p1, other, i))
                    removed.push_back(i);
            }
            // Kept pieces reach 2 mm past their cut ends, so two kerbs that meet at a
            // corner overlap instead of leaving a hairline gap.
            const float grow = 2.0f * kEdgeEps / own.len;
            std::vector<Interval> keep;
            float at = 0.0f;
            for (const Interval& r : merged(removed)) {
                if (r.first > at)
                    keep.push_back({at > 0.0f ? std::max(0.0f, at - grow) : 0.0f, std::min(1.0f, r.first + grow)});
                at = std::max(at, r.second);
            }
            if (at < 1.0f)
                keep.push_back({at > 0.0f ? std::max(0.0f, at - grow) : 0.0f, 1.0f});
            emit(p0, p1, keep, out);
        }
    }
    // Crosswalk sides where the strip lies over a carriageway: a walker on the crossing
    // cannot step sideways into the road.
    for (const Box& s : strips) {
        for (float side : {1.0f, -1.0f}) {
            const glm::vec2 shift = leftOf(s.u) * (s.halfWidth * side);
            const glm::vec2 p0 = s.o + shift, p1 = s.o + s.u * s.len + shift;
            std::vector<Interval> inside;
            Interval i;
            for (const LaneBox& lb : laneBoxes) {
                Box grown = lb.box;
                grown.halfWidth += kEdgeEps;  // meet the kerb edge exactly at the corner
                if (clip(p0, p1, grown, i))
                    inside.push_back(i);
            }
            emit(p0, p1, merged(inside), out);
        }
    }
    return out;
}

}  // namespace throng::sim
