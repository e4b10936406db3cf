// The wall grid returns every segment near a point, once, in ascending order, exactly
// as a brute-force scan over all segments does.
#include "TestRegistry.h"

#include "simcore/base/SegmentGrid.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <random>
#include <vector>

using namespace throng::sim;

namespace {
float distanceToSegment(glm::vec2 p, const Segment& s)
{
    const glm::vec2 ab = s.b - s.a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - s.a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::distance(p, s.a + ab * t);
}
}  // namespace

class TestSegmentGrid : public QObject {
    Q_OBJECT
private slots:
    void findsEveryNearSegmentOnceInOrder()
    {
        std::mt19937 gen(5);
        std::uniform_real_distribution<float> u(-40.0f, 40.0f), len(-15.0f, 15.0f);
        std::vector<Segment> segments;
        for (int i = 0; i < 400; ++i) {
            const glm::vec2 a(u(gen), u(gen));
            segments.push_back({a, a + glm::vec2(len(gen), len(gen))});
        }
        segments.push_back({{3, 3}, {3, 3}});  // zero length
        SegmentGrid grid;
        grid.build(segments, 3.0f);
        for (int q = 0; q < 500; ++q) {
            const glm::vec2 p(u(gen) * 1.2f, u(gen) * 1.2f);  // some queries fall outside the grid
            const float r = q % 3 == 0 ? 0.4f : 4.5f;
            std::vector<std::uint32_t> found;
            grid.forEachNear(p, r, [&](std::uint32_t k) { found.push_back(k); });
            for (std::size_t k = 1; k < found.size(); ++k)
                QVERIFY2(found[k - 1] < found[k], "indices must be ascending and unique");
            for (std::uint32_t k = 0; k < segments.size(); ++k)
                if (distanceToSegment(p, segments[k]) <= r)
                    QVERIFY2(std::binary_search(found.begin(), found.end(), k), "a near segment was missed");
        }
    }

    void emptyGridFindsNothing()
    {
        SegmentGrid grid;
        grid.build({}, 2.0f);
        int calls = 0;
        grid.forEachNear({0, 0}, 100.0f, [&](std::uint32_t) { ++calls; });
        QCOMPARE(calls, 0);
    }
};

THRONG_REGISTER_TEST(TestSegmentGrid)
#include "TestSegmentGrid.moc"
