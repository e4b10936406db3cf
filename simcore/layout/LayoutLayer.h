#pragma once
// The layout layer (issue 29): edits made to a recorded crowd after the simulation, kept
// in the scene file as an ordered list of operations and applied to the recorded frames
// (LayoutApply.h) for everything that reads them, without simulating again. Plain data.

#include "simcore/scene/Clip.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace throng::sim {

enum class LayoutKind : std::uint8_t {
    Translate,   // move the agents' trajectories by an offset
    Rotate,      // turn them about a pivot (positions and headings)
    TimeOffset,  // start them later (or earlier): frame f shows what frame f - frames recorded
    Mirror,      // reflect them across a vertical plane through a line on the ground
    Delete,      // remove them from a frame on, or entirely
    Expand,      // scale their distances from their centre, frame by frame
    Duplicate,   // add a copy of each, moved by an offset, with an id of its own (and so a look of its own)
    Swap,        // show them with another look, tint or agent type (its character) for the whole shot
    ReplaceClip, // play another clip (an action, or idle, walk, run) over the frames
    Resolve,     // nudge the agents the operations before it moved apart where their bodies now overlap
};
inline constexpr int kLayoutKindCount = 10;
const char* toString(LayoutKind kind);
bool layoutKindFromName(std::string_view name, LayoutKind& kind);

// Which agents an operation edits: every agent any of the lists names (ids; the members
// of spawn groups or placed agents' groups by name; agents of types by name; agents
// inside a ground polygon on a frame of the recording). A resolve may name none: then
// every agent.
struct AgentSelector {
    std::vector<std::uint32_t> ids;
    std::vector<std::string> groups;
    std::vector<std::string> types;
    std::vector<glm::vec2> lasso;  // (x, z), the scene's coordinates; empty: none
    std::size_t lassoFrame = 0;    // the recorded frame the lasso was drawn on
    bool operator==(const AgentSelector&) const = default;
};

inline constexpr std::size_t kLastFrame = std::numeric_limits<std::size_t>::max();

struct LayoutOp {
    std::string name;  // optional, unique among the layer's operations
    LayoutKind kind = LayoutKind::Translate;
    bool enabled = true;
    AgentSelector agents;
    std::size_t firstFrame = 0, lastFrame = kLastFrame;  // the frames it edits, inclusive
    glm::vec2 offset{0.0f};                // translate, duplicate: (dx, dz), m
    float angleDeg = 0.0f;                 // rotate: counter-clockwise seen from above
    std::optional<glm::vec2> pivot;        // rotate: (x, z); none: the agents' centre on firstFrame
    int frames = 0;                        // time offset: frames later (negative: earlier)
    bool holdFirst = true;                 // time offset: before its new start, stand in its first pose (else absent)
    glm::vec2 axis[2]{{0.0f, -1.0f}, {0.0f, 1.0f}};  // mirror: two points of the line, (x, z)
    float factor = 1.0f;                   // expand: > 0
    int look = -1;                         // swap: index into the type's looks; -1 keeps the drawn one
    int tint = kKeepTint;                  // swap: index into the type's tints, -1 = untinted; kKeepTint keeps it
    std::string type;                      // swap: the agent type to show instead; empty keeps it
    Clip clip = Clip::Idle;                // replace clip: what plays instead
    static constexpr int kKeepTint = -2;
    bool operator==(const LayoutOp&) const = default;
};

struct LayoutLayer {
    std::vector<LayoutOp> ops;  // applied in order
    bool operator==(const LayoutLayer&) const = default;
};

}  // namespace throng::sim
