#include "editor/viewport/AgentRenderer.h"

#include "editor/viewport/AgentGlyphMesh.h"
#include "editor/viewport/AgentShaders.h"
#include "editor/viewport/BirdGlyphMesh.h"
#include "editor/viewport/CarGlyphMesh.h"
#include "editor/viewport/ShaderProgram.h"
#include "editor/viewport/ViewportPalette.h"

#include <glm/gtc/type_ptr.hpp>

#include <QOpenGLFunctions_3_3_Core>

#include <algorithm>
#include <cstddef>

namespace throng::editor {

namespace {

constexpr GLsizei kInstanceStride = sizeof(AgentGlyph);

// Points the bound VAO's instance attributes at instance `first` of `instances`: GL 3.3
// has no base instance, so a range of instances starts where the pointers do.
void pointInstancesAt(QOpenGLFunctions_3_3_Core& gl, unsigned instances, int first)
{
    const std::size_t at = std::size_t(first) * sizeof(AgentGlyph);
    gl.glBindBuffer(GL_ARRAY_BUFFER, instances);
    gl.glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, kInstanceStride,
                             reinterpret_cast<const void*>(at + offsetof(AgentGlyph, position)));
    gl.glVertexAttribPointer(4, 4, GL_FLOAT, GL_FALSE, kInstanceStride,
                             reinterpret_cast<const void*>(at + offsetof(AgentGlyph, radiusM)));
}

}  // namespace

bool AgentRenderer::initialize(QOpenGLFunctions_3_3_Core& gl)
{
    m_program = buildShaderProgram("agent", shaders::kGlyphVertex, shaders::kGlyphFragment);
    if (!m_program)
        return false;
    for (Instances* set : {&m_bodies, &m_cars, &m_birds}) {
        gl.glGenBuffers(1, &set->buffer);
        gl.glGenVertexArrays(1, &set->spriteVao);
        gl.glBindVertexArray(set->spriteVao);
        bindInstanceAttributes(gl, set->buffer, true);
        gl.glBindVertexArray(0);
    }
    createShape(gl, m_flat, AgentGlyphMesh::flat(AgentGlyphMesh::kDetailed), m_bodies.buffer);
    createShape(gl, m_prism, AgentGlyphMesh::prism(AgentGlyphMesh::kDetailed), m_bodies.buffer);
    createShape(gl, m_coarseFlat, AgentGlyphMesh::flat(AgentGlyphMesh::kCoarse), m_bodies.buffer);
    createShape(gl, m_coarsePrism, AgentGlyphMesh::prism(AgentGlyphMesh::kCoarse), m_bodies.buffer);
    createShape(gl, m_carFlat, CarGlyphMesh::flat(), m_cars.buffer);
    createShape(gl, m_carSolid, CarGlyphMesh::solid(), m_cars.buffer);
    createShape(gl, m_bird, BirdGlyphMesh::detailed(), m_birds.buffer);
    createShape(gl, m_coarseBird, BirdGlyphMesh::coarse(), m_birds.buffer);
    createShape(gl, m_farBird, BirdGlyphMesh::far(), m_birds.buffer);
    gl.glGenBuffers(1, &m_fallbackBuffer);
    m_spriteProgram = buildShaderProgram("agent impostor", shaders::kImpostorVertex, shaders::kImpostorFragment);
    return m_spriteProgram && m_characters.initialize(gl);
}

void AgentRenderer::bindInstanceAttributes(QOpenGLFunctions_3_3_Core& gl, unsigned instances, bool divisor)
{
    gl.glEnableVertexAttribArray(3);
    gl.glEnableVertexAttribArray(4);
    pointInstancesAt(gl, instances, 0);
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
    for (Shape* shape :
         {&m_flat, &m_prism, &m_coarseFlat, &m_coarsePrism, &m_carFlat, &m_carSolid, &m_bird, &m_coarseBird, &m_farBird}) {
        gl.glDeleteBuffers(1, &shape->vbo);
        gl.glDeleteVertexArrays(1, &shape->vao);
        *shape = {};
    }
    for (Instances* set : {&m_bodies, &m_cars, &m_birds}) {
        gl.glDeleteVertexArrays(1, &set->spriteVao);
        gl.glDeleteBuffers(1, &set->buffer);
        *set = {};
    }
    gl.glDeleteBuffers(1, &m_fallbackBuffer);
    m_fallbackBuffer = 0;
    m_characters.destroy(gl);
    m_spriteProgram.reset();
    m_program.reset();
}

void AgentRenderer::upload(QOpenGLFunctions_3_3_Core& gl, AgentBatch bodies, AgentBatch cars, AgentBatch birds)
{
    static_assert(sizeof(AgentGlyph) == 8 * sizeof(float), "the shader reads two vec4 per instance");
    if (!m_program)
        return;
    uploadInstances(gl, m_bodies, bodies);
    uploadInstances(gl, m_cars, cars);
    uploadInstances(gl, m_birds, birds);
}

