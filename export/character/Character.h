#pragma once
// A rigged character as plain data: skeleton, one skinned mesh, and looping clips stored
// as joint poses sampled evenly over one cycle. Built by code or loaded from a file;
// never writes files and never knows which agent wears it.

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace throng::exporting {

struct Joint {
    std::string name;
    int parent = -1;                  // index of an earlier joint, -1 for the skeleton root (joint 0)
    glm::vec3 restTranslation{0.0f};  // local, m
    glm::quat restRotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 restScale{1.0f};
};

// What a part of the mesh is made of. The export gives each its own material: the type's
// tint on the top, a per-agent colour from a palette on skin, hair, bottom and shoes.
enum class MaterialSlot : std::uint8_t { Body, Skin, Top, Bottom, Hair, GreyHair, Shoes, Hat, Bag };
inline constexpr int kMaterialSlotCount = 9;
const char* toString(MaterialSlot slot);

// A run of CharacterMesh::indices drawn with one slot's material. Its vertices belong to
// it alone (a vertex on a sleeve's edge is written once for each side).
struct MeshPart {
    MaterialSlot slot = MaterialSlot::Body;
    std::uint32_t firstIndex = 0, indexCount = 0;
    float wornShare = 1.0f;  // < 1: an accessory that this share of agents wear (AgentVariation)
};

// How fine a built-in character's mesh is: near for close-ups and renders, mid for the
// middle distance and the viewport, far for the back of a crowd.
enum class Lod : std::uint8_t { Near, Mid, Far };
const char* toString(Lod lod);
bool lodFromName(std::string_view name, Lod& lod);

// Indexed triangles in bind space (the agent root's space: feet at y = 0, facing +X, up +Y).
struct CharacterMesh {
    std::vector<glm::vec3> positions;                 // m
    std::vector<glm::vec3> normals;                   // unit length
    std::vector<std::array<std::uint16_t, 4>> joints; // influence joints; unused slots are 0
    std::vector<glm::vec4> weights;                   // sum to 1 in float32; unused slots are 0
    std::vector<std::uint32_t> indices;               // counter-clockwise seen from outside
    std::vector<glm::mat4> inverseBindMatrices;       // one per joint
    std::vector<MeshPart> parts;                      // in index order; empty: one Body part of all
};

// The mesh's parts; a mesh without any gets one Body part over all its indices.
std::vector<MeshPart> partsOf(const CharacterMesh& mesh);
// Sorts a vertex's influences by weight, zeroes the joints of unused slots and makes the
// weights sum to exactly 1 in float32 (what the Khronos validator demands).
void normaliseInfluences(std::array<std::uint16_t, 4>& joints, glm::vec4& weights);

// One pose: every joint's local rotation (absolute, not relative to rest) and the local
// translation of joint 0 (the hips bob; other joints keep their rest translation).
struct Pose {
    std::vector<glm::quat> rotations;
    glm::vec3 rootTranslation{0.0f};
};

// A looping clip: `samples` poses evenly spaced over one cycle (sample k at phase k / n).
struct CycleClip {
    std::string name;
    float strideM = 1.0f;  // distance the character covers in one cycle at scale 1, m, > 0
    std::vector<Pose> samples;
};

// An action a brain picks (sim::Clip's names): a loop of poses over the action's cycle
// (sim::clipCycleS), played over a standing agent in full and, over walking or running,
// on the joints `layered` marks only (the upper body: a wave while walking).
struct ActionClip {
    CycleClip clip;                     // clip.name: the action's name, as sim::toString gives it
    std::vector<std::uint8_t> layered;  // per joint: 1 = played over locomotion too
    float blendS = 0.3f;                // s to blend in, and out again
    // Plays once from the frame it starts and holds its last sample (fall, get_up:
    // sim::isOneShot), in full over locomotion too, instead of looping.
    bool oneShot = false;
};

// A leg whose ankle IK can place (LegIk.h): hip, knee and ankle joints, each the child
// of the one before, and where the idle pose plants the ankle (the character's space).
struct Leg {
    int upper = -1, lower = -1, foot = -1;
    glm::vec3 plantedAnkle{0.0f};
};

struct Character {
    std::string name;
    std::vector<Joint> joints;  // joint 0 is the root of the skeleton
    CharacterMesh mesh;
    CycleClip idle, walk, run;  // idle is one pose held still; walk and run loop
    bool hasIdle = true;        // false: a stopped agent holds the moving clip (wheels, wings)
    // Speeds (m/s at scale 1) the gait blends between: idle below idleSpeed, all walk from
    // walkSpeed, walk turning into run between runStartSpeed and runSpeed.
    float idleSpeed = 0.05f, walkSpeed = 0.4f, runStartSpeed = 2.2f, runSpeed = 3.0f;
    // More gaits than walk and run (a horse's walk, trot, canter and gallop): the ladder
    // from the slowest to the fastest, each the whole gait at its speed in ladderSpeeds
    // (m/s at scale 1, rising) and blending into the next one up to that one's speed.
    // walk and run are then its first and last, for readers that blend those two only.
    // Empty: walk and run by walkSpeed, runStartSpeed and runSpeed.
    std::vector<CycleClip> ladder;
    std::vector<float> ladderSpeeds;
    // The share of the export's joint rotation tolerance (GltfOptions) this character's
    // keys keep to: a horse's long legs carry a rotation's error 1.3 m to the hoof.
    float keyToleranceScale = 1.0f;
    std::vector<ActionClip> actions;  // none: every action plays the locomotion its speed gives
    std::vector<Leg> legs;            // none: actions over a standing agent keep their own legs

    // The index in `actions` of the action of that name, or -1.
    int actionIndex(std::string_view name) const;
};

// The pose of `clip` at `phase` cycles (any real; wraps), interpolating neighbouring samples.
Pose sampleClip(const CycleClip& clip, double phase);
// Joint by joint: rotations nlerp'd in the shorter arc, root translations lerp'd; t in [0, 1].
Pose blendPoses(const Pose& a, const Pose& b, float t);
// As blendPoses, with t for the joints `layered` marks and `rest` for the others and the
// root translation.
Pose blendPosesLayered(const Pose& a, const Pose& b, const std::vector<std::uint8_t>& layered, float t, float rest);
// Each joint's transform in the character's space for `pose` (rest translation, pose rotation).
std::vector<glm::mat4> jointGlobalTransforms(const Character& character, const Pose& pose);
// The same into `out` (resized to the joint count) for only the joints `wanted` marks, which
// must mark each one's parent too (a leg's chain without the arms); the others are left.
void jointGlobalTransforms(const Character& character, const Pose& pose, const std::vector<std::uint8_t>& wanted,
                           std::vector<glm::mat4>& out);
// The rest pose: rest rotations and the rest translation of joint 0.
Pose restPose(const Character& character);
// Inverse bind matrices of the rest pose, in the character's space.
std::vector<glm::mat4> restInverseBindMatrices(const std::vector<Joint>& joints);
// Empty when the character is consistent; else what is wrong (joint order, weights, sizes).
std::string checkCharacter(const Character& character);

}  // namespace throng::exporting
