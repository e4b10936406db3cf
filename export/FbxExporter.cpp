#include "export/FbxExporter.h"

#include "export/character/AgentVariation.h"
#include "export/character/CharacterLibrary.h"
#include "export/detail/AgentBake.h"
#include "export/detail/AssimpScene.h"
#include "export/detail/AssimpSet.h"
#include "export/detail/CrowdSetup.h"
#include "export/detail/ExportCancel.h"
#include "export/detail/FbxFraming.h"
#include "export/detail/StagingDirectory.h"
#include "simcore/base/ThreadTeam.h"

#include <assimp/Exporter.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

namespace throng::exporting {

namespace {

using detail::AssimpScene;
using detail::toAssimp;

glm::mat4 trs(glm::vec3 t, glm::quat r, glm::vec3 s)
{
    return glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
}

// One agent's nodes, meshes and channels.
class FbxAgents {
public:
    FbxAgents(AssimpScene& out, aiNode* crowd, const sim::Scene& scene, const sim::FrameCache& cache,
              const CharacterLibrary& library, std::uint64_t seed, const detail::JointClock& jointClock)
        : m_out(out), m_crowd(crowd), m_scene(scene), m_cache(cache), m_library(library), m_seed(seed),
          m_jointClock(jointClock)
    {
    }

    void add(std::size_t i, const detail::AgentWork& w);

private:
    unsigned materialOf(const MeshPart& part, const AgentVariation& v, std::size_t typeIndex);

