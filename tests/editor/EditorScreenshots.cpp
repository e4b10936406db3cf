// editor_screenshots: the pictures of docs/editor.md and the README, taken from the real
// window driven as a user drives it (never a test). Run under a display:
//   xvfb-run -a -s "-screen 0 1920x1080x24" editor_screenshots OUTDIR
// writes OUTDIR/editor-layout.png, editor-brains.png, editor-new-scene.png,
// editor-timeline.png, editor-shortcuts.png, editor-overlays.png, editor-steering.png,
// editor-3d-set.png and editor-layout-edits.png.
#include "EditorUiDriver.h"

#include "editor/DarkTheme.h"
#include "editor/HelpMenu.h"
#include "editor/WorkspaceLayout.h"
#include "editor/brain/BrainEditorPanel.h"
#include "editor/layout/LayoutPanel.h"
#include "editor/panels/OutlinerPanel.h"
#include "editor/panels/TimelinePanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <QApplication>
#include <QDialog>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QWheelEvent>

#include <cmath>
#include <iostream>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

bool save(QWidget& widget, const QString& path)
{
    QTest::qWait(200);
    const bool ok = widget.grab().save(path);
    std::cout << (ok ? "wrote " : "could not write ") << path.toStdString() << '\n';
    return ok;
}

// The View menu's choices as a first launch has them (the HUD on, agents by tint, no
// overlays), whatever an earlier picture or run left in the settings.
void defaultViewSettings()
{
    QSettings().remove("viewport");
}

// The crossroads demo in a 1280 x 800 window, shown and settled: each picture's start.
bool showCrossroads(MainWindow& window, const QTemporaryDir& dir)
{
    if (!showWithScene(window, dir, "crossroads.yaml"))
        return false;
    window.resize(1280, 800);
    QTest::qWait(100);
    return true;
}

