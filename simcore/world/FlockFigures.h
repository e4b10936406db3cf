#pragma once
// Whether a World's fliers flock, in three figures a user checks after a murmuration:
// polarisation (do they fly one way), spread (do they stay together) and the distance
// from their centre to the leaders they follow. Reads the World's current state only.

#include <cstdint>

namespace throng::sim {

class World;

struct FlockFigures {
    std::uint64_t fliers = 0;       // agents of kind flier
    double polarisation = 0.0;      // |mean of the fliers' unit velocities|, 0..1
    double spreadM = 0.0;           // RMS distance of the fliers from their centre, m
    double centreToLeaderM = 0.0;   // centre of fliers that have a leader to their leaders' mean position, m
    std::uint64_t followers = 0;    // fliers that have a leader

    static FlockFigures of(const World& world);
};

}  // namespace throng::sim
