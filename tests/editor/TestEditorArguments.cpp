// The `throng` command line: what a user types and what it means, and a clear error for
// every mistake.
#include "TestRegistry.h"

#include "editor/EditorArguments.h"

#include <QTest>

using namespace throng::editor;

class TestEditorArguments : public QObject {
    Q_OBJECT

private slots:
    void editorOpensAnOptionalScene()
    {
        QCOMPARE(EditorArguments::parse({}).mode, EditorArguments::Mode::Editor);
        const EditorArguments a = EditorArguments::parse({"plaza.yaml"});
        QVERIFY(a.error.isEmpty());
        QCOMPARE(a.mode, EditorArguments::Mode::Editor);
        QCOMPARE(a.scenePath, QString("plaza.yaml"));
    }

    void screenshotDefaults()
    {
        const EditorArguments a = EditorArguments::parse({"--screenshot", "out.png", "plaza.yaml"});
        QVERIFY2(a.error.isEmpty(), qPrintable(a.error));
        QCOMPARE(a.mode, EditorArguments::Mode::Screenshot);
        QCOMPARE(a.screenshot.outputPath, QString("out.png"));
        QCOMPARE(a.screenshot.scenePath, QString("plaza.yaml"));
        QCOMPARE(a.screenshot.frame, 0);
        QCOMPARE(a.screenshot.sizePx, QSize(1280, 720));
        QCOMPARE(a.screenshot.view, ViewMode::Top);
    }

    void screenshotOptionsInAnyOrder()
    {
        const EditorArguments a = EditorArguments::parse(
            {"plaza.yaml", "--view", "3d", "--size", "640x360", "--screenshot", "out.png", "--frame", "48"});
        QVERIFY2(a.error.isEmpty(), qPrintable(a.error));
        QCOMPARE(a.screenshot.scenePath, QString("plaza.yaml"));
        QCOMPARE(a.screenshot.frame, 48);
        QCOMPARE(a.screenshot.sizePx, QSize(640, 360));
        QCOMPARE(a.screenshot.view, ViewMode::Orbit);
    }

    void cameraPerspIsTheIssueSpellingOfThe3dView()
    {
        const EditorArguments a =
            EditorArguments::parse({"--screenshot", "o.png", "crossroads.yaml", "--camera", "persp"});
        QVERIFY2(a.error.isEmpty(), qPrintable(a.error));
        QCOMPARE(a.screenshot.view, ViewMode::Orbit);
        QCOMPARE(EditorArguments::parse({"--screenshot", "o.png", "s.yaml", "--camera", "top"}).screenshot.view,
                 ViewMode::Top);
        QVERIFY(EditorArguments::parse({"--screenshot", "o.png", "s.yaml", "--camera", "side"}).error.contains("side"));
    }

    void helpWins()
    {
        QCOMPARE(EditorArguments::parse({"--frame", "x", "--help"}).mode, EditorArguments::Mode::Help);
        QVERIFY(EditorArguments::usage().contains("--screenshot"));
    }

    void mistakesAreExplained_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("no scene") << QStringList{"--screenshot", "out.png"} << "scene file";
        QTest::newRow("no output") << QStringList{"--screenshot"} << "--screenshot needs a value";
        QTest::newRow("negative frame") << QStringList{"--screenshot", "o.png", "s.yaml", "--frame", "-3"} << "--frame";
        QTest::newRow("frame not a number")
            << QStringList{"--screenshot", "o.png", "s.yaml", "--frame", "ten"} << "ten";
        QTest::newRow("size without x") << QStringList{"--screenshot", "o.png", "s.yaml", "--size", "640"} << "WxH";
        QTest::newRow("size too small") << QStringList{"--screenshot", "o.png", "s.yaml", "--size", "4x4"} << "4x4";
        QTest::newRow("unknown view") << QStringList{"--screenshot", "o.png", "s.yaml", "--view", "side"} << "side";
        QTest::newRow("unknown option") << QStringList{"--fast", "s.yaml"} << "--fast";
        QTest::newRow("two scenes") << QStringList{"a.yaml", "b.yaml"} << "one scene";
        QTest::newRow("frame without screenshot") << QStringList{"s.yaml", "--frame", "2"} << "--screenshot";
    }

    void mistakesAreExplained()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, mentions);
        const EditorArguments a = EditorArguments::parse(args);
        QVERIFY2(a.error.contains(mentions), qPrintable("error was: '" + a.error + "'"));
    }
};

THRONG_REGISTER_TEST(TestEditorArguments)
#include "TestEditorArguments.moc"
