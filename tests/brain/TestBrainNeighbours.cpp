// Per-neighbour values: logic runs per neighbour, scalars broadcast to every neighbour,
// and filter nodes collapse the values of the neighbours an agent actually has.
#include "BrainRig.h"
#include "TestRegistry.h"

#include <QTest>

using namespace throng;
using namespace throng::test;

namespace {
constexpr std::size_t K = sim::kBrainNeighbours;
}

class TestBrainNeighbours : public QObject {
    Q_OBJECT
private slots:
    void filtersCollapseOnlyRealNeighbours()
    {
        GraphBuilder b;
        const auto d = b.sensor("neighbour_distance");
        const char* modes[] = {"nearest", "least", "most", "average", "count"};
        std::vector<sim::NodeId> f;
        for (const char* m : modes) {
            f.push_back(b.add("filter", {txt("mode", m), num("threshold", 1.5f), num("empty", -1)}));
            b.link(d, 0, f.back(), 0);
        }
        BrainRig rig(b.g, 2);
        QVERIFY2(rig.ok(), rig.errors.c_str());
        std::vector<float> dist(2 * K, 100.0f);  // slots past the count hold junk the filters must ignore
        dist[0] = 3;
        dist[1] = 1;
        dist[2] = 2;
        rig.set("neighbour_distance", dist);
        rig.counts = {3, 0};
        rig.step();
        const float want0[] = {3, 1, 3, 2, 2};
        const float want1[] = {-1, -1, -1, -1, 0};  // no neighbours: the empty value; count 0
        for (std::size_t m = 0; m < f.size(); ++m) {
            QCOMPARE(rig.value(f[m], 0, 0), want0[m]);
            QCOMPARE(rig.value(f[m], 0, 1), want1[m]);
        }
    }

    void reasonsAboutEachNeighbour()
    {
        // Threat = the most "close AND ahead" among the neighbours.
        GraphBuilder b;
        const auto dist = b.sensor("neighbour_distance");
        const auto bearing = b.sensor("neighbour_bearing");
        const auto close = b.add("fuzz.trapezoid", {nums("points", {0, 0, 1, 3})});
        const auto ahead = b.add("fuzz.triangle", {nums("points", {-45, 0, 45})});
        const auto both = b.add("rule.and");
        const auto threat = b.add("filter", {txt("mode", "most")});
        const auto bias = b.sensor("speed");
        const auto shifted = b.add("math.add");  // a scalar added to each neighbour's value
        const auto nearestShifted = b.add("filter", {txt("mode", "nearest")});
        b.link(dist, 0, close, 0);
        b.link(bearing, 0, ahead, 0);
        b.link(close, 0, both, 0);
        b.link(ahead, 0, both, 1);
        b.link(both, 0, threat, 0);
        b.link(dist, 0, shifted, 0);
        b.link(bias, 0, shifted, 1);
        b.link(shifted, 0, nearestShifted, 0);
        BrainRig rig(b.g, 1);
        QVERIFY2(rig.ok(), rig.errors.c_str());
        std::vector<float> d(K, 0.0f), br(K, 0.0f);
        // Neighbour 0: close but behind. Neighbour 1: ahead but far. Neighbour 2: 2 m, 22.5° off.
        d[0] = 0.5f, br[0] = 180;
        d[1] = 10, br[1] = 0;
        d[2] = 2, br[2] = 22.5f;
        rig.set("neighbour_distance", d);
        rig.set("neighbour_bearing", br);
        rig.set("speed", {7});
        rig.counts = {3};
        rig.step();
        QCOMPARE(rig.value(threat), 0.5f);  // min(0.5 close, 0.5 ahead) from neighbour 2
        QCOMPARE(rig.value(nearestShifted), 7.5f);
        const float* perNeighbour = rig.eval->nodeValues(both, 0);
        QCOMPARE(perNeighbour[0], 0.0f);
        QCOMPARE(perNeighbour[1], 0.0f);
        QCOMPARE(perNeighbour[2], 0.5f);
    }

    void soundSourcesAreItemsToo()
    {
        // The loudest bell is 0.9 at 20 m; the distance of sources louder than 0.5 averages 15 m.
        GraphBuilder b;
        const auto strength = b.sensor("sound_source_strength", {txt("channel", "bell")});
        const auto dist = b.sensor("sound_source_distance", {txt("channel", "bell")});
        const auto loud = b.add("math.compare", {txt("mode", "gt"), num("value", 0.5f)});
        const auto loudDist = b.add("math.multiply");
        const auto loudest = b.add("filter", {txt("mode", "most")});
        const auto heard = b.add("filter", {txt("mode", "count"), num("threshold", 0.5f)});
        const auto sumDist = b.add("filter", {txt("mode", "average")});
        b.link(strength, 0, loud, 0);
        b.link(strength, 0, loudest, 0);
        b.link(strength, 0, heard, 0);
        b.link(loud, 0, loudDist, 0);
        b.link(dist, 0, loudDist, 1);
        b.link(loudDist, 0, sumDist, 0);
        BrainRig rig(b.g, 1);
        QVERIFY2(rig.ok(), rig.errors.c_str());
        QCOMPARE(rig.eval->program().itemSets, (std::vector<std::string>{"sound:bell"}));
        std::vector<float> s(K, 0.0f), d(K, 0.0f);
        s[0] = 0.9f, d[0] = 20;
        s[1] = 0.6f, d[1] = 10;
        s[2] = 0.1f, d[2] = 5;
        s[3] = 1.0f;  // past the count: ignored
        rig.set("sound_source_strength", s, "bell");
        rig.set("sound_source_distance", d, "bell");
        rig.sourceCounts["sound:bell"] = {3};
        rig.step();
        QCOMPARE(rig.value(loudest), 0.9f);
        QCOMPARE(rig.value(heard), 2.0f);
        QCOMPARE(rig.value(sumDist), 10.0f);  // (20 + 10 + 0) / 3
        // Neighbours and sound sources cannot meet in one node unfiltered.
        GraphBuilder m;
        const auto nd = m.sensor("neighbour_distance");
        const auto sd = m.sensor("sound_source_distance", {txt("channel", "bell")});
        const auto add = m.add("math.add");
        m.link(nd, 0, add, 0);
        m.link(sd, 0, add, 1);
        const sim::BrainCompileResult r = sim::compileBrain(m.g);
        QVERIFY(!r.ok());
        QCOMPARE(r.errors[0].message, std::string("node 3 (math.add): input 1 gives one value per source heard on 'bell' "
                                                  "(node 2) but another input one per neighbour; filter one of them first"));
    }
};

THRONG_REGISTER_TEST(TestBrainNeighbours)
#include "TestBrainNeighbours.moc"
