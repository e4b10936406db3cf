#include "EditorUiDriver.h"

#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <QDir>
#include <QFile>
#include <QTabBar>
#include <QTest>
#include <QToolButton>

#include <algorithm>

namespace throng::editor::test {

bool showWithScene(MainWindow& window, const QTemporaryDir& dir, const QString& name)
{
    // The demos refer to their brains as "../brains/": copy the two folders side by side.
    const QString resources = QStringLiteral(THRONG_SOURCE_DIR "/resources/");
    if (!QDir(dir.path()).mkpath("scenes") || !QDir(dir.path()).mkpath("brains"))
        return false;
    for (const QString& brain : QDir(resources + "brains").entryList({"*.brain.yaml"}, QDir::Files))
        if (!QFile::exists(dir.filePath("brains/" + brain)) &&
            !QFile::copy(resources + "brains/" + brain, dir.filePath("brains/" + brain)))
            return false;
    const QString copy = dir.filePath("scenes/" + name);
    QFile::remove(copy);
    if (!QFile::copy(resources + "scenes/" + name, copy))
        return false;
    QFile(copy).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
    return showWithSceneFile(window, copy);
}

bool showWithSceneFile(MainWindow& window, const QString& path)
{
    window.resize(1400, 900);
    window.show();
    window.activateWindow();
    if (!QTest::qWaitForWindowExposed(&window) || !QTest::qWaitForWindowActive(&window))
        return false;
    if (!window.openScene(path))
        return false;
    QCoreApplication::processEvents();
    // The agents come with frame 0 from the simulation's thread (a scene with nobody in
    // it records no frame): frame the set with them, as a user sees it once they show.
    const sim::Scene& scene = window.document().scene();
    const bool crowd = !scene.agents.empty() || !scene.heroes.empty() || !scene.vehicles.empty() ||
                       std::any_of(scene.groups.begin(), scene.groups.end(), [](const sim::SpawnGroup& g) {
                           return g.count > 0;
                       });
    if (crowd && !QTest::qWaitFor([&window] { return window.simulation().recordedFrames() > 0; }, 60000))
        qWarning("no frame 0 came for %s (a scene the simulation cannot run?)", qPrintable(path));
    window.viewport().frameAll();
    return true;
}

QPoint pixelOf(MainWindow& window, glm::vec2 ground)
{
    return window.viewport().worldToPixel({ground.x, 0.0f, ground.y}).toPoint();
}

bool clickToolButton(MainWindow& window, const QString& key)
{
    auto* button = window.findChild<QToolButton*>(key + "Button");
    if (!button)
        return false;
    QTest::mouseClick(button, Qt::LeftButton);
    return window.viewport().tool() && window.viewport().tool()->objectKey() == key;
}

bool clickDockTab(MainWindow& window, const QString& title)
{
    for (QTabBar* bar : window.findChildren<QTabBar*>())
        for (int t = 0; t < bar->count(); ++t)
            if (bar->tabText(t).remove('&') == title && bar->isVisible()) {
                QTest::mouseClick(bar, Qt::LeftButton, Qt::NoModifier, bar->tabRect(t).center());
                return true;
            }
    return false;
}

void dragOnGround(MainWindow& window, const std::vector<glm::vec2>& points)
{
    QWidget* viewport = &window.viewport();
    constexpr int kMovesPerLeg = 10;
    QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, pixelOf(window, points.front()));
    for (std::size_t i = 1; i < points.size(); ++i)
        for (int k = 1; k <= kMovesPerLeg; ++k) {
            const glm::vec2 p = points[i - 1] + (points[i] - points[i - 1]) * (float(k) / kMovesPerLeg);
            QTest::mouseMove(viewport, pixelOf(window, p));
        }
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, pixelOf(window, points.back()));
}

void clickOnGround(MainWindow& window, glm::vec2 point)
{
    QTest::mouseClick(&window.viewport(), Qt::LeftButton, Qt::NoModifier, pixelOf(window, point));
}

}  // namespace throng::editor::test
