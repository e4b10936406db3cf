// `throng-cli check` on what a run trips on (issue 23, finding 8 and 5): it said "valid"
// for a room at 1e6 m whose walkers froze, for walkers painted inside a crate, and for
// A* walkers sent to a goal they could never reach. Each now gets a warning naming it,
// the scene stays valid (status 0), and a sound scene still gets none.
#include "CliRunner.h"
#include "TestRegistry.h"

#include <QTemporaryDir>
#include <QTest>

using throng::test::runCli;
using throng::test::writeText;

namespace {

std::size_t count(const std::string& text, const std::string& what)
{
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

}  // namespace

class TestCliCheckGeometry : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    throng::test::CliOutput check(const char* name, const char* yaml)
    {
        return runCli({"check", writeText(m_dir.filePath(name), yaml).toStdString()});
    }

private slots:
    void farCoordinatesWarn()
    {
        const auto r = check("far.yaml", R"(throng: 1
settings: {bounds: {min: [999950, 1999950], max: [1000050, 2000050]}}
agent_types: [{name: walker}]
goals: [{name: g, position: [1000020.03, 2000000], radius: 1}]
agents: [{id: 1, type: walker, position: [1000000, 2000000], goal: g}]
)");
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.find(": valid (") != std::string::npos);
        QVERIFY2(r.err.find("far.yaml: warning: settings.bounds: coordinates this far from (0, 0) are held in the "
                            "scene file only to 0.125 m") != std::string::npos,
                 r.err.c_str());
        QVERIFY2(r.err.find("relative to the scene's centre (1000000, 2000000)") != std::string::npos, r.err.c_str());
        // And the run is a walk, not the frozen crowd of before.
        const QString csv = m_dir.filePath("far.csv");
        const auto run = runCli({"run", m_dir.filePath("far.yaml").toStdString(), "--frames", "48", "--quiet",
                                 "--trajectories", csv.toStdString()});
        QCOMPARE(run.status, 0);
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QStringList rows = QString::fromUtf8(f.readAll()).trimmed().split('\n');
        QCOMPARE(rows.size(), 1 + 48);
        const double x0 = rows[1].split(',')[2].toDouble(), x47 = rows[48].split(',')[2].toDouble();
        QVERIFY2(x47 - x0 > 1.0, qPrintable(QString("walked %1 m in 2 s").arg(x47 - x0)));
    }

    void agentsInsideTheSetWarn()
    {
        const auto r = check("inside.yaml", R"(throng: 1
settings: {seed: 3, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types: [{name: walker, radius: 0.3}]
obstacles:
  - {name: crate, shape: box, center: [0, 0], size: [3, 2]}
  - {name: pillar, shape: circle, center: [10, 0], radius: 2.5}
walls: [{points: [[-10, 10], [10, 10]]}]
agents:
  - {id: 1, type: walker, position: [0.5, 0.2]}
  - {id: 2, type: walker, position: [10.2, 0.1]}
  - {id: 3, type: walker, position: [5, 10.1]}
  - {id: 4, type: walker, position: [5, 5]}
groups:
  - {name: painted, type: walker, count: 40, rect: {min: [7, -3], max: [13, 3]}}
  - {name: buried, type: walker, count: 10, rect: {min: [-1, -0.5], max: [1, 0.5]}}
)");
        QCOMPARE(r.status, 0);
        QVERIFY2(r.err.find("inside.yaml: warning: agents[0]: agent 1 starts inside a wall or obstacle at (0.5, 0.2)") !=
                     std::string::npos,
                 r.err.c_str());
        QVERIFY2(r.err.find("warning: agents[1]: agent 2 starts inside") != std::string::npos, r.err.c_str());
        // Agent 3 only overlaps the wall by 0.2 m: pushed clear in a frame, as ever; no warning.
        QVERIFY2(r.err.find("agents[2]") == std::string::npos, r.err.c_str());
        QVERIFY2(r.err.find("agents[3]") == std::string::npos, r.err.c_str());
        // Members drawn over the pillar are drawn again where they fit; none fits in the crate.
        QVERIFY2(r.err.find("group 'painted'") == std::string::npos, r.err.c_str());
        QVERIFY2(r.err.find("warning: groups[1]: 10 of 10 members of group 'buried' spawn inside walls or obstacles") !=
                     std::string::npos,
                 r.err.c_str());
        QVERIFY2(r.out.find("warnings") != std::string::npos, r.out.c_str());
    }

    void unreachableGoalsAndNarrowExitsWarn()
    {
        const auto r = check("reach.yaml", R"(throng: 1
settings: {bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: planner, radius: 0.3, navigation: astar}
  - {name: big, radius: 0.4}
walls:
  - {points: [[4, -4], [12, -4], [12, 4], [4, 4], [4, -4]]}
  - {points: [[-12, 0.25], [-12, 8], [-18, 8], [-18, -8], [-12, -8], [-12, -0.25]]}
goals:
  - {name: vault, position: [8, 0], radius: 1}
  - {name: hatch, position: [-12, 0], radius: 0.25, exit: true}
agents:
  - {id: 1, type: planner, position: [-5, 0], goal: vault}
  - {id: 2, type: planner, position: [0, 6], goal: vault}
  - {id: 3, type: planner, position: [6, 2], goal: vault}
  - {id: 4, type: big, position: [-15, 0], goal: hatch}
groups:
  - {name: crowd, type: planner, count: 5, rect: {min: [-3, -15], max: [3, -10]}, goal: vault}
)");
        QCOMPARE(r.status, 0);
        QVERIFY2(r.err.find("reach.yaml: warning: goals[0]: goal 'vault' cannot be reached by 7 agents of type "
                            "'planner' (agent 1, 2; 5 of group 'crowd'): walls or obstacles close it off from where "
                            "they start; A* walkers wait where they stand") != std::string::npos,
                 r.err.c_str());
        QVERIFY2(r.err.find("warning: goals[1]: exit 'hatch' cannot be reached by a body of radius 0.4 m (type 'big')") !=
                     std::string::npos,
                 r.err.c_str());
        QCOMPARE(count(r.err, "warning:"), std::size_t(2));
    }

    void soundDoorsGetNoWarning()
    {
        // A 1 m door with an exit across it, walkers of radius 0.3 inside, A* walkers to
        // a goal round a pillar: nothing to warn about.
        const auto r = check("sound.yaml", R"(throng: 1
settings: {seed: 5, bounds: {min: [-10, -10], max: [12, 10]}}
agent_types:
  - {name: walker, radius: 0.3}
  - {name: planner, radius: 0.3, navigation: astar}
walls:
  - {points: [[7, 0.5], [7, 7], [-7, 7], [-7, -7], [7, -7], [7, -0.5]]}
obstacles: [{shape: circle, center: [0, 0], radius: 1}]
goals:
  - {name: door, position: [7, 0], radius: 0.5, exit: true}
  - {name: yard, position: [10, 5], radius: 1}
groups:
  - {name: crowd, type: walker, count: 50, rect: {min: [-6, -6], max: [-2, 6]}, goal: door}
  - {name: planners, type: planner, count: 10, rect: {min: [2, -6], max: [6, -2]}, goal: yard}
)");
        QCOMPARE(r.status, 0);
        QVERIFY2(r.err.empty(), r.err.c_str());
    }
};

THRONG_REGISTER_TEST(TestCliCheckGeometry)
#include "TestCliCheckGeometry.moc"
