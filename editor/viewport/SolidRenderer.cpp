#include "editor/viewport/SolidRenderer.h"

#include "editor/viewport/ShaderProgram.h"

#include <glm/gtc/type_ptr.hpp>

#include <QOpenGLFunctions_3_3_Core>

#include <cstddef>

namespace throng::editor {

namespace {

const char* const kSolidVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_colour;
layout(location = 3) in float a_glow;
uniform mat4 u_viewProjection;
out vec4 v_colour;
out vec3 v_normal;
out float v_glow;
void main()
{
    v_colour = a_colour;
    v_normal = a_normal;
    v_glow = a_glow;
    gl_Position = u_viewProjection * vec4(a_position, 1.0);
}
)";

// The light and the shading of AgentShaders' glyphs, so the set and the crowd match.
const char* const kSolidFragmentShader = R"(#version 330 core
in vec4 v_colour;
in vec3 v_normal;
in float v_glow;
out vec4 o_colour;
void main()
{
    vec3 light = normalize(vec3(0.35, 1.0, 0.25));
    float shade = 0.45 + 0.55 * max(dot(normalize(v_normal), light), 0.0);
    o_colour = vec4(v_colour.rgb * mix(shade, 1.0, v_glow), v_colour.a);
}
)";

}  // namespace

bool SolidRenderer::initialize(QOpenGLFunctions_3_3_Core& gl)
{
    m_program = buildShaderProgram("solid", kSolidVertexShader, kSolidFragmentShader);
    if (!m_program)
        return false;
    gl.glGenVertexArrays(1, &m_vao);
    gl.glGenBuffers(1, &m_vbo);
    gl.glBindVertexArray(m_vao);
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    constexpr GLsizei stride = sizeof(exporting::SolidVertex);
    gl.glEnableVertexAttribArray(0);
    gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                             reinterpret_cast<const void*>(offsetof(exporting::SolidVertex, position)));
    gl.glEnableVertexAttribArray(1);
    gl.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                             reinterpret_cast<const void*>(offsetof(exporting::SolidVertex, normal)));
    gl.glEnableVertexAttribArray(2);
    gl.glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride,
                             reinterpret_cast<const void*>(offsetof(exporting::SolidVertex, colour)));
    gl.glEnableVertexAttribArray(3);
    gl.glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, stride,
                             reinterpret_cast<const void*>(offsetof(exporting::SolidVertex, glow)));
    gl.glBindVertexArray(0);
    return true;
}

void SolidRenderer::destroy(QOpenGLFunctions_3_3_Core& gl)
{
    gl.glDeleteBuffers(1, &m_vbo);
    gl.glDeleteVertexArrays(1, &m_vao);
    m_vbo = m_vao = 0;
    m_vertexCount = 0;
    m_program.reset();
}

void SolidRenderer::upload(QOpenGLFunctions_3_3_Core& gl, const exporting::SolidMesh& mesh)
{
    if (!m_program)
        return;
    const auto& vertices = mesh.vertices();
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(exporting::SolidVertex)), vertices.data(),
                    GL_STATIC_DRAW);
    m_vertexCount = int(vertices.size());
}

void SolidRenderer::draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view)
{
    if (!m_program || m_vertexCount == 0 || !view.perspective)
        return;
    m_program->bind();
    gl.glUniformMatrix4fv(m_program->uniformLocation("u_viewProjection"), 1, GL_FALSE,
                          glm::value_ptr(view.viewProjection));
    gl.glBindVertexArray(m_vao);
    gl.glDrawArrays(GL_TRIANGLES, 0, m_vertexCount);
    gl.glBindVertexArray(0);
    m_program->release();
}

}  // namespace throng::editor
