#pragma once
// Casts the camera ray through a widget pixel onto the terrain (or the ground plane
// y = 0 without one): how tools learn which ground point is under the mouse. Pure
// geometry; no GL, no widgets.

#include "simcore/scene/Scene.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <QPointF>
#include <QSize>

#include <optional>

namespace throng::editor {

// The first point of the terrain the ray through `pixel` (widget pixels of a `sizePx`
// view drawn with `viewProjection`) meets between the near and far planes; empty when
// it meets none.
std::optional<glm::vec3> castToGround(const glm::mat4& viewProjection, QSize sizePx, QPointF pixel,
                                      const sim::Terrain& terrain);

}  // namespace throng::editor
