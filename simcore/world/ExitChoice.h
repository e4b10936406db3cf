#pragma once
// The exit choice phase (SpawnGroup::exits, Source::exits; RiMEA test 11): a group's or a
// source's walkers choose among several exits the one they expect to leave by soonest, and
// choose again as the crowd moves. A walker expects to leave exit e after
//
//     max(d / v, q / c)
//
// seconds: d is its walking distance to e (down e's flow field where the World has one,
// else straight), v its own speed, q how many walkers bound for e are nearer to it than
// this one, and c the exit's capacity, kExitFlowPerMetre times its width (the goal's
// diameter). So a walker takes the nearest exit while its queue would clear before it
// arrives, and a farther one when the near one's queue would hold it longer than the walk.
// When the World is built the walkers choose in order of nearness to an exit, each counting
// those who chose before it (a source's agents choose as they enter); then every
// kChoiceRoundS of simulated time a quarter of them (by id) choose again, each switching
// only when another exit is clearly sooner (kSwitchShare and kSwitchS), so a crowd does not
// swing between exits. Walkers whose brain picks their goal take no part (the World leaves
// them out). Serial and by id: the same for any thread count.

#include "simcore/world/StepView.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace throng::sim {

inline constexpr float kExitFlowPerMetre = 1.3f;  // persons/m/s through a door, for the queue's wait
inline constexpr double kChoiceRoundS = 0.5;      // a round of choices every so often
inline constexpr std::uint32_t kChoiceRounds = 4; // each walker chooses again every kChoiceRounds rounds
inline constexpr float kSwitchShare = 0.9f;       // another exit must be this much sooner ...
inline constexpr float kSwitchS = 1.0f;           // ... and at least this many seconds sooner

class ExitChoice {
public:
    struct Switch {
        std::uint32_t agent;  // dense index
        std::int32_t goal;    // the exit it is now bound for
    };

    // setOf: per agent, an index into `sets` (-1, or beyond its end: it does not choose);
    // sets: goal indices.
    void build(std::vector<std::int32_t> setOf, std::vector<std::vector<std::int32_t>> sets);
    bool active() const { return !m_sets.empty(); }
    // Every goal some walker may choose, each once.
    std::vector<std::int32_t> goals() const;
    // The choosers' first choices, made once the World's flow fields exist.
    std::vector<Switch> first(const StepView& v) const;
    // Whether the step that starts at timeS (steps of dtS) holds a round of choices.
    static bool roundAt(double timeS, double dtS);
    // The round's changes of exit: the choosers whose turn it is, still in the scene.
    std::vector<Switch> choose(const StepView& v, double timeS) const;
    // The choices of `agents` (dense indices) that have just entered the scene.
    std::vector<Switch> onEntry(const StepView& v, const std::vector<std::uint32_t>& agents) const;

private:
    // How soon agent i expects to leave by the best exit of its set, and by its current one.
    struct Options {
        std::int32_t best = -1;
        float bestS = 0.0f, currentS = 0.0f;
    };
    // Per goal, the sorted walking distances of the walkers still bound for it.
    std::vector<std::vector<float>> boundFor(const StepView& v) const;
    Options options(const StepView& v, std::size_t i, const std::vector<std::vector<float>>& bound) const;
    std::int32_t setOf(std::size_t i) const { return i < m_setOf.size() ? m_setOf[i] : -1; }
    // Walking distance from agent i to goal g, m.
    float distanceM(const StepView& v, std::size_t i, std::int32_t g) const;

    std::vector<std::int32_t> m_setOf;
    std::vector<std::vector<std::int32_t>> m_sets;
};

}  // namespace throng::sim
