// A placed agent's hand-set look, tint and height (what the variation brush paints) in
// the scene file: read in the list and the table form, written back only when set, bad
// indices reported at their line and column, and honoured by export over the drawn
// variation.
#include "EditorTestSupport.h"
#include "TestRegistry.h"

#include "export/character/AgentVariation.h"
#include "simcore/io/SceneIO.h"

#include <QTest>

#include <string>

using namespace throng;
using namespace throng::editor::test;

namespace {

const QByteArray kTypes = R"(throng: 1
agent_types:
  - name: walker
    variation: {looks: [man, woman], tints: [[1, 0, 0], [0, 1, 0], [0, 0, 1]], height: [0.9, 1.1]}
)";

sim::LoadResult load(const QTemporaryDir& dir, const QByteArray& agents)
{
    return sim::loadScene(writeScene(dir, "v.yaml", kTypes + agents).toStdString());
}

std::string firstError(const sim::LoadResult& r)
{
    for (const sim::Diagnostic& d : r.diagnostics)
        if (d.severity == sim::Severity::Error)
            return d.format();
    return r.diagnostics.empty() ? std::string("no diagnostic") : r.diagnostics.front().format();
}

}  // namespace

class TestAgentVariationFile : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void listFormReadsAndWritesOnlyWhatIsSet()
    {
        const sim::LoadResult r = load(m_dir, "agents:\n"
                                              "  - {id: 1, type: walker, position: [0, 0], look: 1, tint: 2, height: 1.05}\n"
                                              "  - {id: 2, type: walker, position: [2, 0]}\n");
        QVERIFY2(r.ok(), firstError(r).c_str());
        const sim::Agent& a = r.scene.agents[0];
        QCOMPARE(a.look, 1);
        QCOMPARE(a.tint, 2);
        QCOMPARE(a.heightScale, 1.05f);
        QCOMPARE(r.scene.agents[1].tint, -1);  // unset: drawn per agent
        const std::string yaml = sim::sceneToYaml(r.scene);
        QVERIFY(yaml.find("tint: 2") != std::string::npos);
        QCOMPARE(yaml.find("tint:"), yaml.rfind("tint:"));  // agent 2 writes none
        const QString again = writeScene(m_dir, "again.yaml", QByteArray::fromStdString(yaml));
        const sim::LoadResult back = sim::loadScene(again.toStdString());
        QVERIFY2(back.ok(), firstError(back).c_str());
        QVERIFY(back.scene.agents == r.scene.agents);
    }

    void tableFormTakesDashForDrawn()
    {
        const sim::LoadResult r = load(m_dir, "agents:\n"
                                              "  columns: [id, type, x, z, look, tint, height]\n"
                                              "  rows: |\n"
                                              "    1 walker 0 0 1 0 1.2\n"
                                              "    2 walker 2 0 - - -\n");
        QVERIFY2(r.ok(), firstError(r).c_str());
        QCOMPARE(r.scene.agents[0].tint, 0);
        QCOMPARE(r.scene.agents[0].heightScale, 1.2f);
        QCOMPARE(r.scene.agents[1].look, -1);
        QCOMPARE(r.scene.agents[1].heightScale, 0.0f);
    }

    void anIndexPastThePaletteIsAnErrorAtItsPlace()
    {
        const sim::LoadResult list = load(m_dir, "agents:\n  - {type: walker, position: [0, 0], tint: 3}\n");
        QVERIFY(!list.ok());
        QVERIFY2(firstError(list).find("v.yaml:6:44: error: agents[0].tint") != std::string::npos,
                 firstError(list).c_str());
        const sim::LoadResult table = load(m_dir, "agents:\n  columns: [type, x, z, look]\n  rows: |\n"
                                                  "    walker 0 0 2\n");
        QVERIFY(!table.ok());
        QVERIFY2(firstError(table).find("v.yaml:8:16: error: agents.rows[0].look") != std::string::npos, firstError(table).c_str());
        const sim::LoadResult height = load(m_dir, "agents:\n  - {type: walker, position: [0, 0], height: 0}\n");
        QVERIFY2(!height.ok(), "a height scale of 0 is refused");
    }

    void exportTakesTheHandSetVariationOverTheDrawnOne()
    {
        sim::Variation v;
        v.tints = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        v.heightScale = {0.9f, 1.1f};
        sim::Agent agent;
        agent.id = 7;
        exporting::AgentVariation drawn = exporting::drawVariation(v, 1, agent.id, 2);
        exporting::AgentVariation kept = drawn;
        exporting::applyHandSetVariation(kept, agent, 2, 3);  // nothing set: the draw stays
        QCOMPARE(kept.tint, drawn.tint);
        QCOMPARE(kept.heightScale, drawn.heightScale);
        agent.tint = (drawn.tint + 1) % 3;
        agent.look = 1 - int(drawn.look);
        agent.heightScale = 1.3f;
        exporting::applyHandSetVariation(drawn, agent, 2, 3);
        QCOMPARE(drawn.tint, agent.tint);
        QCOMPARE(int(drawn.look), agent.look);
        QCOMPARE(drawn.heightScale, 1.3f);
        QCOMPARE(drawn.speedFactor, kept.speedFactor);  // the simulation's draws are untouched
    }
};

THRONG_REGISTER_TEST(TestAgentVariationFile)
#include "TestAgentVariationFile.moc"
