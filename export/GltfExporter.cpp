#include "export/GltfExporter.h"

#include "export/character/CharacterLibrary.h"
#include "export/character/Gait.h"
#include "export/detail/AgentBake.h"
#include "export/detail/AgentRig.h"
#include "export/detail/AnimationChannels.h"
#include "export/detail/CharacterAssets.h"
#include "export/detail/CompactBake.h"
#include "export/detail/CrowdSetup.h"
#include "export/detail/ExactBake.h"
#include "export/detail/GltfBuilder.h"
#include "export/detail/SetNodes.h"
#include "export/detail/GltfFiles.h"
#include "export/detail/KeyReduction.h"
#include "simcore/base/ThreadTeam.h"

#include <tiny_gltf.h>

#include <glm/common.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <map>
#include <system_error>

namespace throng::exporting {

namespace {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian");

constexpr float kDegToRad = 3.14159265358979f / 180.0f;

using detail::AgentWork;

tinygltf::Value runExtras(const sim::FrameCache& cache, const GltfOptions& options, std::uint64_t seed)
{
    tinygltf::Value::Object extras;
    extras["generator"] = tinygltf::Value(std::string("Throng"));
    extras["fps"] = tinygltf::Value(static_cast<double>(cache.fps()));
    extras["frameCount"] = tinygltf::Value(static_cast<int>(cache.frameCount()));
    extras["agentCount"] = tinygltf::Value(static_cast<int>(cache.agentCount()));
    extras["mode"] = tinygltf::Value(std::string(options.mode == GltfMode::Exact ? "exact" : "compact"));
    extras["seed"] = tinygltf::Value(std::to_string(seed));
    extras["jointFrameStep"] = tinygltf::Value(options.jointFrameStep);
    extras["set"] = tinygltf::Value(options.includeSet);
    return tinygltf::Value(std::move(extras));
}

tinygltf::Value agentExtras(const sim::AgentInfo& info, const std::string& type, const Character& look,
                            const AgentVariation& v, std::uint64_t seed)
{
    tinygltf::Value::Object extras;
    extras["agentId"] = tinygltf::Value(static_cast<int>(info.id));
    extras["type"] = tinygltf::Value(type);
    extras["character"] = tinygltf::Value(look.name);
    extras["tint"] = tinygltf::Value(v.tint);
    auto r4 = [](float x) { return tinygltf::Value(std::round(static_cast<double>(x) * 1e4) / 1e4); };
    extras["heightScale"] = r4(v.heightScale);  // the node's scale carries the exact value
    extras["speedFactor"] = r4(v.speedFactor);
    extras["phaseOffset"] = r4(v.phaseOffset);
    tinygltf::Value::Array worn;
    for (const MeshPart& part : look.mesh.parts)
        if (part.slot >= MaterialSlot::Hat && wearsPart(part, seed, info.id))
            worn.emplace_back(std::string(toString(part.slot)));
    if (!worn.empty())
        extras["wears"] = tinygltf::Value(std::move(worn));
    return tinygltf::Value(std::move(extras));
}

detail::Clock makeClock(detail::GltfBuilder& b, std::vector<float> times)
{
    detail::Clock clock;
    clock.times = std::move(times);
    clock.accessor = b.addTimes(clock.times);
    return clock;
}

// One material per (type, tint) that some agent wears.
int materialFor(tinygltf::Model& model, std::map<std::pair<std::size_t, int>, int>& made, const sim::AgentType& type,
                std::size_t typeIndex, int tint)
{
    const auto key = std::make_pair(typeIndex, tint);
    if (auto it = made.find(key); it != made.end())
        return it->second;
    tinygltf::Material material;
    material.name = type.name + (tint >= 0 ? "_tint" + std::to_string(tint) : std::string());
    if (tint >= 0) {
        const glm::vec3 rgb = glm::clamp(type.variation.tints[static_cast<std::size_t>(tint)], 0.0f, 1.0f);
        material.pbrMetallicRoughness.baseColorFactor = {rgb.r, rgb.g, rgb.b, 1.0};
    } else {
        const glm::dvec3 rgb = untintedColour(typeIndex);
        material.pbrMetallicRoughness.baseColorFactor = {rgb.r, rgb.g, rgb.b, 1.0};
    }
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = 0.8;
    model.materials.push_back(std::move(material));
    return made[key] = static_cast<int>(model.materials.size()) - 1;
}

// One material per (slot, palette colour) that some agent's part wears.
int slotMaterial(tinygltf::Model& model, std::map<std::pair<int, int>, int>& made, MaterialSlot slot, int colour)
{
    const auto key = std::make_pair(static_cast<int>(slot), colour);
    if (auto it = made.find(key); it != made.end())
        return it->second;
    const glm::vec3 rgb = slotPalette(slot)[static_cast<std::size_t>(colour)];
    tinygltf::Material material;
    material.name = std::string(toString(slot)) + "_" + std::to_string(colour);
    material.pbrMetallicRoughness.baseColorFactor = {rgb.r, rgb.g, rgb.b, 1.0};
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = slot == MaterialSlot::Skin ? 0.55 : 0.8;
    model.materials.push_back(std::move(material));
    return made[key] = static_cast<int>(model.materials.size()) - 1;
}

// A far scene's frames are relative to its origin (sim::FrameCache::origin): one node at
// the origin (glTF's numbers are doubles) carries every agent's root, so the file is in
// the scene's coordinates without rounding each key to the floats of 1e6 m. Skinned
// bodies stay where they are: their nodes' transforms do not move them.
void moveRootsToOrigin(tinygltf::Model& model, glm::dvec3 origin)
{
    if (origin == glm::dvec3(0.0))
        return;
    tinygltf::Node node;
    node.name = "scene_origin";
    node.translation = {origin.x, origin.y, origin.z};
    std::vector<int> kept;
    for (int n : model.scenes[0].nodes)
        (model.nodes[static_cast<std::size_t>(n)].mesh < 0 ? node.children : kept).push_back(n);
    kept.insert(kept.begin(), static_cast<int>(model.nodes.size()));
    model.nodes.push_back(std::move(node));
    model.scenes[0].nodes = std::move(kept);
}

}  // namespace

ExportResult exportGltf(const sim::Scene& scene, const sim::FrameCache& cache, const GltfOptions& options,
                        const ProgressFn& progress, GltfExportStats* stats)
{
    detail::CrowdStart start;
    if (std::optional<ExportResult> ended = detail::startCrowd(
            detail::checkCrowdInput(scene, cache, options.path, {}, options.jointFrameStep,
                                    {options.positionToleranceM, options.rotationToleranceDeg,
                                     options.rootRotationToleranceDeg}),
            scene, cache, options, progress, start))
        return *ended;
    const CharacterLibrary& library = start.library;
    const std::uint64_t seed = start.seed;
    const std::size_t frames = cache.frameCount(), agents = cache.agentCount();
    const float fps = cache.fps();
    // One frame leaves nothing to window: the exact bake serves it.
    const bool compact = options.mode == GltfMode::Compact && frames >= 2;

    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "Throng";
    model.asset.extras = runExtras(cache, options, seed);
    model.scenes.emplace_back();
    model.scenes[0].name = "crowd";
    model.scenes[0].extras = model.asset.extras;
    model.defaultScene = 0;
    detail::GltfBuilder builder(model);

    std::map<std::size_t, detail::CharacterAccessors> assets;
    std::map<std::pair<std::size_t, int>, int> materials;
    std::map<std::pair<int, int>, int> slotMaterials;

    builder.beginAnimationData();
    builder.setUse(detail::GltfBuilder::Use::Clocks);
    const std::vector<float>& allTimes = start.times;
    const detail::Clock frameClock = makeClock(builder, allTimes);
    const detail::Clock pairClock =
        frames >= 2 ? makeClock(builder, {0.0f, allTimes.back()}) : frameClock;
    detail::JointClock& jointClock = start.jointClock;
    jointClock.clock = jointClock.frames.size() == frames ? frameClock
                                                          : makeClock(builder, std::move(jointClock.clock.times));

    model.animations.emplace_back();
    model.animations[0].name = "crowd";
    // tinygltf's types copy when a vector grows: size the big vectors once.
    std::size_t maxJoints = 0;
    for (std::size_t c = 0; c < library.characterCount(); ++c)
        maxJoints = std::max(maxJoints, library.character(c).joints.size());
    model.nodes.reserve(agents * (maxJoints + 2));
    // The buffer's bound without key reduction: untouched capacity costs no memory, and
    // the buffer never moves hundreds of megabytes to grow.
    model.buffers[0].data.reserve(model.buffers[0].data.size() + (1u << 20) + agents * frames * (32 + 8 * maxJoints));
    model.meshes.reserve(agents);
    model.skins.reserve(agents);
    model.accessors.reserve(agents * (maxJoints + 6) + 64);
    model.scenes[0].nodes.reserve(2 * agents);
    model.animations[0].samplers.reserve(agents * (maxJoints + 3));
    model.animations[0].channels.reserve(agents * (maxJoints + 3));
    detail::AnimationChannels channels(builder, model.animations[0], pairClock);
    detail::CompactCycles cycles(builder, library);

    const detail::AgentBaker baker(scene, cache, library, seed, allTimes, jointClock,
                                   {.compact = compact,
                                    .positionToleranceM = options.positionToleranceM,
                                    .rotationToleranceRad = options.rotationToleranceDeg * kDegToRad,
                                    .rootRotationToleranceRad = options.rootRotationToleranceDeg * kDegToRad});
    const sim::ThreadTeam team(options.threads);

    std::vector<detail::CompactPlan> plans;
    if (compact) {
        plans.reserve(agents);
        builder.setUse(detail::GltfBuilder::Use::Joints);
        if (!detail::bakeInOrder(baker, agents, false, team, progress, 0.0f, 0.2f,
                                 [&](std::size_t, const AgentWork& w) {
                                     plans.push_back(cycles.plan(w.character, w.positions, w.gait, w.variation, fps));
                                 }))
            return detail::cancelledExport(options.path);
        cycles.writeBanks();
    }

    // Each agent's rig, materials, root motion and joints, in agent order.
    auto writeAgent = [&](std::size_t i, const AgentWork& w) {
        const sim::AgentInfo& info = cache.agents()[i];
        const sim::AgentType& type = scene.agentTypes[info.typeIndex];
        const Character& character = library.character(w.character);
        if (!assets.count(w.character)) {
            builder.setUse(detail::GltfBuilder::Use::Geometry);
            assets[w.character] = detail::writeCharacterAssets(builder, character);
        }
        detail::AgentRigSpec spec;
        spec.name = "agent_" + std::to_string(info.id) + "_" + type.name;
        for (const MeshPart& part : partsOf(character.mesh)) {
            const auto colour = static_cast<int>(w.variation.colour[static_cast<std::size_t>(part.slot)]);
            if (!wearsPart(part, seed, info.id))
                spec.partMaterials.push_back(-1);
            else if (slotPalette(part.slot).empty())  // the top and a whole body wear the tint
                spec.partMaterials.push_back(materialFor(model, materials, type, info.typeIndex, w.variation.tint));
            else
                spec.partMaterials.push_back(slotMaterial(model, slotMaterials, part.slot, colour));
        }
        spec.heightScale = w.variation.heightScale;
        spec.translation = w.positions[0];
        spec.rotation = w.yaw[0];
        spec.extras = agentExtras(info, type.name, character, w.variation, seed);
        const detail::AgentRig rig = detail::addAgentRig(model, character, assets[w.character], spec, w.firstPose);

        channels.nextAgent();
        builder.setUse(detail::GltfBuilder::Use::RootMotion);
        channels.vec3Channel(rig.root, "translation", frameClock, w.positions, w.positionKept);
        channels.rotationChannel(rig.root, w.yaw, frameClock, w.yawKept);
        if (std::find(w.hidden.begin(), w.hidden.end(), 1) != w.hidden.end()) {
            // Gone through an exit or not present: the whole character scales to
            // nothing on those frames (STEP, so it never shrinks visibly on the way).
            const glm::vec3 shown(w.variation.heightScale);
            std::vector<float> times;
            std::vector<glm::vec3> scales;
            for (std::size_t f = 0; f < frames; ++f) {
                if (f > 0 && w.hidden[f] == w.hidden[f - 1])
                    continue;
                times.push_back(frameClock.times[f]);
                scales.push_back(w.hidden[f] ? glm::vec3(0.0f) : shown);
            }
            channels.addSampler(rig.root, "scale", builder.addTimes(times), builder.addVec3Keys(scales), "STEP");
        }
        builder.setUse(detail::GltfBuilder::Use::Joints);
        if (compact)
            cycles.bakeAgent(channels, plans[i], rig, pairClock.accessor);
        else
            detail::writeJoints(channels, jointClock, w.joints, rig);
    };
    if (!detail::bakeInOrder(baker, agents, true, team, progress, compact ? 0.2f : 0.0f, 0.8f, writeAgent))
        return detail::cancelledExport(options.path);
    if (options.includeSet) {
        builder.setUse(detail::GltfBuilder::Use::Geometry);
        detail::addSetNodes(builder, channels, scene, glm::dvec2(cache.origin().x, cache.origin().z), frameClock, fps,
                            options.firstFrame);
    }
    builder.endAnimationData();
    moveRootsToOrigin(model, cache.origin());
    if (detail::cancelledAt(progress, 0.8f))
        return detail::cancelledExport(options.path);

    if (stats) {
        *stats = {};
        stats->geometryBytes = builder.bytesFor(detail::GltfBuilder::Use::Geometry);
        stats->clockBytes = builder.bytesFor(detail::GltfBuilder::Use::Clocks);
        stats->rootMotionBytes = builder.bytesFor(detail::GltfBuilder::Use::RootMotion);
        stats->jointBytes = builder.bytesFor(detail::GltfBuilder::Use::Joints);
        for (const tinygltf::AnimationSampler& s : model.animations[0].samplers)
            stats->animationKeys += model.accessors[s.output].count;
    }
    ExportResult result = detail::writeModel(model, options.path, options.prettyJson, progress);
    if (result.ok() && stats)
        for (const std::string& p : result.writtenPaths) {
            std::error_code ec;
            const std::uintmax_t size = std::filesystem::file_size(p, ec);
            stats->fileBytes += ec ? 0 : static_cast<std::size_t>(size);
        }
    if (result.ok() && progress)
        progress(1.0f);
    return result;
}

}  // namespace throng::exporting
