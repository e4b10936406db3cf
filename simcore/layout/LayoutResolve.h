#pragma once
// The layout layer's resolve (LayoutKind::Resolve) on one frame: nudges apart the bodies
// that the operations before it pushed into each other, moving only the agents it may move
// (those the edits changed on this frame), and keeps them a body's radius off the walls.
// A pair that overlapped in the recording too is left as the simulation had it. Frame by
// frame and deterministic: a frame's result depends on that frame alone, so the viewport's
// one frame and an export's every frame agree, and bodies drift apart as smoothly as they
// come together. Pure arithmetic over the frame; no scene, no recording kept.

#include "simcore/world/FrameCache.h"

#include <glm/vec2.hpp>

#include <array>
#include <cstdint>
#include <span>

namespace throng::sim {

struct ResolveFrame {
    std::span<AgentFrame> laid;            // the frame as the operations before left it; nudged in place
    std::span<const AgentFrame> recorded;  // the recording's frame: laid's first recorded.size() agents
    std::span<const float> radius;         // per laid agent, m
    std::span<const std::uint8_t> movable; // per laid agent: 1 = it may be nudged
    std::span<const std::array<glm::vec2, 2>> walls;  // segments, in the frame's coordinates
};

// Bodies closer than the sum of their radii less `toleranceM` / 2 are pushed apart (the
// check after the edits, LayoutCheck.h, allows `toleranceM`): both halfway when both may
// move, else the movable one all the way; a few rounds over the pairs (until no push is
// over 0.1 mm), then off the walls. Costs what the moving agents and the bodies near them
// cost, not the whole frame.
void resolveFrame(const ResolveFrame& frame, float toleranceM = 0.05f);

}  // namespace throng::sim
