// Playing, stepping and scrubbing the live simulation with the timeline's buttons and
// scrub bar, saving an edited scene with Ctrl+S and opening it again, and exporting
// through File > Export, as a user does.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/exporting/ExportDialog.h"
#include "editor/panels/TimelinePanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/ShownAgents.h"
#include "editor/viewport/Viewport.h"
#include "export/ExportFormats.h"
#include "simcore/world/World.h"
#include "simcore/layout/LayoutApply.h"
#include "simcore/io/SceneIO.h"
#include "editor/simulation/ShownRecording.h"

#include <glm/geometric.hpp>

#include <map>

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QListWidget>
#include <QSpinBox>
#include <QSet>
#include <QSlider>
#include <QTest>
#include <QToolButton>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

class TestPlaybackAndFilesUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void playAdvancesFramesAndMovesAgentsAndScrubbingGoesBack()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        SimulationController& sim = window.simulation();
        QCOMPARE(frameText(window), QString("Frame 0"));

        QVERIFY(clickButton(window, "playButton"));
        QVERIFY(sim.isPlaying());
        QTRY_VERIFY_WITH_TIMEOUT(window.viewport().frameIndex() >= 24, 20000);
        QVERIFY(frameText(window) != QString("Frame 0"));
        QVERIFY(clickButton(window, "playButton"));  // pause
        QVERIFY(!sim.isPlaying());

        // A second of walking moves most pedestrians by more than 0.3 m.
        const std::size_t shown = window.viewport().frameIndex();
        const auto start = sim.cache().frame(0), now = sim.cache().frame(shown);
        std::size_t moved = 0;
        for (std::size_t i = 0; i < start.size(); ++i)
            moved += glm::length(now[i].position - start[i].position) > 0.3f;
        QVERIFY2(moved > start.size() / 2, qPrintable(QString("%1 of %2 moved").arg(moved).arg(start.size())));

        // Scrub back with the keyboard on the scrub bar: Home is frame 0.
        // It spans the shot; its strip covers the recorded frames.
        TimelineRuler* scrub = window.timeline().scrubBar();
        QCOMPARE(scrub->maximum() + 1, int(sim.totalFrames()));
        QCOMPARE(scrub->cachedFrames(), sim.recordedFrames());
        scrub->setFocus();
        QTest::keyClick(scrub, Qt::Key_Home);
        QCOMPARE(window.viewport().frameIndex(), std::size_t(0));
        QCOMPARE(frameText(window), QString("Frame 0"));
        QTest::keyClick(scrub, Qt::Key_Right);
        QCOMPARE(window.viewport().frameIndex(), std::size_t(1));

        // Step computes or shows the next frame.
        QVERIFY(clickButton(window, "stepButton"));
        QTRY_COMPARE(window.viewport().frameIndex(), std::size_t(2));
        QVERIFY(clickButton(window, "restartButton"));
        QCOMPARE(window.viewport().frameIndex(), std::size_t(0));
    }

    void anEditKeepsTheFramesUpToTheShownOne()
    {
        // Issue 6: frames after the shown one are recomputed with the edit
        // (TestResumeAfterEditUi checks what they hold).
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        SimulationController& sim = window.simulation();
        QVERIFY(clickButton(window, "stepButton"));
        QTRY_COMPARE(window.viewport().frameIndex(), std::size_t(1));
        QVERIFY(clickToolButton(window, "obstacle"));
        clickOnGround(window, {-30, -30});
        QCOMPARE(window.document().scene().obstacles.size(), std::size_t(5));
        QCOMPARE(sim.recordedFrames(), std::size_t(2));
        QCOMPARE(sim.currentFrame(), std::size_t(1));
        QCOMPARE(window.viewport().frameIndex(), std::size_t(1));
        QVERIFY(clickButton(window, "stepButton"));
        QTRY_COMPARE(window.viewport().frameIndex(), std::size_t(2));
    }

    void savedSceneOpensAgainTheSame()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "crowdBrush"));
        dragOnGround(window, {{25, 25}, {35, 30}});
        QVERIFY(clickToolButton(window, "wall"));
        clickOnGround(window, {20, 40});
        clickOnGround(window, {40, 40});
        QTest::keyClick(&window.viewport(), Qt::Key_Return);
        QVERIFY(window.isWindowModified());
        QVERIFY(window.document().scene().agents.size() > 10);

        QTest::keyClick(&window.viewport(), Qt::Key_S, Qt::ControlModifier);
        QVERIFY(!window.isWindowModified());
        QVERIFY(!window.document().isModified());

        MainWindow reopened;
        reopened.show();
        QVERIFY(reopened.openScene(window.document().filePath()));
        const sim::Scene& a = window.document().scene();
        const sim::Scene& b = reopened.document().scene();
        QCOMPARE(b.agents.size(), a.agents.size());
        QCOMPARE(b.walls.size(), a.walls.size());
        for (std::size_t i = 0; i < a.agents.size(); ++i) {
            QCOMPARE(b.agents[i].id, a.agents[i].id);
            QVERIFY(glm::length(b.agents[i].position - a.agents[i].position) < 1e-3f);
            QVERIFY(std::abs(b.agents[i].headingDeg - a.agents[i].headingDeg) < 1e-2f);
        }
        QVERIFY(b.walls.back().points == a.walls.back().points);
    }

    void exportWritesAGlbOfTheChosenFrames()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QTest::keyClick(&window.viewport(), Qt::Key_E, Qt::ControlModifier | Qt::ShiftModifier);
        auto* dialog = window.findChild<ExportDialog*>("exportDialog");
        QVERIFY(dialog);
        QTRY_VERIFY(dialog->isVisible());
        auto* path = dialog->findChild<QLineEdit*>("exportPath");
        const QString out = m_dir.filePath("crowd.glb");
        // Indenting is for a .gltf's JSON: a .glb has none, and its box greys out.
        auto* indented = dialog->findChild<QCheckBox*>("exportIndented");
        QVERIFY(indented && !indented->isEnabled());
        path->selectAll();
        QTest::keyClicks(path, m_dir.filePath("crowd.gltf"));
        QVERIFY(indented->isEnabled());
        path->selectAll();
        QTest::keyClicks(path, out);
        QVERIFY(!indented->isEnabled());
        auto* last = dialog->findChild<QSpinBox*>("exportLastFrame");
        last->selectAll();
        QTest::keyClicks(last, "24");
        QTest::keyClick(last, Qt::Key_Tab);
        QCOMPARE(last->value(), 24);
        QTest::mouseClick(dialog->findChild<QPushButton*>("exportButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isBusy(), 60000);
        QVERIFY2(dialog->outcome().startsWith("Wrote"), qPrintable(dialog->outcome()));
        QFile file(out);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.read(4), QByteArray("glTF"));
        QVERIFY(file.size() > 10000);
        // The set comes with the crowd unless its box is cleared.
        const QByteArray withSet = file.readAll();
        for (const char* node : {"\"set_ground\"", "\"set_lanes\"", "\"set_crosswalks\"", "\"set_lights\"",
                                 "\"set_lamp_north_south_green\""})
            QVERIFY2(withSet.contains(node), node);
        auto* set = dialog->findChild<QCheckBox*>("exportSet");
        QVERIFY(set->isChecked() && set->isEnabled());
        QTest::mouseClick(set, Qt::LeftButton, {}, QPoint(8, set->height() / 2));
        QVERIFY(!set->isChecked());
        const QString bare = m_dir.filePath("bare.glb");
        path->selectAll();
        QTest::keyClicks(path, bare);
        QTest::mouseClick(dialog->findChild<QPushButton*>("exportButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isBusy(), 60000);
        QVERIFY2(dialog->outcome().startsWith("Wrote"), qPrintable(dialog->outcome()));
        QFile bareFile(bare);
        QVERIFY(bareFile.open(QIODevice::ReadOnly));
        const QByteArray without = bareFile.readAll();
        QVERIFY(!without.contains("\"set_") && without.contains("\"agent_"));
        QVERIFY(without.size() < withSet.size());
        // Formats without a set grey the box out.
        auto* format = dialog->findChild<QComboBox*>("exportFormat");
        format->setCurrentIndex(format->findData(QStringLiteral("csv")));
        QVERIFY(!set->isEnabled());
    }

    // USD and FBX from the dialog, chosen with the keyboard: the joint bake (USD's compact
    // mode writes its clips layer beside the stage) and the bodies' detail; FBX shares no
    // cycles, so its Joints box greys out.
    void exportWritesUsdAndFbxWithTheirChoices()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        ExportDialog* dialog = window.showExportDialog();
        auto* format = dialog->findChild<QComboBox*>("exportFormat");
        auto* joints = dialog->findChild<QComboBox*>("exportJoints");
        auto* detail = dialog->findChild<QComboBox*>("exportDetail");
        auto* path = dialog->findChild<QLineEdit*>("exportPath");
        auto* last = dialog->findChild<QSpinBox*>("exportLastFrame");
        QVERIFY(format && joints && detail && path && last);
        auto choose = [&](QComboBox* box, const QString& key) {
            box->setFocus();
            QTest::keyClick(box, Qt::Key_Home);
            for (int k = 0; k < box->count() && box->currentData().toString() != key; ++k)
                QTest::keyClick(box, Qt::Key_Down);
            return box->currentData().toString() == key;
        };
        last->selectAll();
        QTest::keyClicks(last, "24");
        QTest::keyClick(last, Qt::Key_Tab);
        QCOMPARE(last->value(), 24);

        QVERIFY(choose(format, "usd"));
        QVERIFY(path->text().endsWith(".usda"));
        QVERIFY(joints->isEnabled() && detail->isEnabled());
        joints->setFocus();
        QTest::keyClick(joints, Qt::Key_Down);
        QCOMPARE(exporting::JointBake(joints->currentData().toInt()), exporting::JointBake::Compact);
        const QString usd = m_dir.filePath("shot.usda");
        path->selectAll();
        QTest::keyClicks(path, usd);
        QTest::mouseClick(dialog->findChild<QPushButton*>("exportButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isBusy(), 120000);
        QVERIFY2(dialog->outcome().startsWith("Wrote"), qPrintable(dialog->outcome()));
        QFile stage(usd), clips(m_dir.filePath("shot.clips.usda"));
        QVERIFY(stage.open(QIODevice::ReadOnly) && clips.open(QIODevice::ReadOnly));
        const QByteArray stageText = stage.readAll();
        QVERIFY(stageText.startsWith("#usda 1.0") && stageText.contains("endTimeCode = 24"));
        QVERIFY(stageText.contains("asset[] assetPaths = [@./shot.clips.usda@]"));
        QVERIFY(clips.readAll().contains("def SkelAnimation \"man_0_walk\""));

        QVERIFY(choose(format, "fbx"));
        QVERIFY(!joints->isEnabled() && detail->isEnabled());
        detail->setFocus();
        QTest::keyClick(detail, Qt::Key_End);
        QCOMPARE(exporting::Lod(detail->currentData().toInt()), exporting::Lod::Far);
        const QString fbx = m_dir.filePath("shot.fbx");
        path->selectAll();
        QTest::keyClicks(path, fbx);
        QTest::mouseClick(dialog->findChild<QPushButton*>("exportButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isBusy(), 120000);
        QVERIFY2(dialog->outcome().startsWith("Wrote"), qPrintable(dialog->outcome()));
        QFile file(fbx);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QVERIFY(file.read(18) == QByteArray("Kaydara FBX Binary"));
        QVERIFY(choose(format, "csv"));
        QVERIFY(!joints->isEnabled() && !detail->isEnabled());
    }

    // A scene with a layout layer, opened and exported from the dialog: the CSV is the
    // laid-out crowd (agent 1 deleted, the others 5 m east of where they walked).
    void exportWritesTheLayoutLayersEdits()
    {
        const QString path = m_dir.filePath("laid.yaml");
        QFile scene(path);
        QVERIFY(scene.open(QIODevice::WriteOnly));
        scene.write("throng: 1\n"
                    "settings: {fps: 10, duration: 2, seed: 4}\n"
                    "agent_types: [{name: walker}]\n"
                    "goals: [{name: exit, position: [8, 0], radius: 1}]\n"
                    "groups: [{name: g, type: walker, count: 6, rect: {min: [-6, -3], max: [0, 3]}, goal: exit}]\n"
                    "layout:\n"
                    "  - {op: delete, agents: {ids: [1]}}\n"
                    "  - {op: translate, agents: {groups: [g]}, offset: [5, 0]}\n");
        scene.close();
        MainWindow window;
        QVERIFY(showWithSceneFile(window, path));
        ExportDialog* dialog = window.showExportDialog();
        auto* format = dialog->findChild<QComboBox*>("exportFormat");
        format->setCurrentIndex(format->findData(QStringLiteral("csv")));
        auto* pathEdit = dialog->findChild<QLineEdit*>("exportPath");
        const QString csv = m_dir.filePath("laid.csv");
        pathEdit->selectAll();
        QTest::keyClicks(pathEdit, csv);
        QTest::mouseClick(dialog->findChild<QPushButton*>("exportButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isBusy(), 60000);
        QVERIFY2(dialog->outcome().startsWith("Wrote"), qPrintable(dialog->outcome()));
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QStringList rows = QString::fromUtf8(file.readAll()).trimmed().split('\n').mid(1);
        QSet<QString> agents;
        for (const QString& row : rows) {
            const QStringList f = row.split(',');
            agents.insert(f[1]);
            QVERIFY2(f[2].toDouble() > -1.01, qPrintable(row));  // started at x >= -6, moved 5 m east
        }
        QCOMPARE(agents.size(), 5);  // agent 1 gone
        QVERIFY(!agents.contains("1"));
        QCOMPARE(rows.size() % 5, 0);
        QVERIFY(rows.size() >= 100);
    }

    // The viewport shows the recording through the layout layer: the deleted agent is not
    // drawn, the moved ones stand 5 m east of the simulation's places; an operation whose
    // agent the recording lacks is named in Messages.
    void theViewportShowsTheLayoutLayer()
    {
        const char* base = "throng: 1\n"
                           "settings: {fps: 10, duration: 2, seed: 4}\n"
                           "agent_types: [{name: walker}]\n"
                           "goals: [{name: exit, position: [8, 0], radius: 1}]\n"
                           "groups: [{name: g, type: walker, count: 6, rect: {min: [-6, -3], max: [0, 3]}, goal: exit}]\n";
        auto shownAt = [&](const QString& name, const QByteArray& layout, std::map<sim::AgentId, glm::vec3>& feet,
                           QString& messages) {
            const QString path = m_dir.filePath(name);
            QFile scene(path);
            if (!scene.open(QIODevice::WriteOnly))
                return false;
            scene.write(QByteArray(base) + layout);
            scene.close();
            MainWindow window;
            if (!showWithSceneFile(window, path))
                return false;
            auto* viewport = window.findChild<Viewport*>();
            if (!QTest::qWaitFor([&] { return !viewport->shownAgents().empty(); }, 20000))
                return false;
            const ShownAgents& shown = viewport->shownAgents();
            for (std::size_t i = 0; i < shown.size(); ++i)
                if (shown.drawn(i))
                    feet[shown.id(i)] = shown.feet(i);
            for (QListWidget* list : window.findChildren<QListWidget*>())
                for (int row = 0; row < list->count(); ++row)
                    messages += list->item(row)->text() + "\n";
            return true;
        };
        std::map<sim::AgentId, glm::vec3> plain, laid;
        QString plainMessages, laidMessages;
        QVERIFY(shownAt("plain.yaml", "", plain, plainMessages));
        QVERIFY(shownAt("shown.yaml",
                        "layout:\n"
                        "  - {op: delete, agents: {ids: [1]}}\n"
                        "  - {op: translate, agents: {groups: [g]}, offset: [5, 0]}\n"
                        "  - {op: delete, agents: {ids: [42]}}\n",
                        laid, laidMessages));
        QCOMPARE(plain.size(), std::size_t(6));
        QCOMPARE(laid.size(), std::size_t(5));
        QVERIFY(!laid.count(1));
        for (const auto& [id, at] : laid)
            QVERIFY2(glm::length(at - (plain.at(id) + glm::vec3(5, 0, 0))) < 1e-3f, qPrintable(QString::number(id)));
        QVERIFY2(laidMessages.contains("1 agent is not in the recording (id 42)"), qPrintable(laidMessages));
    }

    // While a run records, the shown frames grow with it, each laid out once; the result
    // is the whole recording laid out at once (with a translate and expand, and with a time
    // offset later and one earlier, which read other frames: laid out anew only a few times
    // over the run, not on every frame, and once more at the end).
    void theShownRecordingKeepsUpWithTheRun()
    {
        for (const char* extra : {"", "  - {op: time_offset, agents: {ids: [2, 3]}, later: 7}\n"
                                      "  - {op: time_offset, agents: {ids: [4]}, later: -5}\n"}) {
            const std::string yaml = std::string("throng: 1\n"
                                                 "settings: {fps: 10, duration: 8, seed: 4}\n"
                                                 "agent_types: [{name: walker}]\n"
                                                 "goals: [{name: exit, position: [8, 0], radius: 1}]\n"
                                                 "groups: [{name: g, type: walker, count: 6, rect: {min: [-6, -3], "
                                                 "max: [0, 3]}, goal: exit}]\n"
                                                 "layout:\n"
                                                 "  - {op: translate, agents: {ids: [1, 2]}, offset: [2, 1]}\n"
                                                 "  - {op: expand, agents: {groups: [g]}, factor: 1.5}\n") +
                                     extra;
            const sim::LoadResult loaded = sim::parseScene(yaml, "grow.yaml", "");
            QVERIFY(loaded.ok());
            sim::World world(loaded.scene);
            sim::FrameCache cache;
            world.startRecording(cache);
            ShownRecording shown;
            std::vector<sim::AgentFrame> frame;
            for (int f = 1; f < 80; ++f) {
                world.step();
                world.snapshot(frame);
                cache.append(frame);
                QCOMPARE(shown.frames(cache, loaded.scene).frameCount(), cache.frameCount());
            }
            // 80 frames: laid out whole on frame 1, then at 25 and 51 (a tenth and 24 more).
            QVERIFY2(shown.fullLayouts() <= (*extra ? 3u : 1u), qPrintable(QString::number(shown.fullLayouts())));
            QCOMPARE(shown.frames(cache, loaded.scene).hash(), sim::applyLayout(loaded.scene, cache).hash());
            QVERIFY(shown.frames(cache, loaded.scene).hash() != cache.hash());
            QVERIFY(shown.fullLayouts() <= 4);
        }
    }

    void exportCanBeCancelledAndLeavesNoFile()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        ExportDialog* dialog = window.showExportDialog();
        auto* path = dialog->findChild<QLineEdit*>("exportPath");
        const QString out = m_dir.filePath("never.glb");
        path->setText(out);
        QTest::mouseClick(dialog->findChild<QPushButton*>("exportButton"), Qt::LeftButton);
        QVERIFY(dialog->isBusy());
        QTest::mouseClick(dialog->findChild<QPushButton*>("cancelButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isBusy(), 30000);
        QVERIFY2(dialog->outcome().startsWith("Cancelled"), qPrintable(dialog->outcome()));
        QVERIFY(!QFile::exists(out));
    }

    // The format list is the export table; the text cache writes a file per agent into
    // the directory the path names, and switching back gives the path a suffix again.
    void exportWritesTheTextCacheIntoADirectory()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        ExportDialog* dialog = window.showExportDialog();
        auto* format = dialog->findChild<QComboBox*>("exportFormat");
        QCOMPARE(std::size_t(format->count()), exporting::exportFormats().size());
        auto* path = dialog->findChild<QLineEdit*>("exportPath");
        QVERIFY(path->text().endsWith(".glb"));
        format->setCurrentIndex(format->findData(QStringLiteral("text-cache")));
        QVERIFY2(!path->text().endsWith(".glb"), qPrintable(path->text()));
        const QString out = m_dir.filePath("caches/shot1");
        path->setText(out);
        dialog->findChild<QSpinBox*>("exportLastFrame")->setValue(4);
        QTest::mouseClick(dialog->findChild<QPushButton*>("exportButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isBusy(), 60000);
        QVERIFY2(dialog->outcome().startsWith("Wrote"), qPrintable(dialog->outcome()));
        const QStringList files = QDir(out).entryList(QDir::Files);
        QVERIFY(!files.isEmpty());
        QVERIFY2(dialog->outcome().contains(QString::number(files.size()) + " files"), qPrintable(dialog->outcome()));
        for (const QString& f : files)
            QVERIFY2(f.startsWith("agent_") && f.endsWith(".txt"), qPrintable(f));
        format->setCurrentIndex(format->findData(QStringLiteral("csv")));
        QCOMPARE(path->text(), m_dir.filePath("caches/shot1.csv"));

        // The Maya cache: the same files, rotY for rigs facing +Z, and its manifest.
        format->setCurrentIndex(format->findData(QStringLiteral("maya-cache")));
        const QString maya = m_dir.filePath("caches/maya1");
        path->setText(maya);
        QTest::mouseClick(dialog->findChild<QPushButton*>("exportButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isBusy(), 60000);
        QVERIFY2(dialog->outcome().startsWith("Wrote"), qPrintable(dialog->outcome()));
        QCOMPARE(QDir(maya).entryList(QDir::Files).size(), files.size() + 1);
        QFile manifest(QDir(maya).filePath("throng_cache.txt"));
        QVERIFY(manifest.open(QIODevice::ReadOnly));
        const QByteArray text = manifest.readAll();
        QVERIFY2(text.contains("\nframes 5\n") && text.contains("\nforward +z\n"), text.constData());
    }

    void unsavedChangesAreAskedAbout()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "trafficLight"));
        clickOnGround(window, {20, -12});
        int asked = 0;
        window.setUnsavedChangesPrompt([&asked] {
            ++asked;
            return QMessageBox::Cancel;
        });
        QTest::keyClick(&window.viewport(), Qt::Key_N, Qt::ControlModifier);
        QCOMPARE(asked, 1);
        QCOMPARE(window.document().scene().trafficLights.size(), std::size_t(3));
        window.setUnsavedChangesPrompt([&asked] {
            ++asked;
            return QMessageBox::Discard;
        });
        QTest::keyClick(&window.viewport(), Qt::Key_N, Qt::ControlModifier);
        QCOMPARE(asked, 2);
        QVERIFY(window.document().scene().trafficLights.empty());
        QVERIFY(window.document().filePath().isEmpty());
    }
};

THRONG_REGISTER_TEST(TestPlaybackAndFilesUi)
#include "TestPlaybackAndFilesUi.moc"
