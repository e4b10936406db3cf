#include "report/WedgeChart.h"

#include "report/ChartImage.h"

#include <QtCharts/QBarCategoryAxis>
#include <QtCharts/QBarSeries>
#include <QtCharts/QBarSet>
#include <QtCharts/QChart>
#include <QtCharts/QValueAxis>

#include <QImageWriter>

#include <algorithm>

namespace throng::report {

std::string writeWedgeChart(const std::string& path, const std::string& metric, const std::vector<WedgeBar>& bars)
{
    if (!ensureApplication())
        return "cannot plot " + path + ": the program runs an application that cannot draw";
    QChart chart;
    chart.setTitle(QString::fromStdString(metric) + QStringLiteral(" by variant"));
    chart.setAnimationOptions(QChart::NoAnimation);
    chart.legend()->hide();
    auto* series = new QBarSeries;
    auto* set = new QBarSet(QString::fromStdString(metric));
    set->setColor(QColor(0, 114, 178));
    QStringList labels;
    double top = 0.0;
    for (const WedgeBar& b : bars) {
        *set << (b.value ? *b.value : 0.0);
        top = std::max(top, b.value.value_or(0.0));
        labels << QString::fromStdString(b.label) + (b.value ? QString() : QStringLiteral(" (failed)"));
    }
    series->append(set);
    chart.addSeries(series);
    auto* categories = new QBarCategoryAxis;
    categories->append(labels);
    categories->setLabelsAngle(-45);
    chart.addAxis(categories, Qt::AlignBottom);
    series->attachAxis(categories);
    auto* values = new QValueAxis;
    values->setRange(0.0, top > 0.0 ? top * 1.05 : 1.0);
    values->applyNiceNumbers();
    values->setTitleText(QString::fromStdString(metric));
    chart.addAxis(values, Qt::AlignLeft);
    series->attachAxis(values);
    const int width = std::clamp(int(bars.size()) * 40 + 200, 640, 2400);
    const QImage image = renderChart(chart, QSize(width, 480));
    QImageWriter writer(QString::fromStdString(path), "png");
    if (!writer.write(image))
        return "cannot write " + path + ": " + writer.errorString().toStdString();
    return {};
}

}  // namespace throng::report
