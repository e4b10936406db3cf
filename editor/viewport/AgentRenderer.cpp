#include "editor/viewport/AgentRenderer.h"

#include "editor/viewport/AgentGlyphMesh.h"
#include "editor/viewport/CarGlyphMesh.h"
#include "editor/viewport/ShaderProgram.h"
#include "editor/viewport/ViewportPalette.h"

#include <glm/gtc/type_ptr.hpp>

#include <QOpenGLFunctions_3_3_Core>

#include <algorithm>
#include <cstddef>

namespace throng::editor {

namespace {

// Heading h turns the glyph's +x nose to (cos h, 0, -sin h): counter-clockwise about +y
// seen from above, as the scene defines headings.
const char* const kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_part;
layout(location = 3) in vec4 i_positionHeading;
layout(location = 4) in vec4 i_radiusColour;
uniform mat4 u_viewProjection;
uniform float u_minRadiusAtW1;
uniform float u_heightScale;
out vec3 v_colour;
out vec3 v_normal;
flat out int v_part;
void main()
{
    vec3 centre = i_positionHeading.xyz;
    float c = cos(i_positionHeading.w), s = sin(i_positionHeading.w);
    float w = (u_viewProjection * vec4(centre, 1.0)).w;
    float radius = max(i_radiusColour.x, u_minRadiusAtW1 * w);
    float height = u_heightScale * clamp(5.5 * i_radiusColour.x, 0.5, 1.8);
    vec2 local = a_position.xz * radius;
    vec3 p = centre + vec3(local.x * c + local.y * s, a_position.y * height, -local.x * s + local.y * c);
    v_normal = vec3(a_normal.x * c + a_normal.z * s, a_normal.y, -a_normal.x * s + a_normal.z * c);
    v_colour = i_radiusColour.yzw;
    v_part = int(a_part + 0.5);
    gl_Position = u_viewProjection * vec4(p, 1.0);
}
)";

const char* const kFragmentShader = R"(#version 330 core
in vec3 v_colour;
in vec3 v_normal;
flat in int v_part;
uniform bool u_lit;
uniform vec3 u_noseColour;
out vec4 o_colour;
void main()
{
    vec3 colour = v_part == 2 ? u_noseColour : (v_part == 1 ? v_colour * 0.55 : v_colour);
    if (u_lit) {
        vec3 light = normalize(vec3(0.35, 1.0, 0.25));
        colour *= 0.45 + 0.55 * max(dot(normalize(v_normal), light), 0.0);
    }
    o_colour = vec4(colour, 1.0);
}
)";

// One point per agent; the fragment shader cuts the square point into a disc.
const char* const kSpriteVertexShader = R"(#version 330 core
layout(location = 3) in vec4 i_positionHeading;
layout(location = 4) in vec4 i_radiusColour;
uniform mat4 u_viewProjection;
uniform float u_pixelsPerMetre;
uniform float u_minRadiusPx;
out vec3 v_colour;
void main()
{
    gl_Position = u_viewProjection * vec4(i_positionHeading.xyz, 1.0);
    gl_PointSize = 2.0 * max(i_radiusColour.x * u_pixelsPerMetre, u_minRadiusPx);
    v_colour = i_radiusColour.yzw;
}
)";

const char* const kSpriteFragmentShader = R"(#version 330 core
in vec3 v_colour;
out vec4 o_colour;
void main()
{
    vec2 d = gl_PointCoord * 2.0 - 1.0;
    if (dot(d, d) > 1.0)
        discard;
    o_colour = vec4(v_colour, 1.0);
}
)";

}  // namespace

