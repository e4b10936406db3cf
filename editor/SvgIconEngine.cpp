#include "editor/SvgIconEngine.h"

#include <QApplication>
#include <QFile>
#include <QPainter>
#include <QPalette>
#include <QPixmap>
#include <QPixmapCache>
#include <QSvgRenderer>

namespace throng::editor {

namespace {

// Material's figure for disabled icons: faded enough to read as off, still recognisable.
constexpr qreal kDisabledOpacity = 0.4;

}  // namespace

SvgIconEngine::SvgIconEngine(const QString& path) : m_path(path)
{
    QFile file(path);
    if (file.open(QIODevice::ReadOnly))
        m_svg = file.readAll();
}

void SvgIconEngine::paint(QPainter* painter, const QRect& rect, QIcon::Mode mode, QIcon::State state)
{
    const qreal scale = painter->device() ? painter->device()->devicePixelRatioF() : 1.0;
    const QPixmap drawn = pixmap(rect.size() * scale, mode, state);
    painter->drawPixmap(rect, drawn);
}

QPixmap SvgIconEngine::pixmap(const QSize& size, QIcon::Mode mode, QIcon::State state)
{
    Q_UNUSED(state);
    if (size.isEmpty())
        return {};
    // Selected icons take the palette's selection text, which a theme may change.
    const QColor selected = QApplication::palette().color(QPalette::HighlightedText);
    const QString cacheKey = QStringLiteral("throng-icon:%1:%2x%3:%4:%5")
                                 .arg(m_path)
                                 .arg(size.width())
                                 .arg(size.height())
                                 .arg(int(mode))
                                 .arg(selected.rgba());
    QPixmap cached;
    if (QPixmapCache::find(cacheKey, &cached))
        return cached;

    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    if (mode == QIcon::Disabled)
        painter.setOpacity(kDisabledOpacity);
    QSvgRenderer renderer(m_svg);
    renderer.render(&painter, QRectF(QPointF(0, 0), QSizeF(size)));
    if (mode == QIcon::Selected) {
        painter.setCompositionMode(QPainter::CompositionMode_SourceIn);
        painter.fillRect(image.rect(), selected);
    }
    painter.end();
    const QPixmap result = QPixmap::fromImage(image);
    QPixmapCache::insert(cacheKey, result);
    return result;
}

QIconEngine* SvgIconEngine::clone() const
{
    return new SvgIconEngine(*this);
}

QString SvgIconEngine::key() const
{
    return QStringLiteral("throng-svg");
}

bool SvgIconEngine::isNull()
{
    return m_svg.isEmpty();
}

}  // namespace throng::editor
