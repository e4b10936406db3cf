#include "editor/viewport/CharacterRenderer.h"

#include "editor/viewport/ShaderProgram.h"
#include "export/character/AgentVariation.h"

#include <glm/gtc/type_ptr.hpp>

#include <QOpenGLFunctions_3_3_Core>

#include <algorithm>
#include <cstddef>

namespace throng::editor {

namespace {

// Heading h turns the character's +x nose to (cos h, 0, -sin h), as the glyph and the
// glTF export turn it; its feet stay on the agent's position. Slots are numbered as
// exporting::MaterialSlot numbers them: body 0 and top 2 wear the agent's colour, skin 1
// to bag 8 their palette colour u_palette[8 * slot + index]; hat 7 and bag 8 only where
// worn (else the vertex leaves the clip volume and its triangles are not drawn).
const char* const kCharacterVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_slot;
layout(location = 3) in vec4 i_positionHeading;
layout(location = 4) in vec4 i_scaleColour;
layout(location = 5) in uint i_look;
uniform mat4 u_viewProjection;
uniform vec3 u_palette[72];
out vec3 v_colour;
out vec3 v_normal;
void main()
{
    int slot = int(a_slot + 0.5);
    if (slot >= 7 && (i_look & (1u << uint(24 + slot - 7))) == 0u) {
        v_colour = vec3(0.0);
        v_normal = vec3(0.0, 1.0, 0.0);
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    float c = cos(i_positionHeading.w), s = sin(i_positionHeading.w);
    vec3 local = a_position * i_scaleColour.x;
    vec3 p = i_positionHeading.xyz + vec3(local.x * c + local.z * s, local.y, -local.x * s + local.z * c);
    v_normal = vec3(a_normal.x * c + a_normal.z * s, a_normal.y, -a_normal.x * s + a_normal.z * c);
    v_colour = i_scaleColour.yzw;
    if (slot == 1 || slot >= 3)
        v_colour = u_palette[8 * slot + int((i_look >> uint(3 * (slot - 1))) & 7u)];
    gl_Position = u_viewProjection * vec4(p, 1.0);
}
)";

// Lit as the glyph is (same light, same ambient share), so both read alike side by side.
const char* const kCharacterFragment = R"(#version 330 core
in vec3 v_colour;
in vec3 v_normal;
out vec4 o_colour;
void main()
{
    vec3 light = normalize(vec3(0.35, 1.0, 0.25));
    float lambert = max(dot(normalize(v_normal), light), 0.0);
    o_colour = vec4(v_colour * (0.45 + 0.55 * lambert), 1.0);
}
)";

struct PoseVertex {
    glm::vec3 position;
    glm::vec3 normal;
    float slot;
};

// u_palette: 8 colours per material slot, the export's palettes (AgentVariation).
std::vector<glm::vec3> slotPalettes()
{
    std::vector<glm::vec3> colours(8 * exporting::kMaterialSlotCount, glm::vec3(1.0f));
    for (int slot = 0; slot < exporting::kMaterialSlotCount; ++slot) {
        const std::span<const glm::vec3> palette = exporting::slotPalette(exporting::MaterialSlot(slot));
        for (std::size_t k = 0; k < palette.size() && k < 8; ++k)
            colours[std::size_t(8 * slot) + k] = palette[k];
    }
    return colours;
}

}  // namespace

bool CharacterRenderer::initialize(QOpenGLFunctions_3_3_Core& gl)
{
    m_program = buildShaderProgram("character", kCharacterVertex, kCharacterFragment);
    if (!m_program)
        return false;
    gl.glGenVertexArrays(1, &m_vao);
    gl.glGenBuffers(1, &m_vertices);
    gl.glGenBuffers(1, &m_indices);
    gl.glGenBuffers(1, &m_instanceBuffer);
    gl.glBindVertexArray(m_vao);
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_vertices);
    gl.glEnableVertexAttribArray(0);
    gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(PoseVertex),
                             reinterpret_cast<const void*>(offsetof(PoseVertex, position)));
    gl.glEnableVertexAttribArray(1);
    gl.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(PoseVertex),
                             reinterpret_cast<const void*>(offsetof(PoseVertex, normal)));
    gl.glEnableVertexAttribArray(2);
    gl.glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(PoseVertex),
                             reinterpret_cast<const void*>(offsetof(PoseVertex, slot)));
    gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indices);
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_instanceBuffer);
    gl.glEnableVertexAttribArray(3);
    gl.glEnableVertexAttribArray(4);
    gl.glEnableVertexAttribArray(5);
    gl.glVertexAttribDivisor(3, 1);
    gl.glVertexAttribDivisor(4, 1);
    gl.glVertexAttribDivisor(5, 1);
    gl.glBindVertexArray(0);
    return true;
}

void CharacterRenderer::destroy(QOpenGLFunctions_3_3_Core& gl)
{
    for (unsigned* buffer : {&m_vertices, &m_indices, &m_instanceBuffer}) {
        gl.glDeleteBuffers(1, buffer);
        *buffer = 0;
    }
    gl.glDeleteVertexArrays(1, &m_vao);
    m_vao = 0;
    m_meshes.clear();
    m_program.reset();
}

