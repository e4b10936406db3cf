#include "EditorTestSupport.h"

#include "EditorUiDriver.h"

#include "editor/MessagesPanel.h"
#include "editor/panels/OutlinerPanel.h"
#include "editor/panels/TimelinePanel.h"
#include "editor/simulation/SimulationController.h"
#include "simcore/io/SceneIO.h"

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QScrollArea>
#include <QSlider>

#include <QApplication>
#include <QFile>
#include <QTest>
#include <QTimer>

#include <cmath>
#include <cstdlib>
#include <memory>

namespace throng::editor::test {

QString writeScene(const QTemporaryDir& dir, const QString& name, const QByteArray& yaml)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(yaml) != yaml.size())
        qFatal("cannot write the test scene %s", qPrintable(path));
    return path;
}

sim::Scene loadTestScene(const QTemporaryDir& dir, const QByteArray& yaml)
{
    const QString path = writeScene(dir, "scene.yaml", yaml);
    sim::LoadResult loaded = sim::loadScene(path.toStdString());
    if (!loaded.ok())
        qFatal("test scene does not load: %s", loaded.diagnostics.front().format().c_str());
    return loaded.scene;
}

QImage renderOffscreen(Viewport& viewport, QSize sizePx)
{
    viewport.setAttribute(Qt::WA_DontShowOnScreen);
    viewport.resize(sizePx);
    viewport.show();
    return viewport.grabFramebuffer();
}

QRgb pixelAt(const QImage& image, const Viewport& viewport, QPointF widgetPos)
{
    const double scale = double(image.width()) / double(viewport.width());
    const int x = int(std::lround(widgetPos.x() * scale)), y = int(std::lround(widgetPos.y() * scale));
    return image.valid(x, y) ? image.pixel(x, y) : 0;
}

bool sameColour(QRgb pixel, glm::vec4 colour, int tolerance)
{
    auto channel = [](float c) { return int(std::lround(c * 255.0f)); };
    return std::abs(qRed(pixel) - channel(colour.r)) <= tolerance &&
           std::abs(qGreen(pixel) - channel(colour.g)) <= tolerance &&
           std::abs(qBlue(pixel) - channel(colour.b)) <= tolerance;
}

int pixelsOf(MainWindow& window, const QImage& image, glm::vec2 centre, float radiusM, glm::vec4 colour, int tolerance)
{
    int hits = 0;
    for (float dx = -radiusM; dx <= radiusM; dx += 0.05f)
        for (float dz = -radiusM; dz <= radiusM; dz += 0.05f)
            if (dx * dx + dz * dz <= radiusM * radiusM)
                hits += sameColour(pixelAt(image, window.viewport(),
                                           window.viewport().worldToPixel({centre.x + dx, 0.0f, centre.y + dz})),
                                   colour, tolerance);
    return hits;
}

QString describe(QRgb pixel)
{
    return QStringLiteral("rgb(%1, %2, %3)").arg(qRed(pixel)).arg(qGreen(pixel)).arg(qBlue(pixel));
}

QString describe(glm::vec4 colour)
{
    return describe(qRgb(int(std::lround(colour.r * 255.0f)), int(std::lround(colour.g * 255.0f)),
                         int(std::lround(colour.b * 255.0f))));
}

bool showWithYaml(MainWindow& window, const QTemporaryDir& dir, const QString& name, const QByteArray& yaml)
{
    return showWithSceneFile(window, writeScene(dir, name, yaml));
}

bool clickButton(MainWindow& window, const QString& objectName)
{
    auto* button = window.findChild<QAbstractButton*>(objectName);
    if (!button)
        return false;
    QTest::mouseClick(button, Qt::LeftButton);
    return true;
}

bool playToFrame(MainWindow& window, std::size_t frame, int timeoutMs)
{
    SimulationController& sim = window.simulation();
    if (!sim.isPlaying() && !clickButton(window, "playButton"))
        return false;
    const bool reached = QTest::qWaitFor([&] { return window.viewport().frameIndex() >= frame; }, timeoutMs);
    if (sim.isPlaying())
        clickButton(window, "playButton");
    return reached;
}

bool playUntilRecorded(MainWindow& window, std::size_t last, int timeoutMs)
{
    SimulationController& sim = window.simulation();
    if (!clickButton(window, "playButton"))
        return false;
    const bool recorded = QTest::qWaitFor([&] { return sim.recordedFrames() > last; }, timeoutMs);
    if (sim.isPlaying())
        clickButton(window, "playButton");
    return recorded && !sim.isPlaying();
}

