#include "export/detail/GltfBuilder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace throng::exporting::detail {

GltfBuilder::GltfBuilder(tinygltf::Model& model) : m_model(model)
{
    if (m_model.buffers.empty())
        m_model.buffers.emplace_back();
}

std::size_t GltfBuilder::append(const void* data, std::size_t bytes)
{
    std::vector<unsigned char>& buffer = m_model.buffers[0].data;
    const std::size_t offset = buffer.size();
    buffer.resize(offset + ((bytes + 3) & ~std::size_t(3)), 0);
    m_bytes[static_cast<int>(m_use)] += (bytes + 3) & ~std::size_t(3);
    if (bytes > 0)
        std::memcpy(buffer.data() + offset, data, bytes);
    return offset;
}

int GltfBuilder::addView(std::size_t offset, std::size_t length, int stride, int target)
{
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = length;
    view.byteStride = static_cast<std::size_t>(stride);
    view.target = target;
    m_model.bufferViews.push_back(std::move(view));
    return static_cast<int>(m_model.bufferViews.size()) - 1;
}

int GltfBuilder::addAccessor(int view, std::size_t byteOffset, int componentType, std::size_t count, int type,
                             bool normalized)
{
    tinygltf::Accessor accessor;
    accessor.bufferView = view;
    accessor.byteOffset = byteOffset;
    accessor.componentType = componentType;
    accessor.count = count;
    accessor.type = type;
    accessor.normalized = normalized;
    m_model.accessors.push_back(std::move(accessor));
    return static_cast<int>(m_model.accessors.size()) - 1;
}

void GltfBuilder::beginAnimationData()
{
    m_animationStart = m_model.buffers[0].data.size();
    m_animationView = addView(m_animationStart, 0, 0, 0);
}

void GltfBuilder::endAnimationData()
{
    m_model.bufferViews[m_animationView].byteLength = m_model.buffers[0].data.size() - m_animationStart;
}

int GltfBuilder::addTimes(std::span<const float> times)
{
    const std::size_t offset = append(times.data(), times.size_bytes());
    const int a = addAccessor(m_animationView, offset - m_animationStart, TINYGLTF_COMPONENT_TYPE_FLOAT, times.size(),
                              TINYGLTF_TYPE_SCALAR);
    m_model.accessors[a].minValues = {times.front()};
    m_model.accessors[a].maxValues = {times.back()};
    return a;
}

int GltfBuilder::addVec3Keys(std::span<const glm::vec3> keys)
{
    static_assert(sizeof(glm::vec3) == 12);
    const std::size_t offset = append(keys.data(), keys.size_bytes());
    return addAccessor(m_animationView, offset - m_animationStart, TINYGLTF_COMPONENT_TYPE_FLOAT, keys.size(),
                       TINYGLTF_TYPE_VEC3);
}

void GltfBuilder::quantise(std::span<const glm::quat> keys, std::int16_t* out)
{
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const glm::quat& q = keys[k];
        const float xyzw[4] = {q.x, q.y, q.z, q.w};
        for (int c = 0; c < 4; ++c)
            out[4 * k + c] = static_cast<std::int16_t>(std::lround(std::clamp(xyzw[c], -1.0f, 1.0f) * 32767.0f));
    }
}

int GltfBuilder::addRotationKeys(std::span<const glm::quat> keys)
{
    std::vector<std::int16_t> packed(4 * keys.size());
    quantise(keys, packed.data());
    const std::size_t offset = append(packed.data(), packed.size() * sizeof(std::int16_t));
    return addAccessor(m_animationView, offset - m_animationStart, TINYGLTF_COMPONENT_TYPE_SHORT, keys.size(),
                       TINYGLTF_TYPE_VEC4, true);
}

int GltfBuilder::addWindow(std::size_t regionOffset, std::size_t first, std::size_t elementBytes, int componentType,
                           std::size_t count, int type, bool normalized)
{
    return addAccessor(m_animationView, regionOffset + first * elementBytes, componentType, count, type, normalized);
}

std::size_t GltfBuilder::regionOffsetOf(int accessor) const { return m_model.accessors[accessor].byteOffset; }

}  // namespace throng::exporting::detail