    AssimpScene& m_out;
    aiNode* m_crowd;
    const sim::Scene& m_scene;
    const sim::FrameCache& m_cache;
    const CharacterLibrary& m_library;
    std::uint64_t m_seed;
    const detail::JointClock& m_jointClock;
};

unsigned FbxAgents::materialOf(const MeshPart& part, const AgentVariation& v, std::size_t typeIndex)
{
    if (!slotPalette(part.slot).empty()) {
        const std::size_t colour = v.colour[static_cast<std::size_t>(part.slot)];
        return m_out.material(std::string(toString(part.slot)) + "_" + std::to_string(colour),
                              slotPalette(part.slot)[colour]);
    }
    const sim::AgentType& type = m_scene.agentTypes[typeIndex];
    if (v.tint < 0)
        return m_out.material(type.name + "_colour", glm::vec3(untintedColour(typeIndex)));
    return m_out.material(type.name + "_tint" + std::to_string(v.tint),
                          glm::clamp(type.variation.tints[static_cast<std::size_t>(v.tint)], 0.0f, 1.0f));
}

void FbxAgents::add(std::size_t i, const detail::AgentWork& w)
{
    const sim::AgentInfo& info = m_cache.agents()[i];
    const sim::AgentType& type = m_scene.agentTypes[info.typeIndex];
    const Character& c = m_library.character(w.character);
    const std::string name = "agent_" + std::to_string(info.id) + "_" + type.name;
    const float fps = m_cache.fps();
    const std::size_t frames = m_cache.frameCount();
    const glm::vec3 height(w.variation.heightScale);

    aiNode* root = m_out.addNode(m_crowd, name, toAssimp(trs(w.positions[0], w.yaw[0], height)));
    AssimpScene::Channel motion;
    for (const std::uint32_t f : w.positionKept)
        motion.translation.emplace_back(double(f) / double(fps), w.positions[f]);
    for (std::size_t f = 0; f < frames; ++f)
        motion.rotation.emplace_back(double(f) / double(fps), w.yaw[f]);
    motion.scale = detail::stepKeys(std::vector<std::uint8_t>(w.hidden.begin(), w.hidden.end()), fps, height,
                                    height * detail::kHiddenScale);
    m_out.addChannel(name, std::move(motion));

    // The joints: the first pose, then every joint frame's rotation (and the hips' place).
    const detail::BakedJoints& b = w.joints;
    const std::size_t keys = m_jointClock.frames.size();
    std::vector<aiNode*> joints;
    std::vector<std::pair<std::string, glm::mat4>> bones;
    for (std::size_t j = 0; j < c.joints.size(); ++j) {
        const Joint& joint = c.joints[j];
        const std::string jointName = name + "__" + joint.name;
        const glm::vec3 t = j == 0 ? w.firstPose.rootTranslation : joint.restTranslation;
        aiNode* parent = joint.parent >= 0 ? joints[static_cast<std::size_t>(joint.parent)] : root;
        joints.push_back(m_out.addNode(parent, jointName, toAssimp(trs(t, w.firstPose.rotations[j], joint.restScale))));
        bones.emplace_back(jointName, j < c.mesh.inverseBindMatrices.size() ? c.mesh.inverseBindMatrices[j]
                                                                            : glm::mat4(1.0f));
        AssimpScene::Channel channel;
        for (std::size_t k = 0; k < keys; ++k) {
            const double time = double(m_jointClock.frames[k]) / double(fps);
            channel.rotation.emplace_back(time, b.rotations[j * keys + k]);
            if (j == 0)
                channel.translation.emplace_back(time, b.rootTranslation[k]);
        }
        if (j != 0)
            channel.translation = {{0.0, joint.restTranslation}};
        channel.scale = {{0.0, joint.restScale}};
        m_out.addChannel(jointName, std::move(channel));
    }

    // The body: a skinned mesh per part it wears, each with its own vertices.
    aiNode* body = m_out.addNode(root, name + "_body");
    std::vector<unsigned> meshes;
    const std::vector<MeshPart> parts = partsOf(c.mesh);
    for (const MeshPart& part : parts) {
        if (!wearsPart(part, m_seed, info.id))
            continue;
        std::map<std::uint32_t, unsigned> local;
        std::vector<detail::SkinnedVertex> vertices;
        std::vector<unsigned> indices;
        for (std::uint32_t k = part.firstIndex; k < part.firstIndex + part.indexCount; ++k) {
            const std::uint32_t v = c.mesh.indices[k];
            const auto [it, added] = local.emplace(v, static_cast<unsigned>(vertices.size()));
            if (added) {
                detail::SkinnedVertex s;
                s.position = c.mesh.positions[v];
                s.normal = c.mesh.normals[v];
                for (int n = 0; n < 4; ++n) {
                    s.joints[n] = c.mesh.joints[v][static_cast<std::size_t>(n)];
                    s.weights[n] = c.mesh.weights[v][n];
                }
                vertices.push_back(s);
            }
            indices.push_back(it->second);
        }
        meshes.push_back(m_out.addMesh(name + "_" + toString(part.slot), vertices, indices,
                                       materialOf(part, w.variation, info.typeIndex), bones));
    }
    m_out.setMeshes(body, meshes);
}

}  // namespace

ExportResult exportFbx(const sim::Scene& scene, const sim::FrameCache& cache, const FbxOptions& options,
                       const ProgressFn& progress)
{
    detail::CrowdStart start;
    if (std::optional<ExportResult> ended = detail::startCrowd(
            detail::checkCrowdInput(scene, cache, options.path, {".fbx"}, options.jointFrameStep,
                                    {options.positionToleranceM}),
            scene, cache, options, progress, start))
        return *ended;
    ExportResult result;
    const std::size_t frames = cache.frameCount(), agents = cache.agentCount();
    // Rotations are keyed on every joint frame (Euler angles do not interpolate): the
    // tolerances only decide what the baker keeps, which this writer does not read.
    const detail::AgentBaker baker(scene, cache, start.library, start.seed, start.times, start.jointClock,
                                   {.compact = false, .positionToleranceM = options.positionToleranceM});

    AssimpScene out;
    const glm::dvec3 origin = cache.origin();
    aiNode* crowd = out.addNode(nullptr, "Crowd", toAssimp(glm::translate(glm::mat4(1.0f), glm::vec3(origin))));
    FbxAgents writer(out, crowd, scene, cache, start.library, start.seed, start.jointClock);
    if (!detail::bakeInOrder(baker, agents, true, sim::ThreadTeam(options.threads), progress, 0.0f, 0.6f,
                             [&](std::size_t i, const detail::AgentWork& w) { writer.add(i, w); }))
        return detail::cancelledExport(options.path);
    if (options.includeSet)
        detail::addAssimpSet(out, crowd, scene, glm::dvec2(origin.x, origin.z), frames, cache.fps(),
                             options.firstFrame);
    std::unique_ptr<aiScene> assimpScene = out.release(double(frames - 1) / double(cache.fps()));
    if (detail::cancelledAt(progress, 0.6f))
        return detail::cancelledExport(options.path);

    detail::StagingDirectory staging(options.path);
    if (!staging.create()) {
        result.error = staging.error();
        return result;
    }
    // Into memory, not through assimp's file stream: that writes each value with a seek
    // and a write of its own, which took over half the export's time.
    Assimp::Exporter exporter;
    const aiExportDataBlob* blob = exporter.ExportToBlob(assimpScene.get(), "fbx");
    if (blob == nullptr) {
        result.error = "cannot export '" + options.path + "': assimp: " + exporter.GetErrorString();
        return result;
    }
    assimpScene.reset();  // the file's size again, no longer needed
    // assimp's binary writer leaves out the null records every reader needs: put them in.
    std::string error;
    const std::vector<unsigned char> mended =
        detail::mendFbxFraming({static_cast<unsigned char*>(blob->data), blob->size},
                               {.fps = cache.fps(), .durationS = double(frames - 1) / double(cache.fps())}, error);
    exporter.FreeBlob();
    if (mended.empty()) {
        result.error = "cannot export '" + options.path + "': assimp wrote " + error;
        return result;
    }
    {
        std::ofstream file(staging.filePath("crowd.fbx"), std::ios::binary | std::ios::trunc);
        file.write(reinterpret_cast<const char*>(mended.data()), static_cast<std::streamsize>(mended.size()));
        if (!file.flush()) {
            result.error = "cannot write '" + options.path + "': " + std::strerror(errno);
            return result;
        }
    }
    if (detail::cancelledAt(progress, 0.95f))
        return detail::cancelledExport(options.path);
    if (!staging.syncToDisk() || !staging.publish("crowd.fbx", options.path)) {
        result.error = staging.error();
        return result;
    }
    result.writtenPaths.push_back(options.path);
    if (progress)
        progress(1.0f);
    return result;
}

}  // namespace throng::exporting
