#include "GltfReadBack.h"

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
    if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        return {};
    const tinygltf::BufferView& view = model.bufferViews.at(accessor.bufferView);
    const tinygltf::Buffer& buffer = model.buffers.at(view.buffer);
    const std::size_t components = tinygltf::GetNumComponentsInType(accessor.type);
    const std::size_t stride = view.byteStride ? view.byteStride : components * sizeof(float);
    std::vector<float> values(accessor.count * components);
    for (std::size_t i = 0; i < accessor.count; ++i)
        std::memcpy(&values[i * components], buffer.data.data() + view.byteOffset + accessor.byteOffset + i * stride,
                    components * sizeof(float));
    return values;
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

}  // namespace throng::test
