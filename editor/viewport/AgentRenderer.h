#pragma once
// Draws every agent with instanced calls: flat oriented glyphs in the top view, lit
// prisms in perspective, vehicles as cars and fliers as birds (instance sets of their
// own), never smaller than a few pixels. With level of detail (the default) agents are sorted into ground
// cells once per upload, and each frame draws only the cells in view: near ones with the
// detailed glyph, farther ones with the coarse glyph, and those only a few pixels wide as
// impostors (one small quad each, showing the same silhouette, shading and nose); far
// birds are a bird of two triangles, never a walker's impostor.
// In perspective, near agents whose type has a character are drawn as that character
// (CharacterRenderer), posed and scaled per agent, up to kCharacterLimit of them.
// Owns its GL buffers; create, draw and destroy it with the context current. Knows
// nothing of scenes or worlds.

#include "editor/viewport/AgentCells.h"
#include "editor/viewport/AgentGlyph.h"
#include "editor/viewport/AgentPose.h"
#include "editor/viewport/CharacterRenderer.h"
#include "editor/viewport/RenderView.h"

#include <QOpenGLShaderProgram>

#include <array>
#include <memory>
#include <span>
#include <vector>

class QOpenGLFunctions_3_3_Core;

namespace throng::editor {

struct GlyphVertex;

class AgentRenderer {
public:
    static constexpr float kMinRadiusPx = 2.0f;
    // A bird is its wings: thin, so it keeps a wingspan of at least 6 pixels.
    static constexpr float kMinBirdRadiusPx = 3.0f;
    // Coarse glyphs above this many agents, or when agents are under kCoarseBelowPx in
    // radius on screen (top view): their detail would not show, their vertices would cost.
    static constexpr int kDetailedLimit = 5000;
    static constexpr float kCoarseBelowPx = 6.0f;
    // Below this radius on screen an agent is one impostor quad (six vertices instead of
    // a mesh of hundreds) drawing the glyph's outline, shade and nose.
    static constexpr float kSpriteBelowPx = 3.0f;
    // Level-of-detail switches, radius on screen in pixels (AgentCells).
    static constexpr DetailThresholds kTopDetail{kSpriteBelowPx, kCoarseBelowPx};
    static constexpr DetailThresholds kPerspectiveDetail{3.0f, 12.0f};
    // At most this many agents are drawn as characters in a frame (cars first, then the
    // walkers of the nearest cells); the rest keep glyphs and impostors. Under llvmpipe a
    // character costs about 0.05 ms a frame (editor_figures --characters), so 5,000 of
    // them keep a close-up of 100,000 agents interactive.
    static constexpr int kCharacterLimit = 5000;

    bool initialize(QOpenGLFunctions_3_3_Core& gl);
    void destroy(QOpenGLFunctions_3_3_Core& gl);
    // `bodies` are walkers, `cars` vehicles and `birds` fliers.
    void upload(QOpenGLFunctions_3_3_Core& gl, AgentBatch bodies, AgentBatch cars, AgentBatch birds = {});
    // The characters AgentPose::character indexes, `levels` tables each (near first).
    void setCharacters(QOpenGLFunctions_3_3_Core& gl, std::span<const PoseTable> tables, int levels)
    {
        m_characters.setCharacters(gl, tables, levels);
    }
    // On: near agents as characters in perspective; off (the default): glyphs only.
    void setAgentsAsCharacters(bool on) { m_agentsAsCharacters = on; }
    bool agentsAsCharacters() const { return m_agentsAsCharacters; }
    // Agents the last draw() drew as characters.
    int lastCharactersDrawn() const { return m_characters.lastDrawn(); }
    void draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view);

    // Off: every agent of a set drawn with one shape chosen for the whole set, as before
    // level of detail (the reference the tests and figures compare with).
    void setLevelOfDetail(bool on) { m_levelOfDetail = on; }
    bool levelOfDetail() const { return m_levelOfDetail; }
    // Instances per AgentDetail drawn by the last draw() with level of detail, both sets.
    const std::array<int, kAgentDetailLevels>& lastDrawnByDetail() const { return m_lastDrawn; }

private:
    struct Shape {
        unsigned vao = 0, vbo = 0;
        int vertexCount = 0;
    };
    // The shapes one instance set is drawn with at each level of detail.
    struct Looks {
        const Shape& detailed;
        const Shape& coarse;
        const Shape* far = nullptr;  // impostor-level agents; null: impostor quads
        bool bird = false;           // the shapes are BirdGlyphMesh's
    };
    struct Instances {
        unsigned buffer = 0, spriteVao = 0;
        int count = 0;
        float maxRadiusM = 0.0f;
        AgentCells cells;
        AgentDrawPlan plan;
        std::vector<AgentPose> poses;  // by upload index (cells.order() maps to it); may be empty
    };
    void createShape(QOpenGLFunctions_3_3_Core& gl, Shape& shape, const std::vector<GlyphVertex>& vertices,
                     unsigned instances);
    void bindInstanceAttributes(QOpenGLFunctions_3_3_Core& gl, unsigned instances, bool divisor);
    void uploadInstances(QOpenGLFunctions_3_3_Core& gl, Instances& set, AgentBatch batch);
    void takeCharacters(const Instances& set);
    void drawSet(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, const Instances& set, const Shape& flat,
                 const Shape& solid, bool coarse);
    void drawSprites(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, const Instances& set,
                     std::span<const InstanceRange> ranges);
    void drawBirds(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, bool coarse);
    void drawPlanned(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, Instances& set, const Looks& looks,
                     const DetailThresholds& thresholds);
    void bindGlyphProgram(QOpenGLFunctions_3_3_Core& gl, const RenderView& view, bool bird = false);
    void drawRanges(QOpenGLFunctions_3_3_Core& gl, unsigned vao, unsigned instances, int vertexCount,
                    std::span<const InstanceRange> ranges);

    std::unique_ptr<QOpenGLShaderProgram> m_program;
    std::unique_ptr<QOpenGLShaderProgram> m_spriteProgram;
    Shape m_flat, m_prism, m_coarseFlat, m_coarsePrism, m_carFlat, m_carSolid, m_bird, m_coarseBird, m_farBird;
    Instances m_bodies, m_cars, m_birds;
    bool m_levelOfDetail = true;
    bool m_agentsAsCharacters = false;
    CharacterRenderer m_characters;
    int m_characterBudget = 0;
    // This set's near ranges left to glyphs, and near agents without a character.
    std::array<std::vector<InstanceRange>, 2> m_glyphRanges;
    std::vector<AgentGlyph> m_fallback;
    unsigned m_fallbackBuffer = 0;
    std::array<int, kAgentDetailLevels> m_lastDrawn{};
};

}  // namespace throng::editor
