#include "report/ChartImage.h"

#include <QtCharts/QChart>

#include <QApplication>
#include <QGraphicsScene>
#include <QPainter>

namespace throng::report {

bool ensureApplication()
{
    if (QCoreApplication::instance())
        return qobject_cast<QApplication*>(QCoreApplication::instance()) != nullptr;
    // A report needs no screen: the offscreen platform renders the same pixels anywhere,
    // including a farm node with no display.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "throng-cli";
    static char* argv[] = {name, nullptr};
    static QApplication* app = new QApplication(argc, argv);
    return app != nullptr;
}

QImage renderChart(QChart& chart, QSize size)
{
    QGraphicsScene scene;
    scene.addItem(&chart);
    chart.resize(size);
    scene.setSceneRect(0, 0, size.width(), size.height());
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    {
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        scene.render(&painter, QRectF(0, 0, size.width(), size.height()), scene.sceneRect());
    }
    scene.removeItem(&chart);
    return image;
}

}  // namespace throng::report
