#pragma once
// Parts the bodies that a group spawned on top of each other, before the first frame.
// Drawn at random, a dense group (2 persons/m² of 0.3 m discs) starts with pairs pressed
// up to 90 % into each other, which the first steps threw apart and the stats counted as
// overlaps (issue 23). The members move the least that parts them: rounds of Jacobi
// projection, each overlapping pair pushed apart by its overlap, split evenly between two
// members and taken whole by a member against a body that stays (one placed earlier).
// Each move, and in the first round every member's place, is kept clear of walls and
// obstacles by a callback. Pure: no scene, no state.

#include <glm/vec2.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace throng::sim {

struct SpreadBody {
    glm::vec2 p;
    float r = 0.0f;
    bool movable = false;    // a member of the group being spread; else a body that stays
    std::uint64_t key = 0;   // distinct per body: coincident pairs part along a direction it seeds
};

// settle(q, r, out): where a body of radius r that would move to q may go instead (out,
// clear of the statics); false when it may not move there at all.
using SettleFn = std::function<bool(glm::vec2 q, float r, glm::vec2& out)>;

// Parts the movable bodies until no pair overlaps by more than toleranceM, or maxRounds.
void spreadBodies(std::vector<SpreadBody>& bodies, const SettleFn& settle, float toleranceM, int maxRounds);

}  // namespace throng::sim
