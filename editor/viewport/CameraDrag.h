#pragma once
// Which camera move a mouse drag in the viewport makes, by the Maya/Houdini convention:
// with Alt held the left button orbits (pans in the top view), the middle pans and the
// right zooms towards where the drag began; without Alt the middle pans and the right
// orbits in 3D (Shift: pans) or pans from above. Holds the drag's state between events.

#include "editor/viewport/CameraRig.h"

#include <glm/vec3.hpp>

#include <QPointF>

#include <optional>

namespace throng::editor {

class CameraDrag {
public:
    // Whether a drag is under way.
    bool active() const { return m_button != Qt::NoButton; }
    // A drag begins with `button` pressed at `pixel`; `alt`: Alt was held. ground: the
    // ground under the pixel, which an Alt+right drag zooms towards.
    void begin(Qt::MouseButton button, bool alt, QPointF pixel, std::optional<glm::vec3> ground);
    // The mouse moved to `pixel`: moves `camera` (sized to the view) by the drag's rule.
    void move(QPointF pixel, Qt::KeyboardModifiers modifiers, CameraRig& camera);
    // `button` was released; true when that ended the drag.
    bool end(Qt::MouseButton button);

private:
    Qt::MouseButton m_button = Qt::NoButton;
    bool m_alt = false;  // the drag began with Alt held: the DCC bindings
    QPointF m_last, m_press;
    std::optional<glm::vec3> m_pressGround;
};

}  // namespace throng::editor
