#pragma once
// The user guide's reader (Help > User Guide): a QTextBrowser whose pictures fit its width,
// scaled down (never up) with their shape kept, again whenever it is resized, so that no
// screenshot hides behind a sideways scroll bar.

#include <QHash>
#include <QSize>
#include <QTextBrowser>

namespace throng::editor {

class GuideBrowser : public QTextBrowser {
    Q_OBJECT

public:
    explicit GuideBrowser(QWidget* parent = nullptr);

protected:
    void doSetSource(const QUrl& name, QTextDocument::ResourceType type) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    // Sets each picture's shown size to its own, or the width there is if that is less.
    void fitImages();
    // A picture's own size in pixels (empty if it cannot be read); read once.
    QSize naturalSize(const QString& name);

    QHash<QString, QSize> m_sizes;
};

}  // namespace throng::editor
