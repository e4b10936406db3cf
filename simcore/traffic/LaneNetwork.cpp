#include "simcore/traffic/LaneNetwork.h"
#include "simcore/traffic/detail/LaneMaths.h"
#include "simcore/traffic/detail/StripClip.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace throng::sim {

// Left of the direction of travel seen from above (x east, z south): east -> north (-z).
using detail::leftOf;

LaneNetwork::LaneNetwork(const Scene& scene)
{
    for (const Lane& lane : scene.lanes) {
        LaneGeometry g;
        g.name = lane.name;
        g.widthM = lane.widthM;
        g.speedLimit = lane.speedLimit;
        g.loop = lane.loop;
        // Repeated points would give zero-length segments with no tangent.
        for (glm::vec2 p : lane.points)
            if (g.points.empty() || glm::distance(g.points.back(), p) > 1e-6f)
                g.points.push_back(p);
        if (g.points.size() < 2)
            g.points.push_back(g.points.empty() ? glm::vec2(0.0f) : g.points.back() + glm::vec2(1e-3f, 0.0f));
        g.cumulative.assign(1, 0.0f);
        for (std::size_t k = 1; k < g.points.size(); ++k)
            g.cumulative.push_back(g.cumulative.back() + glm::distance(g.points[k - 1], g.points[k]));
        m_lanes.push_back(std::move(g));
    }

    std::vector<int> crosswalkLight(scene.crosswalks.size(), -1);
    for (std::size_t li = 0; li < scene.trafficLights.size(); ++li)
        for (const StopLine& line : scene.trafficLights[li].stopLines) {
            if (!line.crosswalk.empty()) {
                for (std::size_t c = 0; c < scene.crosswalks.size(); ++c)
                    if (scene.crosswalks[c].name == line.crosswalk && crosswalkLight[c] < 0)
                        crosswalkLight[c] = int(li);
                continue;
            }
            const int lane = findLane(line.lane);
            if (lane < 0)
                continue;
            LaneStopLine s{lane, std::clamp(line.atM, 0.0f, length(lane)), int(li), int(m_stopLineCount++)};
            m_stopLines.push_back(s);
            m_lanes[std::size_t(lane)].stopLines.push_back(s);
        }
    for (LaneGeometry& g : m_lanes)
        std::stable_sort(g.stopLines.begin(), g.stopLines.end(),
                         [](const LaneStopLine& a, const LaneStopLine& b) { return a.s < b.s; });

    for (std::size_t c = 0; c < scene.crosswalks.size(); ++c) {
        const Crosswalk& cw = scene.crosswalks[c];
        CrosswalkStrip strip;
        strip.a = cw.from;
        strip.b = cw.to;
        strip.lengthM = glm::distance(cw.from, cw.to);
        strip.dir = strip.lengthM > 0.0f ? (cw.to - cw.from) / strip.lengthM : glm::vec2(1.0f, 0.0f);
        strip.halfWidthM = 0.5f * cw.widthM;
        strip.light = crosswalkLight[c];
        findRoadPart(strip);
        m_crosswalks.push_back(strip);
        m_crosswalkStopLine.push_back(strip.light >= 0 ? int(m_stopLineCount++) : -1);
        addCrosswalkStretches(int(c));
    }
    for (LaneGeometry& g : m_lanes) {
        std::stable_sort(g.stretches.begin(), g.stretches.end(),
                         [](const LaneStretch& a, const LaneStretch& b) { return a.s0 < b.s0; });
        for (LaneStretch& st : g.stretches) {
            st.boxEntryS = st.s0;
            for (const LaneStopLine& line : g.stopLines)  // ascending: the last match is the nearest
                if (line.s <= st.s0 && st.s0 - line.s <= kBoxM)
                    st.boxEntryS = line.s;
        }
    }
    for (const LaneGeometry& g : m_lanes)
        m_stretches.insert(m_stretches.end(), g.stretches.begin(), g.stretches.end());
}

int LaneNetwork::findLane(const std::string& name) const
{
    for (std::size_t i = 0; i < m_lanes.size(); ++i)
        if (m_lanes[i].name == name)
            return int(i);
    return -1;
}

