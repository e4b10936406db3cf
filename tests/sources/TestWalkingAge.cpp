// Walking speed by age (issue 26, RiMEA test 7): a type that sets `variation.age` draws each
// walker's age from the range and scales its speed by Weidmann's curve. Checked against the
// curve's values written out here (the guideline's figure at every tenth year, linear in
// between), on walkers measured from their positions; the draw is the same in the World and
// the exports, and the file keeps the key and refuses ages off the curve.
#include "TestRegistry.h"

#include "export/character/AgentVariation.h"
#include "simcore/io/SceneIO.h"
#include "simcore/scene/WalkingAge.h"
#include "simcore/world/World.h"

#include <QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace throng;
using namespace throng::sim;

namespace {

// Weidmann's mean walking speeds, m/s, at 10, 20, ..., 80 years: the test's own copy.
constexpr float kCurve[] = {1.20f, 1.60f, 1.52f, 1.50f, 1.45f, 1.25f, 1.05f, 0.70f};

float expectedAt(float years)
{
    const float at = (years - 10.0f) / 10.0f;
    const int k = std::min(int(at), 6);
    return kCurve[k] + (at - float(k)) * (kCurve[k + 1] - kCurve[k]);
}

Scene parseAges(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "ages.yaml", "");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

// `count` walkers of the aged type in lanes 3 m apart heading east for a far exit, and one
// of a type with no age; `speed` is the aged type's speed range.
std::string field(int count, const char* ages, const char* speed = "[1, 1]")
{
    std::ostringstream y;
    y << "throng: 1\nsettings: {fps: 30, seed: 21, duration: 30, bounds: {min: [-5, -80], max: [505, 80]}}\n"
         "agent_types:\n"
         "  - {name: aged, radius: 0.2, max_speed: 1.34, variation: {speed: "
      << speed << ", age: " << ages
      << "}}\n"
         "  - {name: ageless, radius: 0.2, max_speed: 1.34, variation: {speed: [1, 1]}}\n"
         "goals:\n  - {name: east, position: [500, 0], radius: 1, exit: true}\n"
         "agents:\n";
    for (int k = 0; k < count; ++k)
        y << "  - {type: aged, position: [0, " << (-75 + 3 * k) << "], goal: east}\n";
    y << "  - {type: ageless, position: [0, 76], goal: east}\n";
    return y.str();
}

}  // namespace

class TestWalkingAge : public QObject {
    Q_OBJECT

private slots:
    // The curve at its points, between them, and held at its ends.
    void theCurveIsWeidmanns()
    {
        for (int decade = 1; decade <= 8; ++decade)
            QCOMPARE(weidmannSpeedAtAge(10.0f * float(decade)), kCurve[decade - 1]);
        QCOMPARE(weidmannSpeedAtAge(25.0f), 1.56f);
        QVERIFY(std::abs(weidmannSpeedAtAge(73.0f) - 0.945f) < 1e-6f);
        QCOMPARE(weidmannSpeedAtAge(5.0f), 1.20f);
        QCOMPARE(weidmannSpeedAtAge(95.0f), 0.70f);
        for (float a = 10.0f; a <= 80.0f; a += 0.5f)
            QVERIFY(std::abs(weidmannSpeedAtAge(a) - expectedAt(a)) < 1e-5f);
    }

    // Each walker's age lies in its range, the ages spread over it, and each walks at
    // Weidmann's speed for its age, measured from its positions between 4 s and 14 s. The
    // walker of the type with no age has none and walks at its type's speed.
    void eachWalkerWalksAtItsAgesSpeed()
    {
        World world(parseAges(field(50, "[20, 80]")));
        QCOMPARE(world.agentCount(), std::size_t(51));
        float youngest = 100.0f, oldest = 0.0f;
        for (std::size_t i = 0; i < 50; ++i) {
            const float age = world.ageYears(i);
            QVERIFY2(age >= 20.0f && age <= 80.0f, qPrintable(QString::number(age)));
            youngest = std::min(youngest, age);
            oldest = std::max(oldest, age);
        }
        QVERIFY(youngest < 30.0f && oldest > 70.0f);
        QCOMPARE(world.ageYears(50), 0.0f);
        while (world.timeS() < 4.0 - 1e-9)
            world.step();
        const std::vector<glm::vec3> at4(world.positions().begin(), world.positions().end());
        while (world.timeS() < 14.0 - 1e-9)
            world.step();
        double slowest = 10.0, fastest = 0.0;
        for (std::size_t i = 0; i < 51; ++i) {
            const double speed = double(glm::distance(world.positions()[i], at4[i])) / 10.0;
            const double expected = i < 50 ? double(expectedAt(world.ageYears(i))) : 1.34;
            QVERIFY2(std::abs(speed - expected) < 0.02,
                     qPrintable(QString("walker %1, %2 years: %3 m/s, expected %4")
                                    .arg(i).arg(double(world.ageYears(i))).arg(speed).arg(expected)));
            if (i < 50) {
                slowest = std::min(slowest, speed);
                fastest = std::max(fastest, speed);
            }
        }
        QVERIFY2(slowest < 1.0 && fastest > 1.5, qPrintable(QString("%1 to %2").arg(slowest).arg(fastest)));
    }

