#pragma once
// Base of every brush (crowd, erase, orient, variation, assign): a disk on the ground that
// follows the mouse. Owns what all brushes share: the radius, changed by [ and ] or by a
// Ctrl+drag (the disk stays put, its rim follows the mouse), a tool setting and never an
// undo step; the disk drawn under the cursor; the radius field of the options bar. The
// strokes are the subclasses'; this class never edits the scene.

#include "editor/tools/ViewportTool.h"

#include <glm/vec2.hpp>

#include <QColor>

class QHBoxLayout;

namespace throng::editor {

class BrushTool : public ViewportTool {
    Q_OBJECT

public:
    static constexpr float kMinRadiusM = 0.1f;
    static constexpr float kMaxRadiusM = 100.0f;
    static constexpr float kRadiusStep = 1.25f;  // ] multiplies the radius by this, [ divides

    BrushTool(SceneDocument& document, Viewport& viewport, float radiusM, QObject* parent = nullptr);

    float radiusM() const { return m_radiusM; }
    // Clamped to [kMinRadiusM, kMaxRadiusM]; the options bar's field and the disk follow.
    void setRadiusM(float radiusM);
    bool isResizing() const { return m_resizing; }
    // Where the disk is drawn (under the cursor, or where a resize began); empty when the
    // cursor is off the ground.
    std::optional<glm::vec3> diskCentre() const;

    void mousePressed(const ToolMouse& mouse) final;
    void mouseMoved(const ToolMouse& mouse) final;
    void mouseReleased(const ToolMouse& mouse) final;
    // [ and ] step the radius; Escape also ends a resize at the radius it began with.
    bool keyPressed(QKeyEvent* event) override;
    void cancel() override;
    void drawOverlay(QPainter& painter) const override;

signals:
    void radiusChanged(float radiusM);

protected:
    // Asked at the press before a stroke: false = no stroke (the tool has said why).
    virtual bool strokeAllowed() { return true; }
    // A stroke at ground points (x, z): its first point, each later one, and its end.
    virtual void strokeBegan(glm::vec2 point) = 0;
    virtual void strokeMoved(glm::vec2 point) = 0;
    virtual void strokeEnded() {}
    virtual QColor brushColour() const = 0;
    // Adds "Radius" and its spin box, named `objectName`, to an options row; the box and
    // the radius follow each other.
    void addRadiusOption(QWidget* box, QHBoxLayout* row, const QString& objectName);

private:
    void resizeTo(QPointF pixel);
    void endResize(bool keep);

    float m_radiusM;
    std::optional<glm::vec3> m_cursor;
    bool m_resizing = false;
    glm::vec3 m_resizeCentre{0.0f};
    double m_resizeStartX = 0.0;   // widget pixel where the resize began
    float m_resizeStartRadiusM = 0.0f;
    double m_pixelsPerM = 1.0;     // at the resize centre, along the screen's x
};

}  // namespace throng::editor
