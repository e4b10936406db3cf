// The orient, variation and assign brushes driven like a user: paint a crowd with the
// crowd brush, pick the brush on the tool bar, set its options in the tool options bar
// and drag over part of the crowd. Checks what the user would: the agents under the
// stroke changed and the others did not, one undo step restores them, redo again, and
// a hand-set variation survives save and reopen.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSpinBox>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

float segmentDistance(glm::vec2 p, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}

glm::vec2 ground(const sim::Agent& a)
{
    return {a.position.x, a.position.z};
}

// Paints a band of agents (random headings) across the open block north-west of the
// crossing; returns how many.
std::size_t paintBand(MainWindow& window)
{
    if (!clickToolButton(window, "crowdBrush"))
        return 0;
    dragOnGround(window, {{-38, -25}, {-14, -25}});
    // They show once the simulation's thread brings frame 0 of the painted scene.
    const std::size_t painted = window.document().scene().agents.size();
    if (!QTest::qWaitFor([&] { return window.viewport().agentCount() == kCrossroadsAgents + painted; }, 30000))
        return 0;
    return painted;
}

// Headings equal up to whole turns, degrees.
bool sameHeading(float a, float b, float toleranceDeg)
{
    return std::abs(std::remainder(a - b, 360.0f)) <= toleranceDeg;
}

}  // namespace

class TestBrushesUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void orientBrushCombsHeadingsAlongTheStroke()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        const std::size_t painted = paintBand(window);
        QVERIFY2(painted >= 40, qPrintable(QString::number(painted)));
        const std::vector<sim::Agent> before = window.document().scene().agents;

        QVERIFY(clickToolButton(window, "orientBrush"));
        // North-east over the west half of the band: 45 degrees (z points south).
        const glm::vec2 from(-36, -22), to(-28, -30);
        dragOnGround(window, {from, to});
        const std::vector<sim::Agent>& after = window.document().scene().agents;
        QCOMPARE(after.size(), painted);
        const glm::vec2 dir = glm::normalize(to - from);
        std::size_t combed = 0, kept = 0;
        for (std::size_t i = 0; i < after.size(); ++i) {
            const float d = segmentDistance(ground(after[i]), from + dir, to - dir);
            if (d <= 2.0f) {
                QVERIFY2(sameHeading(after[i].headingDeg, 45.0f, 3.0f),
                         qPrintable(QString("agent %1 at %2, %3 heads %4").arg(i).arg(after[i].position.x)
                                        .arg(after[i].position.z).arg(after[i].headingDeg)));
                ++combed;
            } else if (segmentDistance(ground(after[i]), from, to) > 3.5f) {
                QCOMPARE(after[i].headingDeg, before[i].headingDeg);
                ++kept;
            }
            QCOMPARE(ground(after[i]), ground(before[i]));  // combing never moves anyone
        }
        QVERIFY2(combed >= 5 && kept >= 10, qPrintable(QString("%1 combed, %2 kept").arg(combed).arg(kept)));
        QCOMPARE(window.document().undoStack()->count(), 2);  // paint, comb
        QVERIFY(window.document().undoStack()->text(1).startsWith("Comb"));

        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QTRY_VERIFY(window.document().scene().agents == before);
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY(sameHeading(window.document().scene().agents[0].headingDeg, after[0].headingDeg, 0.0f));
        QCOMPARE(window.document().undoStack()->index(), 2);
    }

    void variationBrushSetsTintLookAndHeightAndTheySurviveSaving()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(paintBand(window) >= 40);
        const std::vector<sim::Agent> before = window.document().scene().agents;
        for (const sim::Agent& a : before)
            QVERIFY(a.tint == -1 && a.look == -1 && a.heightScale == 0.0f);  // drawn from the type

        QVERIFY(clickToolButton(window, "variationBrush"));
        // Tint 3 of the pedestrian palette (index 2), look 2 (woman, index 1), height 1.25:
        // the brush numbers tints and looks from 1, as Properties does.
        window.findChild<QSpinBox*>("variationTintIndex")->setValue(3);
        QTest::mouseClick(window.findChild<QCheckBox*>("variationLookCheck"), Qt::LeftButton);
        window.findChild<QSpinBox*>("variationLookIndex")->setValue(2);
        QTest::mouseClick(window.findChild<QCheckBox*>("variationHeightCheck"), Qt::LeftButton);
        window.findChild<QDoubleSpinBox*>("variationHeightMin")->setValue(1.25);
        window.findChild<QDoubleSpinBox*>("variationHeightMax")->setValue(1.25);
        const glm::vec2 from(-16, -25), to(-22, -25);
        dragOnGround(window, {from, to});

        const std::vector<sim::Agent>& after = window.document().scene().agents;
        std::size_t varied = 0, untouched = 0;
        for (std::size_t i = 0; i < after.size(); ++i) {
            const float d = segmentDistance(ground(after[i]), from, to);
            if (d <= 2.8f) {
                QVERIFY2(after[i].tint == 2 && after[i].look == 1 && after[i].heightScale == 1.25f,
                         qPrintable(QString("agent %1: tint %2 look %3 height %4").arg(i).arg(after[i].tint)
                                        .arg(after[i].look).arg(after[i].heightScale)));
                ++varied;
            } else if (d > 3.2f) {
                QVERIFY(after[i] == before[i]);
                ++untouched;
            }
        }
        QVERIFY2(varied >= 5 && untouched >= 20, qPrintable(QString("%1 varied, %2 untouched").arg(varied).arg(untouched)));
        // The viewport shows the varied agents in tint 2 of their palette.
        const glm::vec3 tint2 = window.document().scene().agentTypes[0].variation.tints[2];
        QTest::qWait(50);
        const QImage shown = window.viewport().grabFramebuffer();
        std::size_t inTint = 0;
        for (std::size_t i = 0; i < after.size(); ++i)
            if (after[i].tint == 2)
                inTint += sameColour(pixelAt(shown, window.viewport(), window.viewport().worldToPixel(after[i].position)),
                                     glm::vec4(tint2, 1.0f), 16);
        QVERIFY2(inTint * 4 >= varied * 3, qPrintable(QString("%1 of %2 shown in the tint").arg(inTint).arg(varied)));
        QVERIFY(window.document().undoStack()->text(1).startsWith("Vary"));
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QTRY_VERIFY(window.document().scene().agents == before);
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY(!(window.document().scene().agents == before));
        const std::vector<sim::Agent> variedAgents = window.document().scene().agents;

        // Saved and opened again, every agent keeps its hand-set variation.
        QTest::keyClick(&window.viewport(), Qt::Key_S, Qt::ControlModifier);
        QTRY_VERIFY(!window.document().isModified());
        SceneDocument reopened;
        const std::vector<sim::Diagnostic> problems = reopened.load(window.document().filePath());
        QVERIFY2(problems.empty(), problems.empty() ? "" : problems.front().format().c_str());
        const std::vector<sim::Agent>& loaded = reopened.scene().agents;
        QCOMPARE(loaded.size(), variedAgents.size());
        for (std::size_t i = 0; i < loaded.size(); ++i) {
            QCOMPARE(loaded[i].tint, variedAgents[i].tint);
            QCOMPARE(loaded[i].look, variedAgents[i].look);
            QCOMPARE(loaded[i].heightScale, variedAgents[i].heightScale);
        }
    }

    void randomTintDrawsFromTheTypesPalette()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(paintBand(window) >= 40);
        QVERIFY(clickToolButton(window, "variationBrush"));  // tint on, "random" by default
        dragOnGround(window, {{-38, -25}, {-14, -25}});
        const std::size_t palette = window.document().scene().agentTypes[0].variation.tints.size();
        QCOMPARE(palette, std::size_t(5));
        std::vector<int> seen(palette, 0);
        for (const sim::Agent& a : window.document().scene().agents) {
            QVERIFY2(a.tint >= 0 && a.tint < int(palette), qPrintable(QString::number(a.tint)));
            ++seen[std::size_t(a.tint)];
        }
        QVERIFY2(std::count(seen.begin(), seen.end(), 0) <= 1, "a random tint uses the whole palette");
    }

    void assignBrushGivesAGoalToTheAgentsUnderIt()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(paintBand(window) >= 40);
        const std::vector<sim::Agent> before = window.document().scene().agents;
        QVERIFY(clickToolButton(window, "assignBrush"));
        auto* goal = window.findChild<QComboBox*>("assignGoal");
        QVERIFY(goal);
        goal->setCurrentIndex(goal->findText("nw_corner"));
        const glm::vec2 from(-38, -25), to(-30, -25);
        dragOnGround(window, {from, to});
        const std::vector<sim::Agent>& after = window.document().scene().agents;
        std::size_t assigned = 0;
        for (std::size_t i = 0; i < after.size(); ++i) {
            const float d = segmentDistance(ground(after[i]), from, to);
            if (d <= 2.8f) {
                QCOMPARE(after[i].goal, std::string("nw_corner"));
                QCOMPARE(after[i].type, before[i].type);  // type left as it was ("(keep)")
                ++assigned;
            } else if (d > 3.2f) {
                QVERIFY(after[i].goal.empty());
            }
        }
        QVERIFY(assigned >= 5);
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QTRY_VERIFY(window.document().scene().agents == before);
    }
};

THRONG_REGISTER_TEST(TestBrushesUi)
#include "TestBrushesUi.moc"
