#include "report/GroundPlot.h"

#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>
#include <QTransform>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace throng::report {

namespace {

// Plot margins in pixels: axis labels left and below, the colour scale right.
constexpr int kLeft = 56, kBottom = 40, kTop = 30, kRight = 90;

struct Extent {
    glm::dvec2 lo{1e300}, hi{-1e300};
    void add(glm::dvec2 p)
    {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    bool empty() const { return lo.x > hi.x; }
};

// What the plot shows: the set, the measurements and the walkers, within the bounds.
Extent viewExtent(const sim::Scene& scene, const sim::RunAnalysis& a)
{
    Extent e;
    for (const sim::Wall& w : scene.walls)
        for (const glm::vec2& p : w.points)
            e.add(glm::dvec2(p));
    for (const sim::Measurement& m : scene.measurements)
        for (const glm::vec2& p : m.points)
            e.add(glm::dvec2(p));
    for (const sim::Goal& g : scene.goals) {
        e.add(glm::dvec2(g.position) - double(g.radiusM));
        e.add(glm::dvec2(g.position) + double(g.radiusM));
    }
    for (const sim::Trajectory& t : a.trajectories)
        for (const glm::dvec2& p : t.points)
            e.add(p);
    if (e.empty()) {
        e.add(a.boundsMin);
        e.add(a.boundsMax);
    }
    e.lo = glm::max(e.lo, a.boundsMin);
    e.hi = glm::min(e.hi, a.boundsMax);
    if (e.lo.x >= e.hi.x || e.lo.y >= e.hi.y) {
        e = Extent{};
        e.add(a.boundsMin);
        e.add(a.boundsMax);
    }
    const glm::dvec2 margin = glm::max((e.hi - e.lo) * 0.04, glm::dvec2(1.0));
    e.lo -= margin;
    e.hi += margin;
    return e;
}

double niceStep(double span, int ticks)
{
    const double raw = span / std::max(ticks, 1);
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= raw)
            return m * p;
    return 10.0 * p;
}

QString metres(double v) { return QString::number(v, 'g', 6); }

}  // namespace

QColor densityColour(double fraction)
{
    // Five stops of a perceptually even ramp (viridis), light yellow at the top.
    static constexpr std::array<std::array<int, 3>, 5> kStops{
        {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}};
    const double t = std::clamp(fraction, 0.0, 1.0) * double(kStops.size() - 1);
    const std::size_t i = std::min<std::size_t>(std::size_t(t), kStops.size() - 2);
    const double u = t - double(i);
    auto mix = [&](int c) { return int(std::lround(kStops[i][c] + (kStops[i + 1][c] - kStops[i][c]) * u)); };
    return QColor(mix(0), mix(1), mix(2));
}

