#pragma once
// The watched agents' steering annotations the runner handed over, by recorded frame,
// and which frames were asked to be described again for the current watch. Plain data;
// the controller keeps it in step with its frame cache.

#include "editor/simulation/SimulationRunner.h"

#include <cstddef>
#include <map>
#include <set>
#include <vector>

namespace throng::editor {

class SteeringRecord {
public:
    void clear();
    // An edit recomputes the frames from `frame` on: their annotations go.
    void dropFrom(std::size_t frame);
    void take(std::vector<SimulationRunner::FrameSteering>&& steering);
    // The annotations recorded with frame `frame` of the agents watched now, in the
    // order recorded; empty when none were. A frame recorded for agents no longer watched
    // (the selection changed since) shows only those still watched.
    std::vector<sim::AgentDebug> watchedAt(std::size_t frame) const;
    // The agents watched from now on: frames recorded for others need describing again.
    void setWatched(std::vector<sim::AgentId> ids);
    // Whether frame `frame` lacks the watched agents' annotations and was not asked for
    // yet under this watch; marks it asked.
    bool wantsDescribing(std::size_t frame);

private:
    bool covers(std::size_t frame) const;
    bool watched(sim::AgentId id) const;

    std::map<std::size_t, std::vector<sim::AgentDebug>> m_frames;
    std::vector<sim::AgentId> m_watched;
    std::set<std::size_t> m_asked;
};

}  // namespace throng::editor
