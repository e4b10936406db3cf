#include "editor/viewport/PoseTable.h"

#include "export/character/Gait.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {

int sampleOf(float phase, int samples)
{
    const float wrapped = phase - std::floor(phase);
    return int(std::lround(double(wrapped) * samples)) % samples;
}

}  // namespace

int PoseTable::rungFor(float speed, float runWeight) const
{
    if (ladderSpeeds.empty())
        return -1;
    if (runWeight >= 0.0f)
        return int(std::lround(std::min(runWeight, 1.0f) * float(ladderSpeeds.size() - 1)));
    if (speed < 0.0f)
        return -1;
    // The rung nearest the speed: past the middle between two rungs' speeds, the upper.
    int rung = 0;
    for (std::size_t r = 1; r < ladderSpeeds.size(); ++r)
        if (speed >= 0.5f * (ladderSpeeds[r - 1] + ladderSpeeds[r]))
            rung = int(r);
    return rung;
}

int PoseTable::poseFor(sim::Clip clip, float phase, float actionPhase, bool moving, float speed, float runWeight) const
{
    if (sim::isAction(clip)) {
        const int a = int(clip) - int(sim::Clip::Wait);
        const bool plays = a < kActions && std::size_t(a) < hasAction.size() && hasAction[std::size_t(a)];
        if (plays && oneShot[std::size_t(a)]) {
            const float progress = std::clamp(actionPhase, 0.0f, 1.0f);
            return actionPose(a, int(std::lround(double(progress) * (kActionPoses - 1))));
        }
        if (plays && !moving)
            return actionPose(a, sampleOf(actionPhase, kActionPoses));
        if (plays) {
            // A horse past its walk: its rung, with the rider's action over it.
            const int rung = rungFor(speed, runWeight);
            if (rung > 0 && std::size_t(a) < ladderActionSlot.size() && ladderActionSlot[std::size_t(a)] >= 0)
                return ladderActionPose(rung, a, sampleOf(phase, kWalkPoses));
            return walkingActionPose(a, sampleOf(phase, kWalkPoses));
        }
        clip = moving ? sim::Clip::Walk : sim::Clip::Idle;
    }
    const bool walks = clip == sim::Clip::Walk || clip == sim::Clip::Run || !hasIdle;
    const int rung = walks ? rungFor(speed, runWeight) : -1;
    if (rung >= 0)
        return ladderPose(rung, sampleOf(phase, kWalkPoses));
    if (walks && runWeight >= 0.0f && hasIdle)
        clip = runWeight >= 0.5f ? sim::Clip::Run : sim::Clip::Walk;
    if (clip == sim::Clip::Run)
        return runPose(sampleOf(phase, kRunPoses));
    if (clip == sim::Clip::Walk || !hasIdle)
        return walkPose(sampleOf(phase, kWalkPoses));
    return 0;
}

void skinMesh(const exporting::Character& character, const exporting::Pose& pose, std::vector<glm::vec3>& positions,
              std::vector<glm::vec3>& normals)
{
    const exporting::CharacterMesh& mesh = character.mesh;
    const std::vector<glm::mat4> globals = exporting::jointGlobalTransforms(character, pose);
    std::vector<glm::mat4> skin(globals.size());
    for (std::size_t j = 0; j < globals.size(); ++j)
        skin[j] = globals[j] * mesh.inverseBindMatrices[j];
    positions.resize(mesh.positions.size());
    normals.resize(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        glm::mat4 m(0.0f);
        for (int k = 0; k < 4; ++k)
            if (mesh.weights[v][k] > 0.0f)
                m += mesh.weights[v][k] * skin[mesh.joints[v][std::size_t(k)]];
        positions[v] = glm::vec3(m * glm::vec4(mesh.positions[v], 1.0f));
        // Joints carry rotation and uniform scale only: the upper 3 x 3 turns normals too.
        const glm::vec3 n = glm::mat3(m) * mesh.normals[v];
        const float length = glm::length(n);
        normals[v] = length > 0.0f ? n / length : mesh.normals[v];
    }
}

