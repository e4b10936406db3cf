#pragma once
// The road geometry of a scene: lanes as arc-length polylines, stop lines resolved to
// (lane, s), crosswalk strips and the lane stretches they cover. Static after
// construction, read-only and thread-safe; it never moves a vehicle or a pedestrian.

#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace throng::sim {

// A point related to one lane: s along the centre line from its first point (m, in
// [0, length]), lateral offset from the centre line (m, positive to the left of the
// direction of travel seen from above) and the distance to the nearest centre-line point.
struct LaneProjection {
    int lane = -1;
    float s = 0.0f;
    float lateralM = 0.0f;
    float distanceM = 0.0f;
};

// Where a crosswalk strip covers a lane: the lane's centre line is inside the strip for
// s in [s0, s1] (m along the lane, s0 < s1).
struct LaneStretch {
    int lane = -1;
    int crosswalk = -1;
    float s0 = 0.0f, s1 = 0.0f;
    // The stop line before the stretch (within kBoxM), where a vehicle commits to it: a
    // vehicle between there and s0 is in the junction box and must be let through.
    // s0 itself when no stop line precedes the stretch.
    float boxEntryS = 0.0f;
};

// A crosswalk strip: centre line a -> b, its unit direction, length and half width (m).
struct CrosswalkStrip {
    glm::vec2 a{0.0f}, b{0.0f};
    glm::vec2 dir{1.0f, 0.0f};
    float lengthM = 0.0f;
    float halfWidthM = 0.0f;
    int light = -1;  // the traffic light whose stop line names this crosswalk; -1 = none
    // The road part: m along the centre line from a, where the strip first and last lies
    // on a lane's carriageway (over its whole width: the smallest and largest such u on
    // either side line or the centre line, widened by 2 cm, the sampling step). Walkers
    // wait before roadU0 / after roadU1, not at the strip's ends, which may lie on the
    // pavement. [0, lengthM] over no lane.
    float roadU0 = 0.0f, roadU1 = 0.0f;
    bool overLane = false;  // some of the strip lies on a carriageway
};

// A vehicles' stop line on a lane, controlled by one traffic light.
struct LaneStopLine {
    int lane = -1;
    float s = 0.0f;  // m along the lane, clamped to [0, length]
    int light = -1;  // index in Scene::trafficLights
    int index = -1;  // dense index over every stop line of every light (throughput counters)
};

// A straight piece of kerb pedestrians may not cross (ground plane, m).
struct BarrierSegment {
    glm::vec2 a{0.0f}, b{0.0f};
};

class LaneNetwork {
public:
    static constexpr float kBoxM = 40.0f;  // m: farthest a stop line may be before a crosswalk it guards

    LaneNetwork() = default;
    // Lanes, crosswalks and the stop lines of every traffic light. The scene must be
    // validated (references resolved by name); unknown names are skipped.
    explicit LaneNetwork(const Scene& scene);

    std::size_t laneCount() const { return m_lanes.size(); }
    int findLane(const std::string& name) const;
    const std::string& laneName(int lane) const { return m_lanes[std::size_t(lane)].name; }
    // True when lane a of this network and lane b of `other` have the same centre line
    // (points and loop): s along one is the same place on the other.
    bool sameCentreLine(int a, const LaneNetwork& other, int b) const;
    float length(int lane) const { return m_lanes[std::size_t(lane)].cumulative.back(); }
    float widthM(int lane) const { return m_lanes[std::size_t(lane)].widthM; }
    float speedLimit(int lane) const { return m_lanes[std::size_t(lane)].speedLimit; }
    bool loops(int lane) const { return m_lanes[std::size_t(lane)].loop; }

    // Point and unit tangent at s (m). A looping lane wraps s into [0, length); an open
    // lane clamps it to its ends.
    glm::vec2 positionAt(int lane, float s) const;
    glm::vec2 tangentAt(int lane, float s) const;
    // s taken into [0, length) for a looping lane, clamped for an open one.
    float wrap(int lane, float s) const;

    // The nearest point of one lane's centre line to p.
    LaneProjection project(int lane, glm::vec2 p) const;
    // The lane whose carriageway holds p (|lateral| <= width / 2 + marginM, s inside the
    // lane), the nearest centre line first; lane -1 when none.
    LaneProjection carriagewayAt(glm::vec2 p, float marginM = 0.0f) const;

    std::size_t crosswalkCount() const { return m_crosswalks.size(); }
    const CrosswalkStrip& crosswalk(int c) const { return m_crosswalks[std::size_t(c)]; }
    // The crosswalk whose strip (grown by marginM on every side) holds p; -1 when none.
    int crosswalkAt(glm::vec2 p, float marginM = 0.0f) const;
    // Whether p is on crosswalk c's road part: inside its strip and on a lane's
    // carriageway (anywhere inside a strip that lies over no lane). What the red-light
    // counter and the walkers' red-light constraint both test.
    bool onRoadPart(int c, glm::vec2 p) const;
    // Every lane stretch a crosswalk covers, in (lane, s0) order.
    const std::vector<LaneStretch>& stretches() const { return m_stretches; }
    // Stretches on one lane, ordered by s0.
    const std::vector<LaneStretch>& stretchesOn(int lane) const { return m_lanes[std::size_t(lane)].stretches; }

    // The pedestrian rule: true when a body of radius radiusM centred at p overlaps a
    // lane's carriageway and p is not on a crosswalk strip.
    bool forbiddenForPedestrian(glm::vec2 p, float radiusM = 0.0f) const;

    // Kerbs as wall segments: each lane's two carriageway edges except where a
    // crosswalk strip or another lane's carriageway covers them, and both sides of each
    // crosswalk strip where it lies over a carriageway. Added to a World's walls they
    // make "no pedestrian in a lane except on a crosswalk" a hard constraint: every way
    // from the pavement into a lane crosses one, except along a crosswalk. (Straight
    // pieces per lane segment; the outside of a sharp bend may leave a small wedge.)
    std::vector<BarrierSegment> pedestrianBarriers() const;

    // Vehicles' stop lines, all lights; and those on one lane ordered by s.
    const std::vector<LaneStopLine>& stopLines() const { return m_stopLines; }
    const std::vector<LaneStopLine>& stopLinesOn(int lane) const { return m_lanes[std::size_t(lane)].stopLines; }
    // Pedestrian stop lines: one per crosswalk named by a light (index in stopLineCount
    // space), or -1 for an uncontrolled crosswalk.
    int crosswalkStopLineIndex(int c) const { return m_crosswalkStopLine[std::size_t(c)]; }
    // Number of stop lines of every kind (vehicle lines and controlled crosswalks).
    std::size_t stopLineCount() const { return m_stopLineCount; }

private:
    struct LaneGeometry {
        std::string name;
        std::vector<glm::vec2> points;
        std::vector<float> cumulative;  // arc length at each point; back() = length
        float widthM = 3.5f, speedLimit = 13.9f;
        bool loop = true;
        std::vector<LaneStretch> stretches;
        std::vector<LaneStopLine> stopLines;
    };
    std::size_t segmentAt(const LaneGeometry& lane, float s) const;
    void addCrosswalkStretches(int c);
    void findRoadPart(CrosswalkStrip& strip) const;

    std::vector<LaneGeometry> m_lanes;
    std::vector<CrosswalkStrip> m_crosswalks;
    std::vector<LaneStretch> m_stretches;
    std::vector<LaneStopLine> m_stopLines;
    std::vector<int> m_crosswalkStopLine;
    std::size_t m_stopLineCount = 0;
};

}  // namespace throng::sim
