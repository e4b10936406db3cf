#pragma once
// Longitudinal car-following models as pure functions: the acceleration a driver picks
// from its speed, the bumper-to-bumper gap to what is ahead and that thing's speed.
// Never returns NaN or infinity, never asks a stopped vehicle to reverse.

#include <limits>

namespace throng::sim {

enum class FollowingModel {
    Idm,      // Intelligent Driver Model (Treiber, Hennecke, Helbing 2000)
    GapTime,  // target speed = (gap - minimum gap) / time constant (capped to one that can
              // stop in the gap), relaxed towards
    Fuzzy,    // accelerate / keep / brake rules on gap and closing speed
};

const char* toString(FollowingModel model);

struct FollowingParams {
    FollowingModel model = FollowingModel::Idm;
    float desiredSpeed = 13.9f;  // m/s, > 0: speed on a free road (IDM v0)
    float timeHeadwayS = 1.2f;   // s, > 0: desired time gap to the leader (IDM T)
    float minGapM = 2.0f;        // m, >= 0: standstill gap (IDM s0)
    float maxAccel = 1.5f;       // m/s^2, > 0: IDM a
    float comfortDecel = 2.0f;   // m/s^2, > 0: IDM b
    float maxDecel = 8.0f;       // m/s^2, >= comfortDecel: what the brakes can do
    float yellowDecel = 3.5f;    // m/s^2: on yellow, stop if that needs at most this, else go on
    float delta = 4.0f;          // IDM acceleration exponent, > 0
    float relaxS = 0.5f;         // s, > 0: GapTime's speed relaxation time
};

inline constexpr float kFreeRoad = std::numeric_limits<float>::infinity();

// Acceleration in m/s^2, in [-maxDecel, maxAccel]. speed >= 0 (m/s); gapM is the
// bumper-to-bumper distance (m; <= 0 means touching; kFreeRoad when nothing is ahead);
// leaderSpeed >= 0 (m/s; 0 for a stop line or a waiting pedestrian).
float followingAcceleration(const FollowingParams& p, float speed, float gapM, float leaderSpeed);

float idmAcceleration(const FollowingParams& p, float speed, float gapM, float leaderSpeed);
float gapTimeAcceleration(const FollowingParams& p, float speed, float gapM, float leaderSpeed);
float fuzzyAcceleration(const FollowingParams& p, float speed, float gapM, float leaderSpeed);

// One step of the ballistic update (Treiber & Kanagaraj 2015): new speed, never below
// zero, and the distance covered, which stops where the speed reaches zero.
struct SpeedStep {
    float speed = 0.0f;     // m/s, >= 0
    float distanceM = 0.0f; // m, >= 0
};
SpeedStep advanceSpeed(float speed, float accel, float dt);

// Whether a vehicle at `speed` can stop within distanceM braking at most decel (m/s^2).
bool canStopWithin(float speed, float distanceM, float decel);

}  // namespace throng::sim
