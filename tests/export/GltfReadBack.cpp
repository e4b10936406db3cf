#include "GltfReadBack.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace throng::test {

bool loadGltf(const std::string& path, tinygltf::Model& model, std::string& error)
{
    tinygltf::TinyGLTF loader;
    std::string warning;
    const bool binary = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
    const bool ok = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                           : loader.LoadASCIIFromFile(&model, &error, &warning, path);
    if (ok && !warning.empty()) {
        error = "tinygltf warning: " + warning;
        return false;
    }
    return ok;
}

std::vector<float> accessorFloats(const tinygltf::Model& model, int accessorIndex)
{
    const tinygltf::Accessor& accessor = model.accessors.at(accessorIndex);
    const bool isFloat = accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool isShort = accessor.componentType == TINYGLTF_COMPONENT_TYPE_SHORT && accessor.normalized;
    if (!isFloat && !isShort)
        return {};
    const tinygltf::BufferView& view = model.bufferViews.at(accessor.bufferView);
    const tinygltf::Buffer& buffer = model.buffers.at(view.buffer);
    const std::size_t components = tinygltf::GetNumComponentsInType(accessor.type);
    const std::size_t size = isFloat ? sizeof(float) : sizeof(std::int16_t);
    const std::size_t stride = view.byteStride ? view.byteStride : components * size;
    std::vector<float> values(accessor.count * components);
    for (std::size_t i = 0; i < accessor.count; ++i)
        for (std::size_t c = 0; c < components; ++c) {
            const unsigned char* p = buffer.data.data() + view.byteOffset + accessor.byteOffset + i * stride + c * size;
            if (isFloat) {
                std::memcpy(&values[i * components + c], p, sizeof(float));
            } else {
                std::int16_t v;
                std::memcpy(&v, p, sizeof v);
                values[i * components + c] = std::max(-1.0f, static_cast<float>(v) / 32767.0f);
            }
        }
    return values;
}

std::vector<std::uint32_t> accessorIndices(const tinygltf::Model& model, int accessorIndex)
{
    const tinygltf::Accessor& accessor = model.accessors.at(accessorIndex);
    const int type = accessor.componentType;
    const std::size_t size = type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                             : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                             : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                              : 0;
    if (size == 0 || accessor.type != TINYGLTF_TYPE_SCALAR)
        return {};
    const tinygltf::BufferView& view = model.bufferViews.at(accessor.bufferView);
    const unsigned char* base = model.buffers.at(view.buffer).data.data() + view.byteOffset + accessor.byteOffset;
    const std::size_t stride = view.byteStride ? view.byteStride : size;
    std::vector<std::uint32_t> values(accessor.count);
    for (std::size_t i = 0; i < accessor.count; ++i) {
        std::uint32_t v = 0;
        std::memcpy(&v, base + i * stride, size);  // little-endian: the low bytes
        values[i] = v;
    }
    return values;
}

std::vector<float> evaluateChannel(const tinygltf::Model& model, int node, const std::string& path, float t)
{
    const tinygltf::AnimationSampler* sampler = samplerFor(model, node, path);
    if (!sampler)
        return {};
    const std::vector<float> times = accessorFloats(model, sampler->input);
    const std::vector<float> values = accessorFloats(model, sampler->output);
    const std::size_t n = values.size() / times.size();
    std::size_t hi = std::upper_bound(times.begin(), times.end(), t) - times.begin();
    if (hi == 0)
        return {values.begin(), values.begin() + n};
    if (hi == times.size())
        return {values.end() - n, values.end()};
    const std::size_t lo = hi - 1;
    const float u = (t - times[lo]) / (times[hi] - times[lo]);
    float sign = 1.0f;
    if (n == 4) {
        float dot = 0.0f;
        for (std::size_t c = 0; c < 4; ++c)
            dot += values[lo * 4 + c] * values[hi * 4 + c];
        sign = dot < 0.0f ? -1.0f : 1.0f;
    }
    std::vector<float> out(n);
    for (std::size_t c = 0; c < n; ++c)
        out[c] = values[lo * n + c] + (sign * values[hi * n + c] - values[lo * n + c]) * u;
    if (n == 4) {
        float len = 0.0f;
        for (float v : out)
            len += v * v;
        for (float& v : out)
            v /= std::sqrt(len);
    }
    return out;
}

const tinygltf::AnimationSampler* samplerFor(const tinygltf::Model& model, int node, const std::string& path)
{
    if (model.animations.empty())
        return nullptr;
    const tinygltf::Animation& animation = model.animations.front();
    for (const tinygltf::AnimationChannel& channel : animation.channels)
        if (channel.target_node == node && channel.target_path == path)
            return &animation.samplers.at(channel.sampler);
    return nullptr;
}

int nodeNamed(const tinygltf::Model& model, const std::string& name)
{
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
        if (model.nodes[i].name == name)
            return static_cast<int>(i);
    return -1;
}

glm::mat4 nodeLocalAt(const tinygltf::Model& model, int node, float t)
{
    const tinygltf::Node& n = model.nodes.at(static_cast<std::size_t>(node));
    glm::vec3 tr(0.0f), sc(1.0f);
    glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
    if (n.translation.size() == 3)
        tr = {n.translation[0], n.translation[1], n.translation[2]};
    if (n.rotation.size() == 4)
        r = glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]));
    if (n.scale.size() == 3)
        sc = {n.scale[0], n.scale[1], n.scale[2]};
    if (const std::vector<float> v = evaluateChannel(model, node, "translation", t); v.size() == 3)
        tr = {v[0], v[1], v[2]};
    if (const std::vector<float> v = evaluateChannel(model, node, "rotation", t); v.size() == 4)
        r = glm::quat(v[3], v[0], v[1], v[2]);
    return glm::translate(glm::mat4(1.0f), tr) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), sc);
}

glm::vec3 jointWorldAt(const tinygltf::Model& model, const std::string& root, const std::vector<std::string>& joints,
                       float t)
{
    const int rootNode = nodeNamed(model, root);
    if (rootNode < 0)
        return glm::vec3(NAN);
    glm::mat4 m = nodeLocalAt(model, rootNode, t);
    for (const std::string& j : joints) {
        const int node = nodeNamed(model, root + "__" + j);
        if (node < 0)
            return glm::vec3(NAN);
        m = m * nodeLocalAt(model, node, t);
    }
    return glm::vec3(m[3]);
}

}  // namespace throng::test
