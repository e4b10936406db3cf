#pragma once
// The brain editor's QGraphicsView: zoom with the wheel (about the mouse), pan with the
// middle button (or Alt + left), box-select by dragging on empty space, and the graph
// keys (Tab palette, F frame all, Shift+F frame selection, Delete, Ctrl+C/V/D, Ctrl+G
// collapse to macro, Ctrl+Shift+G expand). Forwards edits as signals; of its own it draws only
// the hint an empty graph shows.

#include <QGraphicsView>

namespace throng::editor {

class BrainScene;

class BrainView : public QGraphicsView {
    Q_OBJECT

public:
    explicit BrainView(BrainScene* scene, QWidget* parent = nullptr);

    void frameAll();
    void frameSelection();
    // Multiplies the zoom by `factor` about the view's centre (clamped to 0.05..4).
    void zoomBy(double factor);
    double zoom() const { return transform().m11(); }
    // What to do first, drawn in the middle of the view while the graph has no nodes (an
    // empty string: nothing).
    void setHint(const QString& hint);
    QString hint() const { return m_hint; }

signals:
    void paletteRequested(QPoint viewPos);
    void copyRequested();
    void pasteRequested();
    void duplicateRequested();
    void collapseRequested();
    void expandRequested();

protected:
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void drawForeground(QPainter* painter, const QRectF& rect) override;

private:
    void fit(QRectF rect);

    BrainScene* m_scene;
    bool m_panning = false;
    QPoint m_panFrom;
    QPoint m_lastMouse{-1, -1};  // where the palette opens (viewport coordinates)
    QString m_hint;
};

}  // namespace throng::editor
