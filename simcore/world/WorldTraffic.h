#pragma once
// The traffic phase of a World: the TrafficSystem that drives its vehicles, the keyframe
// tracks that drive its heroes, and per walker the signal answer of the current step.
// Vehicles and heroes are agents that others perceive and steer round but never push;
// walkers obey the crosswalk signals and keep off the carriageway (kerbs are walls). The
// phase owns this state, reads the World through a StepView, and each method names the
// agent columns it writes; the call order is the one TrafficSystem.h gives
// (WorldTraffic.cpp).

#include "simcore/hero/HeroTrack.h"
#include "simcore/scene/Scene.h"
#include "simcore/steering/SteeringAgent.h"
#include "simcore/traffic/TrafficSystem.h"
#include "simcore/world/AgentColumns.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace throng::sim {

struct AgentTypes;
struct Segment;
struct StaticSet;
struct StepClock;
struct StepView;

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

    // Building: the system and the hero tracks from the scene (seeded by the World), and
    // the carriageway's kerbs as walls for the walkers.
    void build(const Scene& scene, std::uint64_t seed, int threads);
    void appendKerbs(std::vector<Segment>& walls) const;
    // Once the World has added the traffic's agents (World::addTrafficAgents): agents
    // [firstDriven, n) are driven; the walkers among the first firstDriven, and the
    // heroes, are the pedestrians the traffic sees.
    void markAgents(const AgentColumns& agents, const AgentTypes& types, std::size_t firstDriven);

    // The step's phases, in the World's order.
    // Before steering: the system steps on the pedestrians' state before the step.
    void beforeStep(const AgentColumns& agents);
    // Steering one walker (writes signal[i]): the force it steers by, or, at a red light
    // or caught on the road by one, the stop or the way back to the kerb instead.
    glm::vec3 obeySignal(const StepView& v, std::size_t i, const SteeringAgent& self, glm::vec3 force);
    // A waiting walker is never pushed past its stop point.
    void holdAtSignal(std::size_t i, glm::vec3& p) const;
    // Vehicles and heroes to where the system and the tracks put them at the step's end.
    void drive(const StepClock& clock, const StaticSet& set, AgentColumns& agents);
    // After the collide pass: walkers step out of a hero's clearance, stay behind their
    // stop points and off red crosswalks (writes nextPos and nextVel).
    void afterCollide(const StepView& v, AgentColumns& agents);
    // After the step: the system observes the pedestrians' new state (its counters).
    void afterStep(const AgentColumns& agents);

private:
    void keepOffRedCrosswalks(const StepView& v, std::size_t i, glm::vec3& p) const;
};

}  // namespace throng::sim
