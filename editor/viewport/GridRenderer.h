#pragma once
// Draws the ground: the world-bounds area, the surroundings and an anti-aliased metric
// grid (1 m / 10 m / 100 m ..., chosen by zoom) computed in the fragment shader.
// Owns its GL objects; must be created, drawn and destroyed with the context current.

#include "editor/viewport/RenderView.h"
#include "editor/viewport/VertexBuffer.h"

#include <glm/vec2.hpp>

#include <QOpenGLShaderProgram>

#include <memory>

class QOpenGLFunctions_3_3_Core;

namespace throng::editor {

class GridRenderer {
public:
    bool initialize(QOpenGLFunctions_3_3_Core& gl);
    void destroy(QOpenGLFunctions_3_3_Core& gl);
    // The world bounds (x, z) in metres; the ground plane reaches far beyond them.
    void setBounds(glm::vec2 boundsMin, glm::vec2 boundsMax);
    void draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view);

private:
    std::unique_ptr<QOpenGLShaderProgram> m_program;
    VertexBuffer m_quad;  // the ground: two triangles, remade when the bounds change
    glm::vec2 m_boundsMin{-50.0f}, m_boundsMax{50.0f};
    bool m_dirty = true;
};

}  // namespace throng::editor