void CharacterRenderer::setCharacters(QOpenGLFunctions_3_3_Core& gl, std::span<const PoseTable> tables, int levels)
{
    if (!m_program)
        return;
    m_levels = std::max(1, levels);
    m_posesPerMesh = PoseTable::kPoseCount;
    for (const PoseTable& t : tables)
        m_posesPerMesh = std::max(m_posesPerMesh, t.poseCount());
    std::vector<PoseVertex> vertices;
    std::vector<std::uint32_t> indices;
    m_meshes.clear();
    for (const PoseTable& t : tables) {
        Mesh mesh;
        mesh.firstIndex = int(indices.size());
        mesh.indexCount = int(t.indices.size());
        mesh.baseVertex = int(vertices.size());
        mesh.vertexCount = int(t.vertexCount);
        for (std::size_t v = 0; v < t.positions.size(); ++v)
            vertices.push_back({t.positions[v], t.normals[v], float(t.materialSlots[v % t.vertexCount])});
        indices.insert(indices.end(), t.indices.begin(), t.indices.end());
        m_meshes.push_back(mesh);
    }
    gl.glBindVertexArray(m_vao);
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_vertices);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(PoseVertex)), vertices.data(),
                    GL_STATIC_DRAW);
    gl.glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(),
                    GL_STATIC_DRAW);
    gl.glBindVertexArray(0);
}

void CharacterRenderer::clear()
{
    m_added.clear();
    m_bucketOfAdded.clear();
}

void CharacterRenderer::add(const AgentGlyph& glyph, const AgentPose& pose, int level)
{
    m_added.push_back({glyph.position, glyph.headingRad, pose.heightScale, glyph.colour, pose.lookBits});
    const int mesh = pose.character * m_levels + std::clamp(level, 0, m_levels - 1);
    m_bucketOfAdded.push_back(mesh * m_posesPerMesh + pose.pose);
}

void CharacterRenderer::draw(QOpenGLFunctions_3_3_Core& gl, const RenderView& view)
{
    m_lastDrawn = 0;
    if (!m_program || m_added.empty())
        return;
    // Counting sort by bucket: stable, so the same agents give the same upload.
    const std::size_t buckets = m_meshes.size() * std::size_t(m_posesPerMesh);
    m_bucketStart.assign(buckets + 1, 0);
    for (int b : m_bucketOfAdded)
        ++m_bucketStart[std::size_t(b) + 1];
    for (std::size_t b = 1; b <= buckets; ++b)
        m_bucketStart[b] += m_bucketStart[b - 1];
    m_sorted.resize(m_added.size());
    {
        std::vector<int> next(m_bucketStart.begin(), m_bucketStart.end() - 1);
        for (std::size_t i = 0; i < m_added.size(); ++i)
            m_sorted[std::size_t(next[std::size_t(m_bucketOfAdded[i])]++)] = m_added[i];
    }
    static_assert(sizeof(Instance) == 9 * sizeof(float), "the shader reads two vec4 and a uint per instance");
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_instanceBuffer);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m_sorted.size() * sizeof(Instance)), m_sorted.data(), GL_STREAM_DRAW);

    m_program->bind();
    gl.glUniformMatrix4fv(m_program->uniformLocation("u_viewProjection"), 1, GL_FALSE,
                          glm::value_ptr(view.viewProjection));
    static const std::vector<glm::vec3> palettes = slotPalettes();
    gl.glUniform3fv(m_program->uniformLocation("u_palette"), GLsizei(palettes.size()), glm::value_ptr(palettes[0]));
    gl.glBindVertexArray(m_vao);
    for (std::size_t b = 0; b < buckets; ++b) {
        const int first = m_bucketStart[b], count = m_bucketStart[b + 1] - first;
        if (count == 0)
            continue;
        const Mesh& mesh = m_meshes[b / std::size_t(m_posesPerMesh)];
        const int pose = int(b % std::size_t(m_posesPerMesh));
        // GL 3.3 has no base instance: the bucket's instances start where the pointers do.
        const std::size_t at = std::size_t(first) * sizeof(Instance);
        gl.glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, sizeof(Instance),
                                 reinterpret_cast<const void*>(at + offsetof(Instance, position)));
        gl.glVertexAttribPointer(4, 4, GL_FLOAT, GL_FALSE, sizeof(Instance),
                                 reinterpret_cast<const void*>(at + offsetof(Instance, heightScale)));
        gl.glVertexAttribIPointer(5, 1, GL_UNSIGNED_INT, sizeof(Instance),
                                  reinterpret_cast<const void*>(at + offsetof(Instance, lookBits)));
        gl.glDrawElementsInstancedBaseVertex(
            GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(std::size_t(mesh.firstIndex) * sizeof(std::uint32_t)), count,
            mesh.baseVertex + pose * mesh.vertexCount);
        m_lastDrawn += count;
    }
    gl.glBindVertexArray(0);
    m_program->release();
}

}  // namespace throng::editor