float LaneNetwork::wrap(int lane, float s) const
{
    const float len = length(lane);
    if (!loops(lane) || !(len > 0.0f))
        return std::clamp(s, 0.0f, len);
    float w = std::fmod(s, len);
    if (w < 0.0f)
        w += len;
    return w >= len ? 0.0f : w;
}

std::size_t LaneNetwork::segmentAt(const LaneGeometry& g, float s) const
{
    const auto it = std::upper_bound(g.cumulative.begin(), g.cumulative.end(), s);
    const std::size_t k = std::size_t(it - g.cumulative.begin());
    return std::clamp<std::size_t>(k == 0 ? 0 : k - 1, 0, g.points.size() - 2);
}

glm::vec2 LaneNetwork::positionAt(int lane, float s) const
{
    const LaneGeometry& g = m_lanes[std::size_t(lane)];
    s = wrap(lane, s);
    const std::size_t k = segmentAt(g, s);
    const float segLen = g.cumulative[k + 1] - g.cumulative[k];
    const float t = segLen > 0.0f ? std::clamp((s - g.cumulative[k]) / segLen, 0.0f, 1.0f) : 0.0f;
    return g.points[k] + (g.points[k + 1] - g.points[k]) * t;
}

glm::vec2 LaneNetwork::tangentAt(int lane, float s) const
{
    const LaneGeometry& g = m_lanes[std::size_t(lane)];
    const std::size_t k = segmentAt(g, wrap(lane, s));
    return glm::normalize(g.points[k + 1] - g.points[k]);
}

LaneProjection LaneNetwork::project(int lane, glm::vec2 p) const
{
    const LaneGeometry& g = m_lanes[std::size_t(lane)];
    LaneProjection best;
    best.lane = lane;
    best.distanceM = std::numeric_limits<float>::infinity();
    for (std::size_t k = 0; k + 1 < g.points.size(); ++k) {
        const glm::vec2 a = g.points[k], ab = g.points[k + 1] - a;
        const float len = g.cumulative[k + 1] - g.cumulative[k];
        const float t = std::clamp(glm::dot(p - a, ab) / (len * len), 0.0f, 1.0f);
        const glm::vec2 q = a + ab * t;
        const float d = glm::distance(p, q);
        if (d < best.distanceM) {
            best.distanceM = d;
            best.s = g.cumulative[k] + len * t;
            best.lateralM = glm::dot(p - q, leftOf(ab / len));
        }
    }
    return best;
}

LaneProjection LaneNetwork::carriagewayAt(glm::vec2 p, float marginM) const
{
    LaneProjection best;
    best.distanceM = std::numeric_limits<float>::infinity();
    for (std::size_t l = 0; l < m_lanes.size(); ++l) {
        const LaneGeometry& g = m_lanes[l];
        const LaneProjection pr = project(int(l), p);
        if (pr.distanceM > 0.5f * g.widthM + marginM || pr.distanceM >= best.distanceM)
            continue;
        // Past either end of the centre line is off the carriageway (square ends).
        if (glm::dot(p - g.points.front(), g.points[1] - g.points.front()) < 0.0f)
            continue;
        const std::size_t n = g.points.size();
        if (glm::dot(p - g.points[n - 1], g.points[n - 1] - g.points[n - 2]) > 0.0f)
            continue;
        best = pr;
    }
    return best;
}

int LaneNetwork::crosswalkAt(glm::vec2 p, float marginM) const
{
    for (std::size_t c = 0; c < m_crosswalks.size(); ++c) {
        const CrosswalkStrip& s = m_crosswalks[c];
        const glm::vec2 d = p - s.a;
        const float u = glm::dot(d, s.dir), v = glm::dot(d, leftOf(s.dir));
        if (u >= -marginM && u <= s.lengthM + marginM && std::abs(v) <= s.halfWidthM + marginM)
            return int(c);
    }
    return -1;
}

bool LaneNetwork::onRoadPart(int c, glm::vec2 p) const
{
    const CrosswalkStrip& s = m_crosswalks[std::size_t(c)];
    const glm::vec2 d = p - s.a;
    const float u = glm::dot(d, s.dir), w = glm::dot(d, leftOf(s.dir));
    if (u <= 0.0f || u >= s.lengthM || std::abs(w) >= s.halfWidthM)
        return false;
    return !s.overLane || carriagewayAt(p).lane >= 0;
}

