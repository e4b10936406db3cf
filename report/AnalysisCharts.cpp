#include "report/AnalysisCharts.h"

#include "report/ReportFigures.h"

#include <QtCharts/QLineSeries>
#include <QtCharts/QScatterSeries>
#include <QtCharts/QValueAxis>
#include <QtCharts/QXYSeries>

#include <QPen>

#include <algorithm>
#include <cmath>

namespace throng::report {

namespace {

// Points drawn per series at most: a run of 2,400 frames draws every frame, a longer one
// every k-th (a chart is a picture; the figures come from every frame).
constexpr std::size_t kMaxPoints = 1'500;

// Series colours in order, distinct in print and for the common colour blindnesses (Okabe & Ito).
QColor seriesColour(std::size_t k)
{
    static const QColor kColours[] = {QColor(0, 114, 178), QColor(213, 94, 0), QColor(0, 158, 115),
                                      QColor(204, 121, 167), QColor(230, 159, 0), QColor(86, 180, 233),
                                      QColor(120, 120, 120)};
    return kColours[k % std::size(kColours)];
}

// The time axis ends a little after everyone left, else at the end of the run.
double shownUntilS(const sim::RunAnalysis& a)
{
    const double evac = a.occupancy.evacuationS;
    const double until = evac >= 0.0 ? std::min(a.durationS, std::max(evac * 1.1, evac + 5.0)) : a.durationS;
    return std::max(until, 1.0);
}

std::unique_ptr<QChart> newChart(const QString& title)
{
    auto chart = std::make_unique<QChart>();
    chart->setTitle(title);
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->legend()->setAlignment(Qt::AlignBottom);
    chart->setBackgroundRoundness(0);
    return chart;
}

QValueAxis* addAxis(QChart& chart, Qt::Alignment side, const QString& title, double lo, double hi)
{
    auto* axis = new QValueAxis;
    axis->setTitleText(title);
    axis->setRange(lo, hi);
    axis->applyNiceNumbers();
    axis->setLabelFormat(QStringLiteral("%g"));
    chart.addAxis(axis, side);
    return axis;
}

void attach(QChart& chart, QXYSeries* series, QValueAxis* x, QValueAxis* y, QColor colour,
            Qt::PenStyle style = Qt::SolidLine)
{
    QPen pen(colour, 2.0, style);
    series->setPen(pen);
    series->setColor(colour);
    chart.addSeries(series);
    series->attachAxis(x);
    series->attachAxis(y);
}

void attach(QChart& chart, QAbstractSeries* series, QValueAxis* x, QValueAxis* y)
{
    chart.addSeries(series);
    series->attachAxis(x);
    series->attachAxis(y);
}

// A step series of per-bin values: flat over each bin.
QLineSeries* binSeries(const std::vector<double>& bins, double binS, const QString& name)
{
    auto* s = new QLineSeries;
    s->setName(name);
    for (std::size_t k = 0; k < bins.size(); ++k) {
        s->append(double(k) * binS, bins[k]);
        s->append(double(k + 1) * binS, bins[k]);
    }
    return s;
}

}  // namespace

std::unique_ptr<QChart> occupancyChart(const sim::RunAnalysis& a)
{
    auto chart = newChart(QStringLiteral("Agents in the scene and out over time"));
    const sim::Occupancy& o = a.occupancy;
    auto* in = new QLineSeries;
    in->setName(QStringLiteral("In the scene"));
    auto* out = new QLineSeries;
    out->setName(QStringLiteral("Out through exits"));
    const std::size_t stride = std::max<std::size_t>(1, o.inScene.size() / kMaxPoints);
    std::uint32_t most = 1;
    for (std::size_t f = 0; f < o.inScene.size(); ++f) {
        most = std::max({most, o.inScene[f], o.out[f]});
        if (f % stride == 0 || f + 1 == o.inScene.size()) {
            in->append(double(f) / a.fps, o.inScene[f]);
            out->append(double(f) / a.fps, o.out[f]);
        }
    }
    QValueAxis* x = addAxis(*chart, Qt::AlignBottom, QStringLiteral("Time (s)"), 0.0, shownUntilS(a));
    QValueAxis* y = addAxis(*chart, Qt::AlignLeft, QStringLiteral("Agents"), 0.0, double(most) * 1.05);
    attach(*chart, in, x, y, seriesColour(0));
    attach(*chart, out, x, y, seriesColour(2));
    if (o.evacuationS >= 0.0) {
        auto* mark = new QLineSeries;
        mark->setName(QStringLiteral("Evacuated at %1 s").arg(o.evacuationS, 0, 'f', 1));
        mark->append(o.evacuationS, 0.0);
        mark->append(o.evacuationS, double(most));
        attach(*chart, mark, x, y, seriesColour(1), Qt::DashLine);
    }
    return chart;
}

std::unique_ptr<QChart> flowChart(const sim::RunAnalysis& a)
{
    auto chart = newChart(QStringLiteral("Flow over time (%1 s bins)").arg(a.flowBinS, 0, 'f', 1));
    std::vector<QLineSeries*> series;
    std::vector<Qt::PenStyle> styles;
    double most = 0.5;
    for (std::size_t l = 0; l < a.lines.size(); ++l) {
        const std::vector<double>& bins = a.lineFlowPerSecond[l];
        for (double b : bins)
            most = std::max(most, b);
        const QString name = QStringLiteral("Line %1").arg(QString::fromStdString(a.lines[l].name));
        series.push_back(binSeries(bins, a.flowBinS, name));
        styles.push_back(Qt::SolidLine);
    }
    for (const sim::ExitOutflow& e : a.occupancy.exits) {
        if (e.frames.empty())
            continue;
        const std::vector<double> bins = exitFlowPerSecond(e, a.fps, a.frames, a.flowBinS);
        for (double b : bins)
            most = std::max(most, b);
        series.push_back(binSeries(bins, a.flowBinS, QStringLiteral("Exit %1").arg(QString::fromStdString(e.exit))));
        styles.push_back(Qt::DashLine);
    }
    QValueAxis* x = addAxis(*chart, Qt::AlignBottom, QStringLiteral("Time (s)"), 0.0, shownUntilS(a));
    QValueAxis* y = addAxis(*chart, Qt::AlignLeft, QStringLiteral("Persons per second"), 0.0, most * 1.1);
    for (std::size_t k = 0; k < series.size(); ++k)
        attach(*chart, series[k], x, y, seriesColour(k), styles[k]);
    if (series.empty())
        chart->setTitle(chart->title() + QStringLiteral(" — no measurement line or exit in the scene"));
    return chart;
}

std::unique_ptr<QChart> speedDensityChart(const sim::RunAnalysis& a)
{
    auto chart = newChart(QStringLiteral("Speed against density"));
    double densest = 2.0, fastest = 1.6;
    std::vector<QScatterSeries*> points;
    for (const sim::AreaSpeedDensity& area : a.speedDensity) {
        auto* s = new QScatterSeries;
        s->setName(QStringLiteral("Area %1").arg(QString::fromStdString(area.name)));
        s->setMarkerSize(5.0);
        s->setBorderColor(Qt::transparent);
        const std::size_t stride = std::max<std::size_t>(1, area.samples.size() / kMaxPoints);
        for (std::size_t k = 0; k < area.samples.size(); k += stride) {
            const sim::SpeedDensitySample& x = area.samples[k];
            s->append(x.densityPerM2, x.speedMps);
            densest = std::max(densest, x.densityPerM2);
            fastest = std::max(fastest, x.speedMps);
        }
        points.push_back(s);
    }
    densest = std::min(std::ceil(densest * 1.1), 10.0);
    auto* curve = new QLineSeries;
    curve->setName(QStringLiteral("Weidmann (1993)"));
    for (double rho = 0.0; rho <= std::min(densest, 5.4) + 1e-9; rho += 0.05)
        curve->append(rho, sim::weidmannSpeed(rho));
    QValueAxis* x = addAxis(*chart, Qt::AlignBottom, QStringLiteral("Density (persons/m²)"), 0.0, densest);
    QValueAxis* y = addAxis(*chart, Qt::AlignLeft, QStringLiteral("Speed (m/s)"), 0.0, fastest * 1.05);
    for (std::size_t k = 0; k < points.size(); ++k) {
        QColor c = seriesColour(k);
        c.setAlpha(150);
        points[k]->setColor(c);
        attach(*chart, points[k], x, y);
    }
    attach(*chart, curve, x, y, Qt::black);
    if (points.empty())
        chart->setTitle(chart->title() + QStringLiteral(" — draw a measurement area to measure it"));
    return chart;
}

}  // namespace throng::report
