#define GLM_ENABLE_EXPERIMENTAL  // glm::decompose lives in gtx
#include "export/character/UserClipSampler.h"

#include "simcore/scene/Clip.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <optional>

namespace throng::exporting {

namespace {

float component(const unsigned char* p, int type, bool normalized)
{
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p, 4); return f; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0f : *p;
    case TINYGLTF_COMPONENT_TYPE_BYTE: { const auto v = static_cast<std::int8_t>(*p); return normalized ? std::max(v / 127.0f, -1.0f) : v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { std::uint16_t v; std::memcpy(&v, p, 2); return normalized ? v / 65535.0f : v; }
    case TINYGLTF_COMPONENT_TYPE_SHORT: { std::int16_t v; std::memcpy(&v, p, 2); return normalized ? std::max(v / 32767.0f, -1.0f) : v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t v; std::memcpy(&v, p, 4); return static_cast<float>(v); }
    default: return 0.0f;
    }
}

struct Channel {
    std::vector<float> times, values;
    int components = 0;
    std::string interpolation;
};

// The channel's value at time t: clamped at the ends, STEP or linear (slerp-like nlerp for
// rotations); a CUBICSPLINE key's value is its middle element.
std::vector<float> valueAt(const Channel& ch, float t)
{
    const int n = ch.components;
    const bool cubic = ch.interpolation == "CUBICSPLINE";
    auto key = [&](std::size_t k) { return ch.values.data() + (cubic ? (3 * k + 1) : k) * n; };
    const std::size_t count = ch.times.size();
    std::size_t hi = std::upper_bound(ch.times.begin(), ch.times.end(), t) - ch.times.begin();
    if (hi == 0 || count == 1)
        return {key(0), key(0) + n};
    if (hi >= count)
        return {key(count - 1), key(count - 1) + n};
    const std::size_t lo = hi - 1;
    if (ch.interpolation == "STEP")
        return {key(lo), key(lo) + n};
    const float u = (t - ch.times[lo]) / (ch.times[hi] - ch.times[lo]);
    std::vector<float> out(n);
    float sign = 1.0f;
    if (n == 4) {
        float dot = 0.0f;
        for (int i = 0; i < 4; ++i)
            dot += key(lo)[i] * key(hi)[i];
        sign = dot < 0.0f ? -1.0f : 1.0f;
    }
    for (int i = 0; i < n; ++i)
        out[i] = key(lo)[i] + (sign * key(hi)[i] - key(lo)[i]) * u;
    return out;
}

std::string lower(std::string s)
{
    for (char& c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

int findClip(const tinygltf::Model& model, const std::string& wanted, std::initializer_list<const char*> keywords)
{
    int best = -1;
    for (std::size_t a = 0; a < model.animations.size(); ++a) {
        const std::string name = lower(model.animations[a].name);
        bool match = !wanted.empty() ? model.animations[a].name == wanted : false;
        for (const char* k : keywords)
            match = match || (wanted.empty() && name.find(k) != std::string::npos);
        if (match && (best < 0 || name.size() < model.animations[best].name.size()))
            best = static_cast<int>(a);
    }
    return best;
}

// The joints an action plays over walking: all but the root, the hips and the legs with
// what hangs from them (by name, case-insensitive, so any skeleton's naming will do).
std::vector<std::uint8_t> upperBodyByName(const Character& c)
{
    static const char* const trunk[] = {"hip", "pelvis"};  // left out, its children not
    static const char* const legs[] = {"leg", "thigh", "knee", "shin", "calf", "ankle", "foot", "toe"};
    auto named = [](const std::string& name, const auto& words) {
        for (const char* word : words)
            if (name.find(word) != std::string::npos)
                return true;
        return false;
    };
    std::vector<std::uint8_t> layered(c.joints.size(), 1), leg(c.joints.size(), 0);
    for (std::size_t j = 0; j < c.joints.size(); ++j) {
        const std::string name = lower(c.joints[j].name);
        const int parent = c.joints[j].parent;  // parents come first
        leg[j] = named(name, legs) || (parent >= 0 && leg[static_cast<std::size_t>(parent)]) ? 1 : 0;
        layered[j] = j == 0 || leg[j] || named(name, trunk) ? 0 : 1;
    }
    return layered;
}

}  // namespace

std::vector<float> readFloats(const tinygltf::Model& model, int index)
{
    const tinygltf::Accessor& a = model.accessors.at(index);
    const int n = tinygltf::GetNumComponentsInType(a.type);
    const int size = tinygltf::GetComponentSizeInBytes(a.componentType);
    std::vector<float> out(a.count * n, 0.0f);
    if (a.bufferView < 0 || n <= 0 || size <= 0)
        return out;
    const tinygltf::BufferView& view = model.bufferViews.at(a.bufferView);
    const std::vector<unsigned char>& data = model.buffers.at(view.buffer).data;
    const std::size_t stride = view.byteStride ? view.byteStride : static_cast<std::size_t>(n * size);
    for (std::size_t e = 0; e < a.count; ++e)
        for (int c = 0; c < n; ++c) {
            const std::size_t at = view.byteOffset + a.byteOffset + e * stride + static_cast<std::size_t>(c * size);
            if (at + size <= data.size())
                out[e * n + c] = component(data.data() + at, a.componentType, a.normalized);
        }
    return out;
}

bool readSkinnedMesh(const tinygltf::Model& model, const tinygltf::Node& node, const tinygltf::Skin& skin,
                     const std::map<int, int>& jointOfNode, CharacterMesh& mesh, std::string& error)
{
    for (const tinygltf::Primitive& p : model.meshes.at(node.mesh).primitives) {
        if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1)
            continue;
        if (!p.attributes.count("POSITION") || !p.attributes.count("JOINTS_0") || !p.attributes.count("WEIGHTS_0")) {
            error = "its skinned mesh has no POSITION, JOINTS_0 or WEIGHTS_0";
            return false;
        }
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        const std::vector<float> pos = readFloats(model, p.attributes.at("POSITION"));
        const std::vector<float> nrm = p.attributes.count("NORMAL") ? readFloats(model, p.attributes.at("NORMAL")) : std::vector<float>{};
        const std::vector<float> jnt = readFloats(model, p.attributes.at("JOINTS_0"));
        const std::vector<float> wgt = readFloats(model, p.attributes.at("WEIGHTS_0"));
        const std::size_t count = pos.size() / 3;
        for (std::size_t v = 0; v < count; ++v) {
            mesh.positions.emplace_back(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]);
            glm::vec3 n = nrm.size() >= 3 * (v + 1) ? glm::vec3(nrm[3 * v], nrm[3 * v + 1], nrm[3 * v + 2]) : glm::vec3(0, 1, 0);
            mesh.normals.push_back(glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 1.0f, 0.0f));
            std::array<std::uint16_t, 4> j{};
            glm::vec4 w(0.0f);
            for (int k = 0; k < 4; ++k) {
                const auto slot = static_cast<std::size_t>(jnt[4 * v + k]);
                w[k] = wgt[4 * v + k];
                const auto it = slot < skin.joints.size() ? jointOfNode.find(skin.joints[slot]) : jointOfNode.end();
                j[k] = it == jointOfNode.end() ? 0 : static_cast<std::uint16_t>(it->second);
                if (it == jointOfNode.end())
                    w[k] = 0.0f;
            }
            mesh.joints.push_back(j);
            mesh.weights.push_back(w);
        }
        if (p.indices >= 0) {
            for (float i : readFloats(model, p.indices))
                mesh.indices.push_back(base + static_cast<std::uint32_t>(i));
        } else {
            for (std::uint32_t i = 0; i < count; ++i)
                mesh.indices.push_back(base + i);
        }
    }
    if (mesh.positions.empty()) {
        error = "its skinned mesh has no triangles";
        return false;
    }
    return true;
}

