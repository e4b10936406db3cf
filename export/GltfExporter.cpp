#include "export/GltfExporter.h"

#include "export/detail/AtomicFile.h"
#include "export/detail/BodyMesh.h"
#include "export/detail/StagingDirectory.h"

#include <tiny_gltf.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <span>
#include <fstream>
#include <system_error>

namespace throng::exporting {

namespace {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian");

// A GLB stores its total length in 32 bits; keep room for the JSON chunk.
constexpr std::uint64_t kMaxGlbBinBytes = 0xFFFFFFFFull - (256ull << 20);

// Colours for types that carry no tint of their own, distinct and mid-bright.
constexpr double kPalette[][3] = {{0.85, 0.33, 0.26}, {0.22, 0.55, 0.85}, {0.35, 0.72, 0.36},
                                  {0.92, 0.70, 0.20}, {0.60, 0.40, 0.78}, {0.25, 0.75, 0.75}};

// Agents transposed together from the frame-major cache to per-agent key arrays: reads
// and writes then both stay within a few cache lines per step.
constexpr std::size_t kAgentBlock = 64;

bool endsWithGlb(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".glb";
}

// The .bin's name is also its URI, so it keeps only characters a URI needs no escape for.
std::string binFileName(const std::string& gltfPath)
{
    std::string stem = std::filesystem::path(gltfPath).stem().string();
    for (char& c : stem) {
        const bool safe = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_' || c == '~';
        if (!safe)
            c = '_';
    }
    return (stem.empty() ? std::string("crowd") : stem) + ".bin";
}

bool cancelledAt(const ProgressFn& progress, float fraction) { return progress && !progress(fraction); }

// Appends `n` zeroed bytes and returns their offset (always a multiple of 4).
std::size_t reserveBytes(tinygltf::Model& model, std::size_t n)
{
    std::vector<unsigned char>& data = model.buffers[0].data;
    const std::size_t offset = data.size();
    data.resize(offset + n);
    return offset;
}

int addBufferView(tinygltf::Model& model, std::size_t offset, std::size_t length, int stride, int target)
{
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = length;
    view.byteStride = static_cast<std::size_t>(stride);
    view.target = target;
    model.bufferViews.push_back(std::move(view));
    return static_cast<int>(model.bufferViews.size()) - 1;
}

int addFloatAccessor(tinygltf::Model& model, int view, std::size_t byteOffset, std::size_t count, int type)
{
    tinygltf::Accessor accessor;
    accessor.bufferView = view;
    accessor.byteOffset = byteOffset;
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.count = count;
    accessor.type = type;
    model.accessors.push_back(std::move(accessor));
    return static_cast<int>(model.accessors.size()) - 1;
}

tinygltf::Value crowdExtras(const sim::FrameCache& cache)
{
    tinygltf::Value::Object extras;
    extras["generator"] = tinygltf::Value(std::string("Throng"));
    extras["fps"] = tinygltf::Value(static_cast<double>(cache.fps()));
    extras["frameCount"] = tinygltf::Value(static_cast<int>(cache.frameCount()));
    extras["agentCount"] = tinygltf::Value(static_cast<int>(cache.agentCount()));
    return tinygltf::Value(std::move(extras));
}

float bodyHeightM(const sim::AgentType& type, const GltfOptions& options)
{
    return std::min(type.radiusM * options.bodyHeightPerRadius, options.maxBodyHeightM);
}

// One mesh (and material) per agent type that some agent uses; -1 for unused types.
std::vector<int> addBodyMeshes(tinygltf::Model& model, const sim::Scene& scene, const sim::FrameCache& cache,
                               const GltfOptions& options)
{
    std::vector<int> meshOfType(scene.agentTypes.size(), -1);
    for (const sim::AgentInfo& agent : cache.agents()) {
        int& mesh = meshOfType[agent.typeIndex];
        if (mesh >= 0)
            continue;
        const sim::AgentType& type = scene.agentTypes[agent.typeIndex];
        const detail::BodyMesh body = detail::makeBodyMesh(type.radiusM, bodyHeightM(type, options));

        // POSITION and NORMAL interleaved in one view, hence the stride.
        const std::size_t vertexBytes = 2 * sizeof(glm::vec3);
        const std::size_t offset = reserveBytes(model, body.positions.size() * vertexBytes);
        unsigned char* out = model.buffers[0].data.data() + offset;
        for (std::size_t v = 0; v < body.positions.size(); ++v) {
            std::memcpy(out + v * vertexBytes, &body.positions[v], sizeof(glm::vec3));
            std::memcpy(out + v * vertexBytes + sizeof(glm::vec3), &body.normals[v], sizeof(glm::vec3));
        }
        const int view = addBufferView(model, offset, body.positions.size() * vertexBytes, int(vertexBytes),
                                       TINYGLTF_TARGET_ARRAY_BUFFER);
        const int position = addFloatAccessor(model, view, 0, body.positions.size(), TINYGLTF_TYPE_VEC3);
        model.accessors[position].minValues = {body.min.x, body.min.y, body.min.z};
        model.accessors[position].maxValues = {body.max.x, body.max.y, body.max.z};
        const int normal = addFloatAccessor(model, view, sizeof(glm::vec3), body.normals.size(), TINYGLTF_TYPE_VEC3);

        tinygltf::Material material;
        material.name = type.name;
        if (type.variation.tints.empty()) {
            const double* rgb = kPalette[agent.typeIndex % std::size(kPalette)];
            material.pbrMetallicRoughness.baseColorFactor = {rgb[0], rgb[1], rgb[2], 1.0};
        } else {
            const glm::vec3 rgb = glm::clamp(type.variation.tints.front(), 0.0f, 1.0f);
            material.pbrMetallicRoughness.baseColorFactor = {rgb.r, rgb.g, rgb.b, 1.0};
        }
        material.pbrMetallicRoughness.metallicFactor = 0.0;
        material.pbrMetallicRoughness.roughnessFactor = 0.8;
        model.materials.push_back(std::move(material));

        tinygltf::Primitive primitive;
        primitive.attributes["POSITION"] = position;
        primitive.attributes["NORMAL"] = normal;
        primitive.material = static_cast<int>(model.materials.size()) - 1;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        tinygltf::Mesh gltfMesh;
        gltfMesh.name = "body_" + type.name;
        gltfMesh.primitives.push_back(std::move(primitive));
        model.meshes.push_back(std::move(gltfMesh));
        mesh = static_cast<int>(model.meshes.size()) - 1;
    }
    return meshOfType;
}

// The one time accessor every sampler shares: frame f at f / fps seconds.
int addKeyTimes(tinygltf::Model& model, const sim::FrameCache& cache)
{
    const std::size_t frames = cache.frameCount();
    const std::size_t offset = reserveBytes(model, frames * sizeof(float));
    float* times = reinterpret_cast<float*>(model.buffers[0].data.data() + offset);
    for (std::size_t f = 0; f < frames; ++f)
        times[f] = static_cast<float>(static_cast<double>(f) / static_cast<double>(cache.fps()));
    const int view = addBufferView(model, offset, frames * sizeof(float), 0, 0);
    const int accessor = addFloatAccessor(model, view, 0, frames, TINYGLTF_TYPE_SCALAR);
    model.accessors[accessor].minValues = {times[0]};
    model.accessors[accessor].maxValues = {times[frames - 1]};
    return accessor;
}

// Rotation about +Y by `headingRad`: turns the body's +X nose to (cos h, 0, -sin h), which
// is counter-clockwise seen from above, as the cache's heading is.
glm::vec4 yawQuaternion(float headingRad)
{
    const double half = 0.5 * static_cast<double>(headingRad);
    return {0.0f, static_cast<float>(std::sin(half)), 0.0f, static_cast<float>(std::cos(half))};
}

void addChannel(tinygltf::Animation& animation, int timeAccessor, int outputAccessor, int node, const char* path)
{
    tinygltf::AnimationSampler sampler;
    sampler.input = timeAccessor;
    sampler.output = outputAccessor;
    sampler.interpolation = "LINEAR";
    animation.samplers.push_back(std::move(sampler));
    tinygltf::AnimationChannel channel;
    channel.sampler = static_cast<int>(animation.samplers.size()) - 1;
    channel.target_node = node;
    channel.target_path = path;
    animation.channels.push_back(std::move(channel));
}

// Fills the key arrays of agents [first, last) for every frame.
void writeAgentKeys(const sim::FrameCache& cache, std::size_t first, std::size_t last, glm::vec3* translations,
                    glm::vec4* rotations)
{
    const std::size_t frames = cache.frameCount();
    for (std::size_t f = 0; f < frames; ++f) {
        const std::span<const sim::AgentFrame> frame = cache.frame(f);
        for (std::size_t i = first; i < last; ++i) {
            const std::size_t key = i * frames + f;
            translations[key] = frame[i].position;
            rotations[key] = yawQuaternion(frame[i].headingRad);
            // q and -q are the same rotation; keep neighbours in one hemisphere so that
            // readers interpolating component-wise never swing the long way round.
            if (f > 0 && glm::dot(rotations[key], rotations[key - 1]) < 0.0f)
                rotations[key] = -rotations[key];
        }
    }
}

// One node per agent plus its translation and rotation channels. False when cancelled.
bool addAgents(tinygltf::Model& model, const sim::Scene& scene, const sim::FrameCache& cache,
               const std::vector<int>& meshOfType, int timeAccessor, const ProgressFn& progress)
{
    const std::size_t frames = cache.frameCount(), agents = cache.agentCount();
    const std::size_t translationBytes = frames * sizeof(glm::vec3), rotationBytes = frames * sizeof(glm::vec4);
    const std::size_t translationOffset = reserveBytes(model, agents * translationBytes);
    const std::size_t rotationOffset = reserveBytes(model, agents * rotationBytes);
    const int translationView = addBufferView(model, translationOffset, agents * translationBytes, 0, 0);
    const int rotationView = addBufferView(model, rotationOffset, agents * rotationBytes, 0, 0);
    auto* translations = reinterpret_cast<glm::vec3*>(model.buffers[0].data.data() + translationOffset);
    auto* rotations = reinterpret_cast<glm::vec4*>(model.buffers[0].data.data() + rotationOffset);

    tinygltf::Animation animation;
    animation.name = "crowd";
    const std::size_t reportEvery = std::max<std::size_t>(kAgentBlock, agents / 100 / kAgentBlock * kAgentBlock);
    for (std::size_t first = 0; first < agents; first += kAgentBlock) {
        if (first % reportEvery == 0 && cancelledAt(progress, 0.8f * static_cast<float>(first) / static_cast<float>(agents)))
            return false;
        const std::size_t last = std::min(agents, first + kAgentBlock);
        writeAgentKeys(cache, first, last, translations, rotations);
        for (std::size_t i = first; i < last; ++i) {
            const glm::vec3 t0 = translations[i * frames];
            const glm::vec4 r0 = rotations[i * frames];
            const sim::AgentInfo& info = cache.agents()[i];
            tinygltf::Node node;
            node.name = "agent_" + std::to_string(info.id) + "_" + scene.agentTypes[info.typeIndex].name;
            node.mesh = meshOfType[info.typeIndex];
            node.translation = {t0.x, t0.y, t0.z};
            node.rotation = {r0.x, r0.y, r0.z, r0.w};
            model.nodes.push_back(std::move(node));
            const int nodeIndex = static_cast<int>(model.nodes.size()) - 1;
            model.scenes[0].nodes.push_back(nodeIndex);

            const int t = addFloatAccessor(model, translationView, i * translationBytes, frames, TINYGLTF_TYPE_VEC3);
            const int r = addFloatAccessor(model, rotationView, i * rotationBytes, frames, TINYGLTF_TYPE_VEC4);
            addChannel(animation, timeAccessor, t, nodeIndex, "translation");
            addChannel(animation, timeAccessor, r, nodeIndex, "rotation");
        }
    }
    model.animations.push_back(std::move(animation));
    return true;
}

std::string checkInput(const sim::Scene& scene, const sim::FrameCache& cache, const GltfOptions& options)
{
    const std::string& path = options.path;
    const std::string where = "cannot export '" + path + "': ";
    if (path.empty())
        return "cannot export: no output path given";
    if (!(options.bodyHeightPerRadius > 0.0f) || !(options.maxBodyHeightM > 0.0f) ||
        !std::isfinite(options.bodyHeightPerRadius) || !std::isfinite(options.maxBodyHeightM))
        return where + "the body height options must be finite and > 0";
    if (cache.agentCount() == 0 || cache.frameCount() == 0)
        return where + "nothing recorded (" + std::to_string(cache.agentCount()) + " agents, " +
               std::to_string(cache.frameCount()) + " frames)";
    if (!(cache.fps() > 0.0f) || !std::isfinite(cache.fps()))
        return where + "the frame cache's fps (" + std::to_string(cache.fps()) + ") is not > 0";
    for (const sim::AgentInfo& agent : cache.agents()) {
        if (agent.typeIndex >= scene.agentTypes.size())
            return where + "agent " + std::to_string(agent.id) + " has type index " +
                   std::to_string(agent.typeIndex) + " but the scene has " +
                   std::to_string(scene.agentTypes.size()) + " agent types";
        const sim::AgentType& type = scene.agentTypes[agent.typeIndex];
        if (!(type.radiusM > 0.0f) || !std::isfinite(type.radiusM))
            return where + "agent type '" + type.name + "' has radius " + std::to_string(type.radiusM) + ", not > 0";
    }
    return {};
}

ExportResult cancelled(const std::string& path)
{
    ExportResult result;
    result.cancelled = true;
    result.error = "export to '" + path + "' cancelled";
    return result;
}

ExportResult failed(std::string error)
{
    ExportResult result;
    result.error = std::move(error);
    return result;
}

ExportResult writeGlb(const tinygltf::Model& model, const std::string& path, const ProgressFn& progress)
{
    if (model.buffers[0].data.size() > kMaxGlbBinBytes)
        return failed("cannot export '" + path + "': " + std::to_string(model.buffers[0].data.size() >> 20) +
                      " MiB of binary data do not fit a .glb (4 GiB at most); write .gltf instead");
    detail::AtomicFile file(path);
    if (!file.open())
        return failed(file.error());
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, file.stream(), false, true))
        return failed("cannot write '" + path + "': the glTF serialiser failed");
    if (cancelledAt(progress, 0.95f))
        return cancelled(path);
    if (!file.commit())
        return failed(file.error());
    return ExportResult{{path}, {}, false};
}

