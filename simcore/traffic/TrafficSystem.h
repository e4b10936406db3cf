#pragma once
// Vehicles on lanes and the signals they and pedestrians obey: owns vehicle state as
// structure of arrays and advances it by fixed steps, each vehicle reading only the
// previous state (identical results for any thread count). Never moves a pedestrian; it
// answers the questions a World asks about them and counts what they did.
//
// A World's step, in this order (both advance 1 / fps; keep their step counts equal):
//   1. pedsBefore = the walkers' state (PedestrianView per walker)
//   2. traffic.step(pedsBefore)              vehicles move, yielding to walkers
//   3. per walker, in its sense phase:       traffic.pedestrianSignal(...) -> stop or go;
//      when stopping, steer to stopPoint and clamp crowd pushes with holdBehindStopLine
//   4. the World moves its walkers           (kerbs: LaneNetwork::pedestrianBarriers as walls)
//   5. traffic.observePedestrians(pedsBefore, pedsAfter)   red-light entries, contacts
// Stats: counters().redLightViolations(), carPedestrianCollisions; throughput().

#include "simcore/base/ThreadTeam.h"
#include "simcore/scene/Scene.h"
#include "simcore/traffic/CarFollowing.h"
#include "simcore/traffic/LaneNetwork.h"
#include "simcore/traffic/LightPhase.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace throng::sim {

// A pedestrian as traffic sees it (ground plane, x and z).
struct PedestrianView {
    glm::vec2 position{0.0f};  // m
    glm::vec2 velocity{0.0f};  // m/s
    float radiusM = 0.3f;      // m, > 0
};

struct TrafficOptions {
    std::uint64_t seed = 0;     // used when overrideSeed; else the scene's seed
    bool overrideSeed = false;
    int threads = 0;            // 0 = one per core this process may run on
    // Car-following parameters per vehicle agent type name, over the scene's choice of
    // model (tests); a type not listed gets the defaults of the model its lane, its type
    // or the scene sets (carFollowingOf), with desiredSpeed = the type's max speed.
    std::vector<std::pair<std::string, FollowingParams>> modelByType;
    // The reaction delays, crosswalk margins and yield rules are the scene's (Scene::traffic).
    float respawnDelayMinS = 0.5f, respawnDelayMaxS = 6.0f;  // s: off-stage time at an open lane's end
    float stopMarginM = 0.5f;    // m: a vehicle waits with its front this far before a stop line
    float pedestrianDecel = 1.5f;// m/s^2: what a pedestrian brakes with (yellow decision)
    float lookaheadM = 120.0f;   // m: farthest stop line, crosswalk or pedestrian a vehicle reacts to
};

struct TrafficCounters {
    std::uint64_t vehicleRedLightViolations = 0;    // a vehicle's front crossed a stop line on red
    std::uint64_t pedestrianRedLightViolations = 0; // a pedestrian stepped onto a crosswalk's road part on red
                                                    // (LaneNetwork::onRoadPart, light at the step's end)
    std::uint64_t carPedestrianCollisions =
        0; // vehicle-pedestrian pairs closer than the sum of radii, summed over steps
    std::uint64_t vehicleCollisions = 0;            // vehicle pairs closer than the sum of radii, summed over steps
    std::uint64_t nonFiniteValues = 0;              // NaN/inf vehicle positions or speeds seen
    std::uint64_t vehicleSteps = 0;                 // active vehicle-steps simulated
    std::uint64_t redLightViolations() const { return vehicleRedLightViolations + pedestrianRedLightViolations; }
};

// Crossings of one stop line: vehicles crossing a lane's line, or pedestrians stepping
// onto a controlled crosswalk from either end.
struct StopLineThroughput {
    int light = -1;
    int lane = -1;       // a vehicles' line, or -1
    int crosswalk = -1;  // a crosswalk's ends, or -1
    std::uint64_t crossings = 0;
    std::uint64_t greenPhases = 0;  // green phases begun so far (the first counts at time 0)
    double perGreen() const { return greenPhases ? double(crossings) / double(greenPhases) : 0.0; }
};

// The answer to a pedestrian at p: whether it is about to step onto the road part of a
// crosswalk (CrosswalkStrip::roadU0 .. roadU1: the kerb, not the strip's end, which may
// lie on the pavement), must wait, and where (a point before that kerb line, at its own
// side offset and a body radius back from the line). On the road part when the light is
// red it clears the road: `clearing`, to the nearer kerb's clearPoint.
struct PedestrianSignal {
    int crosswalk = -1;      // the crosswalk it is approaching or on; -1 = none
    bool onCrosswalk = false;// already on the strip: keep going, never stop there
    bool mustStop = false;
    LightPhase phase = LightPhase::Green;
    glm::vec2 stopPoint{0.0f};
    float distanceToLineM = 0.0f;  // from its centre to the crosswalk end line
    bool vehicleCrossing = false;  // a vehicle is on the strip or too close to stop before it
    glm::vec2 inward{0.0f};        // unit: the direction onto the crosswalk at its end line
    bool clearing = false;         // on the road part on red: leave it for clearPoint
    glm::vec2 clearPoint{0.0f};    // just off the road past the nearer kerb line
};