bool AgentRenderer::initialize(QOpenGLFunctions_3_3_Core& gl)
{
    m_program = buildShaderProgram("agent", kVertexShader, kFragmentShader);
    if (!m_program)
        return false;
    for (Instances* set : {&m_bodies, &m_cars}) {
        gl.glGenBuffers(1, &set->buffer);
        gl.glGenVertexArrays(1, &set->spriteVao);
        gl.glBindVertexArray(set->spriteVao);
        bindInstanceAttributes(gl, set->buffer, false);
        gl.glBindVertexArray(0);
    }
    createShape(gl, m_flat, AgentGlyphMesh::flat(AgentGlyphMesh::kDetailed), m_bodies.buffer);
    createShape(gl, m_prism, AgentGlyphMesh::prism(AgentGlyphMesh::kDetailed), m_bodies.buffer);
    createShape(gl, m_coarseFlat, AgentGlyphMesh::flat(AgentGlyphMesh::kCoarse), m_bodies.buffer);
    createShape(gl, m_coarsePrism, AgentGlyphMesh::prism(AgentGlyphMesh::kCoarse), m_bodies.buffer);
    createShape(gl, m_carFlat, CarGlyphMesh::flat(), m_cars.buffer);
    createShape(gl, m_carSolid, CarGlyphMesh::solid(), m_cars.buffer);
    m_spriteProgram = buildShaderProgram("agent sprite", kSpriteVertexShader, kSpriteFragmentShader);
    return bool(m_spriteProgram);
}

void AgentRenderer::bindInstanceAttributes(QOpenGLFunctions_3_3_Core& gl, unsigned instances, bool divisor)
{
    gl.glBindBuffer(GL_ARRAY_BUFFER, instances);
    constexpr GLsizei instanceStride = sizeof(AgentGlyph);
    gl.glEnableVertexAttribArray(3);
    gl.glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, instanceStride,
                             reinterpret_cast<const void*>(offsetof(AgentGlyph, position)));
    gl.glEnableVertexAttribArray(4);
    gl.glVertexAttribPointer(4, 4, GL_FLOAT, GL_FALSE, instanceStride,
                             reinterpret_cast<const void*>(offsetof(AgentGlyph, radiusM)));
    if (divisor) {
        gl.glVertexAttribDivisor(3, 1);
        gl.glVertexAttribDivisor(4, 1);
    }
}

void AgentRenderer::createShape(QOpenGLFunctions_3_3_Core& gl, Shape& shape, const std::vector<GlyphVertex>& vertices,
                                unsigned instances)
{
    shape.vertexCount = int(vertices.size());
    gl.glGenVertexArrays(1, &shape.vao);
    gl.glGenBuffers(1, &shape.vbo);
    gl.glBindVertexArray(shape.vao);
    gl.glBindBuffer(GL_ARRAY_BUFFER, shape.vbo);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(GlyphVertex)), vertices.data(),
                    GL_STATIC_DRAW);
    constexpr GLsizei stride = sizeof(GlyphVertex);
    gl.glEnableVertexAttribArray(0);
    gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                             reinterpret_cast<const void*>(offsetof(GlyphVertex, position)));
    gl.glEnableVertexAttribArray(1);
    gl.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                             reinterpret_cast<const void*>(offsetof(GlyphVertex, normal)));
    gl.glEnableVertexAttribArray(2);
    gl.glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                             reinterpret_cast<const void*>(offsetof(GlyphVertex, part)));
    bindInstanceAttributes(gl, instances, true);
    gl.glBindVertexArray(0);
}

void AgentRenderer::destroy(QOpenGLFunctions_3_3_Core& gl)
{
    for (Shape* shape : {&m_flat, &m_prism, &m_coarseFlat, &m_coarsePrism, &m_carFlat, &m_carSolid}) {
        gl.glDeleteBuffers(1, &shape->vbo);
        gl.glDeleteVertexArrays(1, &shape->vao);
        *shape = {};
    }
    for (Instances* set : {&m_bodies, &m_cars}) {
        gl.glDeleteVertexArrays(1, &set->spriteVao);
        gl.glDeleteBuffers(1, &set->buffer);
        *set = {};
    }
    m_spriteProgram.reset();
    m_program.reset();
}