PoseTable buildPoseTable(const exporting::Character& character)
{
    PoseTable table;
    table.vertexCount = character.mesh.positions.size();
    table.indices = character.mesh.indices;
    table.materialSlots.assign(table.vertexCount, 0);
    for (const exporting::MeshPart& part : exporting::partsOf(character.mesh))
        for (std::uint32_t i = part.firstIndex; i < part.firstIndex + part.indexCount; ++i)
            table.materialSlots[character.mesh.indices[i]] = std::uint8_t(part.slot);
    table.hasIdle = character.hasIdle;
    table.positions.reserve(table.vertexCount * PoseTable::kPoseCount);
    table.normals.reserve(table.vertexCount * PoseTable::kPoseCount);
    table.jointCount = character.joints.size();
    table.joints.reserve(table.jointCount * PoseTable::kPoseCount);
    std::vector<glm::vec3> p, n;
    auto add = [&](const exporting::Pose& pose) {
        const std::vector<glm::mat4> globals = exporting::jointGlobalTransforms(character, pose);
        table.joints.insert(table.joints.end(), globals.begin(), globals.end());
        skinMesh(character, pose, p, n);
        table.positions.insert(table.positions.end(), p.begin(), p.end());
        table.normals.insert(table.normals.end(), n.begin(), n.end());
    };
    add(exporting::sampleClip(character.idle, 0.0));
    for (int k = 0; k < PoseTable::kWalkPoses; ++k)
        add(exporting::sampleClip(character.walk, double(k) / PoseTable::kWalkPoses));
    for (int k = 0; k < PoseTable::kRunPoses; ++k)
        add(exporting::sampleClip(character.run, double(k) / PoseTable::kRunPoses));
    // The actions as the export poses them (gaitPose): standing, the action in full;
    // walking, the walk with the action's upper body at mid-cycle.
    std::vector<int> actionOf(PoseTable::kActions, -1);
    for (int a = 0; a < PoseTable::kActions; ++a) {
        actionOf[std::size_t(a)] = character.actionIndex(sim::toString(sim::Clip(int(sim::Clip::Wait) + a)));
        table.hasAction.push_back(actionOf[std::size_t(a)] >= 0 ? 1 : 0);
        table.oneShot.push_back(
            actionOf[std::size_t(a)] >= 0 && character.actions[std::size_t(actionOf[std::size_t(a)])].oneShot ? 1 : 0);
    }
    const exporting::Pose idle = exporting::sampleClip(character.idle, 0.0);
    for (int a = 0; a < PoseTable::kActions; ++a)
        for (int k = 0; k < PoseTable::kActionPoses; ++k) {
            exporting::GaitFrame g;
            g.moveWeight = 0.0f;
            double phase = double(k) / PoseTable::kActionPoses;
            if (table.oneShot[std::size_t(a)]) {  // from the first sample to the held last
                const auto& samples = character.actions[std::size_t(actionOf[std::size_t(a)])].clip.samples;
                phase = double(k) / (PoseTable::kActionPoses - 1) * double(samples.size() - 1) / double(samples.size());
            }
            g.action = {actionOf[std::size_t(a)], phase, 1.0f};
            add(g.action.action >= 0 ? exporting::gaitPose(character, g) : idle);
        }
    for (int a = 0; a < PoseTable::kActions; ++a)
        for (int k = 0; k < PoseTable::kWalkPoses; ++k) {
            exporting::GaitFrame g;
            g.phase = double(k) / PoseTable::kWalkPoses;
            g.action = {actionOf[std::size_t(a)], 0.5, 1.0f};
            add(exporting::gaitPose(character, g));
        }
    table.ladderSpeeds = character.ladderSpeeds;
    for (const exporting::CycleClip& rung : character.ladder)
        for (int k = 0; k < PoseTable::kWalkPoses; ++k)
            add(exporting::sampleClip(rung, double(k) / PoseTable::kWalkPoses));
    // Each rung past the first with each looping action over it, as gaitPose layers it.
    table.ladderActionSlot.assign(PoseTable::kActions, -1);
    if (character.ladder.empty())
        return table;
    for (int a = 0; a < PoseTable::kActions; ++a)
        if (table.hasAction[std::size_t(a)] && !table.oneShot[std::size_t(a)])
            table.ladderActionSlot[std::size_t(a)] = std::int8_t(table.ladderActions++);
    const std::size_t rungs = character.ladder.size();
    for (std::size_t r = 1; r < rungs; ++r)
        for (int a = 0; a < PoseTable::kActions; ++a) {
            if (table.ladderActionSlot[std::size_t(a)] < 0)
                continue;
            for (int k = 0; k < PoseTable::kWalkPoses; ++k) {
                exporting::GaitFrame g;
                g.phase = double(k) / PoseTable::kWalkPoses;
                g.runWeight = float(r) / float(rungs - 1);
                g.action = {actionOf[std::size_t(a)], 0.5, 1.0f};
                add(exporting::gaitPose(character, g));
            }
        }
    return table;
}

}  // namespace throng::editor
