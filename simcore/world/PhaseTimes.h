#pragma once
// Where a World's steps spend their wall-clock time, phase by phase (World::stepOnce's
// column: WorldStep.cpp). The step marks the clock once as it begins and once after each
// phase that ran; the time since the last mark goes to that phase. A phase that did not
// run in a step (no brains, no traffic) gets none of it. Costs a clock read per phase,
// about 25 ns, against a step of milliseconds; results never depend on it.

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace throng::sim {

enum class StepPhase : std::uint8_t {
    Enter,     // sources, reaction times, exit choice
    Grid,      // the neighbour grid, at both ends of the step
    Navigate,  // plans, waypoints, flow directions
    Brain,     // senses and programs
    Traffic,   // the traffic system, heroes, signals
    Move,      // steer, avoid, integrate, constrain (and keeping formations)
    Collide,   // the collide pass and the contact rounds
    Commit,    // animation, arrivals, the swap, action points
    Count,     // the run's figures
};
inline constexpr std::size_t kStepPhaseCount = 9;

// The phases' names, as the bench's JSON keys them, in StepPhase's order.
inline constexpr std::array<std::string_view, kStepPhaseCount> kStepPhaseNames = {
    "enter", "grid", "navigate", "brain", "traffic", "move", "collide", "commit", "count"};
static_assert(std::size_t(StepPhase::Count) + 1 == kStepPhaseCount, "a name for every phase");

class PhaseTimes {
public:
    using Clock = std::chrono::steady_clock;

    // A step begins: the clock is marked.
    void begin() { m_mark = Clock::now(); }
    // Phase p has just run: the time since the last mark is its, and the clock is marked.
    void lap(StepPhase p)
    {
        const Clock::time_point now = Clock::now();
        m_nanoseconds[std::size_t(p)] += std::uint64_t(std::chrono::nanoseconds(now - m_mark).count());
        m_mark = now;
    }
    // A step ended (after its last lap).
    void endStep() { ++m_steps; }

    std::uint64_t steps() const { return m_steps; }
    double seconds(StepPhase p) const { return double(m_nanoseconds[std::size_t(p)]) * 1e-9; }
    double totalSeconds() const
    {
        std::uint64_t sum = 0;
        for (const std::uint64_t ns : m_nanoseconds)
            sum += ns;
        return double(sum) * 1e-9;
    }

private:
    std::array<std::uint64_t, kStepPhaseCount> m_nanoseconds{};
    std::uint64_t m_steps = 0;
    Clock::time_point m_mark{};
};

}  // namespace throng::sim
