#include "editor/GuideBrowser.h"

#include <QImage>
#include <QPixmap>
#include <QResizeEvent>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextFragment>
#include <QTextImageFormat>

#include <algorithm>
#include <cmath>
#include <vector>

namespace throng::editor {

GuideBrowser::GuideBrowser(QWidget* parent) : QTextBrowser(parent)
{
    setUndoRedoEnabled(false);
}

void GuideBrowser::doSetSource(const QUrl& name, QTextDocument::ResourceType type)
{
    QTextBrowser::doSetSource(name, type);
    fitImages();
}

void GuideBrowser::resizeEvent(QResizeEvent* event)
{
    QTextBrowser::resizeEvent(event);
    fitImages();
}

QSize GuideBrowser::naturalSize(const QString& name)
{
    if (const auto it = m_sizes.constFind(name); it != m_sizes.constEnd())
        return *it;
    const QVariant resource = document()->resource(QTextDocument::ImageResource, QUrl(name));
    QSize size;
    if (resource.canConvert<QImage>())
        size = resource.value<QImage>().size();
    if (size.isEmpty() && resource.canConvert<QPixmap>())
        size = resource.value<QPixmap>().size();
    if (size.isEmpty() && resource.canConvert<QByteArray>())
        size = QImage::fromData(resource.toByteArray()).size();
    m_sizes.insert(name, size);
    return size;
}

void GuideBrowser::fitImages()
{
    QTextDocument* doc = document();
    // The text's width: the viewport less the document's margins on both sides.
    const double room = std::max(64.0, double(viewport()->width()) - 2.0 * doc->documentMargin() - 2.0);
    struct Change {
        int position, length;
        QTextImageFormat format;
    };
    std::vector<Change> changes;
    for (QTextBlock block = doc->begin(); block.isValid(); block = block.next())
        for (QTextBlock::iterator it = block.begin(); !it.atEnd(); ++it) {
            const QTextFragment fragment = it.fragment();
            if (!fragment.isValid() || !fragment.charFormat().isImageFormat())
                continue;
            QTextImageFormat image = fragment.charFormat().toImageFormat();
            const QSize natural = naturalSize(image.name());
            if (natural.isEmpty())
                continue;
            const double width = std::min(double(natural.width()), room);
            const double height = std::round(double(natural.height()) * width / double(natural.width()));
            if (image.width() == width && image.height() == height)
                continue;
            image.setWidth(width);
            image.setHeight(height);
            changes.push_back({fragment.position(), fragment.length(), image});
        }
    QTextCursor cursor(doc);
    for (const Change& c : changes) {
        cursor.setPosition(c.position);
        cursor.setPosition(c.position + c.length, QTextCursor::KeepAnchor);
        cursor.setCharFormat(c.format);
    }
}

}  // namespace throng::editor
