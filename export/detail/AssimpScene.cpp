#include "export/detail/AssimpScene.h"

#include <assimp/material.h>
#include <assimp/metadata.h>

#include <algorithm>

namespace throng::exporting::detail {

aiMatrix4x4 toAssimp(const glm::mat4& m)
{
    // assimp's matrices are row-major with the translation in the last column: row r is
    // glm's row r, that is m[c][r] over the columns c.
    return aiMatrix4x4(m[0][0], m[1][0], m[2][0], m[3][0], m[0][1], m[1][1], m[2][1], m[3][1], m[0][2], m[1][2],
                       m[2][2], m[3][2], m[0][3], m[1][3], m[2][3], m[3][3]);
}

AssimpScene::AssimpScene() : m_scene(new aiScene), m_root(new aiNode("RootNode"))
{
    m_scene->mRootNode = m_root;
}

AssimpScene::~AssimpScene()
{
    // Whatever was not handed over: the scene's own destructor frees what it holds.
    if (!m_linked)
        for (aiNode* n : m_nodes)
            delete n;
    for (aiMesh* m : m_meshes)
        delete m;
    for (aiMaterial* m : m_materials)
        delete m;
    for (aiNodeAnim* c : m_channels)
        delete c;
    delete m_scene;
}

aiNode* AssimpScene::addNode(aiNode* parent, const std::string& name, const aiMatrix4x4& transform)
{
    auto* node = new aiNode(name);
    node->mTransformation = transform;
    m_nodes.push_back(node);
    m_children[parent ? parent : m_root].push_back(node);
    return node;
}

void AssimpScene::setMeshes(aiNode* node, const std::vector<unsigned>& meshes)
{
    node->mNumMeshes = static_cast<unsigned>(meshes.size());
    node->mMeshes = new unsigned[meshes.size()];
    std::copy(meshes.begin(), meshes.end(), node->mMeshes);
}

void AssimpScene::linkNodes()
{
    for (auto& [parent, children] : m_children)
        parent->addChildren(static_cast<unsigned>(children.size()), children.data());
    m_children.clear();
    m_linked = true;
}

unsigned AssimpScene::material(const std::string& name, glm::vec3 rgb, bool glow)
{
    if (const auto it = m_materialIndex.find(name); it != m_materialIndex.end())
        return it->second;
    auto* material = new aiMaterial;
    const aiString id(name);
    material->AddProperty(&id, AI_MATKEY_NAME);
    const aiColor3D colour(rgb.r, rgb.g, rgb.b);
    material->AddProperty(&colour, 1, AI_MATKEY_COLOR_DIFFUSE);
    if (glow)
        material->AddProperty(&colour, 1, AI_MATKEY_COLOR_EMISSIVE);
    m_materials.push_back(material);
    return m_materialIndex[name] = static_cast<unsigned>(m_materials.size() - 1);
}

unsigned AssimpScene::addMesh(const std::string& name, const std::vector<SkinnedVertex>& vertices,
                              const std::vector<unsigned>& indices, unsigned material,
                              const std::vector<std::pair<std::string, glm::mat4>>& bones)
{
    auto* mesh = new aiMesh;
    mesh->mName = name;
    mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh->mMaterialIndex = material;
    mesh->mNumVertices = static_cast<unsigned>(vertices.size());
    mesh->mVertices = new aiVector3D[vertices.size()];
    mesh->mNormals = new aiVector3D[vertices.size()];
    for (std::size_t v = 0; v < vertices.size(); ++v) {
        mesh->mVertices[v] = aiVector3D(vertices[v].position.x, vertices[v].position.y, vertices[v].position.z);
        mesh->mNormals[v] = aiVector3D(vertices[v].normal.x, vertices[v].normal.y, vertices[v].normal.z);
    }
    mesh->mNumFaces = static_cast<unsigned>(indices.size() / 3);
    mesh->mFaces = new aiFace[mesh->mNumFaces];
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
        mesh->mFaces[f].mNumIndices = 3;
        mesh->mFaces[f].mIndices = new unsigned[3]{indices[3 * f], indices[3 * f + 1], indices[3 * f + 2]};
    }
    // A bone per joint that weighs on some vertex (FBX makes its parents limbs too).
    std::vector<std::vector<aiVertexWeight>> weights(bones.size());
    for (std::size_t v = 0; v < vertices.size(); ++v)
        for (int k = 0; k < 4; ++k)
            if (vertices[v].weights[k] > 0.0f)
                weights[vertices[v].joints[k]].emplace_back(static_cast<unsigned>(v), vertices[v].weights[k]);
    std::vector<aiBone*> made;
    for (std::size_t b = 0; b < bones.size(); ++b) {
        if (weights[b].empty())
            continue;
        auto* bone = new aiBone;
        bone->mName = bones[b].first;
        bone->mOffsetMatrix = toAssimp(bones[b].second);
        bone->mNumWeights = static_cast<unsigned>(weights[b].size());
        bone->mWeights = new aiVertexWeight[weights[b].size()];
        std::copy(weights[b].begin(), weights[b].end(), bone->mWeights);
        made.push_back(bone);
    }
    if (!made.empty()) {
        mesh->mNumBones = static_cast<unsigned>(made.size());
        mesh->mBones = new aiBone*[made.size()];
        std::copy(made.begin(), made.end(), mesh->mBones);
    }
    m_meshes.push_back(mesh);
    return static_cast<unsigned>(m_meshes.size() - 1);
}

