#pragma once
// The traffic side of a World: the TrafficSystem that drives its vehicles, the keyframe
// tracks that drive its heroes, and per walker the signal answer of the current step.
// Plain state the World's traffic phases (WorldTraffic.cpp) read and write; it never
// steps anything on its own.

#include "simcore/hero/HeroTrack.h"
#include "simcore/traffic/TrafficSystem.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace throng::sim {

struct WorldTraffic {
    std::optional<TrafficSystem> system;  // when the scene has lanes or vehicles
    std::vector<HeroTrack> heroes;

    // World agent index of each of the system's vehicles and of each hero track.
    std::vector<std::uint32_t> vehicleAgent, heroAgent;
    // Per World agent: 1 = moved only by traffic or a keyframe track (never steered, never pushed).
    std::vector<std::uint8_t> driven;
    // Per World agent: 1 = a vehicle waiting off stage to re-enter its open lane (it stands
    // at the lane's end, where others wait too: no overlap counts for it). anyOffStage
    // when some is.
    std::vector<std::uint8_t> offStage;
    bool anyOffStage = false;
    // World agents the traffic treats as pedestrians (walkers and heroes), and their
    // state before and after the step being computed.
    std::vector<std::uint32_t> pedestrians;
    std::vector<PedestrianView> before, after;
    // Per World agent: the signal answer it steered by this step (crosswalk -1 = none).
    std::vector<PedestrianSignal> signal;

    // Names for the stats, by the LaneNetwork's (scene's) indices.
    std::vector<std::string> laneNames, crosswalkNames, lightNames;

    bool isDriven(std::size_t i) const { return i < driven.size() && driven[i] != 0; }
};

}  // namespace throng::sim
