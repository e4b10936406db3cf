#pragma once
// The collide phase: bodies still overlapping after steering move apart, each by its
// share of the overlap (DetourCrowd's collision handling, done Jacobi-style: every agent
// reads the others' proposed positions and moves only itself); moves are capped at the
// agent's max speed and its brain's hold, and walls stay hard. Then, on each decision,
// the contact rounds part the ground bodies that still press into each other. Free
// functions over the StepView, like Constraints.h: the phase keeps no state of its own
// (Collide.cpp).

#include "simcore/world/AgentColumns.h"

#include <cstdint>
#include <span>

namespace throng::sim {

class BrainPhase;
struct StepView;

// Per agent in `collideFree` (the boids kernel's flags): none of its k nearest can end the
// step within contact distance, as long as every agent lies within `boidSlackM` of where
// its old velocity takes it (checked here; should one not, the pass runs in full, so the
// result is the same either way).
inline constexpr std::uint8_t kCollideFree = 1;

// The contact rounds' shortcut: a round passes by the agents it would leave where they are
// (Collide.cpp: settleContacts). The same result either way; `shortcut` false works out
// every agent in every round (WorldOptions::contactShortcut, for the tests that compare).
// agents: the agents the rounds have gone through, round by round, in all; passedBy: of
// those, the ones the shortcut passed by; marginBroken: the decisions whose first round
// went through every agent, as the collide pass had moved some body too far for its
// proofs (kClearMarginM, Collide.cpp).
struct ContactRounds {
    bool shortcut = true;
    std::uint64_t agents = 0, passedBy = 0, marginBroken = 0;
};

// Moves agents.nextPos to where the phase puts each body (writes nextPos, nextVel,
// resolvedPos and contactMoved), and counts the contact rounds' work in `rounds`.
void collide(const StepView& v, const BrainPhase& brains, AgentColumns& agents,
             std::span<const std::uint8_t> collideFree, float boidSlackM, bool hasStatics, ContactRounds& rounds);

}  // namespace throng::sim
