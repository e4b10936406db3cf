#include "simcore/nav/NavPassages.h"

#include "simcore/base/detail/PlanarSegments.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace throng::sim {

std::size_t openNarrowPassages(NavGrid& grid, const NavShapes& shapes, float bodyRadiusM, float inflateM)
{
    if (!(inflateM > bodyRadiusM) || grid.cellCount() == 0)
        return 0;
    std::vector<Segment> segments = shapes.walls;
    for (const NavBox& b : shapes.boxes) {
        Segment sides[4];
        boxSides(b, sides);
        segments.insert(segments.end(), sides, sides + 4);
    }
    const float bucketM = std::max(1.0f, 4.0f * inflateM);
    SegmentGrid near;
    near.build(segments, bucketM);
    // Circles and boxes bucketed by their centres (as points), so that a cell looks only at
    // those near it: a scene may hold thousands of pillars or cones.
    std::vector<Segment> circleCentres, boxCentres;
    float largestCircleM = 0.0f, largestBoxM = 0.0f;
    for (const NavCircle& circle : shapes.circles) {
        circleCentres.push_back({circle.centre, circle.centre});
        largestCircleM = std::max(largestCircleM, circle.radiusM);
    }
    for (const NavBox& b : shapes.boxes) {
        boxCentres.push_back({b.centre, b.centre});
        largestBoxM = std::max(largestBoxM, glm::length(b.halfSize));
    }
    SegmentGrid circlesNear, boxesNear;
    circlesNear.build(circleCentres, bucketM);
    boxesNear.build(boxCentres, bucketM);
    // A shape's point nearest the cell's centre, with the distance to its surface.
    struct Touch {
        glm::vec2 point;
        float distanceM;
    };
    const float bodyReach = std::max(bodyRadiusM, 0.75f * grid.cellM());  // NavGrid's rule for the body alone
    const float across = inflateM + grid.cellM();
    std::vector<std::uint8_t> seen(std::size_t(grid.cellCount()), 0);
    std::vector<NavCell> open;
    std::vector<Touch> touches;
    auto consider = [&](NavCell cell) {
        const int k = grid.index(cell);
        if (seen[std::size_t(k)] || grid.walkableIndex(k))
            return;
        seen[std::size_t(k)] = 1;
        const glm::vec2 c = grid.centre(cell);
        bool inBox = false;
        boxesNear.forEachNear(c, largestBoxM, [&](std::uint32_t b) { inBox = inBox || shapes.boxes[b].contains(c); });
        if (inBox)
            return;
        touches.clear();
        near.forEachNear(c, across, [&](std::uint32_t s) {
            const glm::vec2 q = detail::closestOnSegment(c, near.segment(s).a, near.segment(s).b);
            touches.push_back({q, glm::distance(q, c)});
        });
        circlesNear.forEachNear(c, across + largestCircleM, [&](std::uint32_t k) {
            const NavCircle& circle = shapes.circles[k];
            const glm::vec2 d = circle.centre - c;
            const float len = glm::length(d);
            if (len - circle.radiusM <= across)
                touches.push_back({len > 0.0f ? c + d * ((len - circle.radiusM) / len) : c, len - circle.radiusM});
        });
        bool fits = true;
        for (const Touch& t : touches)
            fits = fits && t.distanceM > bodyReach;
        if (!fits)
            return;
        // In a passage: a shape within the inflation (the one that closed the cell) and one on
        // the opposite side of the centre (more than 120 degrees round from it: not the other
        // wall of a room's corner) within the inflation and a cell: the band the inflation
        // leaves between them is narrower than a cell, so it may hold no centre.
        for (std::size_t i = 0; i < touches.size(); ++i)
            for (std::size_t j = 0; j < touches.size(); ++j)
                if (touches[i].distanceM <= inflateM && touches[j].distanceM <= across &&
                    glm::dot(touches[i].point - c, touches[j].point - c) <
                        -0.5f * touches[i].distanceM * touches[j].distanceM) {
                    open.push_back(cell);
                    return;
                }
    };
    // The cells the inflation can have closed: within inflateM of a shape.
    auto around = [&](glm::vec2 lo, glm::vec2 hi) {
        const NavCell c0 = grid.cellOf(lo - glm::vec2(inflateM)), c1 = grid.cellOf(hi + glm::vec2(inflateM));
        for (int z = std::max(c0.z, 0); z <= std::min(c1.z, grid.rows() - 1); ++z)
            for (int x = std::max(c0.x, 0); x <= std::min(c1.x, grid.cols() - 1); ++x)
                consider({x, z});
    };
    for (const Segment& s : segments)
        around(glm::min(s.a, s.b), glm::max(s.a, s.b));
    for (const NavCircle& circle : shapes.circles)
        around(circle.centre - glm::vec2(circle.radiusM), circle.centre + glm::vec2(circle.radiusM));
    for (const NavCell& cell : open)
        grid.setWalkable(cell, true);
    return open.size();
}

}  // namespace throng::sim