unsigned AssimpScene::addRigidMesh(const std::string& name, const std::vector<glm::vec3>& positions,
                                   const std::vector<glm::vec3>& normals, unsigned material)
{
    std::vector<SkinnedVertex> vertices(positions.size());
    std::vector<unsigned> indices(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) {
        vertices[v].position = positions[v];
        vertices[v].normal = normals[v];
        indices[v] = static_cast<unsigned>(v);
    }
    return addMesh(name, vertices, indices, material, {});
}

void AssimpScene::addChannel(const std::string& node, Channel c)
{
    auto* channel = new aiNodeAnim;
    channel->mNodeName = node;
    channel->mNumPositionKeys = static_cast<unsigned>(c.translation.size());
    channel->mPositionKeys = new aiVectorKey[c.translation.size()];
    for (std::size_t k = 0; k < c.translation.size(); ++k) {
        const auto& [t, v] = c.translation[k];
        channel->mPositionKeys[k] = aiVectorKey(t, aiVector3D(v.x, v.y, v.z));
    }
    channel->mNumRotationKeys = static_cast<unsigned>(c.rotation.size());
    channel->mRotationKeys = new aiQuatKey[c.rotation.size()];
    for (std::size_t k = 0; k < c.rotation.size(); ++k) {
        const auto& [t, q] = c.rotation[k];
        channel->mRotationKeys[k] = aiQuatKey(t, aiQuaternion(q.w, q.x, q.y, q.z));
    }
    channel->mNumScalingKeys = static_cast<unsigned>(c.scale.size());
    channel->mScalingKeys = new aiVectorKey[c.scale.size()];
    for (std::size_t k = 0; k < c.scale.size(); ++k) {
        const auto& [t, v] = c.scale[k];
        channel->mScalingKeys[k] = aiVectorKey(t, aiVector3D(v.x, v.y, v.z));
    }
    m_channels.push_back(channel);
}

std::unique_ptr<aiScene> AssimpScene::release(double durationS)
{
    if (!m_linked)
        linkNodes();
    m_scene->mNumMeshes = static_cast<unsigned>(m_meshes.size());
    m_scene->mMeshes = new aiMesh*[m_meshes.size()];
    std::copy(m_meshes.begin(), m_meshes.end(), m_scene->mMeshes);
    m_meshes.clear();
    if (m_materials.empty())
        material("default", glm::vec3(0.6f));
    m_scene->mNumMaterials = static_cast<unsigned>(m_materials.size());
    m_scene->mMaterials = new aiMaterial*[m_materials.size()];
    std::copy(m_materials.begin(), m_materials.end(), m_scene->mMaterials);
    m_materials.clear();
    if (!m_channels.empty()) {
        auto* animation = new aiAnimation;
        animation->mName = "crowd";
        animation->mTicksPerSecond = 1.0;
        animation->mDuration = durationS;
        animation->mNumChannels = static_cast<unsigned>(m_channels.size());
        animation->mChannels = new aiNodeAnim*[m_channels.size()];
        std::copy(m_channels.begin(), m_channels.end(), animation->mChannels);
        m_channels.clear();
        m_scene->mNumAnimations = 1;
        m_scene->mAnimations = new aiAnimation*[1]{animation};
    }
    m_scene->mMetaData = aiMetadata::Alloc(2);
    m_scene->mMetaData->Set(0, "UnitScaleFactor", 100.0);
    m_scene->mMetaData->Set(1, "OriginalUnitScaleFactor", 100.0);
    aiScene* scene = m_scene;
    m_scene = nullptr;
    return std::unique_ptr<aiScene>(scene);
}

}  // namespace throng::exporting::detail
