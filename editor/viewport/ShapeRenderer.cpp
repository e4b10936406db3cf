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
    gl.glGenVertexArrays(1, &m_vao);
    gl.glGenBuffers(1, &m_vbo);
    gl.glBindVertexArray(m_vao);
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    constexpr GLsizei stride = sizeof(ShapeVertex);
    gl.glEnableVertexAttribArray(0);
    gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                             reinterpret_cast<const void*>(offsetof(ShapeVertex, position)));
    gl.glEnableVertexAttribArray(1);
    gl.glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride,
                             reinterpret_cast<const void*>(offsetof(ShapeVertex, normal)));
    gl.glEnableVertexAttribArray(2);
    gl.glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                             reinterpret_cast<const void*>(offsetof(ShapeVertex, halfWidthM)));
    gl.glEnableVertexAttribArray(3);
    gl.glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, stride,
                             reinterpret_cast<const void*>(offsetof(ShapeVertex, colour)));
    gl.glBindVertexArray(0);
    return true;
}

void ShapeRenderer::destroy(QOpenGLFunctions_3_3_Core& gl)
{
    gl.glDeleteBuffers(1, &m_vbo);
    gl.glDeleteVertexArrays(1, &m_vao);
    m_vbo = m_vao = 0;
    m_vertexCount = 0;
    m_program.reset();
}

void ShapeRenderer::upload(QOpenGLFunctions_3_3_Core& gl, const ShapeMesh& mesh)
{
    if (!m_program)
        return;
    const auto& vertices = mesh.vertices();
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(ShapeVertex)), vertices.data(),
                    GL_STATIC_DRAW);
    m_vertexCount = int(vertices.size());
}

void ShapeRenderer::draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view)
{
    if (!m_program || m_vertexCount == 0)
        return;
    m_program->bind();
    gl.glUniformMatrix4fv(m_program->uniformLocation("u_viewProjection"), 1, GL_FALSE,
                          glm::value_ptr(view.viewProjection));
    m_program->setUniformValue("u_minHalfWidthAtW1", kMinHalfWidthPx * view.metresPerPixel);
    gl.glBindVertexArray(m_vao);
    gl.glDrawArrays(GL_TRIANGLES, 0, m_vertexCount);
    gl.glBindVertexArray(0);
    m_program->release();
}

}  // namespace throng::editor