// tinygltf's file writer does not report short writes; a complete staged file is
// exactly as long as the data (.bin) or ends with the JSON's closing brace (.gltf).
bool stagedFileComplete(const std::string& path, std::uintmax_t expectedSize, bool json)
{
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || (!json && size != expectedSize) || (json && size < 2))
        return false;
    if (!json)
        return true;
    std::ifstream in(path, std::ios::binary);
    char tail[2] = {};
    in.seekg(-2, std::ios::end);
    in.read(tail, 2);
    return in && tail[0] == '}' && tail[1] == '\n';
}

ExportResult writeGltfAndBin(tinygltf::Model& model, const std::string& path, bool prettyJson,
                             const ProgressFn& progress)
{
    namespace fs = std::filesystem;
    const std::string binName = binFileName(path);
    const std::string gltfName = fs::path(path).filename().string();
    const std::string binPath = (fs::path(path).parent_path() / binName).string();
    model.buffers[0].uri = binName;

    detail::StagingDirectory staging(path);
    if (!staging.create())
        return failed(staging.error());
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&model, staging.filePath(gltfName), false, false, prettyJson, false))
        return failed("cannot write '" + path + "' or '" + binPath + "'");
    if (!stagedFileComplete(staging.filePath(binName), model.buffers[0].data.size(), false))
        return failed("could not write all of '" + binPath + "' (disk full?)");
    if (!stagedFileComplete(staging.filePath(gltfName), 0, true))
        return failed("could not write all of '" + path + "' (disk full?)");
    if (cancelledAt(progress, 0.95f))
        return cancelled(path);
    // The .bin first: the .gltf that names it must never appear before it.
    if (!staging.syncToDisk() || !staging.publish(binName, binPath) || !staging.publish(gltfName, path))
        return failed(staging.error());
    return ExportResult{{path, binPath}, {}, false};
}

}  // namespace

ExportResult exportGltf(const sim::Scene& scene, const sim::FrameCache& cache, const GltfOptions& options,
                        const ProgressFn& progress)
{
    if (std::string error = checkInput(scene, cache, options); !error.empty())
        return failed(std::move(error));
    if (cancelledAt(progress, 0.0f))
        return cancelled(options.path);

    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "Throng";
    model.asset.extras = crowdExtras(cache);
    model.buffers.emplace_back();
    model.scenes.emplace_back();
    model.scenes[0].name = "crowd";
    model.scenes[0].extras = crowdExtras(cache);
    model.defaultScene = 0;

    const std::vector<int> meshOfType = addBodyMeshes(model, scene, cache, options);
    const int timeAccessor = addKeyTimes(model, cache);
    if (!addAgents(model, scene, cache, meshOfType, timeAccessor, progress))
        return cancelled(options.path);
    if (cancelledAt(progress, 0.8f))
        return cancelled(options.path);

    ExportResult result = endsWithGlb(options.path) ? writeGlb(model, options.path, progress)
                                                    : writeGltfAndBin(model, options.path, options.prettyJson, progress);
    if (result.ok() && progress)
        progress(1.0f);
    return result;
}

}  // namespace throng::exporting
