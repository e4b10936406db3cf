#pragma once
// Draws one of the set's SVG icons at any size, in each QIcon mode as the dark theme wants
// it: as drawn when normal or active, faded when disabled, in the selection's text colour
// when selected (light lines would vanish on the yellow highlight). Never edits the SVG.

#include <QByteArray>
#include <QIconEngine>
#include <QString>

namespace throng::editor {

class SvgIconEngine : public QIconEngine {
public:
    // `path` is a file or resource holding the SVG; it is read once, here.
    explicit SvgIconEngine(const QString& path);

    void paint(QPainter* painter, const QRect& rect, QIcon::Mode mode, QIcon::State state) override;
    QPixmap pixmap(const QSize& size, QIcon::Mode mode, QIcon::State state) override;
    QIconEngine* clone() const override;
    QString key() const override;
    bool isNull() override;

private:
    QString m_path;
    QByteArray m_svg;
};

}  // namespace throng::editor