bool LaneNetwork::forbiddenForPedestrian(glm::vec2 p, float radiusM) const
{
    return carriagewayAt(p, radiusM).lane >= 0 && crosswalkAt(p) < 0;
}

void LaneNetwork::findRoadPart(CrosswalkStrip& strip) const
{
    // Sampled every 2 cm: a waiting walker stands its radius and more before roadU0.
    constexpr float kSampleM = 0.02f;
    const glm::vec2 side = leftOf(strip.dir);
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    // Only the part of the centre line that can meet a carriageway is sampled: inside the
    // lanes' bounding box grown by the lane's and the strip's half widths (a 1,000 km
    // crosswalk over a street took 9 s here when sampled whole).
    glm::vec2 boxMin(std::numeric_limits<float>::infinity()), boxMax(-std::numeric_limits<float>::infinity());
    for (const LaneGeometry& g : m_lanes)
        for (const glm::vec2 p : g.points) {
            boxMin = glm::min(boxMin, p - glm::vec2(0.5f * g.widthM + strip.halfWidthM));
            boxMax = glm::max(boxMax, p + glm::vec2(0.5f * g.widthM + strip.halfWidthM));
        }
    float u0 = 0.0f, u1 = m_lanes.empty() ? -1.0f : strip.lengthM;  // the centre line's stretch inside the box (slabs)
    for (int axis = 0; axis < 2 && u0 <= u1; ++axis) {
        const float a = strip.a[axis], d = strip.dir[axis];
        if (std::abs(d) < 1e-12f) {
            if (a < boxMin[axis] || a > boxMax[axis])
                u1 = -1.0f;
            continue;
        }
        const float t0 = (boxMin[axis] - a) / d, t1 = (boxMax[axis] - a) / d;
        u0 = std::max(u0, std::min(t0, t1));
        u1 = std::min(u1, std::max(t0, t1));
    }
    const int samples = int(std::ceil(strip.lengthM / kSampleM));
    const int first = u0 <= u1 ? std::max(0, int(std::floor(u0 / kSampleM)) - 1) : samples + 1;
    const int last = u0 <= u1 ? std::min(samples, int(std::ceil(u1 / kSampleM)) + 1) : samples;
    for (int k = first; k <= last; ++k) {
        const float u = std::min(strip.lengthM, float(k) * kSampleM);
        for (const float w : {-strip.halfWidthM, 0.0f, strip.halfWidthM})
            if (carriagewayAt(strip.a + strip.dir * u + side * w).lane >= 0) {
                lo = std::min(lo, u);
                hi = std::max(hi, u);
            }
    }
    // A sample's width out: the kerb lies between the last sample off the road and the first on it.
    strip.overLane = lo <= hi;
    strip.roadU0 = lo <= hi ? std::max(0.0f, lo - kSampleM) : 0.0f;
    strip.roadU1 = lo <= hi ? std::min(strip.lengthM, hi + kSampleM) : strip.lengthM;
}

void LaneNetwork::addCrosswalkStretches(int c)
{
    const CrosswalkStrip& strip = m_crosswalks[std::size_t(c)];
    for (std::size_t l = 0; l < m_lanes.size(); ++l) {
        LaneGeometry& g = m_lanes[l];
        std::vector<LaneStretch> found;
        for (std::size_t k = 0; k + 1 < g.points.size(); ++k) {
            float t0 = 0.0f, t1 = 1.0f;
            if (!detail::clipToStrip(g.points[k], g.points[k + 1], strip.a, strip.dir, strip.lengthM, strip.halfWidthM,
                                     t0, t1))
                continue;
            const float len = g.cumulative[k + 1] - g.cumulative[k];
            const float s0 = g.cumulative[k] + len * t0, s1 = g.cumulative[k] + len * t1;
            if (!found.empty() && std::abs(found.back().s1 - s0) < 1e-4f)
                found.back().s1 = s1;
            else
                found.push_back({int(l), c, s0, s1});
        }
        for (const LaneStretch& s : found)
            if (s.s1 > s.s0)
                g.stretches.push_back(s);
    }
}

}  // namespace throng::sim
