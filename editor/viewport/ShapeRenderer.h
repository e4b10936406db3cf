#pragma once
// Uploads a ShapeMesh and draws it flat on the ground, widening thin lines to at least
// kMinHalfWidthPx on screen in either view. Owns its GL buffer (create, draw and destroy
// it with the context current); never builds geometry itself.

#include "editor/viewport/RenderView.h"
#include "editor/viewport/ShapeMesh.h"
#include "editor/viewport/VertexBuffer.h"

#include <QOpenGLShaderProgram>

#include <memory>

class QOpenGLFunctions_3_3_Core;

namespace throng::editor {

class ShapeRenderer {
public:
    static constexpr float kMinHalfWidthPx = 0.75f;

    bool initialize(QOpenGLFunctions_3_3_Core& gl);
    void destroy(QOpenGLFunctions_3_3_Core& gl);
    // Copies the mesh to the GPU (now, if the context is current and initialised).
    void upload(QOpenGLFunctions_3_3_Core& gl, const ShapeMesh& mesh);
    void draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view);

private:
    std::unique_ptr<QOpenGLShaderProgram> m_program;
    VertexBuffer m_vertices;
};

}  // namespace throng::editor
