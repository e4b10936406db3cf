#define GLM_ENABLE_EXPERIMENTAL  // glm::decompose lives in gtx
#include "export/character/UserCharacter.h"

#include "export/character/UserClipSampler.h"

#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace throng::exporting {

namespace {

glm::mat4 nodeLocal(const tinygltf::Node& n)
{
    if (n.matrix.size() == 16) {
        glm::mat4 m;
        for (int i = 0; i < 16; ++i)
            glm::value_ptr(m)[i] = static_cast<float>(n.matrix[i]);
        return m;
    }
    glm::vec3 t(0.0f), s(1.0f);
    glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
    if (n.translation.size() == 3)
        t = {n.translation[0], n.translation[1], n.translation[2]};
    if (n.rotation.size() == 4)
        r = glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]));
    if (n.scale.size() == 3)
        s = {n.scale[0], n.scale[1], n.scale[2]};
    return glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
}

void setFromMatrix(Joint& joint, const glm::mat4& m)
{
    glm::vec3 skew;
    glm::vec4 perspective;
    glm::decompose(m, joint.restScale, joint.restRotation, joint.restTranslation, skew, perspective);
    joint.restRotation = glm::normalize(joint.restRotation);
}

}  // namespace

std::optional<Character> loadCharacterFile(const std::string& path, const ClipNames& clipNames, std::string& error)
{
    const std::string where = "character file '" + path + "'";
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string warning, loadError;
    const bool glb = path.size() >= 4 && (path.compare(path.size() - 4, 4, ".glb") == 0 || path.compare(path.size() - 4, 4, ".GLB") == 0);
    const bool loaded = glb ? loader.LoadBinaryFromFile(&model, &loadError, &warning, path)
                            : loader.LoadASCIIFromFile(&model, &loadError, &warning, path);
    if (!loaded) {
        error = "cannot load " + where + ": " + (loadError.empty() ? std::string("not a glTF file") : loadError);
        return std::nullopt;
    }
    const auto meshNode = std::find_if(model.nodes.begin(), model.nodes.end(),
                                       [](const tinygltf::Node& n) { return n.mesh >= 0 && n.skin >= 0; });
    if (model.skins.empty() || meshNode == model.nodes.end()) {
        error = where + " has no skin: export the mesh with its armature (a skinned mesh with joints)";
        return std::nullopt;
    }
    if (model.animations.empty()) {
        error = where + " has no animation clips: it needs at least a walk clip (idle and run are optional)";
        return std::nullopt;
    }
    const tinygltf::Skin& skin = model.skins[meshNode->skin];

    // Skeleton: skin joints ordered parents first, under one root; what lies above the
    // top joints (an armature node) and the turn from +Z to +X forward go into the root.
    std::vector<int> parentOf(model.nodes.size(), -1);
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        for (int child : model.nodes[n].children)
            parentOf[child] = static_cast<int>(n);
    auto depth = [&](int n) { int d = 0; while (parentOf[n] >= 0) { n = parentOf[n]; ++d; } return d; };
    // Keep the file's joint order when parents already come first, else order by depth.
    std::vector<int> nodes = skin.joints;
    std::set<int> seen;
    bool parentsFirst = true;
    for (int n : nodes) {
        for (int up = parentOf[n]; up >= 0; up = parentOf[up])
            if (std::find(nodes.begin(), nodes.end(), up) != nodes.end()) {
                parentsFirst = parentsFirst && seen.count(up);
                break;
            }
        seen.insert(n);
    }
    if (!parentsFirst)
        std::stable_sort(nodes.begin(), nodes.end(), [&](int a, int b) { return depth(a) < depth(b); });
    std::map<int, int> jointOfNode;
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    std::set<int> inSkin(nodes.begin(), nodes.end());
    const auto isTop = [&](int n) { for (int up = parentOf[n]; up >= 0; up = parentOf[up]) if (inSkin.count(up)) return false; return true; };
    const bool oneTop = std::count_if(nodes.begin(), nodes.end(), isTop) == 1;
    Character c;
    c.name = path;
    if (!oneTop) {  // several top joints hang from a synthetic root
        Joint root;
        root.name = "root";
        c.joints.push_back(root);
    }
    for (int n : nodes) {
        int up = parentOf[n];
        glm::mat4 above(1.0f);
        while (up >= 0 && !jointOfNode.count(up)) {
            above = nodeLocal(model.nodes[up]) * above;
            up = parentOf[up];
        }
        Joint joint;
        joint.name = model.nodes[n].name.empty() ? "joint_" + std::to_string(n) : model.nodes[n].name;
        joint.parent = up >= 0 ? jointOfNode[up] : (oneTop ? -1 : 0);
        setFromMatrix(joint, up >= 0 ? above * nodeLocal(model.nodes[n]) : turn * above * nodeLocal(model.nodes[n]));
        jointOfNode[n] = static_cast<int>(c.joints.size());
        c.joints.push_back(joint);
    }

    std::string meshError;
    if (!readSkinnedMesh(model, *meshNode, skin, jointOfNode, c.mesh, meshError)) {
        error = where + ": " + meshError;
        return std::nullopt;
    }
    for (std::size_t v = 0; v < c.mesh.weights.size(); ++v)
        normaliseInfluences(c.mesh.joints[v], c.mesh.weights[v]);
    // The file's inverse bind matrices: the turn sits in the joints, so skinned vertices
    // come out turned too. The synthetic root binds at identity and weighs nothing.
    std::vector<glm::mat4> ibm(c.joints.size(), glm::mat4(1.0f));
    const std::vector<float> fileIbm = skin.inverseBindMatrices >= 0 ? readFloats(model, skin.inverseBindMatrices) : std::vector<float>{};
    for (std::size_t k = 0; k < skin.joints.size(); ++k) {
        glm::mat4 m(1.0f);
        if (fileIbm.size() >= 16 * (k + 1))
            m = glm::make_mat4(fileIbm.data() + 16 * k);
        ibm[jointOfNode[skin.joints[k]]] = m;
    }
    c.mesh.inverseBindMatrices = ibm;

    if (!sampleUserClips(model, c, jointOfNode, clipNames, error)) {
        error = where + ": " + error;
        return std::nullopt;
    }
    if (std::string problem = checkCharacter(c); !problem.empty()) {
        error = where + ": " + problem;
        return std::nullopt;
    }
    return c;
}

}  // namespace throng::exporting
