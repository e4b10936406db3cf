// A brain the compiler rejects still opens: the offending node is drawn red with the
// message as its tooltip, the Messages dock lists the error, and connecting the missing
// input clears the mark.
#include "BrainTestScenes.h"
#include "BrainUiDriver.h"
#include "TestRegistry.h"

#include "editor/MessagesPanel.h"
#include "editor/brain/BrainGraphModel.h"
#include "editor/brain/BrainScene.h"
#include "editor/brain/LinkItem.h"
#include "editor/brain/NodeItem.h"

#include <QTest>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {
QStringList rows(MainWindow& window)
{
    QStringList out;
    for (int i = 0; i < window.messages().count(); ++i)
        out << window.messages().item(i)->text();
    return out;
}
}  // namespace

class TestBrainErrors : public QObject {
    Q_OBJECT

private slots:
    void theOffendingNodeIsMarkedAndListed()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kBrokenBrainScene));
        BrainScene& scene = ui.panel().scene();
        QCOMPARE(int(scene.nodeItems().size()), 5);
        NodeItem* andNode = scene.nodeItem(3);
        QVERIFY2(andNode->error().contains("needs at least 2 connected inputs"), qPrintable(andNode->error()));
        QCOMPARE(andNode->toolTip(), andNode->error());
        QVERIFY(scene.nodeItem(1)->error().isEmpty());
        QVERIFY(scene.nodeItem(4)->error().isEmpty());
        // The Messages dock names the node, with the scene file's line for it.
        QTRY_VERIFY(rows(window).join('\n').contains("node 3"));
        const QString all = rows(window).join('\n');
        QVERIFY2(all.contains("node 3 (rule.and)") && all.contains("scene.yaml:9:"), qPrintable(all));
        // Fixing it in the editor clears the mark and says so.
        ui.dragLink(5, 0, 3, 1);
        QCOMPARE(ui.linkCount(), 4);
        QVERIFY2(scene.nodeItem(3)->error().isEmpty(), qPrintable(scene.nodeItem(3)->error()));
        QVERIFY(ui.panel().errors().empty());
        QTRY_VERIFY2(rows(window).join('\n').contains("compiles"), qPrintable(rows(window).join('\n')));
    }

    void aBadLinkIsMarkedOnTheLink()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        // Link 1 leaves port 1 of an input node, which has only port 0.
        QVERIFY(ui.open(dir, "throng: 1\nbrains:\n  - name: b\n    nodes:\n"
                             "      - {id: 1, type: input, position: [0, 0], params: {sensor: speed}}\n"
                             "      - {id: 2, type: output, position: [300, 0], params: {channel: speed}}\n"
                             "      - {id: 3, type: output, position: [300, 200], params: {channel: turn}}\n"
                             "    links:\n      - {from: [1, 0], to: [2, 0]}\n      - {from: [1, 1], to: [3, 0]}\n"));
        bool marked = false;
        for (const sim::BrainError& e : ui.panel().errors())
            marked = marked || e.link == 1;
        QVERIFY(marked);
        // The link has no port to start from, so it is not drawn; its node carries the
        // error instead when the compiler names one, and the dock lists it.
        QTRY_VERIFY2(rows(window).join('\n').contains("link 1"), qPrintable(rows(window).join('\n')));
        for (LinkItem* link : ui.panel().scene().linkItems())
            QCOMPARE(link->hasError(), link->index() == 1);
    }
};

THRONG_REGISTER_TEST(TestBrainErrors)
#include "TestBrainErrors.moc"
