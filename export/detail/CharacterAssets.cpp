#include "export/detail/CharacterAssets.h"

#include <glm/gtc/type_ptr.hpp>

#include <cstring>
#include <vector>

namespace throng::exporting::detail {

CharacterAccessors writeCharacterAssets(GltfBuilder& b, const Character& c)
{
    const CharacterMesh& m = c.mesh;
    const std::size_t n = m.positions.size();
    CharacterAccessors out;

    // POSITION, NORMAL and WEIGHTS_0 interleaved: 40 bytes a vertex.
    constexpr std::size_t kStride = 40;
    std::vector<unsigned char> vertices(n * kStride);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (std::size_t v = 0; v < n; ++v) {
        std::memcpy(&vertices[v * kStride], glm::value_ptr(m.positions[v]), 12);
        std::memcpy(&vertices[v * kStride + 12], glm::value_ptr(m.normals[v]), 12);
        std::memcpy(&vertices[v * kStride + 24], glm::value_ptr(m.weights[v]), 16);
        lo = glm::min(lo, m.positions[v]);
        hi = glm::max(hi, m.positions[v]);
    }
    const std::size_t vertexOffset = b.append(vertices.data(), vertices.size());
    const int vertexView = b.addView(vertexOffset, vertices.size(), kStride, TINYGLTF_TARGET_ARRAY_BUFFER);
    out.attributes["POSITION"] = b.addAccessor(vertexView, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, n, TINYGLTF_TYPE_VEC3);
    b.model().accessors[out.attributes["POSITION"]].minValues = {lo.x, lo.y, lo.z};
    b.model().accessors[out.attributes["POSITION"]].maxValues = {hi.x, hi.y, hi.z};
    out.attributes["NORMAL"] = b.addAccessor(vertexView, 12, TINYGLTF_COMPONENT_TYPE_FLOAT, n, TINYGLTF_TYPE_VEC3);
    out.attributes["WEIGHTS_0"] = b.addAccessor(vertexView, 24, TINYGLTF_COMPONENT_TYPE_FLOAT, n, TINYGLTF_TYPE_VEC4);

    // JOINTS_0 as bytes while the skeleton allows, else shorts.
    const bool bytes = c.joints.size() <= 256;
    std::vector<unsigned char> joints(n * (bytes ? 4 : 8));
    for (std::size_t v = 0; v < n; ++v)
        for (int k = 0; k < 4; ++k) {
            if (bytes)
                joints[v * 4 + k] = static_cast<unsigned char>(m.joints[v][k]);
            else
                std::memcpy(&joints[v * 8 + 2 * k], &m.joints[v][k], 2);
        }
    const std::size_t jointOffset = b.append(joints.data(), joints.size());
    const int jointView = b.addView(jointOffset, joints.size(), bytes ? 4 : 8, TINYGLTF_TARGET_ARRAY_BUFFER);
    out.attributes["JOINTS_0"] = b.addAccessor(
        jointView, 0, bytes ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE : TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, n, TINYGLTF_TYPE_VEC4);

    const bool shortIndices = n <= 65535;
    std::vector<unsigned char> indices(m.indices.size() * (shortIndices ? 2 : 4));
    for (std::size_t i = 0; i < m.indices.size(); ++i) {
        if (shortIndices) {
            const auto s = static_cast<std::uint16_t>(m.indices[i]);
            std::memcpy(&indices[2 * i], &s, 2);
        } else {
            std::memcpy(&indices[4 * i], &m.indices[i], 4);
        }
    }
    const std::size_t indexOffset = b.append(indices.data(), indices.size());
    const int indexView = b.addView(indexOffset, indices.size(), 0, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    const int indexType = shortIndices ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    for (const MeshPart& part : partsOf(m))
        out.partIndices.push_back(b.addAccessor(indexView, part.firstIndex * (shortIndices ? 2u : 4u), indexType,
                                                part.indexCount, TINYGLTF_TYPE_SCALAR));

    std::vector<float> ibm;
    for (const glm::mat4& mat : m.inverseBindMatrices)
        ibm.insert(ibm.end(), glm::value_ptr(mat), glm::value_ptr(mat) + 16);
    const std::size_t ibmOffset = b.append(ibm.data(), ibm.size() * sizeof(float));
    const int ibmView = b.addView(ibmOffset, ibm.size() * sizeof(float), 0, 0);
    out.inverseBindMatrices =
        b.addAccessor(ibmView, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, m.inverseBindMatrices.size(), TINYGLTF_TYPE_MAT4);
    return out;
}

}  // namespace throng::exporting::detail
