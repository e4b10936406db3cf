#include "export/detail/AgentRig.h"

#include <cmath>

namespace throng::exporting::detail {

namespace {

// Static TRS in micrometres and millionths: the JSON carries "0.97748", not
// "0.97748005390167236", which for a 10,000-agent crowd is megabytes.
double r6(double v) { return std::round(v * 1e6) / 1e6 + 0.0; }
std::vector<double> vec3(const glm::vec3& v) { return {r6(v.x), r6(v.y), r6(v.z)}; }
std::vector<double> quat4(const glm::quat& q)
{
    const glm::dquat d = glm::normalize(glm::dquat(q));
    return {r6(d.x), r6(d.y), r6(d.z), r6(d.w)};
}

}  // namespace

AgentRig addAgentRig(tinygltf::Model& model, const Character& c, const CharacterAccessors& assets,
                     const AgentRigSpec& spec, const Pose& firstPose)
{
    AgentRig rig;
    rig.root = static_cast<int>(model.nodes.size());
    rig.firstJoint = rig.root + 1;
    const int body = rig.firstJoint + static_cast<int>(c.joints.size());

    tinygltf::Node root;
    root.name = spec.name;
    root.translation = vec3(spec.translation);
    root.rotation = quat4(spec.rotation);
    if (spec.heightScale != 1.0f)
        root.scale = vec3(glm::vec3(spec.heightScale));
    root.children = {rig.firstJoint};
    root.extras = spec.extras;
    model.nodes.push_back(std::move(root));

    for (std::size_t j = 0; j < c.joints.size(); ++j) {
        const Joint& joint = c.joints[j];
        tinygltf::Node node;
        node.name = spec.name + "__" + joint.name;
        const glm::vec3 t = j == 0 ? firstPose.rootTranslation : joint.restTranslation;
        node.translation = vec3(t);
        node.rotation = quat4(firstPose.rotations[j]);
        if (joint.restScale != glm::vec3(1.0f))
            node.scale = {joint.restScale.x, joint.restScale.y, joint.restScale.z};
        model.nodes.push_back(std::move(node));
        if (joint.parent >= 0)
            model.nodes[rig.firstJoint + joint.parent].children.push_back(rig.firstJoint + static_cast<int>(j));
    }

    tinygltf::Mesh mesh;
    mesh.name = spec.name;
    for (std::size_t p = 0; p < assets.partIndices.size(); ++p) {
        const int material = p < spec.partMaterials.size() ? spec.partMaterials[p] : -1;
        if (material < 0)
            continue;
        tinygltf::Primitive primitive;
        primitive.attributes = assets.attributes;
        primitive.indices = assets.partIndices[p];
        primitive.material = material;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        mesh.primitives.push_back(std::move(primitive));
    }
    model.meshes.push_back(std::move(mesh));

    tinygltf::Skin skin;
    skin.name = spec.name;
    skin.inverseBindMatrices = assets.inverseBindMatrices;
    skin.skeleton = rig.root;
    for (std::size_t j = 0; j < c.joints.size(); ++j)
        skin.joints.push_back(rig.firstJoint + static_cast<int>(j));
    model.skins.push_back(std::move(skin));

    tinygltf::Node bodyNode;
    bodyNode.name = spec.name + "_body";
    bodyNode.mesh = static_cast<int>(model.meshes.size()) - 1;
    bodyNode.skin = static_cast<int>(model.skins.size()) - 1;
    model.nodes.push_back(std::move(bodyNode));

    model.scenes[0].nodes.push_back(rig.root);
    model.scenes[0].nodes.push_back(body);
    return rig;
}

}  // namespace throng::exporting::detail
