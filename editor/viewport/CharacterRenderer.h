#pragma once
// Draws near agents as their characters: every character's pre-skinned poses, at each
// level of detail, in one vertex buffer, and each frame the agents bucketed by
// (character, level, pose) and each bucket drawn instanced, oriented by heading, scaled by
// height, the top in the agent's colour, skin, hair and clothes in its palette colours
// and only the accessories it wears.
// Owns its GL buffers; create, draw and destroy it with the context current. Chooses no
// agents itself: AgentRenderer hands it the near ones.

#include "editor/viewport/AgentGlyph.h"
#include "editor/viewport/AgentPose.h"
#include "editor/viewport/PoseTable.h"
#include "editor/viewport/RenderView.h"

#include <QOpenGLShaderProgram>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

class QOpenGLFunctions_3_3_Core;

namespace throng::editor {

class CharacterRenderer {
public:
    bool initialize(QOpenGLFunctions_3_3_Core& gl);
    void destroy(QOpenGLFunctions_3_3_Core& gl);
    // Uploads every character's poses: character c's table of level l (0 = near) is
    // tables[levels * c + l].
    void setCharacters(QOpenGLFunctions_3_3_Core& gl, std::span<const PoseTable> tables, int levels);
    int characterCount() const { return int(m_meshes.size()) / m_levels; }
    bool hasCharacter(int character) const { return character >= 0 && character < characterCount(); }

    // One frame: clear(), add() the agents to draw, then draw().
    void clear();
    void add(const AgentGlyph& glyph, const AgentPose& pose, int level);
    void draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view);
    // Agents the last draw() drew.
    int lastDrawn() const { return m_lastDrawn; }

private:
    struct Instance {
        glm::vec3 position{0.0f};  // m
        float headingRad = 0.0f;
        float heightScale = 1.0f;
        glm::vec3 colour{1.0f};
        std::uint32_t lookBits = 0;
    };
    struct Mesh {
        int firstIndex = 0, indexCount = 0;  // into the index buffer
        int baseVertex = 0, vertexCount = 0; // pose 0's first vertex; one pose's vertices
    };
    std::unique_ptr<QOpenGLShaderProgram> m_program;
    unsigned m_vao = 0, m_vertices = 0, m_indices = 0, m_instanceBuffer = 0;
    std::vector<Mesh> m_meshes;          // by character and level
    int m_levels = 1;
    int m_posesPerMesh = PoseTable::kPoseCount;  // the most poses a table has (a gait ladder adds some)
    std::vector<Instance> m_added;       // this frame's agents, in add() order
    std::vector<int> m_bucketOfAdded;    // (character, level, pose) bucket of each
    std::vector<int> m_bucketStart;      // counting sort scratch, m_posesPerMesh per mesh + 1
    std::vector<Instance> m_sorted;      // by bucket: what is uploaded
    int m_lastDrawn = 0;
};

}  // namespace throng::editor
