#include "editor/viewport/ShapeRenderer.h"

#include "editor/viewport/ShaderProgram.h"

#include <glm/gtc/type_ptr.hpp>

#include <QOpenGLFunctions_3_3_Core>

#include <cstddef>

namespace throng::editor {

namespace {

const char* const kShapeVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec2 a_normal;
layout(location = 2) in float a_halfWidth;
layout(location = 3) in vec4 a_colour;
uniform mat4 u_viewProjection;
uniform float u_minHalfWidthAtW1;
out vec4 v_colour;
void main()
{
    float w = (u_viewProjection * vec4(a_position, 1.0)).w;
    float extra = max(u_minHalfWidthAtW1 * w - a_halfWidth, 0.0);
    vec3 p = a_position + vec3(a_normal.x, 0.0, a_normal.y) * extra;
    v_colour = a_colour;
    gl_Position = u_viewProjection * vec4(p, 1.0);
}
)";

const char* const kShapeFragmentShader = R"(#version 330 core
in vec4 v_colour;
out vec4 o_colour;
void main()
{
    o_colour = v_colour;
}
)";

}  // namespace

bool ShapeRenderer::initialize(QOpenGLFunctions_3_3_Core& gl)
{
    m_program = buildShaderProgram("shape", kShapeVertexShader, kShapeFragmentShader);
    if (!m_program)
        return false;
    m_vertices.create(gl, sizeof(ShapeVertex),
                      {{3, offsetof(ShapeVertex, position)},
                       {2, offsetof(ShapeVertex, normal)},
                       {1, offsetof(ShapeVertex, halfWidthM)},
                       {4, offsetof(ShapeVertex, colour)}});
    return true;
}

void ShapeRenderer::destroy(QOpenGLFunctions_3_3_Core& gl)
{
    m_vertices.destroy(gl);
    m_program.reset();
}

void ShapeRenderer::upload(QOpenGLFunctions_3_3_Core& gl, const ShapeMesh& mesh)
{
    m_vertices.upload(gl, mesh.vertices());
}

void ShapeRenderer::draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view)
{
    if (!m_program || m_vertices.vertexCount() == 0)
        return;
    m_program->bind();
    gl.glUniformMatrix4fv(m_program->uniformLocation("u_viewProjection"), 1, GL_FALSE,
                          glm::value_ptr(view.viewProjection));
    m_program->setUniformValue("u_minHalfWidthAtW1", kMinHalfWidthPx * view.metresPerPixel);
    m_vertices.drawTriangles(gl);
    m_program->release();
}

}  // namespace throng::editor
