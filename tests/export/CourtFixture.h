#pragma once
// A recorded shot the USD and FBX export tests share: a walled court of 40 m x 30 m with a
// lane, a crosswalk, a post, a traffic light (signal: green 3 s, yellow 1, red 3) and twelve
// walkers at 12 fps for 120 frames, eight of type walker leaving through a door (out of the
// shot before the end), four of type visitor (two tints) walking to a bench; everything
// shifted by `shift` metres. And the trajectories CSV read back.

#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec3.hpp>

#include <map>
#include <string>

namespace throng::test {

struct CourtShot {
    sim::Scene scene;
    sim::FrameCache cache;
};

CourtShot recordCourt(double shift);

// A trajectories CSV's rows: agent id -> frame -> position (the scene's coordinates).
std::map<int, std::map<int, glm::dvec3>> readTrajectoryRows(const std::string& csvPath);
// Its headings: agent id -> frame -> heading, radians (the CSV's degrees).
std::map<int, std::map<int, double>> readTrajectoryHeadings(const std::string& csvPath);

}  // namespace throng::test
