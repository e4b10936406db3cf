#include "editor/viewport/ViewportHud.h"

#include "editor/Timecode.h"

#include <QFontDatabase>
#include <QLinearGradient>
#include <QLocale>
#include <QPainter>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {
constexpr int kMarginPx = 8, kPaddingPx = 7, kSwatchPx = 10;
constexpr qint64 kFpsWindowMs = 1000;
const QString kSwatch = QStringLiteral("  \u25A0 ");
// A gradient's line: a bar of its stops, then its two ends ("0 % to 100 %").
const QString kGradient = QStringLiteral("  \u25AC\u25AC\u25AC\u25AC\u25AC ");

QString count(std::size_t n)
{
    return QLocale::c().toString(qulonglong(n)).replace(',', QChar(0x2009));  // thin space between thousands
}
}  // namespace

ViewportHud::ViewportHud(QWidget* parent) : QWidget(parent)
{
    setObjectName("viewportHud");
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_TranslucentBackground);
    m_clock.start();
    // The view's fps falls to 0 when nothing is drawn: shown without a new frame too.
    auto* refresh = new QTimer(this);
    connect(refresh, &QTimer::timeout, this, [this] {
        if (isVisible())
            update();
    });
    refresh->start(500);
}

void ViewportHud::setFigures(HudFigures figures)
{
    m_figures = std::move(figures);
    update();
}

void ViewportHud::framePainted()
{
    const qint64 now = m_clock.elapsed();
    m_paints.push_back(now);
    while (!m_paints.empty() && m_paints.front() < now - kFpsWindowMs)
        m_paints.pop_front();
}

double ViewportHud::viewFps() const
{
    if (m_paints.size() < 2 || m_paints.back() < m_clock.elapsed() - kFpsWindowMs)
        return 0.0;
    const double spanMs = double(m_paints.back() - m_paints.front());
    return spanMs > 0.0 ? double(m_paints.size() - 1) * 1000.0 / spanMs : 0.0;
}

QStringList ViewportHud::lines() const
{
    const HudFigures& f = m_figures;
    QStringList out;
    QString time = tr("Frame %1   %2").arg(f.frame).arg(timecode(f.frame, f.fps));
    if (f.timeS)
        time += tr("   %1 s").arg(*f.timeS, 0, 'f', 2);
    out << time;
    out << tr("Agents %1").arg(count(f.shown));
    for (std::size_t t = 0; t < f.perType.size() && t < kTypeLines; ++t)
        out << QStringLiteral("  %1 %2").arg(QString::fromStdString(f.perType[t].first), count(f.perType[t].second));
    if (f.perType.size() > kTypeLines) {
        std::size_t rest = 0;
        for (std::size_t t = kTypeLines; t < f.perType.size(); ++t)
            rest += f.perType[t].second;
        out << tr("  %1 more types %2").arg(f.perType.size() - kTypeLines).arg(count(rest));
    }
    out << tr("Arrived %1   Out %2").arg(count(f.arrived), count(f.out));
    if (f.layoutOverlaps + f.layoutWallCrossings > 0)
        out << tr("Layout: %1 overlaps, %2 wall crossings   %3 here")
                   .arg(count(f.layoutOverlaps), count(f.layoutWallCrossings), count(f.layoutFlagged));
    out << tr("Simulation %1 steps/s   View %2 fps")
               .arg(f.stepsPerSecond > 0.0 ? QString::number(std::lround(f.stepsPerSecond)) : QStringLiteral("-"))
               .arg(std::lround(viewFps()));
    for (const ColourLegend& legend : f.legends) {
        out << QString::fromStdString(legend.title);
        if (legend.gradient && legend.entries.size() >= 2) {
            out << kGradient + tr("%1 to %2").arg(QString::fromStdString(legend.entries.front().label),
                                                  QString::fromStdString(legend.entries.back().label));
            continue;
        }
        for (const ColourLegend::Entry& e : legend.entries)
            out << kSwatch + QString::fromStdString(e.label);
        if (legend.more > 0)
            out << tr("  %1 more").arg(legend.more);
    }
    return out;
}

void ViewportHud::paintEvent(QPaintEvent*)
{
    const QStringList text = lines();
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setPointSizeF(std::max(7.5, font.pointSizeF() * 0.85));
    painter.setFont(font);
    const QFontMetrics metrics(font);
    int width = 0;
    for (const QString& line : text)
        width = std::max(width, metrics.horizontalAdvance(line));
    const int lineHeight = metrics.height();
    const QRect box(kMarginPx, kMarginPx, width + 2 * kPaddingPx, int(text.size()) * lineHeight + 2 * kPaddingPx);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(20, 22, 25, 190));
    painter.drawRoundedRect(box, 5, 5);

    // Each legend entry's swatch is drawn over its "■" in the entry's colour, a
    // gradient's stops over its bar.
    std::vector<glm::vec3> swatches;
    std::vector<const ColourLegend*> gradients;
    for (const ColourLegend& legend : m_figures.legends)
        if (legend.gradient && legend.entries.size() >= 2)
            gradients.push_back(&legend);
        else
            for (const ColourLegend::Entry& e : legend.entries)
                swatches.push_back(e.colour);
    std::size_t entry = 0, gradient = 0;
    int y = box.top() + kPaddingPx;
    for (const QString& line : text) {
        painter.setPen(QColor(225, 228, 232));
        painter.drawText(QRect(box.left() + kPaddingPx, y, width, lineHeight), Qt::AlignLeft | Qt::AlignVCenter, line);
        if (line.startsWith(kSwatch) && entry < swatches.size()) {
            const glm::vec3 c = swatches[entry++];
            const int x = box.left() + kPaddingPx + metrics.horizontalAdvance(QStringLiteral("  "));
            const QRect square(x, y + (lineHeight - kSwatchPx) / 2, kSwatchPx, kSwatchPx);
            painter.fillRect(square.adjusted(-1, -1, 1, 1), QColor(20, 22, 25));
            painter.fillRect(square, QColor::fromRgbF(c.r, c.g, c.b));
        } else if (line.startsWith(kGradient) && gradient < gradients.size()) {
            const std::vector<ColourLegend::Entry>& stops = gradients[gradient++]->entries;
            const int x = box.left() + kPaddingPx + metrics.horizontalAdvance(QStringLiteral("  "));
            const int barWidth = metrics.horizontalAdvance(kGradient.mid(2).trimmed());
            const QRect bar(x, y + (lineHeight - kSwatchPx) / 2, barWidth, kSwatchPx);
            QLinearGradient fill(bar.topLeft(), bar.topRight());
            for (std::size_t k = 0; k < stops.size(); ++k)
                fill.setColorAt(double(k) / double(stops.size() - 1),
                                QColor::fromRgbF(stops[k].colour.r, stops[k].colour.g, stops[k].colour.b));
            painter.fillRect(bar.adjusted(-1, -1, 1, 1), QColor(20, 22, 25));
            painter.fillRect(bar, fill);
        }
        y += lineHeight;
    }
}

}  // namespace throng::editor
