#pragma once
// Draws every agent with one instanced call: flat oriented glyphs in the top view, lit
// prisms in perspective, never smaller than a few pixels. Owns its GL buffers; create,
// draw and destroy it with the context current. Knows nothing of scenes or worlds.

#include "editor/viewport/RenderView.h"

#include <glm/vec3.hpp>

#include <QOpenGLShaderProgram>

#include <memory>
#include <span>

class QOpenGLFunctions_3_3_Core;

namespace throng::editor {

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
    void upload(QOpenGLFunctions_3_3_Core& gl, std::span<const AgentGlyph> glyphs);
    void draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view);

private:
    struct Shape {
        unsigned vao = 0, vbo = 0;
        int vertexCount = 0;
    };
    void createShape(QOpenGLFunctions_3_3_Core& gl, Shape& shape, bool prism, int segments);

    void drawSprites(QOpenGLFunctions_3_3_Core& gl, const RenderView& view);

    std::unique_ptr<QOpenGLShaderProgram> m_program;
    std::unique_ptr<QOpenGLShaderProgram> m_spriteProgram;
    unsigned m_spriteVao = 0;
    Shape m_flat, m_prism, m_coarseFlat, m_coarsePrism;
    float m_maxRadiusM = 0.0f;
    unsigned m_instances = 0;
    int m_instanceCount = 0;
};

}  // namespace throng::editor
