// The crowd brush's type mix as a user sets it: the Mix button in the tool options bar
// opens a table with one row per agent type and a weight each; typed weights of 3 and 1
// make a large stroke paint about three of the first type for one of the second, and a
// weight of 0 paints none of that type.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/tools/TypeMixTable.h"

#include <QDoubleSpinBox>
#include <QTableWidget>
#include <QTest>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

const QByteArray kTwoTypes = R"(throng: 1
settings: {fps: 24, seed: 3, duration: 10, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, max_force: 3}
  - {name: child, radius: 0.25, max_speed: 1.0, max_force: 3}
)";

QToolButton* mixButton(MainWindow& window)
{
    return window.findChild<QToolBar*>("toolOptionsToolBar")->findChild<QToolButton*>("brushMix");
}

// Opens the table from the Mix button, types each weight and closes it with Escape.
void setWeights(MainWindow& window, const std::vector<std::pair<QString, QString>>& weights)
{
    QToolButton* button = mixButton(window);
    QVERIFY(button);
    QTest::mouseClick(button, Qt::LeftButton);
    auto* table = button->findChild<TypeMixTable*>();
    QVERIFY(table);
    QTRY_VERIFY(table->isVisible());
    for (const auto& [type, weight] : weights) {
        auto* spin = table->findChild<QDoubleSpinBox*>("mixWeight_" + type);
        QVERIFY2(spin, qPrintable(type));
        typeInto(spin, weight);
    }
    QTest::keyClick(table, Qt::Key_Escape);
    QTRY_VERIFY(!table->isVisible());
}

// A serpentine over the middle of the ground, rows 10 m apart.
void paintLargeStroke(MainWindow& window)
{
    dragOnGround(window, {{-25, -20}, {25, -20}, {25, -10}, {-25, -10}, {-25, 0}, {25, 0}, {25, 10}, {-25, 10},
                          {-25, 20}, {25, 20}});
}

}  // namespace

class TestTypeMixUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void theTableListsTheTypesAndTheDefault()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "mix.yaml", kTwoTypes));
        QVERIFY(clickToolButton(window, "crowdBrush"));
        QToolButton* button = mixButton(window);
        QVERIFY(button);
        QCOMPARE(button->text(), QString("walker"));  // an empty mix paints the first pedestrian type
        QTest::mouseClick(button, Qt::LeftButton);
        auto* table = button->findChild<TypeMixTable*>();
        QTRY_VERIFY(table && table->isVisible());
        QCOMPARE(table->table()->rowCount(), 2);
        QCOMPARE(table->table()->item(0, 0)->text(), QString("walker"));
        QCOMPARE(table->table()->item(1, 0)->text(), QString("child"));
        QCOMPARE(table->findChild<QDoubleSpinBox*>("mixWeight_walker")->value(), 1.0);
        QCOMPARE(table->findChild<QDoubleSpinBox*>("mixWeight_child")->value(), 0.0);
        QTest::keyClick(table, Qt::Key_Escape);
        QTRY_VERIFY(!table->isVisible());
    }

    void weightsOfThreeAndOnePaintTypesInThatRatio()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "mix.yaml", kTwoTypes));
        QVERIFY(clickToolButton(window, "crowdBrush"));
        setWeights(window, {{"walker", "3"}, {"child", "1"}});
        QCOMPARE(mixButton(window)->text(), QString("walker 3 : child 1"));
        window.viewport().setFocus();
        for (int i = 0; i < 3; ++i)
            QTest::keyClick(&window.viewport(), Qt::Key_BracketRight);  // 5.9 m: a wide stroke
        const int steps = window.document().undoStack()->count();
        paintLargeStroke(window);
        QCOMPARE(window.document().undoStack()->count(), steps + 1);
        std::size_t walkers = 0, children = 0;
        for (const sim::Agent& a : window.document().scene().agents) {
            walkers += a.type == "walker" ? 1 : 0;
            children += a.type == "child" ? 1 : 0;
        }
        const std::size_t total = window.document().scene().agents.size();
        QCOMPARE(walkers + children, total);
        QVERIFY2(total >= 600, qPrintable(QString::number(total)));
        const double share = double(walkers) / double(total);
        QVERIFY2(share > 0.70 && share < 0.80,
                 qPrintable(QString("%1 walkers, %2 children: %3 walkers").arg(walkers).arg(children).arg(share)));

        // Child 0: the next stroke paints walkers only.
        undo(window);
        QTRY_COMPARE(window.document().scene().agents.size(), std::size_t(0));
        setWeights(window, {{"child", "0"}});
        QCOMPARE(mixButton(window)->text(), QString("walker 3"));
        paintLargeStroke(window);
        QVERIFY(window.document().scene().agents.size() >= 600);
        for (const sim::Agent& a : window.document().scene().agents)
            QCOMPARE(a.type, std::string("walker"));
    }
};

THRONG_REGISTER_TEST(TestTypeMixUi)
#include "TestTypeMixUi.moc"