// The next stop line ahead of a vehicle's front on its lane (within the lookahead).
struct VehicleStopLine {
    bool found = false;
    float distanceM = 0.0f;  // from the vehicle's front to the line, >= 0
    LightPhase phase = LightPhase::Green;
    int light = -1;
};

// Where a waiting walker, pushed by others from its place to `to`, may end up: anywhere
// but past its stop point toward the crosswalk (that component of the push is removed;
// sideways and backwards nudges stay). The caller keeps the walker's forward axis: a
// nudge is not a turn. Returns `to` unchanged when the signal does not say stop.
glm::vec2 holdBehindStopLine(const PedestrianSignal& signal, glm::vec2 to);

class TrafficSystem {
public:
    // Vehicles of a validated scene on their lanes; lights and crosswalks resolved.
    explicit TrafficSystem(const Scene& scene, const TrafficOptions& options = {});

    // Advances all vehicles by one step of 1 / fps. `pedestrians` is the pedestrians'
    // state at the start of the step (vehicles yield to them); may be empty.
    void step(std::span<const PedestrianView> pedestrians);
    // Counts what pedestrians did during the step that just ended: entries onto a
    // crosswalk's road part on red, crosswalk throughput (entries over a strip's end), and
    // contacts with the vehicles' current positions. before[i] and after[i] are the same pedestrian; sizes must match.
    void observePedestrians(std::span<const PedestrianView> before, std::span<const PedestrianView> after);
    // Whether a pedestrian at p must stop before a crosswalk at the current time: on red,
    // on yellow when it can still stop, on green until its own reaction delay is over,
    // and whenever a vehicle is on the strip or can no longer stop before it.
    // heading: the direction it wants to go (toward its next waypoint; any length, not
    // its velocity, which is zero while it waits; within 60 degrees of a crosswalk's
    // axis counts as walking along it); speedMps: its current speed, for the
    // yellow decision; pedId keys its own reaction delay after green. Thread-safe.
    PedestrianSignal pedestrianSignal(glm::vec2 p, glm::vec2 heading, float speedMps, float radiusM,
                                      std::uint32_t pedId) const;

    // Brain-driven vehicles (TrafficBrain.cpp): per vehicle, the speed (m/s) its brain
    // wants one second from now, or NaN to leave it to the car-following model alone. A
    // brain can only lower what the model allows: the vehicle takes the smaller of
    // (wanted - speed) / 1 s, within -comfortDecel .. maxAccel (wanted capped by the
    // lane's speed limit; never reversing), and the model's acceleration for its leader
    // gap, the stop line ahead and the pedestrians, with the model's start-up delay. So
    // whatever a brain says, gaps, red lights and crosswalks hold as without it.
    // Call before step(); an empty span hands every vehicle back to the model.
    void setBrainSpeeds(std::span<const float> wantedMps);
    // Takes the lights' edited phases and timing (same lights in the same order: what they
    // control stays); the clock (the step) goes on. For resuming after an edit.
    void retime(const std::vector<TrafficLight>& lights) { m_lights = lights; }
    // Resuming after an edit of the lanes, crosswalks, lights' stop lines, vehicles or a
    // vehicle type (the rule is in WorldState.h; TrafficAdopt.cpp): this system, built
    // from the edited scene, takes old's clock (the step), counters and per stop line its
    // throughput, and per vehicle kept by id and lane name its motion and car-following
    // state; on a lane whose centre line changed, s is that of the nearest point to where
    // it stood. Returns per vehicle of this system its index in old (-1: it starts from
    // its scene state, being new or on another lane).
    std::vector<std::int32_t> adoptFrom(const TrafficSystem& old);
    // The clock of a system whose World had none before the edit: `step` steps done.
    void startAt(std::uint64_t step);
    // The stop line ahead of vehicle i's front at the current time (its light's phase).
    VehicleStopLine stopLineAhead(std::size_t i) const;

    const LaneNetwork& lanes() const { return m_net; }
    std::size_t vehicleCount() const { return m_s.size(); }
    std::uint64_t stepIndex() const { return m_step; }
    float dt() const { return m_dt; }
    double timeS() const { return double(m_step) * double(m_dt); }
    LightPhase lightPhase(int light) const;

