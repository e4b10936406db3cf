#pragma once
// Loads an exported .gltf/.glb back with tinygltf and reads its animation the way an
// importer would: accessor floats, and the sampler animating one node's property.
// Test-only.

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace throng::test {

// Loads .glb or .gltf by extension; false with `error` set when tinygltf refuses it.
bool loadGltf(const std::string& path, tinygltf::Model& model, std::string& error);
// Every value of a FLOAT or normalised SHORT accessor as float, tightly packed (count x components).
std::vector<float> accessorFloats(const tinygltf::Model& model, int accessor);
// Every value of an UNSIGNED_BYTE, _SHORT or _INT scalar accessor (indices), in order.
std::vector<std::uint32_t> accessorIndices(const tinygltf::Model& model, int accessor);
// The sampler of the first animation's channel targeting `node`'s `path`, or nullptr.
const tinygltf::AnimationSampler* samplerFor(const tinygltf::Model& model, int node, const std::string& path);
// The value of `node`'s `path` channel at time t (s), interpolated linearly (rotations:
// normalised, the short way), as a reader would; empty when there is no such channel.
std::vector<float> evaluateChannel(const tinygltf::Model& model, int node, const std::string& path, float t);
// The node's local transform at time t: its animated channels where it has them, else
// its static translation, rotation and scale.
glm::mat4 nodeLocalAt(const tinygltf::Model& model, int node, float t);
// Index of the node named `name`, or -1.
int nodeNamed(const tinygltf::Model& model, const std::string& name);
// World position at time t of the last of `joints`, the chain of nodes under the agent
// node `root` named `<root>__<joint>` (the exporter's names); NaN when a node is missing.
glm::vec3 jointWorldAt(const tinygltf::Model& model, const std::string& root, const std::vector<std::string>& joints,
                       float t);

}  // namespace throng::test