    // The type's speed range still applies on top of the age's: every walker is within
    // that range of its age's speed. The exports draw the same factor the World walks by.
    void theSpeedRangeScalesTheAgesSpeed()
    {
        const Scene s = parseAges(field(20, "[30, 70]", "[0.9, 1.1]"));
        World world(s);
        while (world.timeS() < 4.0 - 1e-9)
            world.step();
        const std::vector<glm::vec3> at4(world.positions().begin(), world.positions().end());
        while (world.timeS() < 14.0 - 1e-9)
            world.step();
        for (std::size_t i = 0; i < 20; ++i) {
            const double speed = double(glm::distance(world.positions()[i], at4[i])) / 10.0;
            const double ages = double(expectedAt(world.ageYears(i)));
            QVERIFY2(speed > 0.9 * ages - 0.02 && speed < 1.1 * ages + 0.02,
                     qPrintable(QString("%1 m/s at %2 years").arg(speed).arg(double(world.ageYears(i)))));
            const exporting::AgentVariation v = exporting::drawVariation(s.agentTypes[0].variation, 21,
                                                                         std::uint32_t(world.id(i)), 1);
            QVERIFY2(std::abs(1.34 * double(v.speedFactor) - speed) < 0.02,
                     qPrintable(QString("export factor %1, walked %2 m/s").arg(double(v.speedFactor)).arg(speed)));
        }
    }

    // The key is written only when set and reads back the same; ages off the curve, a
    // reversed range and an age on a vehicle type are refused or warned of, with the line.
    void theFileKeepsAndChecksTheKey()
    {
        const Scene s = parseAges(field(2, "[25, 65]"));
        QCOMPARE(s.agentTypes[0].variation.ageYears, glm::vec2(25.0f, 65.0f));
        QCOMPARE(s.agentTypes[1].variation.ageYears, glm::vec2(0.0f));
        const std::string written = sceneToYaml(s);
        QVERIFY2(written.find("age: [25, 65]") != std::string::npos, written.c_str());
        QCOMPARE(written.find("age:"), written.rfind("age:"));
        QVERIFY(parseAges(written).agentTypes == s.agentTypes);
        struct Bad {
            const char* ages;
            const char* message;
        };
        for (const Bad& bad : {Bad{"[5, 30]", "within 10 to 80 years"}, Bad{"[30, 90]", "within 10 to 80 years"},
                               Bad{"[60, 30]", "min greater than max"}, Bad{"[0, 0]", "within 10 to 80 years"},
                               Bad{"old", "age"}}) {
            const LoadResult r = parseScene(field(1, bad.ages), "ages.yaml", "");
            QVERIFY2(!r.ok(), bad.ages);
            QVERIFY2(r.diagnostics[0].format().find(bad.message) != std::string::npos &&
                         r.diagnostics[0].format().find("ages.yaml:4") != std::string::npos,
                     r.diagnostics[0].format().c_str());
        }
        const LoadResult car = parseScene("throng: 1\nagent_types:\n"
                                          "  - {name: car, kind: vehicle, variation: {age: [20, 30]}}\n",
                                          "ages.yaml", "");
        QVERIFY(car.ok());
        QCOMPARE(car.diagnostics.size(), std::size_t(1));
        QCOMPARE(car.diagnostics[0].severity, Severity::Warning);
        QVERIFY2(car.diagnostics[0].format().find("variation.age") != std::string::npos,
                 car.diagnostics[0].format().c_str());
        // A vehicle or flier type with no variation, or one without these keys, is no matter.
        const LoadResult plain = parseScene("throng: 1\nagent_types:\n  - {name: car, kind: vehicle}\n"
                                            "  - {name: bird, kind: flier, variation: {speed: [1, 1]}}\n",
                                            "ages.yaml", "");
        QVERIFY(plain.ok());
        QVERIFY(plain.diagnostics.empty());
    }
};

THRONG_REGISTER_TEST(TestWalkingAge)
#include "TestWalkingAge.moc"