void AgentRenderer::uploadInstances(QOpenGLFunctions_3_3_Core& gl, Instances& set, AgentBatch batch)
{
    const std::span<const AgentGlyph> glyphs = batch.glyphs;
    const std::span<const AgentPose> poses = batch.poses;
    if (poses.size() == glyphs.size())
        set.poses.assign(poses.begin(), poses.end());
    else
        set.poses.clear();
    // Uploaded in cell order, whether level of detail is on or not: the draw order of
    // agents that overlap is not part of what they show.
    set.cells.build(glyphs);
    const std::span<const AgentGlyph> sorted = set.cells.sorted();
    gl.glBindBuffer(GL_ARRAY_BUFFER, set.buffer);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(sorted.size_bytes()), sorted.data(), GL_DYNAMIC_DRAW);
    set.count = int(glyphs.size());
    set.maxRadiusM = 0.0f;
    for (const AgentGlyph& g : glyphs)
        set.maxRadiusM = std::max(set.maxRadiusM, g.radiusM);
}

void AgentRenderer::draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view)
{
    if (!m_program)
        return;
    const int total = m_bodies.count + m_cars.count + m_birds.count;
    if (!m_levelOfDetail) {
        const bool coarse = total > kDetailedLimit;
        drawSet(gl, view, m_bodies, coarse ? m_coarseFlat : m_flat, coarse ? m_coarsePrism : m_prism, coarse);
        drawSet(gl, view, m_cars, m_carFlat, m_carSolid, false);
        drawBirds(gl, view, coarse);
        return;
    }
    m_lastDrawn = {};
    m_characters.clear();
    m_characterBudget = kCharacterLimit;
    const bool p = view.perspective;
    // Cars first: few, and their characters matter most near the walkers they pass.
    const Shape& car = p ? m_carSolid : m_carFlat;
    drawPlanned(gl, view, m_cars, {car, car}, DetailThresholds{0.0f, 0.0f});
    // Past kDetailedLimit agents even the near ones keep the coarse glyph, as without
    // level of detail: under a software renderer each of its triangles costs.
    const bool coarse = total > kDetailedLimit;
    const Shape& coarseBody = p ? m_coarsePrism : m_coarseFlat;
    const DetailThresholds& thresholds = p ? kPerspectiveDetail : kTopDetail;
    drawPlanned(gl, view, m_bodies, {coarse ? coarseBody : (p ? m_prism : m_flat), coarseBody}, thresholds);
    drawPlanned(gl, view, m_birds, {coarse ? m_coarseBird : m_bird, m_coarseBird, &m_farBird, true}, thresholds);
    m_characters.draw(gl, view);
}

void AgentRenderer::takeCharacters(const Instances& set)
{
    m_fallback.clear();
    const std::span<const AgentGlyph> sorted = set.cells.sorted();
    const std::span<const int> order = set.cells.order();
    for (int level = 0; level < 2; ++level) {
        std::vector<InstanceRange>& kept = m_glyphRanges[std::size_t(level)];
        kept.clear();
        for (const InstanceRange& r : set.plan.ranges[std::size_t(level)]) {
            int k = r.first;
            for (; k < r.first + r.count && m_characterBudget > 0; ++k) {
                const AgentPose& pose = set.poses[std::size_t(order[std::size_t(k)])];
                if (m_characters.hasCharacter(pose.character)) {
                    m_characters.add(sorted[std::size_t(k)], pose, level);
                    --m_characterBudget;
                } else {
                    m_fallback.push_back(sorted[std::size_t(k)]);
                }
            }
            if (k < r.first + r.count)
                kept.push_back({k, r.first + r.count - k});
        }
    }
}

void AgentRenderer::drawPlanned(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, Instances& set,
                                const Looks& looks, const DetailThresholds& thresholds)
{
    if (set.count == 0)
        return;
    set.cells.plan(view, thresholds, set.plan);
    const Shape &detailed = looks.detailed, &coarse = looks.coarse;
    std::span<const InstanceRange> near = set.plan.at(AgentDetail::Detailed);
    std::span<const InstanceRange> mid = set.plan.at(AgentDetail::Coarse);
    std::span<const InstanceRange> far = set.plan.at(AgentDetail::Impostor);
    m_fallback.clear();
    if (m_agentsAsCharacters && view.perspective && !set.poses.empty() && m_characters.characterCount() > 0) {
        takeCharacters(set);
        near = m_glyphRanges[0];
        mid = m_glyphRanges[1];
    }
    const bool farAsGlyphs = looks.far && !far.empty();
    if (!near.empty() || !mid.empty() || !m_fallback.empty() || farAsGlyphs) {
        bindGlyphProgram(gl, view, looks.bird);
        drawRanges(gl, detailed.vao, set.buffer, detailed.vertexCount, near);
        drawRanges(gl, coarse.vao, set.buffer, coarse.vertexCount, mid);
        if (farAsGlyphs)
            drawRanges(gl, looks.far->vao, set.buffer, looks.far->vertexCount, far);
        if (!m_fallback.empty()) {
            // Near agents whose type has no character: the detailed glyph, from a buffer of their own.
            gl.glBindBuffer(GL_ARRAY_BUFFER, m_fallbackBuffer);
            gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m_fallback.size() * sizeof(AgentGlyph)), m_fallback.data(),
                            GL_STREAM_DRAW);
            const InstanceRange all{0, int(m_fallback.size())};
            drawRanges(gl, detailed.vao, m_fallbackBuffer, detailed.vertexCount, {&all, 1});
        }
        m_program->release();
    }
    if (!looks.far && !far.empty())
        drawSprites(gl, view, set, far);
    for (int d = 0; d < kAgentDetailLevels; ++d)
        m_lastDrawn[std::size_t(d)] += set.plan.agents[std::size_t(d)];
}

