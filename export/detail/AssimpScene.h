#pragma once
// Builds an assimp scene (aiScene) piece by piece for the FBX export: materials of one
// colour, triangle meshes (skinned or not), nodes, and the channels of one animation.
// Owns what it builds until release() hands the whole scene over; knows no crowd.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include <assimp/scene.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace throng::exporting::detail {

aiMatrix4x4 toAssimp(const glm::mat4& m);

// A vertex's four joint influences: joint indices into the mesh's bone list, weights.
struct SkinnedVertex {
    glm::vec3 position{0.0f}, normal{0.0f, 1.0f, 0.0f};
    unsigned joints[4] = {0, 0, 0, 0};
    float weights[4] = {0.0f, 0.0f, 0.0f, 0.0f};
};

class AssimpScene {
public:
    AssimpScene();
    ~AssimpScene();
    AssimpScene(const AssimpScene&) = delete;
    AssimpScene& operator=(const AssimpScene&) = delete;

    aiNode* root() { return m_root; }
    // A new node under `parent` (nullptr: the root).
    aiNode* addNode(aiNode* parent, const std::string& name, const aiMatrix4x4& transform = aiMatrix4x4());
    // Attaches meshes to a node (once, after every addNode under it: assimp keeps arrays).
    void setMeshes(aiNode* node, const std::vector<unsigned>& meshes);
    // Links every node to its children: call once when all nodes are added.
    void linkNodes();

    // The material of that name; the first call decides its colour.
    unsigned material(const std::string& name, glm::vec3 rgb, bool glow = false);
    // A triangle mesh; `bones` (joint node names, their offset matrices: bind space to
    // joint space) skins it, else it is rigid. Returns its index.
    unsigned addMesh(const std::string& name, const std::vector<SkinnedVertex>& vertices,
                     const std::vector<unsigned>& indices, unsigned material,
                     const std::vector<std::pair<std::string, glm::mat4>>& bones);
    unsigned addRigidMesh(const std::string& name, const std::vector<glm::vec3>& positions,
                          const std::vector<glm::vec3>& normals, unsigned material);

    // The one animation's channel for `node`: keys at seconds (ticks of 1 s).
    struct Channel {
        std::vector<std::pair<double, glm::vec3>> translation, scale;
        std::vector<std::pair<double, glm::quat>> rotation;
    };
    void addChannel(const std::string& node, Channel channel);

    // The finished scene: animation "crowd" of `durationS` (when it has channels), metadata
    // (UnitScaleFactor 100: one unit a metre), then owned by the caller.
    std::unique_ptr<aiScene> release(double durationS);

private:
    aiScene* m_scene;
    aiNode* m_root;
    std::map<aiNode*, std::vector<aiNode*>> m_children;
    std::vector<aiNode*> m_nodes;  // every node but the root, until linked
    std::vector<aiMesh*> m_meshes;
    std::vector<aiMaterial*> m_materials;
    std::map<std::string, unsigned> m_materialIndex;
    std::vector<aiNodeAnim*> m_channels;
    bool m_linked = false;
};

}  // namespace throng::exporting::detail
