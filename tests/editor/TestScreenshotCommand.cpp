// `throng --screenshot` end to end: a valid scene becomes an image of the asked size with
// its agents in it; a broken scene prints file:line:col errors, writes nothing and fails.
#include "EditorTestSupport.h"
#include "TestRegistry.h"

#include "editor/ScreenshotCommand.h"
#include "editor/viewport/ViewportPalette.h"

#include <QFileInfo>
#include <QTest>

#include <sstream>

using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// One agent in the middle of a symmetric set, so it lands on the image centre.
const QByteArray kCentredAgent = "throng: 1\n"
                                 "agent_types: [{name: walker, radius: 0.5}]\n"
                                 "agents: [{type: walker, position: [0, 0]}]\n"
                                 "walls:\n"
                                 "  - {points: [[-3, -2], [3, -2]]}\n"
                                 "  - {points: [[-3, 2], [3, 2]]}\n";

}  // namespace

class TestScreenshotCommand : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void writesTheImageAndPrintsItsPath()
    {
        ScreenshotOptions options;
        options.scenePath = writeScene(m_dir, "centred.yaml", kCentredAgent);
        options.outputPath = m_dir.filePath("shot.png");
        options.sizePx = {320, 200};
        std::ostringstream out, err;
        QCOMPARE(ScreenshotCommand(options, out, err).run(), 0);
        QCOMPARE(QString::fromStdString(out.str()).trimmed(), options.outputPath);

        QImage image(options.outputPath);
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), QSize(320, 200));
        const QRgb centre = image.pixel(160, 100);
        QVERIFY2(sameColour(centre, palette::agentColour(0)), qPrintable(describe(centre) + " at the agent"));
        const QRgb corner = image.pixel(3, 3);
        QVERIFY2(!sameColour(corner, palette::agentColour(0), 60), qPrintable(describe(corner) + " in the corner"));
    }

    void brokenSceneFailsWithItsLocation()
    {
        ScreenshotOptions options;
        options.scenePath = writeScene(m_dir, "broken.yaml",
                                       "throng: 1\n"
                                       "agent_types: [{name: walker}]\n"
                                       "agents:\n"
                                       "  - {type: ghost, position: [0, 0]}\n");
        options.outputPath = m_dir.filePath("never.png");
        std::ostringstream out, err;
        QCOMPARE(ScreenshotCommand(options, out, err).run(), 1);
        const QString errors = QString::fromStdString(err.str());
        QVERIFY2(errors.startsWith(options.scenePath + ":4:") && errors.contains(": error: "), qPrintable(errors));
        QVERIFY(out.str().empty());
        QVERIFY(!QFileInfo::exists(options.outputPath));
    }

    void unwritableOutputFails()
    {
        ScreenshotOptions options;
        options.scenePath = writeScene(m_dir, "centred.yaml", kCentredAgent);
        options.outputPath = m_dir.filePath("missing/folder/shot.png");
        std::ostringstream out, err;
        QCOMPARE(ScreenshotCommand(options, out, err).run(), 1);
        QVERIFY2(QString::fromStdString(err.str()).contains("cannot write"), err.str().c_str());
    }
};

THRONG_REGISTER_TEST(TestScreenshotCommand)
#include "TestScreenshotCommand.moc"
