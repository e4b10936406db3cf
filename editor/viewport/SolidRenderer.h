#pragma once
// Uploads a SolidMesh and draws it lit (the light the agents' glyphs are shaded by),
// depth tested and writing depth, for the perspective view; glowing vertices keep their
// colour. Owns its GL buffer (create, draw and destroy it with the context current);
// never builds geometry itself, and draws nothing in the top view.

#include "editor/viewport/RenderView.h"
#include "editor/viewport/VertexBuffer.h"
#include "export/set/SolidMesh.h"

#include <QOpenGLShaderProgram>

#include <memory>

class QOpenGLFunctions_3_3_Core;

namespace throng::editor {

class SolidRenderer {
public:
    bool initialize(QOpenGLFunctions_3_3_Core& gl);
    void destroy(QOpenGLFunctions_3_3_Core& gl);
    // Copies the mesh to the GPU (now, if the context is current and initialised).
    void upload(QOpenGLFunctions_3_3_Core& gl, const exporting::SolidMesh& mesh);
    // Draws with the depth test as the caller set it up.
    void draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view);

private:
    std::unique_ptr<QOpenGLShaderProgram> m_program;
    VertexBuffer m_vertices;
};

}  // namespace throng::editor
