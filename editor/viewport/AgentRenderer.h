#pragma once
// Draws every agent with instanced calls: flat oriented glyphs in the top view, lit
// prisms in perspective, and vehicles as cars (a second instance set), never smaller
// than a few pixels. Owns its GL buffers; create, draw and destroy it with the context
// current. Knows nothing of scenes or worlds.

#include "editor/viewport/RenderView.h"

#include <glm/vec3.hpp>

#include <QOpenGLShaderProgram>

#include <memory>
#include <span>
#include <vector>

class QOpenGLFunctions_3_3_Core;

namespace throng::editor {

struct GlyphVertex;

// One agent as drawn: 32 bytes per instance.
struct AgentGlyph {
    glm::vec3 position{0.0f};  // m
    float headingRad = 0.0f;   // 0 = +x, counter-clockwise seen from above
    float radiusM = 0.3f;      // > 0
    glm::vec3 colour{1.0f};    // RGB in 0..1
};

class AgentRenderer {
public:
    static constexpr float kMinRadiusPx = 2.0f;
    // Coarse glyphs above this many agents, or when agents are under kCoarseBelowPx in
    // radius on screen (top view): their detail would not show, their vertices would cost.
    static constexpr int kDetailedLimit = 5000;
    static constexpr float kCoarseBelowPx = 6.0f;
    // Below this radius on screen (top view) an agent is one round point sprite: one
    // vertex instead of a mesh, as its heading could not be seen anyway.
    static constexpr float kSpriteBelowPx = 3.0f;

    bool initialize(QOpenGLFunctions_3_3_Core& gl);
    void destroy(QOpenGLFunctions_3_3_Core& gl);
    // `bodies` are walkers and fliers, `cars` vehicles.
    void upload(QOpenGLFunctions_3_3_Core& gl, std::span<const AgentGlyph> bodies, std::span<const AgentGlyph> cars);
    void draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view);

private:
    struct Shape {
        unsigned vao = 0, vbo = 0;
        int vertexCount = 0;
    };
    struct Instances {
        unsigned buffer = 0, spriteVao = 0;
        int count = 0;
        float maxRadiusM = 0.0f;
    };
    void createShape(QOpenGLFunctions_3_3_Core& gl, Shape& shape, const std::vector<GlyphVertex>& vertices,
                     unsigned instances);
    void bindInstanceAttributes(QOpenGLFunctions_3_3_Core& gl, unsigned instances, bool divisor);
    void uploadInstances(QOpenGLFunctions_3_3_Core& gl, Instances& set, std::span<const AgentGlyph> glyphs);
    void drawSet(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, const Instances& set, const Shape& flat,
                 const Shape& solid, bool coarse);
    void drawSprites(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, const Instances& set);

    std::unique_ptr<QOpenGLShaderProgram> m_program;
    std::unique_ptr<QOpenGLShaderProgram> m_spriteProgram;
    Shape m_flat, m_prism, m_coarseFlat, m_coarsePrism, m_carFlat, m_carSolid;
    Instances m_bodies, m_cars;
};

}  // namespace throng::editor
