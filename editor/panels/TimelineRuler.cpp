#include "editor/panels/TimelineRuler.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {

constexpr int kMarginPx = 10;      // room for the first and last labels
constexpr int kStripHeightPx = 6;  // the cache strip along the bottom
constexpr int kMinLabelGapPx = 48;

}  // namespace

TimelineRuler::TimelineRuler(QWidget* parent) : QSlider(Qt::Horizontal, parent)
{
    setFocusPolicy(Qt::StrongFocus);
    setRange(0, 0);
    setPageStep(10);
}

void TimelineRuler::setCachedFrames(std::size_t cachedFrames)
{
    if (cachedFrames == m_cachedFrames)
        return;
    m_cachedFrames = cachedFrames;
    update();
}

void TimelineRuler::setTargetFrame(int frame)
{
    if (frame == m_targetFrame)
        return;
    m_targetFrame = frame;
    update();
}

int TimelineRuler::xOfFrame(int frame) const
{
    const int span = maximum() - minimum();
    if (span <= 0)
        return kMarginPx;
    const double widthPx = double(std::max(1, width() - 2 * kMarginPx));
    return kMarginPx + int(std::lround(widthPx * double(frame - minimum()) / double(span)));
}

int TimelineRuler::frameAtX(int x) const
{
    const int span = maximum() - minimum();
    const double widthPx = double(std::max(1, width() - 2 * kMarginPx));
    const int frame = minimum() + int(std::lround(double(x - kMarginPx) * double(span) / widthPx));
    return std::clamp(frame, minimum(), maximum());
}

QRect TimelineRuler::cacheStrip() const
{
    return {kMarginPx, height() - kStripHeightPx - 2, std::max(1, width() - 2 * kMarginPx) + 1, kStripHeightPx};
}

QSize TimelineRuler::sizeHint() const
{
    return {400, 34};
}

QSize TimelineRuler::minimumSizeHint() const
{
    return {120, 34};
}

bool TimelineRuler::event(QEvent* event)
{
    if (event->type() != QEvent::ToolTip)
        return QSlider::event(event);
    auto* help = static_cast<QHelpEvent*>(event);
    const int frame = frameAtX(help->pos().x());
    const QString state = std::size_t(frame) < m_cachedFrames
                              ? tr("computed")
                              : tr("not computed yet: clicking it computes the frames up to it");
    QToolTip::showText(help->globalPos(), tr("Frame %1 (%2)\n%3").arg(frame).arg(state, toolTip()), this);
    return true;
}

void TimelineRuler::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.fillRect(rect(), QColor::fromRgb(kBackgroundColour));
    const QRect strip = cacheStrip();
    painter.fillRect(strip, QColor::fromRgb(kUncachedColour));
    if (m_cachedFrames > 0) {
        // A frame owns the cell around its tick, so frame 0 alone still shows.
        const int span = std::max(1, maximum() - minimum());
        const int halfCellPx = std::max(1, (strip.width() - 1) / span / 2);
        const int last = std::min(int(m_cachedFrames) - 1, maximum());
        const int x0 = std::max(strip.left(), xOfFrame(minimum()) - halfCellPx);
        const int x1 = std::min(strip.right(), xOfFrame(last) + halfCellPx);
        painter.fillRect(QRect(QPoint(x0, strip.top()), QPoint(x1, strip.bottom())), QColor::fromRgb(kCachedColour));
    }
    paintTicks(painter);
    paintRetime(painter);
    paintHandle(painter);
    if (hasFocus()) {
        painter.setPen(QPen(palette().color(QPalette::Highlight), 1));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(rect().adjusted(0, 0, -1, -1));
    }
}

int TimelineRuler::labelStep() const
{
    const int span = std::max(1, maximum() - minimum());
    const double pxPerFrame = double(std::max(1, width() - 2 * kMarginPx)) / double(span);
    for (int decade = 1;; decade *= 10) {
        for (int factor : {1, 2, 5}) {
            const int step = decade * factor;
            if (double(step) * pxPerFrame >= kMinLabelGapPx || step >= span)
                return step;
        }
    }
}