bool scrubWithKeys(MainWindow& window, std::size_t frame)
{
    QSlider* scrub = window.timeline().scrubBar();
    scrub->setFocus();
    QTest::keyClick(scrub, Qt::Key_Home);
    for (std::size_t f = 0; f < frame; ++f)
        QTest::keyClick(scrub, Qt::Key_Right);
    return window.simulation().currentFrame() == frame && window.viewport().frameIndex() == frame;
}

std::uint64_t hashOfFirst(const sim::FrameCache& cache, std::size_t frames)
{
    sim::FrameCache copy = cache;
    copy.truncate(frames);
    return copy.hash();
}

QString frameText(MainWindow& window)
{
    return window.findChild<QLabel*>("frameLabel")->text();
}

QString agentCountText(MainWindow& window)
{
    return window.findChild<QLabel*>("agentCountLabel")->text();
}

void selectInOutliner(MainWindow& window, const Selection& items)
{
    OutlinerPanel& outliner = window.outliner();
    for (std::size_t k = 0; k < items.size(); ++k) {
        QTreeWidgetItem* heading = outliner.kindRow(items[k].kind);
        if (!heading || int(items[k].index) >= heading->childCount())
            qFatal("the outliner has no row for item %zu of kind %d", items[k].index, int(items[k].kind));
        heading->setExpanded(true);
        QTreeWidgetItem* row = heading->child(int(items[k].index));
        outliner.scrollToItem(row);
        QTest::mouseClick(outliner.viewport(), Qt::LeftButton, k == 0 ? Qt::NoModifier : Qt::ControlModifier,
                          outliner.visualItemRect(row).center());
    }
}

QByteArray sceneYaml(MainWindow& window)
{
    return QByteArray::fromStdString(sim::sceneToYaml(window.document().scene()));
}

void showInPanel(MainWindow& window, QWidget* widget)
{
    QTRY_VERIFY(widget->isVisible() && widget->height() > 0);
    window.findChild<QWidget*>("properties")->findChild<QScrollArea*>()->ensureWidgetVisible(widget);
}

void pick(MainWindow& window, const QString& name, const QString& text, Scroll scroll)
{
    auto* combo = field<QComboBox>(window, name);
    QVERIFY2(combo, qPrintable(name));
    if (scroll == Scroll::ToWidget)
        showInPanel(window, combo);
    combo->setFocus();
    QTest::keyClicks(combo, text);
    QCOMPARE(combo->currentText(), text);
}

void typeInto(QWidget* widget, const QString& text)
{
    QVERIFY(widget);
    widget->setFocus();
    if (auto* spin = qobject_cast<QAbstractSpinBox*>(widget))
        spin->selectAll();
    else if (auto* edit = qobject_cast<QLineEdit*>(widget))
        edit->selectAll();
    QTest::keyClick(widget, Qt::Key_Backspace);
    QTest::keyClicks(widget, text);
    QTest::keyClick(widget, Qt::Key_Return);
}

void typeInto(MainWindow& window, QWidget* widget, const QString& text)
{
    QVERIFY(widget);
    showInPanel(window, widget);
    typeInto(widget, text);
}

void press(MainWindow& window, const QString& name)
{
    auto* button = field<QPushButton>(window, name);
    QVERIFY2(button, qPrintable(name));
    showInPanel(window, button);
    QTest::mouseClick(button, Qt::LeftButton);
}

void showNewWindow(MainWindow& window)
{
    window.resize(1400, 900);
    window.show();
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(QTest::qWaitForWindowActive(&window));
}

bool clickPopupItem(const QString& text)
{
    auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
    if (!menu)
        return false;
    for (QAction* a : menu->actions())
        if (a->text().remove('&') == text) {
            QTest::mouseClick(menu, Qt::LeftButton, Qt::NoModifier, menu->actionGeometry(a).center());
            return true;
        }
    return false;
}

void whenShown(std::function<bool()> answer)
{
    auto* timer = new QTimer;
    timer->setInterval(20);
    auto tries = std::make_shared<int>(0);
    QObject::connect(timer, &QTimer::timeout, timer, [timer, answer, tries] {
        if (answer() || ++*tries > 250)
            timer->deleteLater();
    });
    timer->start();
}

void undo(MainWindow& window)
{
    QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
}

QString lastMessage(MainWindow& window)
{
    return window.messages().count() > 0 ? window.messages().item(0)->text() : QString();
}

}  // namespace throng::editor::test
