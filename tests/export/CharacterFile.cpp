#include "CharacterFile.h"

#include <tiny_gltf.h>

#include <cctype>

#include <glm/gtc/type_ptr.hpp>

#include <cstring>

namespace throng::test {

namespace {

int addData(tinygltf::Model& m, const void* data, std::size_t bytes, int componentType, std::size_t count, int type,
            int target = 0)
{
    std::vector<unsigned char>& buffer = m.buffers[0].data;
    const std::size_t offset = buffer.size();
    buffer.resize(offset + ((bytes + 3) & ~std::size_t(3)));
    std::memcpy(buffer.data() + offset, data, bytes);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = bytes;
    view.target = target;
    m.bufferViews.push_back(view);
    tinygltf::Accessor a;
    a.bufferView = static_cast<int>(m.bufferViews.size()) - 1;
    a.componentType = componentType;
    a.count = count;
    a.type = type;
    m.accessors.push_back(a);
    return static_cast<int>(m.accessors.size()) - 1;
}

std::vector<double> v4(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }

}  // namespace

bool writeCharacterFile(const exporting::Character& c, const CharacterFileSpec& spec, const std::string& path,
                        std::string& error)
{
    using exporting::Pose;
    // DCC convention: the character faces +Z. Turning the skeleton root by -90 degrees about
    // +Y (and the bind-space mesh with it) takes Throng's +X-facing character there.
    const glm::quat face = glm::angleAxis(glm::radians(-90.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    tinygltf::Model m;
    m.asset.version = "2.0";
    m.buffers.emplace_back();
    m.scenes.emplace_back();
    m.defaultScene = 0;

    std::vector<exporting::Joint> joints = c.joints;
    joints[0].restTranslation = face * joints[0].restTranslation;
    joints[0].restRotation = face * joints[0].restRotation;
    const std::vector<glm::mat4> ibm = exporting::restInverseBindMatrices(joints);

    tinygltf::Node armature;
    armature.name = "Armature";
    armature.children = {1};
    m.nodes.push_back(armature);
    for (std::size_t j = 0; j < joints.size(); ++j) {
        tinygltf::Node n;
        n.name = joints[j].name;
        n.translation = {joints[j].restTranslation.x, joints[j].restTranslation.y, joints[j].restTranslation.z};
        n.rotation = v4(joints[j].restRotation);
        m.nodes.push_back(n);
        if (joints[j].parent >= 0)
            m.nodes[1 + joints[j].parent].children.push_back(1 + static_cast<int>(j));
    }
    const std::size_t v = c.mesh.positions.size();
    std::vector<glm::vec3> pos(v), nrm(v);
    std::vector<std::uint16_t> jnt(4 * v);
    for (std::size_t i = 0; i < v; ++i) {
        pos[i] = face * c.mesh.positions[i];
        nrm[i] = face * c.mesh.normals[i];
        for (int k = 0; k < 4; ++k)
            jnt[4 * i + k] = c.mesh.joints[i][k];
    }
    std::vector<std::uint32_t> idx = c.mesh.indices;
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = addData(m, pos.data(), v * 12, TINYGLTF_COMPONENT_TYPE_FLOAT, v, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& p : pos) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
    m.accessors[prim.attributes["POSITION"]].minValues = {lo.x, lo.y, lo.z};
    m.accessors[prim.attributes["POSITION"]].maxValues = {hi.x, hi.y, hi.z};
    prim.attributes["NORMAL"] = addData(m, nrm.data(), v * 12, TINYGLTF_COMPONENT_TYPE_FLOAT, v, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
    if (spec.skin) {
        prim.attributes["JOINTS_0"] = addData(m, jnt.data(), v * 8, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, v, TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER);
        prim.attributes["WEIGHTS_0"] = addData(m, c.mesh.weights.data(), v * 16, TINYGLTF_COMPONENT_TYPE_FLOAT, v, TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER);
    }
    prim.indices = addData(m, idx.data(), idx.size() * 4, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, idx.size(), TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = "Body";
    mesh.primitives.push_back(prim);
    m.meshes.push_back(mesh);
    tinygltf::Node body;
    body.name = "Body";
    body.mesh = 0;
    if (spec.skin) {
        tinygltf::Skin skin;
        for (std::size_t j = 0; j < joints.size(); ++j)
            skin.joints.push_back(1 + static_cast<int>(j));
        std::vector<float> mats;
        for (const glm::mat4& mat : ibm)
            mats.insert(mats.end(), glm::value_ptr(mat), glm::value_ptr(mat) + 16);
        skin.inverseBindMatrices = addData(m, mats.data(), mats.size() * 4, TINYGLTF_COMPONENT_TYPE_FLOAT, ibm.size(), TINYGLTF_TYPE_MAT4);
        m.skins.push_back(skin);
        body.skin = 0;
    }
    m.nodes.push_back(body);
    m.scenes[0].nodes = {0, static_cast<int>(m.nodes.size()) - 1};

    // Each clip as a 1 s animation whose keys are the clip's samples, looping back to the first.
    for (const std::string& name : spec.clips) {
        // A clip named after one of the character's actions ("Wave", "Cheer") is cut from it.
        std::string lower = name;
        for (char& ch : lower)
            ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        const int action = c.actionIndex(lower);
        const exporting::CycleClip& clip = action >= 0        ? c.actions[static_cast<std::size_t>(action)].clip
                                           : name == "Idle" ? c.idle
                                           : name == "Run"  ? c.run
                                                            : c.walk;
        const std::size_t keys = clip.samples.size() + 1;
        std::vector<float> times(keys);
        for (std::size_t k = 0; k < keys; ++k)
            times[k] = static_cast<float>(k) / static_cast<float>(keys - 1);
        tinygltf::Animation anim;
        anim.name = name;
        const int input = addData(m, times.data(), keys * 4, TINYGLTF_COMPONENT_TYPE_FLOAT, keys, TINYGLTF_TYPE_SCALAR);
        m.accessors[input].minValues = {0.0};
        m.accessors[input].maxValues = {1.0};
        auto channel = [&](int node, const char* path, int output) {
            tinygltf::AnimationSampler s;
            s.input = input;
            s.output = output;
            s.interpolation = "LINEAR";
            anim.samplers.push_back(s);
            tinygltf::AnimationChannel ch;
            ch.sampler = static_cast<int>(anim.samplers.size()) - 1;
            ch.target_node = node;
            ch.target_path = path;
            anim.channels.push_back(ch);
        };
        std::vector<glm::vec3> root(keys);
        for (std::size_t k = 0; k < keys; ++k)
            root[k] = face * clip.samples[k % clip.samples.size()].rootTranslation;
        channel(1, "translation", addData(m, root.data(), keys * 12, TINYGLTF_COMPONENT_TYPE_FLOAT, keys, TINYGLTF_TYPE_VEC3));
        for (std::size_t j = 0; j < joints.size(); ++j) {
            std::vector<glm::quat> q(keys);
            for (std::size_t k = 0; k < keys; ++k) {
                const Pose& p = clip.samples[k % clip.samples.size()];
                q[k] = j == 0 ? face * p.rotations[j] : p.rotations[j];
                if (k > 0 && glm::dot(q[k], q[k - 1]) < 0.0f)
                    q[k] = -q[k];
            }
            std::vector<float> xyzw;
            for (const glm::quat& r : q)
                xyzw.insert(xyzw.end(), {r.x, r.y, r.z, r.w});
            channel(1 + static_cast<int>(j), "rotation",
                    addData(m, xyzw.data(), xyzw.size() * 4, TINYGLTF_COMPONENT_TYPE_FLOAT, keys, TINYGLTF_TYPE_VEC4));
        }
        m.animations.push_back(anim);
    }
    tinygltf::TinyGLTF writer;
    const bool glb = path.size() > 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
    if (!writer.WriteGltfSceneToFile(&m, path, true, true, false, glb)) {
        error = "cannot write " + path;
        return false;
    }
    return true;
}

}  // namespace throng::test
