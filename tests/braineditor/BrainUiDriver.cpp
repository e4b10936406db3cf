#include "BrainUiDriver.h"

#include "editor/brain/BrainGraphModel.h"
#include "editor/brain/BrainScene.h"
#include "editor/brain/BrainView.h"
#include "editor/brain/NodeItem.h"
#include "editor/brain/NodePalette.h"
#include "editor/brain/PortItem.h"

#include <QApplication>
#include <QDockWidget>
#include <QFile>
#include <QLineEdit>
#include <QTest>

namespace throng::editor::test {

BrainUi::BrainUi(MainWindow& window)
    : m_window(window), m_panel(window.findChild<BrainEditorPanel*>("brainEditor"))
{
}

bool BrainUi::open(const QTemporaryDir& dir, const QByteArray& yaml)
{
    if (!m_panel)
        return false;
    const QString path = dir.filePath("scene.yaml");
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(yaml) != yaml.size())
        return false;
    file.close();
    return openPath(path);
}

bool BrainUi::openPath(const QString& path)
{
    if (!m_panel)
        return false;
    m_window.resize(1600, 1100);
    m_window.show();
    m_window.activateWindow();
    if (!QTest::qWaitForWindowExposed(&m_window) || !QTest::qWaitForWindowActive(&m_window))
        return false;
    // The Brains workspace, as a user opens it (closed until asked for).
    if (!m_panel->isVisible())
        QTest::keyClick(&m_window, Qt::Key_B, Qt::ControlModifier);
    QCoreApplication::processEvents();
    if (!m_panel->isVisible())
        return false;
    if (!m_window.openScene(path))
        return false;
    QCoreApplication::processEvents();
    m_panel->view().setFocus();
    return true;
}

QPoint BrainUi::pixel(QPointF scenePos) const
{
    return m_panel->view().mapFromScene(scenePos);
}

sim::NodeId BrainUi::addByTyping(QPointF scenePos, const QString& text)
{
    BrainView& view = m_panel->view();
    view.setFocus();
    QTest::mouseMove(view.viewport(), pixel(scenePos));
    const std::size_t before = m_panel->model().graph().nodes.size();
    QTest::keyClick(&view, Qt::Key_Tab);
    NodePalette& palette = m_panel->palette();
    if (!palette.isVisible())
        return 0;
    QTest::keyClicks(palette.search(), text);
    QTest::keyClick(palette.search(), Qt::Key_Return);
    const sim::BrainGraph& g = m_panel->model().graph();
    return g.nodes.size() > before ? g.nodes.back().id : 0;
}

void BrainUi::drag(QPointF fromScene, QPointF toScene, Qt::KeyboardModifiers mods)
{
    QWidget* vp = m_panel->view().viewport();
    const QPoint a = pixel(fromScene), b = pixel(toScene);
    QTest::mouseMove(vp, a);
    QTest::mousePress(vp, Qt::LeftButton, mods, a);
    constexpr int kSteps = 8;
    for (int k = 1; k <= kSteps; ++k)
        QTest::mouseMove(vp, a + (b - a) * k / kSteps);
    QTest::mouseRelease(vp, Qt::LeftButton, mods, b);
}

void BrainUi::dragLink(sim::NodeId from, int fromPort, sim::NodeId to, int toPort)
{
    BrainScene& scene = m_panel->scene();
    NodeItem* a = scene.nodeItem(from);
    NodeItem* b = scene.nodeItem(to);
    if (!a || !b || !a->outputPort(fromPort) || !b->inputPort(toPort))
        return;
    drag(a->outputPort(fromPort)->centre(), b->inputPort(toPort)->centre());
}

bool BrainUi::editParam(sim::NodeId node, const QString& key, const QString& text)
{
    NodeItem* item = m_panel->scene().nodeItem(node);
    if (!item)
        return false;
    for (int row = 0; item->paramSpec(row); ++row) {
        if (QString::fromStdString(item->paramSpec(row)->key) != key)
            continue;
        const QPoint at = pixel(item->mapToScene(item->paramRect(row).center()));
        QTest::mouseDClick(m_panel->view().viewport(), Qt::LeftButton, Qt::NoModifier, at);
        auto* line = qobject_cast<QLineEdit*>(m_panel->scene().paramEditor());
        if (!line)
            return false;
        line->selectAll();
        QTest::keyClicks(line, text);
        QTest::keyClick(line, Qt::Key_Return);
        return true;
    }
    return false;
}

void BrainUi::click(QPointF scenePos, Qt::KeyboardModifiers mods)
{
    QTest::mouseClick(m_panel->view().viewport(), Qt::LeftButton, mods, pixel(scenePos));
}

void BrainUi::key(int key, Qt::KeyboardModifiers mods)
{
    m_panel->view().setFocus();
    QTest::keyClick(&m_panel->view(), Qt::Key(key), mods);
}

int BrainUi::nodeCount() const
{
    return int(m_panel->model().graph().nodes.size());
}

int BrainUi::linkCount() const
{
    return int(m_panel->model().graph().links.size());
}

}  // namespace throng::editor::test
