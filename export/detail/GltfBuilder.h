#pragma once
// Appends binary data and the bufferViews/accessors that describe it to a tinygltf model
// with one buffer. Animation data goes into one growing region that one bufferView spans,
// so a hundred thousand accessors need no hundred thousand views. No file I/O.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include <tiny_gltf.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <span>
#include <string>

namespace throng::exporting::detail {

class GltfBuilder {
public:
    explicit GltfBuilder(tinygltf::Model& model);

    tinygltf::Model& model() { return m_model; }
    // What the bytes appended from now on are for, so an export can say where its size goes.
    enum class Use { Geometry, Clocks, RootMotion, Joints, Count };
    void setUse(Use use) { m_use = use; }
    std::size_t bytesFor(Use use) const { return m_bytes[static_cast<int>(use)]; }
    // Appends `bytes` bytes (zero-padded to a multiple of 4) and returns their offset in the buffer.
    std::size_t append(const void* data, std::size_t bytes);
    int addView(std::size_t offset, std::size_t length, int stride, int target);
    int addAccessor(int view, std::size_t byteOffset, int componentType, std::size_t count, int type,
                    bool normalized = false);

    // Opens the animation region: everything appended from now on lies in one view.
    void beginAnimationData();
    // Closes it; call once after the last animation key is appended.
    void endAnimationData();
    // Animation accessors (inside the region): times (float, with min/max), vec3 keys
    // (float), rotations as normalised int16 (glTF allows it for rotation outputs only).
    int addTimes(std::span<const float> times);
    int addVec3Keys(std::span<const glm::vec3> keys);
    int addRotationKeys(std::span<const glm::quat> keys);
    // A window of `count` elements of an accessor written earlier in the region, starting
    // at element `first` of the data at `regionOffset`: readers share the bytes.
    int addWindow(std::size_t regionOffset, std::size_t first, std::size_t elementBytes, int componentType,
                  std::size_t count, int type, bool normalized);
    // Appends raw bytes inside the animation region; returns their offset in the region.
    std::size_t appendAnimationBytes(const void* data, std::size_t bytes) { return append(data, bytes) - m_animationStart; }
    // Offset inside the animation region of accessor `accessor`'s first byte.
    std::size_t regionOffsetOf(int accessor) const;
    // Quantises unit quaternions to normalised int16 (x, y, z, w) into `out` (4 per key).
    static void quantise(std::span<const glm::quat> keys, std::int16_t* out);

private:
    tinygltf::Model& m_model;
    Use m_use = Use::Geometry;
    std::size_t m_bytes[static_cast<int>(Use::Count)] = {};
    int m_animationView = -1;
    std::size_t m_animationStart = 0;
};

}  // namespace throng::exporting::detail