bool sampleUserClips(const tinygltf::Model& model, Character& c, const std::map<int, int>& jointOfNode,
                     const ClipNames& names, std::string& error)
{
    std::vector<int> nodeOfJoint(c.joints.size(), -1);
    for (const auto& [node, joint] : jointOfNode)
        nodeOfJoint[joint] = node;
    // What sits between a joint's parent joint and the joint stays as at rest: the local
    // matrix of the joint relative to its parent = (rest local of joint) with the node's
    // own TRS replaced by the animated one.
    std::vector<glm::mat4> restNodeLocal(c.joints.size(), glm::mat4(1.0f)), prefix(c.joints.size(), glm::mat4(1.0f));
    for (std::size_t j = 0; j < c.joints.size(); ++j) {
        if (nodeOfJoint[j] < 0)
            continue;
        const tinygltf::Node& n = model.nodes[nodeOfJoint[j]];
        glm::vec3 t(0.0f), s(1.0f);
        glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
        if (n.translation.size() == 3) t = {n.translation[0], n.translation[1], n.translation[2]};
        if (n.rotation.size() == 4) r = glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]));
        if (n.scale.size() == 3) s = {n.scale[0], n.scale[1], n.scale[2]};
        restNodeLocal[j] = glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
        const glm::mat4 jointLocal = glm::translate(glm::mat4(1.0f), c.joints[j].restTranslation) *
                                     glm::mat4_cast(c.joints[j].restRotation) * glm::scale(glm::mat4(1.0f), c.joints[j].restScale);
        prefix[j] = jointLocal * glm::inverse(restNodeLocal[j]);
    }

    float lowY = 1e9f, highY = -1e9f;
    for (const glm::vec3& p : c.mesh.positions) {
        lowY = std::min(lowY, p.y);
        highY = std::max(highY, p.y);
    }
    const float height = std::max(0.1f, highY - lowY);

    auto sample = [&](int anim, const char* as, float fallbackStride) {
        CycleClip clip;
        clip.name = as;
        const tinygltf::Animation& a = model.animations[anim];
        std::map<std::pair<int, std::string>, Channel> channels;
        float start = 1e30f, end = -1e30f;
        for (const tinygltf::AnimationChannel& ch : a.channels) {
            if (!jointOfNode.count(ch.target_node))
                continue;
            const tinygltf::AnimationSampler& s = a.samplers.at(ch.sampler);
            Channel data{readFloats(model, s.input), readFloats(model, s.output), 0, s.interpolation};
            if (data.times.empty())
                continue;
            data.components = ch.target_path == "rotation" ? 4 : 3;
            start = std::min(start, data.times.front());
            end = std::max(end, data.times.back());
            channels[{jointOfNode.at(ch.target_node), ch.target_path}] = std::move(data);
        }
        if (!(end > start))
            end = start = 0.0f;
        const int samples = std::clamp(static_cast<int>(std::lround((end - start) * 30.0f)), 8, 64);
        auto poseAt = [&](float t) {
            Pose p;
            p.rotations.resize(c.joints.size());
            for (std::size_t j = 0; j < c.joints.size(); ++j) {
                glm::mat4 local(1.0f);
                if (nodeOfJoint[j] >= 0) {
                    const tinygltf::Node& n = model.nodes[nodeOfJoint[j]];
                    glm::vec3 tr = n.translation.size() == 3 ? glm::vec3(n.translation[0], n.translation[1], n.translation[2]) : glm::vec3(0.0f);
                    glm::quat r = n.rotation.size() == 4 ? glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2])) : glm::quat(1, 0, 0, 0);
                    glm::vec3 sc = n.scale.size() == 3 ? glm::vec3(n.scale[0], n.scale[1], n.scale[2]) : glm::vec3(1.0f);
                    const int jj = static_cast<int>(j);
                    if (auto it = channels.find({jj, "translation"}); it != channels.end()) { auto v = valueAt(it->second, t); tr = {v[0], v[1], v[2]}; }
                    if (auto it = channels.find({jj, "rotation"}); it != channels.end()) { auto v = valueAt(it->second, t); r = glm::normalize(glm::quat(v[3], v[0], v[1], v[2])); }
                    if (auto it = channels.find({jj, "scale"}); it != channels.end()) { auto v = valueAt(it->second, t); sc = {v[0], v[1], v[2]}; }
                    local = prefix[j] * glm::translate(glm::mat4(1.0f), tr) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), sc);
                }
                glm::vec3 scale, translation, skew;
                glm::vec4 perspective;
                glm::quat rotation;
                glm::decompose(local, scale, rotation, translation, skew, perspective);
                p.rotations[j] = glm::normalize(rotation);
                if (j == 0)
                    p.rootTranslation = translation;
            }
            return p;
        };
        const glm::vec3 drift = poseAt(end).rootTranslation - poseAt(start).rootTranslation;
        const float travel = std::hypot(drift.x, drift.z);
        clip.strideM = travel > 0.05f ? travel : fallbackStride * height;
        for (int k = 0; k < samples; ++k) {
            const float u = static_cast<float>(k) / static_cast<float>(samples);
            Pose p = poseAt(start + (end - start) * u);
            if (travel > 0.05f)
                p.rootTranslation -= glm::vec3(drift.x, 0.0f, drift.z) * u;
            clip.samples.push_back(std::move(p));
        }
        return clip;
    };

    std::string found;
    for (const tinygltf::Animation& a : model.animations)
        found += (found.empty() ? "" : ", ") + ("'" + a.name + "'");
    const int walk = findClip(model, names.walk, {"walk"});
    if (walk < 0) {
        error = "no walk clip" + (names.walk.empty() ? std::string(" (no clip name contains 'walk')") : " named '" + names.walk + "'") +
                "; its clips are " + found;
        return false;
    }
    const int run = findClip(model, names.run, {"run"});
    const int idle = findClip(model, names.idle, {"idle", "stand"});
    c.walk = sample(walk, "walk", 0.8f);
    c.run = run >= 0 ? sample(run, "run", 1.6f) : c.walk;
    if (run < 0)
        c.run.name = "run";
    if (idle >= 0) {
        c.idle = sample(idle, "idle", 0.8f);
        c.idle.samples.resize(1);
    } else {
        c.idle.name = "idle";
        c.idle.samples = {restPose(c)};
    }
    c.idle.strideM = c.walk.strideM;
    for (const auto& [action, clipName] : names.actions) {
        const int anim = findClip(model, clipName, {});
        if (anim < 0) {
            error = "no clip named '" + clipName + "' for the action '" + action + "'; its clips are " + found;
            return false;
        }
        ActionClip a;
        a.clip = sample(anim, action.c_str(), 0.8f);
        a.layered = upperBodyByName(c);
        const std::optional<sim::Clip> clip = sim::clipFromName(action);
        a.oneShot = clip && sim::isOneShot(*clip);
        c.actions.push_back(std::move(a));
    }
    const float k = height / 1.75f;
    c.idleSpeed = 0.05f * k;
    c.walkSpeed = 0.4f * k;
    c.runStartSpeed = 2.2f * k;
    c.runSpeed = 3.0f * k;
    return true;
}

}  // namespace throng::exporting
