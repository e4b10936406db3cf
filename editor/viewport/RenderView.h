#pragma once
// What every renderer needs to know about the camera for one frame: the matrix, the
// ground size of a pixel and whether to shade. Plain data, filled by CameraRig.

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace throng::editor {

struct RenderView {
    glm::mat4 viewProjection{1.0f};
    // Metres one widget pixel spans at clip-space w = 1: everywhere in the top view; in
    // perspective multiply by the point's clip w (its depth).
    float metresPerPixel = 0.0f;
    bool perspective = false;     // true: agents as lit prisms, depth tested
    glm::vec3 eye{0.0f};          // camera position, m
    glm::vec2 sizePx{1.0f};       // the viewport, widget pixels
};

}  // namespace throng::editor