void playTo(MainWindow& window, std::size_t frame)
{
    window.simulation().seek(frame);  // computes up to it, as a click on the timeline does
    for (int i = 0; i < 600 && window.viewport().frameIndex() < frame; ++i)
        QTest::qWait(50);
}

}  // namespace

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(Viewport::surfaceFormat());
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);  // the user's saved layout stays out of the pictures
    QCoreApplication::setOrganizationName("ThrongScreenshots");
    applyDarkTheme(app);
    if (argc < 2) {
        std::cerr << "usage: editor_screenshots OUTDIR\n";
        return 2;
    }
    const QString out = QString::fromLocal8Bit(argv[1]);
    QDir().mkpath(out);
    QTemporaryDir dir;
    bool ok = true;
    {
        // A new scene: a pedestrian type, a spawn group drawn, a wall and a goal.
        defaultViewSettings();
        MainWindow window;
        window.resize(1280, 800);
        window.show();
        if (!QTest::qWaitForWindowExposed(&window))
            return 1;
        window.viewport().frameAll();
        clickToolButton(window, "group");
        dragOnGround(window, {{-30, -10}, {-15, 10}});
        clickToolButton(window, "wall");
        for (glm::vec2 p : {glm::vec2(0, -30), glm::vec2(0, -3)})
            clickOnGround(window, p);
        QTest::keyClick(&window.viewport(), Qt::Key_Return);
        for (glm::vec2 p : {glm::vec2(0, 3), glm::vec2(0, 30)})
            clickOnGround(window, p);
        QTest::keyClick(&window.viewport(), Qt::Key_Return);
        clickToolButton(window, "goal");
        clickOnGround(window, {25, 0});
        clickToolButton(window, "group");
        // Mid-drag, so the preview and its count show.
        QTest::mousePress(&window.viewport(), Qt::LeftButton, Qt::NoModifier, pixelOf(window, {-30, 15}));
        QTest::mouseMove(&window.viewport(), pixelOf(window, {-22, 22}));
        QTest::mouseMove(&window.viewport(), pixelOf(window, {-15, 28}));
        ok = save(window, out + "/editor-new-scene.png") && ok;
        QTest::mouseRelease(&window.viewport(), Qt::LeftButton, Qt::NoModifier, pixelOf(window, {-15, 28}));
    }
    {
        defaultViewSettings();
        MainWindow window;
        if (!showCrossroads(window, dir))
            return 1;
        window.viewport().frameAll();
        playTo(window, 360);
        window.document().setSelection({{ItemKind::Group, 0}});
        ok = save(window, out + "/editor-layout.png") && ok;
        auto* timeline = window.findChild<QDockWidget*>("timelineDock");
        ok = save(*timeline, out + "/editor-timeline.png") && ok;
        QTest::keyClick(&window.viewport(), Qt::Key_B, Qt::ControlModifier);
        QTest::qWait(200);
        window.viewport().frameAll();
        ok = save(window, out + "/editor-brains.png") && ok;
        QTest::keyClick(&window.viewport(), Qt::Key_B, Qt::ControlModifier);
        QTest::keyClick(&window.viewport(), Qt::Key_Slash, Qt::ControlModifier);
        if (auto* sheet = window.findChild<QDialog*>("shortcutsDialog")) {
            ok = save(*sheet, out + "/editor-shortcuts.png") && ok;
            sheet->close();
        } else {
            ok = false;
        }
    }
    {
        // The viewport explaining the crowd: agents by speed, the HUD, a walker clicked in
        // the selected group with its trail and steering, the density under the crowd.
        defaultViewSettings();
        MainWindow window;
        if (!showCrossroads(window, dir))
            return 1;
        Viewport& viewport = window.viewport();
        viewport.frameAll();
        playTo(window, 300);
        for (int k = 0; k < 6; ++k)  // tint, type, group, goal, path, brain, speed
            QTest::keyClick(&viewport, Qt::Key_C, Qt::ShiftModifier);
        QTest::keyClick(&viewport, Qt::Key_T);
        QTest::keyClick(&viewport, Qt::Key_D);
        QTest::keyClick(&viewport, Qt::Key_M);
        QTest::keyClick(&viewport, Qt::Key_Q);
        // The walker nearest the middle of the view, clicked where it is drawn.
        const ShownAgents& shown = viewport.shownAgents();
        const QPointF middle(viewport.width() * 0.5, viewport.height() * 0.5);
        std::size_t pick = ShownAgents::kNone;
        double best = 1e9;
        for (std::size_t i = 0; i < shown.size(); ++i) {
            const QPointF p = viewport.worldToPixel(shown.feet(i));
            const double d = std::hypot(p.x() - middle.x(), p.y() - middle.y());
            if (shown.drawn(i) && d < best && shown.radiusM(i) < 0.5f) {
                best = d;
                pick = i;
            }
        }
        if (pick != ShownAgents::kNone)
            QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, viewport.worldToPixel(shown.feet(pick)).toPoint());
        playTo(window, 340);
        QTest::qWait(300);
        ok = save(window, out + "/editor-overlays.png") && ok;
        // Zoomed in on the watched walker with the wheel at it, as a user zooms.
        const std::size_t watched = shown.find(viewport.focusedAgent());
        if (watched != ShownAgents::kNone)
            for (int k = 0; k < 12; ++k) {
                const QPointF at = viewport.worldToPixel(shown.feet(watched));
                QWheelEvent wheel(at, viewport.mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                                  Qt::NoScrollPhase, false);
                QApplication::sendEvent(&viewport, &wheel);
            }
        QTest::qWait(300);
        ok = save(viewport, out + "/editor-steering.png") && ok;
    }
    {
        // The 3D set: the crossroads' walls, signal poles and striped crossings in 3D.
        defaultViewSettings();
        MainWindow window;
        if (!showCrossroads(window, dir))
            return 1;
        Viewport& viewport = window.viewport();
        QTest::keyClick(&viewport, Qt::Key_2, Qt::ControlModifier);
        viewport.frameAll();
        for (int k = 0; k < 5; ++k) {  // in towards the middle of the crossing
            const QPointF at(viewport.width() * 0.5, viewport.height() * 0.55);
            QWheelEvent wheel(at, viewport.mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                              Qt::NoScrollPhase, false);
            QApplication::sendEvent(&viewport, &wheel);
        }
        playTo(window, 300);
        ok = save(viewport, out + "/editor-3d-set.png") && ok;
    }
    {
        // Editing the take: a group dragged with Layout Move, another squeezed by an Expand
        // typed in Properties; the check's rings, HUD count and list; the trails of the
        // selected operation's agents.
        defaultViewSettings();
        MainWindow window;
        if (!showCrossroads(window, dir))
            return 1;
        Viewport& viewport = window.viewport();
        viewport.frameAll();
        playTo(window, 240);
        auto* dock = window.findChild<QDockWidget*>("layoutDock");
        dock->show();
        dock->raise();
        window.document().setSelection({{ItemKind::Group, 1}});
        window.layoutPanel().addOperation(sim::LayoutKind::Expand);
        if (auto* factor = window.findChild<QWidget*>("properties")->findChild<QDoubleSpinBox*>("factor")) {
            factor->setFocus();
            factor->selectAll();
            QTest::keyClicks(factor, "0.35");
            QTest::keyClick(factor, Qt::Key_Return);
        }
        window.document().setSelection({{ItemKind::Group, 0}});
        clickToolButton(window, "layoutMove");
        const ShownAgents& shown = viewport.shownAgents();
        glm::vec2 from(0.0f);
        for (std::size_t i = 0; i < shown.size(); ++i)
            if (shown.drawn(i)) {
                from = {shown.feet(i).x, shown.feet(i).z};
                break;
            }
        dragOnGround(window, {from, from + glm::vec2(4.0f, -3.0f)});
        QTest::keyClick(&viewport, Qt::Key_T);  // the trails of the moved group's paths
        QTest::qWait(800);                      // the check settles
        ok = save(window, out + "/editor-layout-edits.png") && ok;
    }
    return ok ? 0 : 1;
}