void AgentRenderer::upload(QOpenGLFunctions_3_3_Core& gl, std::span<const AgentGlyph> bodies,
                           std::span<const AgentGlyph> cars)
{
    static_assert(sizeof(AgentGlyph) == 8 * sizeof(float), "the shader reads two vec4 per instance");
    if (!m_program)
        return;
    uploadInstances(gl, m_bodies, bodies);
    uploadInstances(gl, m_cars, cars);
}

void AgentRenderer::uploadInstances(QOpenGLFunctions_3_3_Core& gl, Instances& set, std::span<const AgentGlyph> glyphs)
{
    gl.glBindBuffer(GL_ARRAY_BUFFER, set.buffer);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(glyphs.size_bytes()), glyphs.data(), GL_DYNAMIC_DRAW);
    set.count = int(glyphs.size());
    set.maxRadiusM = 0.0f;
    for (const AgentGlyph& g : glyphs)
        set.maxRadiusM = std::max(set.maxRadiusM, g.radiusM);
}

void AgentRenderer::draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view)
{
    if (!m_program)
        return;
    const bool coarse = m_bodies.count + m_cars.count > kDetailedLimit;
    drawSet(gl, view, m_bodies, coarse ? m_coarseFlat : m_flat, coarse ? m_coarsePrism : m_prism, coarse);
    drawSet(gl, view, m_cars, m_carFlat, m_carSolid, false);
}

void AgentRenderer::drawSet(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, const Instances& set,
                            const Shape& flat, const Shape& solid, bool coarse)
{
    if (set.count == 0)
        return;
    if (!view.perspective && set.maxRadiusM < kSpriteBelowPx * view.metresPerPixel) {
        drawSprites(gl, view, set);
        return;
    }
    const Shape* shape = view.perspective ? &solid : &flat;
    // Tiny walkers in the top view: the coarse glyph, their detail would not show.
    if (&flat == &m_flat && !coarse && !view.perspective && set.maxRadiusM < kCoarseBelowPx * view.metresPerPixel)
        shape = &m_coarseFlat;
    m_program->bind();
    gl.glUniformMatrix4fv(m_program->uniformLocation("u_viewProjection"), 1, GL_FALSE,
                          glm::value_ptr(view.viewProjection));
    m_program->setUniformValue("u_minRadiusAtW1", kMinRadiusPx * view.metresPerPixel);
    m_program->setUniformValue("u_heightScale", view.perspective ? 1.0f : 0.0f);
    m_program->setUniformValue("u_lit", view.perspective);
    const glm::vec4 nose = palette::kAgentNose;
    m_program->setUniformValue("u_noseColour", nose.r, nose.g, nose.b);
    gl.glBindVertexArray(shape->vao);
    gl.glDrawArraysInstanced(GL_TRIANGLES, 0, shape->vertexCount, set.count);
    gl.glBindVertexArray(0);
    m_program->release();
}

void AgentRenderer::drawSprites(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, const Instances& set)
{
    m_spriteProgram->bind();
    gl.glUniformMatrix4fv(m_spriteProgram->uniformLocation("u_viewProjection"), 1, GL_FALSE,
                          glm::value_ptr(view.viewProjection));
    m_spriteProgram->setUniformValue("u_pixelsPerMetre", 1.0f / std::max(view.metresPerPixel, 1e-6f));
    m_spriteProgram->setUniformValue("u_minRadiusPx", kMinRadiusPx);
    gl.glEnable(GL_PROGRAM_POINT_SIZE);
    gl.glBindVertexArray(set.spriteVao);
    gl.glDrawArrays(GL_POINTS, 0, set.count);
    gl.glBindVertexArray(0);
    gl.glDisable(GL_PROGRAM_POINT_SIZE);
    m_spriteProgram->release();
}

}  // namespace throng::editor