void TimelineRuler::paintTicks(QPainter& painter) const
{
    const int step = labelStep();
    const int minor = step >= 5 ? step / 5 : 1;
    const int baseline = cacheStrip().top() - 2;
    const QColor tickColour(0xa0, 0xa4, 0xab);
    painter.setPen(tickColour);
    QFont font = painter.font();
    font.setPixelSize(10);
    painter.setFont(font);
    const int firstMinor = (minimum() + minor - 1) / minor * minor;
    const bool drawMinor = xOfFrame(minimum() + minor) - xOfFrame(minimum()) >= 4;
    for (int frame = firstMinor; frame <= maximum(); frame += minor) {
        const int x = xOfFrame(frame);
        if (frame % step == 0) {
            painter.drawLine(x, baseline - 8, x, baseline);
            const QString label = QString::number(frame);
            const int labelWidth = painter.fontMetrics().horizontalAdvance(label);
            painter.drawText(x - labelWidth / 2, baseline - 10, label);
        } else if (drawMinor) {
            painter.drawLine(x, baseline - 3, x, baseline);
        }
    }
}

void TimelineRuler::paintHandle(QPainter& painter) const
{
    const QColor colour = QColor::fromRgb(kHandleColour);
    if (m_targetFrame >= 0) {
        painter.setPen(QPen(colour, 1, Qt::DashLine));
        painter.drawLine(xOfFrame(m_targetFrame), 0, xOfFrame(m_targetFrame), height());
    }
    const int x = xOfFrame(value());
    painter.fillRect(QRect(x - 1, 0, 2, height()), colour);
    const QPoint tip[] = {{x - 5, 0}, {x + 5, 0}, {x, 6}};
    painter.setPen(Qt::NoPen);
    painter.setBrush(colour);
    painter.drawPolygon(tip, 3);
}

void TimelineRuler::setRetime(std::optional<Retime> retime)
{
    if (retime == m_retime)
        return;
    m_retime = retime;
    update();
}

void TimelineRuler::paintRetime(QPainter& painter) const
{
    if (!m_retime)
        return;
    const QColor colour = QColor::fromRgb(kRetimeColour);
    const int y = cacheStrip().top() - 14;
    const int x0 = xOfFrame(std::clamp(m_retime->from, minimum(), maximum()));
    const int x1 = xOfFrame(std::clamp(m_retime->from + m_retime->frames, minimum(), maximum()));
    painter.setPen(QPen(colour, 2));
    painter.drawLine(x0, y - 4, x0, y + 4);
    painter.drawLine(x0, y, x1, y);
    const int dir = x1 >= x0 ? 1 : -1;
    painter.drawLine(x1, y, x1 - 5 * dir, y - 4);
    painter.drawLine(x1, y, x1 - 5 * dir, y + 4);
    QFont font = painter.font();
    font.setPixelSize(10);
    painter.setFont(font);
    const QString label = m_retime->frames >= 0 ? QStringLiteral("+%1").arg(m_retime->frames)
                                                : QString::number(m_retime->frames);
    painter.drawText(std::max(x0, x1) + 4, y + 4, label);
}

void TimelineRuler::mousePressEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        QSlider::mousePressEvent(event);
        return;
    }
    if (m_retime && (event->modifiers() & Qt::ShiftModifier)) {
        m_retimePress = frameAtX(int(event->position().x()));
        emit retimeDragged(0, false);
        event->accept();
        return;
    }
    setSliderDown(true);
    setSliderPosition(frameAtX(int(event->position().x())));
    event->accept();
}

void TimelineRuler::mouseMoveEvent(QMouseEvent* event)
{
    if (m_retimePress) {
        emit retimeDragged(frameAtX(int(event->position().x())) - *m_retimePress, false);
        event->accept();
        return;
    }
    if (!isSliderDown()) {
        QSlider::mouseMoveEvent(event);
        return;
    }
    setSliderPosition(frameAtX(int(event->position().x())));
    event->accept();
}

void TimelineRuler::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_retimePress) {
        const int frames = frameAtX(int(event->position().x())) - *m_retimePress;
        m_retimePress.reset();
        emit retimeDragged(frames, true);
        event->accept();
        return;
    }
    if (!isSliderDown()) {
        QSlider::mouseReleaseEvent(event);
        return;
    }
    setSliderPosition(frameAtX(int(event->position().x())));
    setSliderDown(false);
    event->accept();
}

}  // namespace throng::editor
