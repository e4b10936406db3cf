#pragma once
// The membership curve drawn inside a fuzz node, with handles the user drags to edit
// the parameters (points, centre, width, slope). Previews while dragging and hands the
// new parameters to `commit` once on release; never edits the graph itself.

#include "simcore/scene/BrainGraph.h"

#include <QGraphicsItem>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace throng::editor {

class FuzzCurveItem : public QGraphicsItem {
public:
    enum { Type = UserType + 4 };
    using Commit = std::function<void(const std::vector<sim::BrainParam>&)>;

    FuzzCurveItem(QGraphicsItem* parent, QRectF rect);
    int type() const override { return Type; }

    void setCurve(const std::string& nodeType, const std::vector<sim::BrainParam>& params);
    // Where the curve sits in its node (item coordinates of the node).
    void setRect(QRectF rect);
    void setCommit(Commit commit) { m_commit = std::move(commit); }
    // The picked agent's input value, drawn as a marker on the curve.
    void setInputValue(std::optional<float> x);

    int handleCount() const;
    QPointF handleScenePos(int handle) const;
    const std::vector<sim::BrainParam>& params() const { return m_params; }

    QRectF boundingRect() const override { return m_rect; }
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

protected:
    void mousePressEvent(QGraphicsSceneMouseEvent* event) override;
    void mouseMoveEvent(QGraphicsSceneMouseEvent* event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent* event) override;

private:
    QPointF toLocal(float x, float truth) const;
    float toValue(double localX) const;

    QRectF m_rect;
    std::string m_type;
    std::vector<sim::BrainParam> m_params;
    float m_lo = 0.0f, m_hi = 1.0f;
    int m_drag = -1;
    std::optional<float> m_input;
    Commit m_commit;
};

}  // namespace throng::editor