    std::uint32_t id(std::size_t i) const { return m_id[i]; }
    int lane(std::size_t i) const { return m_lane[i]; }
    float s(std::size_t i) const { return m_s[i]; }          // m along the lane (centre)
    float speed(std::size_t i) const { return m_speed[i]; }  // m/s
    float radius(std::size_t i) const { return m_radius[i]; }
    // False while a vehicle that left an open lane waits off stage to re-enter.
    bool active(std::size_t i) const { return m_active[i] != 0; }
    // Times vehicle i has re-entered its open lane after leaving it at the end.
    std::uint32_t respawns(std::size_t i) const { return m_respawns[i]; }
    glm::vec2 position(std::size_t i) const { return m_pos[i]; }
    glm::vec2 forward(std::size_t i) const { return m_fwd[i]; }
    const FollowingParams& params(std::size_t i) const { return m_params[m_paramIndex[i]]; }

    const TrafficCounters& counters() const { return m_counters; }
    const std::vector<StopLineThroughput>& throughput() const { return m_throughput; }

private:
    enum Decision : std::uint8_t { kNone = 0, kStop = 1, kGo = 2 };
    struct NextState {
        float s, speed, goTimer;
        std::uint32_t stops;
        std::uint8_t decision;
        std::int32_t decisionLine;
    };
    struct LanePed {  // a pedestrian inside a lane's corridor
        std::uint32_t ped;
        float s, lateralM;
        bool onCarriageway;  // its centre on some lane's carriageway (not at the kerb)
    };

    void sortByLane();
    void collectPedestrians(std::span<const PedestrianView> peds);
    NextState advanceVehicle(std::size_t i, std::span<const PedestrianView> peds) const;
    float stopLineLimit(std::size_t i, const FollowingParams& q, NextState& next) const;
    float holdPastLine(std::size_t i) const;  // 0 for a vehicle standing past its line on red, else kFreeRoad
    float brainAcceleration(std::size_t i, const FollowingParams& q) const;  // TrafficBrain.cpp
    float yieldLimit(std::size_t i, const FollowingParams& p, std::span<const PedestrianView> peds) const;
    // approachingCount: also walkers about to step onto the strip, not only those on it.
    bool crosswalkConflict(int crosswalk, float uLane, float corridorM, bool approachingCount,
                           std::span<const PedestrianView> peds) const;
    void commit(double t0);
    void respawn();
    float entrySpeed(int lane, std::size_t i) const;
    float aheadM(int lane, float from, float to) const;  // distance forward along a lane; < 0 = behind
    float goDelayS(std::size_t i, std::uint32_t stops) const;
    void updatePositions();
    void countGreenOnsets(double t0, double t1);
    void buildVehicleGrid();
    template <class Fn> void forEachVehicleNear(glm::vec2 p, float radiusM, Fn&& fn) const;
    void countVehicleContacts();
    void countPedestrianContacts(std::span<const PedestrianView> peds);
    void markBusyCrosswalks();

    TrafficOptions m_opt;
    TrafficSettings m_knobs;  // the scene's
    LaneNetwork m_net;
    std::vector<TrafficLight> m_lights;
    std::vector<FollowingParams> m_params;
    std::uint64_t m_seed = 1;
    std::uint64_t m_step = 0;
    float m_dt = 1.0f / 24.0f;
    int m_threads = 1;
    std::shared_ptr<ThreadTeam> m_team;  // made when a step has enough vehicles to share out
    float m_maxRadius = 1.0f;

    // Structure of arrays, dense vehicle index.
    std::vector<std::uint32_t> m_id;
    std::vector<std::int32_t> m_lane;
    std::vector<std::uint16_t> m_paramIndex;
    std::vector<float> m_s, m_speed, m_radius, m_goTimer;
    std::vector<std::uint32_t> m_stops, m_respawns;
    std::vector<std::uint8_t> m_active, m_decision;
    std::vector<std::int32_t> m_decisionLine;
    std::vector<std::uint64_t> m_leftAtStep;  // when an inactive vehicle left its lane
    std::vector<float> m_brainSpeed;           // per vehicle when any is brain-driven; NaN = model
    std::vector<glm::vec2> m_pos, m_fwd;
    std::vector<NextState> m_next;

    // Per step: active vehicles by (lane, s, index); each one's leader (-1 = none).
    std::vector<std::uint32_t> m_order;
    std::vector<std::uint32_t> m_laneBegin;  // lanes + 1 offsets into m_order
    std::vector<std::int32_t> m_leader;
    // Active vehicles binned on a hashed uniform grid after each step (contact counts):
    // per vehicle its cell key and bucket; per bucket a range of m_cellItems.
    std::vector<std::uint64_t> m_cellKey;
    std::vector<std::uint32_t> m_cellStart, m_cellItems, m_cellOf, m_cellCursor;
    float m_cellM = 2.0f;
    std::vector<std::vector<LanePed>> m_lanePeds;          // per lane
    std::vector<std::vector<std::uint32_t>> m_crosswalkPeds;// per crosswalk
    std::vector<std::uint8_t> m_crosswalkBusy;  // per crosswalk: a vehicle on it or committed to it

    TrafficCounters m_counters;
    std::vector<StopLineThroughput> m_throughput;  // indexed like LaneNetwork's stop lines
};

}  // namespace throng::sim
