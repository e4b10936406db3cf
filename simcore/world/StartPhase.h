#pragma once
// The start phase (Variation::reactionS; RiMEA's pre-movement time): a walker whose type
// sets a reaction time stands where it starts until that time has passed, then sets off.
// Each walker's time is drawn uniformly from its type's range when the World is built,
// from the scene's seed and its id alone, so the same seed gives the same times whatever
// else the scene holds. Until it sets off the walker is unstarted and stopped: held like
// one at an action point (the move phase leaves it where it stands, the others go round
// it), but no one counts it as the pile of an arrived crowd. At the start of each step the
// phase lets go, in time order, those whose time has come. Serial and per agent: the same
// for any thread count. The agents a source lets in set off as they enter.

#include "simcore/world/AgentColumns.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace throng::sim {

class StartPhase {
public:
    // The walkers held at the start: dense index and the time each sets off, s.
    void build(std::vector<std::uint32_t> agents, std::vector<double> startS);
    // Holds every one of them (unstarted and stopped), as at the start.
    void holdAll(AgentColumns& agents) const;
    // Lets go the walkers whose time has come by timeS (the step's start); returns how many.
    std::size_t release(double timeS, AgentColumns& agents);
    bool pending() const { return m_done < m_agent.size(); }
    // After a checkpoint is put back: the held ones are let go by their times again.
    void rewind() { m_done = 0; }
    // When agent i (dense index) sets off, s from the start; 0 for one that never waits.
    double startS(std::size_t i) const;

private:
    std::vector<std::uint32_t> m_agent;  // dense index, in (time, index) order
    std::vector<double> m_startS;        // when it sets off, same order
    std::size_t m_done = 0;              // m_agent[0, m_done) have all been let go
};

}  // namespace throng::sim
