#pragma once
// One character's mesh skinned on the CPU into a few static poses (the idle pose, then
// walk and run poses evenly over their cycles), so the viewport draws a posed crowd as
// instanced static meshes. Plain data, no GL; never knows which agent wears which pose.

#include "export/character/Character.h"
#include "simcore/world/FrameCache.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace throng::editor {

struct PoseTable {
    static constexpr int kWalkPoses = 8;
    static constexpr int kRunPoses = 8;
    static constexpr int kActions = sim::kClipCount - int(sim::Clip::Wait);  // sim::Clip's actions, in order
    static constexpr int kActionPoses = 8;  // per action, standing, over its cycle
    // idle, walk 0..7, run 0..7, then per action its standing poses 0..7, then per action
    // its walking poses (walk sample 0..7 with the action's upper body at mid-cycle)
    static constexpr int kPoseCount = 1 + kWalkPoses + kRunPoses + kActions * (kActionPoses + kWalkPoses);

    std::size_t vertexCount = 0;               // vertices of one pose
    std::vector<glm::vec3> positions;          // pose-major: pose p's vertex v at p * vertexCount + v, m
    std::vector<glm::vec3> normals;            // unit length, same layout
    std::vector<std::uint32_t> indices;        // the mesh's triangles, into one pose's vertices
    std::vector<std::uint8_t> materialSlots;   // per vertex of a pose: its part's MaterialSlot
    std::size_t jointCount = 0;                // joints of the character
    std::vector<glm::mat4> joints;             // pose-major: pose p's joint j's transform at p * jointCount + j,
                                               // in the character's space (where the pose puts each joint)
    bool hasIdle = true;                       // false: a stopped agent holds the walk (wheels, wings)
    // A character with a gait ladder (a horse's walk, trot, canter, gallop): its rungs'
    // speeds (m/s); their poses follow every other pose (ladderPose). Empty: none.
    std::vector<float> ladderSpeeds;
    std::vector<std::uint8_t> hasAction;       // per action (kActions): the character plays it
    std::vector<std::uint8_t> oneShot;         // per action: played once and held (fall, get_up)
    // With a gait ladder, per action (kActions): its place among the looping actions the
    // character plays (-1: none), whose poses over each rung past the first follow the
    // rungs' (ladderActionPose).
    std::vector<std::int8_t> ladderActionSlot;
    int ladderActions = 0;                     // how many actions have a slot

    // The pose an agent shows for its recorded clip and gait phase (cycles; wraps). For an
    // action the character plays: its pose at actionPhase (sim::actionPhase) where the
    // agent stands, its walking pose at the gait phase where it moves; for a one-shot
    // (fall, get_up), actionPhase is its progress (sim::oneShotProgress) and it plays in
    // full, moving or not; for an action it lacks, the pose its speed gives. A horse past
    // its walk (a gait ladder's first rung) shows its rung with the action's upper body.
    // Moving, the walk or the run, or a gait ladder's rung (a horse's walk, trot, canter,
    // gallop), that runWeight (exporting::GaitFrame's, 0..1) is nearest; without it (< 0),
    // the recorded clip's walk or run, or the rung nearest the speed (m/s; < 0: unknown).
    int poseFor(sim::Clip clip, float phase, float actionPhase = 0.0f, bool moving = false, float speed = -1.0f,
                float runWeight = -1.0f) const;
    // Pose index of walk sample k (0..kWalkPoses-1) and run sample k.
    static int walkPose(int k) { return 1 + k; }
    static int runPose(int k) { return 1 + kWalkPoses + k; }
    // Pose index of action a's (0..kActions-1) standing sample k, and of its walking pose
    // over walk sample k.
    static int actionPose(int a, int k) { return 1 + kWalkPoses + kRunPoses + a * kActionPoses + k; }
    static int walkingActionPose(int a, int k)
    {
        return 1 + kWalkPoses + kRunPoses + kActions * kActionPoses + a * kWalkPoses + k;
    }
    // Pose index of rung r's sample k (0..kWalkPoses-1) of a gait ladder.
    static int ladderPose(int r, int k) { return kPoseCount + r * kWalkPoses + k; }
    // Pose index of rung r's (1..rungs-1) sample k with action a's (0..kActions-1, one with
    // a ladderActionSlot) upper body at mid-cycle; rung 0's is walkingActionPose(a, k).
    int ladderActionPose(int r, int a, int k) const
    {
        return ladderPose(int(ladderSpeeds.size()), 0) +
               ((r - 1) * ladderActions + ladderActionSlot[std::size_t(a)]) * kWalkPoses + k;
    }
    // How many poses the table holds: kPoseCount, kWalkPoses per rung of a ladder, and as
    // many per looping action and rung past the first.
    int poseCount() const
    {
        const int rungs = int(ladderSpeeds.size());
        return kPoseCount + rungs * kWalkPoses + std::max(0, rungs - 1) * ladderActions * kWalkPoses;
    }
    // The rung of a gait ladder a moving agent shows: the nearest to runWeight's place along
    // it, or without one (< 0) to the speed (m/s); -1 without a ladder or either.
    int rungFor(float speed, float runWeight) const;
};

// Linear blend skinning of `character`'s mesh in `pose`, in the character's space.
void skinMesh(const exporting::Character& character, const exporting::Pose& pose, std::vector<glm::vec3>& positions,
              std::vector<glm::vec3>& normals);
// The idle pose, then walk pose k = sampleClip(walk, k / kWalkPoses), then run likewise,
// then the actions (gaitPose with the action in full; a character without it repeats idle;
// a one-shot's poses run from its start, k / (kActionPoses - 1) of the way, to its end),
// then a gait ladder's rungs, then its rungs past the first with each looping action.
PoseTable buildPoseTable(const exporting::Character& character);

}  // namespace throng::editor