QImage paintGround(const sim::Scene& scene, const sim::RunAnalysis& a, GroundLayer layer, QSize size)
{
    const Extent e = viewExtent(scene, a);
    const QRectF area(kLeft, kTop, std::max(10, size.width() - kLeft - kRight),
                      std::max(10, size.height() - kTop - kBottom));
    const glm::dvec2 span = e.hi - e.lo;
    const double scale = std::min(area.width() / span.x, area.height() / span.y);
    const QRectF plot(area.left(), area.top(), span.x * scale, span.y * scale);
    // The image keeps the set's proportions: no blank band below or beside the plot.
    QImage image(QSize(int(std::ceil(plot.right())) + kRight, int(std::ceil(plot.bottom())) + kBottom),
                 QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    auto toPx = [&](glm::dvec2 w) {
        return QPointF(plot.left() + (w.x - e.lo.x) * scale, plot.top() + (w.y - e.lo.y) * scale);
    };

    p.setFont(QFont(p.font().family(), 9));
    p.drawText(QRectF(0, 4, image.width(), kTop - 6), Qt::AlignCenter,
               layer == GroundLayer::Density ? QStringLiteral("Density over the run (mean persons/m²)")
                                             : QStringLiteral("Trajectories (%1 of %2 walkers)")
                                                   .arg(std::min(a.trajectories.size(), a.walkers))
                                                   .arg(a.walkers));
    p.fillRect(plot, QColor(246, 246, 246));
    p.save();
    p.setClipRect(plot);

    const double peak = std::max(a.density.peakDensity(), 1e-9);
    if (layer == GroundLayer::Density) {
        // Cells edge to edge: antialiased fills would leave seams between them.
        p.setRenderHint(QPainter::Antialiasing, false);
        const sim::DensityMap& d = a.density;
        for (std::size_t r = 0; r < d.rows; ++r)
            for (std::size_t c = 0; c < d.cols; ++c) {
                const double rho = d.densityAt(c, r);
                if (rho <= 0.0)
                    continue;
                const glm::dvec2 lo = d.min + glm::dvec2(double(c), double(r)) * d.cellM;
                const QPointF a0 = toPx(lo), a1 = toPx(lo + glm::dvec2(d.cellM));
                p.fillRect(QRectF(a0, a1), densityColour(rho / peak));
            }
        p.setRenderHint(QPainter::Antialiasing, true);
    } else {
        for (const sim::Trajectory& t : a.trajectories) {
            if (t.points.size() < 2)
                continue;
            QPainterPath path(toPx(t.points[0]));
            for (std::size_t k = 1; k < t.points.size(); ++k)
                path.lineTo(toPx(t.points[k]));
            QColor c = QColor::fromHsv(int((t.agent * 47u) % 360u), 180, 170);
            c.setAlpha(a.trajectories.size() > 300 ? 70 : 150);
            p.strokePath(path, QPen(c, 1.0));
        }
    }

    // The set over the data: obstacles, walls, exits.
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(150, 150, 150));
    for (const sim::Obstacle& o : scene.obstacles) {
        if (o.shape == sim::ObstacleShape::Circle) {
            const double r = double(o.radiusM) * scale;
            p.drawEllipse(toPx(glm::dvec2(o.center)), r, r);
            continue;
        }
        p.save();
        p.translate(toPx(glm::dvec2(o.center)));
        p.rotate(-double(o.angleDeg));
        p.drawRect(QRectF(-o.size.x * scale / 2, -o.size.y * scale / 2, o.size.x * scale, o.size.y * scale));
        p.restore();
    }
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(QColor(30, 30, 30), 2.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    for (const sim::Wall& w : scene.walls)
        for (std::size_t k = 1; k < w.points.size(); ++k)
            p.drawLine(toPx(glm::dvec2(w.points[k - 1])), toPx(glm::dvec2(w.points[k])));
    p.setPen(QPen(QColor(0, 140, 60), 1.5));
    for (const sim::Goal& g : scene.goals)
        if (g.exit) {
            const double r = double(g.radiusM) * scale;
            p.drawEllipse(toPx(glm::dvec2(g.position)), r, r);
            const QPointF c = toPx(glm::dvec2(g.position));
            p.drawText(QRectF(c.x() - 60, c.y() - 8, 120, 16), Qt::AlignCenter, QString::fromStdString(g.name));
        }
    // Measurements: areas outlined, lines with an arrow on their forward side.
    const QColor blue(20, 90, 200);
    for (const sim::Measurement& m : scene.measurements) {
        QPolygonF poly;
        for (const glm::vec2& q : m.points)
            poly << toPx(glm::dvec2(q));
        if (m.shape == sim::MeasurementShape::Area) {
            p.setPen(QPen(blue, 1.5, Qt::DashLine));
            p.setBrush(QColor(20, 90, 200, 30));
            p.drawPolygon(poly);
            p.setBrush(Qt::NoBrush);
            p.drawText(poly.boundingRect().topLeft() + QPointF(3, 12), QString::fromStdString(m.name));
            continue;
        }
        p.setPen(QPen(blue, 2.0));
        p.drawLine(poly[0], poly[1]);
        const glm::dvec2 a0(m.points[0]), b0(m.points[1]);
        const glm::dvec2 mid = (a0 + b0) * 0.5, n = glm::normalize(glm::dvec2(b0.y - a0.y, a0.x - b0.x));
        const QPointF from = toPx(mid), to = from + QPointF(n.x, n.y) * 18.0;
        p.drawLine(from, to);
        const QPointF side(-n.y * 4.0, n.x * 4.0), back = to - QPointF(n.x, n.y) * 6.0;
        p.drawLine(to, back + side);
        p.drawLine(to, back - side);
        p.drawText(poly[1] + QPointF(3, -3), QString::fromStdString(m.name));
    }
    p.restore();

    // Axes in metres.
    p.setPen(QPen(Qt::black, 1.0));
    p.drawRect(plot);
    const QFontMetrics fm(p.font());
    const double stepX = niceStep(span.x, int(plot.width() / 80.0));
    const double stepZ = niceStep(span.y, int(plot.height() / 50.0));
    for (double x = std::ceil(e.lo.x / stepX) * stepX; x <= e.hi.x; x += stepX) {
        const double px = toPx({x, e.lo.y}).x();
        p.drawLine(QPointF(px, plot.bottom()), QPointF(px, plot.bottom() + 4));
        const QString label = metres(x);
        p.drawText(QPointF(px - fm.horizontalAdvance(label) / 2.0, plot.bottom() + 6 + fm.ascent()), label);
    }
    for (double z = std::ceil(e.lo.y / stepZ) * stepZ; z <= e.hi.y; z += stepZ) {
        const double py = toPx({e.lo.x, z}).y();
        p.drawLine(QPointF(plot.left() - 4, py), QPointF(plot.left(), py));
        const QString label = metres(z);
        p.drawText(QPointF(plot.left() - 6 - fm.horizontalAdvance(label), py + fm.ascent() / 2.0 - 1), label);
    }
    p.drawText(QRectF(plot.left(), plot.bottom() + 20, plot.width(), 18), Qt::AlignCenter, QStringLiteral("x (m)"));
    p.save();
    p.translate(12, plot.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-60, -8, 120, 16), Qt::AlignCenter, QStringLiteral("z (m)"));
    p.restore();

    if (layer == GroundLayer::Density) {
        const QRectF bar(plot.right() + 16, plot.top(), 14, std::min(plot.height(), 240.0));
        for (int k = 0; k < int(bar.height()); ++k)
            p.fillRect(QRectF(bar.left(), bar.bottom() - k - 1, bar.width(), 1.0), densityColour(k / bar.height()));
        p.drawRect(bar);
        for (int k = 0; k <= 4; ++k) {
            const double y = bar.bottom() - bar.height() * k / 4.0;
            p.drawText(QPointF(bar.right() + 4, y + fm.ascent() / 2.0 - 1), QString::number(peak * k / 4.0, 'f', 2));
        }
    }
    return image;
}

}  // namespace throng::report
