#include "editor/viewport/GridRenderer.h"

#include "editor/viewport/ShaderProgram.h"
#include "editor/viewport/ViewportPalette.h"

#include <glm/common.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <QOpenGLFunctions_3_3_Core>

#include <algorithm>
#include <array>

namespace throng::editor {

namespace {

const char* const kGridVertexShader = R"(#version 330 core
layout(location = 0) in vec2 a_ground;
uniform mat4 u_viewProjection;
out vec2 v_ground;
void main()
{
    v_ground = a_ground;
    gl_Position = u_viewProjection * vec4(a_ground.x, 0.0, a_ground.y, 1.0);
}
)";

// Lines are one pixel wide whatever the zoom: distances are measured in pixels through
// fwidth. The finer grid fades out before its lines crowd closer than kMinCellPx.
const char* const kGridFragmentShader = R"(#version 330 core
in vec2 v_ground;
uniform vec2 u_boundsMin;
uniform vec2 u_boundsMax;
uniform vec4 u_ground;
uniform vec4 u_outside;
uniform vec4 u_minor;
uniform vec4 u_major;
out vec4 o_colour;
const float kMinCellPx = 12.0;
float lineCoverage(vec2 p, float spacing, vec2 metresPerPixel)
{
    vec2 distPx = abs(fract(p / spacing - 0.5) - 0.5) * spacing / metresPerPixel;
    return clamp(1.0 - min(distPx.x, distPx.y), 0.0, 1.0);
}
void main()
{
    vec2 mpp = max(fwidth(v_ground), vec2(1e-6));
    float level = max(log(kMinCellPx * max(mpp.x, mpp.y)) / log(10.0), 0.0);
    float minorSpacing = pow(10.0, floor(level));
    float fade = 1.0 - fract(level);
    bool inside = all(greaterThanEqual(v_ground, u_boundsMin)) && all(lessThanEqual(v_ground, u_boundsMax));
    vec4 colour = inside ? u_ground : u_outside;
    float strength = inside ? 1.0 : 0.45;
    colour = mix(colour, u_minor, strength * fade * lineCoverage(v_ground, minorSpacing, mpp));
    colour = mix(colour, u_major, strength * lineCoverage(v_ground, 10.0 * minorSpacing, mpp));
    o_colour = colour;
}
)";

void setColour(QOpenGLShaderProgram& p, const char* name, glm::vec4 c)
{
    p.setUniformValue(name, c.r, c.g, c.b, c.a);
}

}  // namespace

bool GridRenderer::initialize(QOpenGLFunctions_3_3_Core& gl)
{
    m_program = buildShaderProgram("grid", kGridVertexShader, kGridFragmentShader);
    if (!m_program)
        return false;
    m_quad.create(gl, sizeof(glm::vec2), {{2, 0}});
    m_dirty = true;
    return true;
}

void GridRenderer::destroy(QOpenGLFunctions_3_3_Core& gl)
{
    m_quad.destroy(gl);
    m_program.reset();
}

void GridRenderer::setBounds(glm::vec2 boundsMin, glm::vec2 boundsMax)
{
    m_boundsMin = boundsMin;
    m_boundsMax = boundsMax;
    m_dirty = true;
}

void GridRenderer::draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view)
{
    if (!m_program)
        return;
    if (m_dirty) {
        // Far enough past the bounds to reach the horizon of the perspective view.
        const glm::vec2 c = 0.5f * (m_boundsMin + m_boundsMax);
        const float reach = 20.0f * std::max(m_boundsMax.x - m_boundsMin.x, m_boundsMax.y - m_boundsMin.y) + 2000.0f;
        const std::array<glm::vec2, 6> quad{c + glm::vec2(-reach, -reach), c + glm::vec2(reach, -reach),
                                            c + glm::vec2(reach, reach),   c + glm::vec2(-reach, -reach),
                                            c + glm::vec2(reach, reach),   c + glm::vec2(-reach, reach)};
        m_quad.upload(gl, quad.data(), quad.size());
        m_dirty = false;
    }
    m_program->bind();
    gl.glUniformMatrix4fv(m_program->uniformLocation("u_viewProjection"), 1, GL_FALSE,
                          glm::value_ptr(view.viewProjection));
    m_program->setUniformValue("u_boundsMin", m_boundsMin.x, m_boundsMin.y);
    m_program->setUniformValue("u_boundsMax", m_boundsMax.x, m_boundsMax.y);
    setColour(*m_program, "u_ground", palette::kGround);
    setColour(*m_program, "u_outside", palette::kBackground);
    setColour(*m_program, "u_minor", palette::kGridMinor);
    setColour(*m_program, "u_major", palette::kGridMajor);
    m_quad.drawTriangles(gl);
    m_program->release();
}

}  // namespace throng::editor
