#pragma once
// After layout edits (LayoutApply.h): what the edits broke that the simulation had kept —
// bodies of agents that now overlap, and agents that now step through a wall. Only what an
// edited agent takes part in and the recording did not already have is reported, frame by
// frame. Reads Scene and the two recordings; never simulates, never changes them.

#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <cstdint>
#include <string>
#include <vector>

namespace throng::sim {

struct LayoutClash {
    std::size_t frame = 0;
    AgentId agent = 0;   // an edited agent
    AgentId other = 0;   // the agent it overlaps; 0 for a wall
    std::string wall;    // the wall it steps through (its name, or "wall N")
    float depthM = 0.0f; // how far the bodies overlap, m (0 for a wall)
};

struct LayoutCheck {
    std::vector<LayoutClash> overlaps;       // by frame, then agent
    std::vector<LayoutClash> wallCrossings;  // by frame, then agent
    std::size_t frames = 0;                  // frames with any clash
};

// Bodies overlap when their centres are closer than the sum of their types' radii less
// `toleranceM` (the simulation's own packing presses bodies a little into each other). An
// agent is edited when any of its frames differs between `recorded` and `laid` (the same
// frames; `laid` holds the recording's agents first, then any copies, which count as edited). A
// pair overlapping on a frame of the recording too is not reported; nor a step through a wall the recording also took.
LayoutCheck checkLayout(const Scene& scene, const FrameCache& recorded, const FrameCache& laid,
                        float toleranceM = 0.05f);

// One clash over a run of consecutive frames: the same two agents overlapping, or the same
// agent stepping through the same wall, from `first` to `last`.
struct LayoutClashSpan {
    std::size_t first = 0, last = 0;
    AgentId agent = 0, other = 0;  // other: 0 for a wall
    std::string wall;
    float deepestM = 0.0f;         // the deepest overlap over the run (0 for a wall)
};
// The check's clashes as such runs, by first frame, then agent; at most `max` (the
// earliest).
std::vector<LayoutClashSpan> clashSpans(const LayoutCheck& check, std::size_t max = 1000);

// "3 overlaps and 1 wall crossing on 4 frames (first: frame 12, agents 4 and 7)"; empty when clean.
std::string describe(const LayoutCheck& check);

}  // namespace throng::sim
