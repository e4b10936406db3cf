// The variation brush counts tints and looks as Properties does, from 1: a user who sets
// the brush to look 2 and tint 3 and strokes over a crowd finds "look 2" (the type's
// second look) and "tint 3" in Properties for the agents under the stroke.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/SceneItem.h"

#include <glm/geometric.hpp>

#include <QCheckBox>
#include <QColor>
#include <QComboBox>
#include <QSpinBox>
#include <QTest>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

class TestVariationNumberingUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void lookTwoOfTheBrushIsLookTwoInProperties()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "crowdBrush"));
        dragOnGround(window, {{-38, -25}, {-14, -25}});
        const std::size_t painted = window.document().scene().agents.size();
        QVERIFY(painted >= 40);

        QVERIFY(clickToolButton(window, "variationBrush"));
        auto* look = window.findChild<QSpinBox*>("variationLookIndex");
        auto* tint = window.findChild<QSpinBox*>("variationTintIndex");
        QVERIFY(look && tint);
        QCOMPARE(look->text(), QString("random"));  // nothing chosen yet
        QTest::mouseClick(window.findChild<QCheckBox*>("variationLookCheck"), Qt::LeftButton);
        typeInto(look, "2");
        typeInto(tint, "3");
        QCOMPARE(look->text(), QString("2"));
        QCOMPARE(tint->text(), QString("3"));
        const glm::vec2 from(-30, -25), to(-22, -25);
        dragOnGround(window, {from, to});

        const sim::Scene& scene = window.document().scene();
        const sim::Variation& palette = scene.agentTypes[0].variation;
        std::size_t varied = 0, shown = 0;
        for (std::size_t i = 0; i < scene.agents.size(); ++i) {
            const sim::Agent& a = scene.agents[i];
            if (std::abs(a.position.z - from.y) > 1.5f || a.position.x < from.x + 1 || a.position.x > to.x - 1)
                continue;
            ++varied;
            QCOMPARE(a.look, 1);  // the second look, 0-based inside
            QCOMPARE(a.tint, 2);
            if (shown++ >= 2)
                continue;
            selectInOutliner(window, {{ItemKind::Agent, i}});
            auto* lookRow = field<QComboBox>(window, "look");
            auto* tintRow = field<QComboBox>(window, "tint");
            QVERIFY(lookRow && tintRow);
            QTRY_COMPARE(lookRow->currentIndex(), 2);  // "(drawn)" comes first
            QCOMPARE(lookRow->currentText(), QString::fromStdString(palette.looks[1]));
            QCOMPARE(tintRow->currentIndex(), 3);
            const glm::vec3 c = palette.tints[2];
            QCOMPARE(tintRow->currentText(), QColor::fromRgbF(c.r, c.g, c.b).name());
        }
        QVERIFY2(varied >= 3, qPrintable(QString::number(varied)));
    }
};

THRONG_REGISTER_TEST(TestVariationNumberingUi)
#include "TestVariationNumberingUi.moc"
