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
    using exporting::SolidVertex;
    m_vertices.create(gl, sizeof(SolidVertex),
                      {{3, offsetof(SolidVertex, position)},
                       {3, offsetof(SolidVertex, normal)},
                       {4, offsetof(SolidVertex, colour)},
                       {1, offsetof(SolidVertex, glow)}});
    return true;
}

void SolidRenderer::destroy(QOpenGLFunctions_3_3_Core& gl)
{
    m_vertices.destroy(gl);
    m_program.reset();
}

void SolidRenderer::upload(QOpenGLFunctions_3_3_Core& gl, const exporting::SolidMesh& mesh)
{
    m_vertices.upload(gl, mesh.vertices());
}

void SolidRenderer::draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view)
{
    if (!m_program || m_vertices.vertexCount() == 0 || !view.perspective)
        return;
    m_program->bind();
    gl.glUniformMatrix4fv(m_program->uniformLocation("u_viewProjection"), 1, GL_FALSE,
                          glm::value_ptr(view.viewProjection));
    m_vertices.drawTriangles(gl);
    m_program->release();
}

}  // namespace throng::editor
