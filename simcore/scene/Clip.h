#pragma once
// The clip an agent plays on a recorded frame: its locomotion (idle, walk, run, chosen by
// speed) or an action its brain picked (output.action with one of the names below).
// Actions loop in time, not by distance: an action's phase on a frame is a function of
// the frame's time and the agent alone (actionPhase), so the viewport and every export
// show the same moment of it, a resumed run plays it on from where it was, and the
// recorded gait phase stays the walk's. The one-shot actions (fall, get_up) play once from
// the frame the agent switched to them and then hold their last pose: their progress is
// the time since that frame over the clip's length (oneShotProgress), which every reader
// of the recorded frames counts the same way.

#include <cstdint>
#include <optional>
#include <string_view>

namespace throng::sim {

enum class Clip : std::uint8_t {
    Idle = 0, Walk = 1, Run = 2,  // locomotion
    Wait, LookAround, Wave, Talk, Phone, Cheer, Sit, ShiftWeight, Point,  // actions
    Fall, GetUp,  // one-shot actions
};
inline constexpr int kClipCount = int(Clip::GetUp) + 1;

// The clip's name in brains (output.action), the CSV and exports: "idle", "look_around".
const char* toString(Clip clip);
// The clip of that name, or nothing.
std::optional<Clip> clipFromName(std::string_view name);
// Whether the clip is one of the actions (not idle, walk or run).
inline bool isAction(Clip clip) { return clip >= Clip::Wait; }
// Whether the action plays once and holds its last pose (fall, get_up) instead of looping.
inline bool isOneShot(Clip clip) { return clip >= Clip::Fall; }
// Seconds one cycle of an action lasts (a wave of the hand, a look left and right); 0 for
// the locomotion clips, whose phase advances by distance walked.
float clipCycleS(Clip clip);
// The action's phase in cycles, in [0, 1), at time `timeS` (a recorded frame's: frame /
// fps) for the agent with this id: time over the cycle, offset per agent (by the id, so
// a crowd that cheers together does not move in lock-step).
float actionPhase(Clip clip, double timeS, std::uint32_t agentId);
// How far a one-shot action has played, in [0, 1], `sinceS` seconds after the frame the
// agent switched to it (0 on that frame); 1 from the clip's length on.
float oneShotProgress(Clip clip, double sinceS);

}  // namespace throng::sim
