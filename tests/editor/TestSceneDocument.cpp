// SceneDocument: opening replaces the scene only when the file is valid, saving writes
// a file that opens to the same scene, and the document says where it lives.
#include "EditorTestSupport.h"
#include "TestRegistry.h"

#include "editor/SceneDocument.h"
#include "simcore/io/SceneIO.h"

#include <QFileInfo>
#include <QSignalSpy>
#include <QTest>

#include <algorithm>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

const QByteArray kThreeAgents = "throng: 1\n"
                                "agent_types: [{name: walker}]\n"
                                "agents:\n"
                                "  - {type: walker, position: [0, 0]}\n"
                                "  - {type: walker, position: [1, 0]}\n"
                                "  - {type: walker, position: [2, 0]}\n"
                                "walls: [{points: [[-3, -3], [3, -3]]}]\n";

// Line 4 names a type that does not exist.
const QByteArray kBrokenOnLine4 = "throng: 1\n"
                                  "agent_types: [{name: walker}]\n"
                                  "agents:\n"
                                  "  - {type: ghost, position: [0, 0]}\n";

}  // namespace

class TestSceneDocument : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void loadingAValidSceneReplacesTheScene()
    {
        const QString path = writeScene(m_dir, "three.yaml", kThreeAgents);
        SceneDocument document;
        QSignalSpy reset(&document, &SceneDocument::sceneReset);
        QSignalSpy pathChanged(&document, &SceneDocument::filePathChanged);
        const std::vector<sim::Diagnostic> diagnostics = document.load(path);
        QVERIFY(!sim::hasErrors(diagnostics));
        QCOMPARE(reset.count(), 1);
        QCOMPARE(pathChanged.count(), 1);
        QCOMPARE(document.scene().agents.size(), std::size_t(3));
        QCOMPARE(document.scene().walls.size(), std::size_t(1));
        QCOMPARE(document.filePath(), QFileInfo(path).absoluteFilePath());
        QVERIFY(!document.isModified());
    }

    void loadingABrokenSceneKeepsTheOldOne()
    {
        SceneDocument document;
        const QString good = writeScene(m_dir, "good.yaml", kThreeAgents);
        QVERIFY(!sim::hasErrors(document.load(good)));
        const sim::Scene before = document.scene();

        QSignalSpy reset(&document, &SceneDocument::sceneReset);
        const QString broken = writeScene(m_dir, "broken.yaml", kBrokenOnLine4);
        const std::vector<sim::Diagnostic> diagnostics = document.load(broken);
        QVERIFY(sim::hasErrors(diagnostics));
        const auto error = std::find_if(diagnostics.begin(), diagnostics.end(),
                                        [](const sim::Diagnostic& d) { return d.severity == sim::Severity::Error; });
        QCOMPARE(error->line, 4);
        QVERIFY(QString::fromStdString(error->message).contains("ghost"));
        QCOMPARE(reset.count(), 0);
        QVERIFY(document.scene() == before);
        QCOMPARE(document.filePath(), QFileInfo(good).absoluteFilePath());
    }

    void loadingAMissingFileReportsIt()
    {
        SceneDocument document;
        const std::vector<sim::Diagnostic> diagnostics = document.load(m_dir.filePath("nowhere.yaml"));
        QVERIFY(sim::hasErrors(diagnostics));
        QVERIFY(document.filePath().isEmpty());
    }

    void savedSceneOpensToTheSameScene()
    {
        SceneDocument document;
        QVERIFY(!sim::hasErrors(document.load(writeScene(m_dir, "original.yaml", kThreeAgents))));
        const QString copy = m_dir.filePath("copy.yaml");
        QSignalSpy pathChanged(&document, &SceneDocument::filePathChanged);
        const sim::SaveResult saved = document.saveAs(copy);
        QVERIFY2(saved.ok, saved.error.c_str());
        QCOMPARE(document.filePath(), QFileInfo(copy).absoluteFilePath());
        QCOMPARE(pathChanged.count(), 1);
        QVERIFY(!document.isModified());

        SceneDocument reopened;
        QVERIFY(!sim::hasErrors(reopened.load(copy)));
        QVERIFY(reopened.scene() == document.scene());
        QVERIFY(document.save().ok);
    }

    void savingANewSceneNeedsAPath()
    {
        SceneDocument document;
        const sim::SaveResult saved = document.save();
        QVERIFY(!saved.ok);
        QVERIFY(!saved.error.empty());
    }

    void savingIntoAMissingFolderFailsAndKeepsThePath()
    {
        SceneDocument document;
        const sim::SaveResult saved = document.saveAs(m_dir.filePath("no/such/folder/scene.yaml"));
        QVERIFY(!saved.ok);
        QVERIFY(document.filePath().isEmpty());
    }
};

THRONG_REGISTER_TEST(TestSceneDocument)
#include "TestSceneDocument.moc"