void AgentRenderer::drawRanges(QOpenGLFunctions_3_3_Core& gl, unsigned vao, unsigned instances, int vertexCount,
                               std::span<const InstanceRange> ranges)
{
    if (ranges.empty())
        return;
    gl.glBindVertexArray(vao);
    for (const InstanceRange& r : ranges) {
        pointInstancesAt(gl, instances, r.first);
        gl.glDrawArraysInstanced(GL_TRIANGLES, 0, vertexCount, r.count);
    }
    pointInstancesAt(gl, instances, 0);
    gl.glBindVertexArray(0);
}

void AgentRenderer::bindGlyphProgram(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, bool bird)
{
    m_program->bind();
    gl.glUniformMatrix4fv(m_program->uniformLocation("u_viewProjection"), 1, GL_FALSE,
                          glm::value_ptr(view.viewProjection));
    m_program->setUniformValue("u_minRadiusAtW1", (bird ? kMinBirdRadiusPx : kMinRadiusPx) * view.metresPerPixel);
    m_program->setUniformValue("u_heightScale", view.perspective ? 1.0f : 0.0f);
    m_program->setUniformValue("u_lit", view.perspective);
    m_program->setUniformValue("u_bird", bird);
    const glm::vec4 nose = palette::kAgentNose;
    m_program->setUniformValue("u_noseColour", nose.r, nose.g, nose.b);
}

void AgentRenderer::drawSet(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, const Instances& set,
                            const Shape& flat, const Shape& solid, bool coarse)
{
    if (set.count == 0)
        return;
    if (!view.perspective && set.maxRadiusM < kSpriteBelowPx * view.metresPerPixel) {
        const InstanceRange all{0, set.count};
        drawSprites(gl, view, set, {&all, 1});
        return;
    }
    const Shape* shape = view.perspective ? &solid : &flat;
    // Tiny walkers in the top view: the coarse glyph, their detail would not show.
    if (&flat == &m_flat && !coarse && !view.perspective && set.maxRadiusM < kCoarseBelowPx * view.metresPerPixel)
        shape = &m_coarseFlat;
    bindGlyphProgram(gl, view);
    const InstanceRange all{0, set.count};
    drawRanges(gl, shape->vao, set.buffer, shape->vertexCount, {&all, 1});
    m_program->release();
}

void AgentRenderer::drawBirds(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, bool coarse)
{
    if (m_birds.count == 0)
        return;
    // Where a walker would be an impostor, the bird of two triangles: never a walker's shape.
    const bool tiny = !view.perspective && m_birds.maxRadiusM < kSpriteBelowPx * view.metresPerPixel;
    const Shape& shape = tiny ? m_farBird : (coarse ? m_coarseBird : m_bird);
    bindGlyphProgram(gl, view, true);
    const InstanceRange all{0, m_birds.count};
    drawRanges(gl, shape.vao, m_birds.buffer, shape.vertexCount, {&all, 1});
    m_program->release();
}

void AgentRenderer::drawSprites(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, const Instances& set,
                                std::span<const InstanceRange> ranges)
{
    m_spriteProgram->bind();
    gl.glUniformMatrix4fv(m_spriteProgram->uniformLocation("u_viewProjection"), 1, GL_FALSE,
                          glm::value_ptr(view.viewProjection));
    m_spriteProgram->setUniformValue("u_halfViewportPx", 0.5f * view.sizePx.x, 0.5f * view.sizePx.y);
    m_spriteProgram->setUniformValue("u_metresPerPixel", std::max(view.metresPerPixel, 1e-9f));
    m_spriteProgram->setUniformValue("u_minRadiusPx", kMinRadiusPx);
    m_spriteProgram->setUniformValue("u_heightScale", view.perspective ? 1.0f : 0.0f);
    m_spriteProgram->setUniformValue("u_eye", view.eye.x, view.eye.y, view.eye.z);
    m_spriteProgram->setUniformValue("u_lit", view.perspective);
    const glm::vec4 nose = palette::kAgentNose;
    m_spriteProgram->setUniformValue("u_noseColour", nose.r, nose.g, nose.b);
    drawRanges(gl, set.spriteVao, set.buffer, 6, ranges);  // one quad per agent
    m_spriteProgram->release();
}

}  // namespace throng::editor
