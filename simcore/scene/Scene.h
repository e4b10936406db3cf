#pragma once
// The authoring document as plain data: everything a scene file holds, nothing the
// simulation derives from it. Never holds runtime arrays, pointers or Qt types.

#include "simcore/layout/LayoutLayer.h"
#include "simcore/scene/BrainGraph.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace throng::sim {

// Ground coordinates: x east, z south, y up (glTF convention). A ground point is (x, z).

struct Settings {
    float fps = 24.0f;            // frames per second, > 0; one simulation step per frame
    float durationS = 10.0f;      // seconds, > 0
    std::uint64_t seed = 1;       // keys every random number of a run
    glm::vec2 boundsMin{-50.0f};  // world bounds (x, z) in metres
    glm::vec2 boundsMax{50.0f};
    float navCellM = 0.5f;        // navigation grid cell edge in metres, > 0
    bool operator==(const Settings&) const = default;
};

enum class AgentKind { Pedestrian, Vehicle, Flier };

// How a vehicle picks its acceleration (simcore/traffic/CarFollowing.h): the Intelligent
// Driver Model, a gap-time rule or fuzzy rules. On a lane or a vehicle type, Inherit takes
// the next one's: the lane's model, else the vehicle type's, else the scene's default.
enum class CarFollowing { Inherit, Idm, GapTime, Fuzzy };

// The crossroads' knobs: how drivers and walkers at crosswalks react (TrafficSystem.h).
// The defaults are the values Throng has always used.
struct TrafficSettings {
    CarFollowing carFollowing = CarFollowing::Idm;  // the default model, never Inherit
    // s, [min, max]: a standing driver moves off this long after it is free to go, drawn
    // anew for each queue it waits in.
    glm::vec2 driverStartDelayS{0.3f, 1.5f};
    // s, [min, max]: a walker waiting at a crosswalk steps off this long after the green
    // begins, drawn anew for each light cycle.
    glm::vec2 walkerStartDelayS{0.0f, 2.0f};
    float crossingMarginM = 0.5f;   // m, >= 0: a vehicle this near a crosswalk's strip holds its walkers at the kerb
    float walkerClearanceM = 0.5f;  // m, >= 0: what a vehicle keeps clear round a walker in its way, beyond both bodies
    // m/s, >= 0: a walker moving into a vehicle's path slower than this is waiting, and the
    // vehicle does not yield to it.
    float waitingSpeed = 0.05f;
    float yieldHorizonS = 3.0f;     // s, > 0: a vehicle yields to a walker reaching its path within this
    bool operator==(const TrafficSettings&) const = default;
};

// How an agent type finds its way to its goal: straight at it, along a shared A* plan
// round walls and obstacles, or down the goal's flow field.
enum class Navigation { Direct, AStar, FlowField };

struct Variation {
    std::vector<std::string> looks;   // mesh variants of the character, empty = default look
    std::vector<glm::vec3> tints;     // RGB palette in 0..1, empty = untinted
    glm::vec2 heightScale{1.0f};      // uniform range [min, max], > 0
    glm::vec2 speedFactor{0.8f, 1.2f};// uniform range [min, max], > 0
    glm::vec2 phaseOffset{0.0f, 1.0f};// gait phase offset range in cycles, [0, 1]
    // Walkers' reaction (pre-movement) time, s, >= 0: each stands where it starts for a time
    // drawn uniformly from [min, max] before it sets off (StartPhase.h). [0, 0] = at once.
    glm::vec2 reactionS{0.0f};
    // Age range, years, within 10 to 80; [0, 0] = no age. Each agent's age is drawn from it
    // and scales its speed by Weidmann's curve (WalkingAge.h).
    glm::vec2 ageYears{0.0f};
    bool operator==(const Variation&) const = default;
};

// Names of a character file's clips to use; empty = found by name (idle/stand, walk, run).
struct CharacterClips {
    std::string idle, walk, run;
    // Action (one of Clip.h's actions: wait, look_around, wave, …, fall, get_up) -> the file's
    // clip that plays it; an action without one plays the locomotion its speed gives.
    std::vector<std::pair<std::string, std::string>> actions;
    bool operator==(const CharacterClips&) const = default;
};

struct BehaviourWeight {
    std::string behaviour;           // one of behaviourNames()
    float weight = 1.0f;             // >= 0
    std::vector<BrainParam> params;  // behaviour parameters (TypeSteering's behaviourParams())
    bool operator==(const BehaviourWeight&) const = default;
};

// What an agent type emits on a sound channel (brains of others hear it with the sound_*
// sensors). An empty channel = silent.
struct SoundEmission {
    std::string channel;
    float strength = 1.0f;  // loudness at the source, > 0 (1 = full)
    float radiusM = 10.0f;  // heard up to this distance, m, > 0
    bool operator==(const SoundEmission&) const = default;
};

struct AgentType {
    std::string name;
    AgentKind kind = AgentKind::Pedestrian;
    float radiusM = 0.3f;       // m, > 0
    float maxSpeed = 1.4f;      // m/s, >= 0
    float maxForce = 3.0f;      // N, >= 0
    float mass = 1.0f;          // kg, > 0
    float perceptionM = 4.0f;   // neighbour perception radius in m, > 0
    float viewAngleDeg = 270.0f;// perception cone, full angle in degrees, (0, 360]
    std::string brain;          // name of a brain in Scene::brains, empty = none
    std::string character;      // built-in character name or a .glb/.gltf path
    CharacterClips clips;       // a character file's clips for idle, walk and run
    Variation variation;
    std::vector<BehaviourWeight> behaviours;  // empty = the defaults for the kind
    bool priorityCombination = false;         // prioritised allocation instead of weighted blending
    float minSpeed = 0.0f;                    // m/s, >= 0: fliers never fly slower
    float banking = 0.0f;                     // s^2/m, >= 0: fliers' bank per m/s^2 of turn
    SoundEmission emits;                      // every agent of the type emits this sound
    // Making way (WorldPriority.h): of two agents that avoid each other, the one of lower
    // priority takes all of the avoidance; equal priorities share it.
    float priority = 0.0f;                    // any finite number; higher = others make way
    std::uint32_t layer = 0;                  // collision layer, 0..31
    std::uint32_t collidesWith = 0xffffffffu; // bit k set = avoids agents on layer k
    Navigation navigation = Navigation::Direct;  // walkers with a goal only
    // Seconds every action blends in and out over on this type's agents; < 0 = each
    // action's own (Clip.h's clips: a few tenths of a second, sit 0.8 s).
    float actionBlendS = -1.0f;
    CarFollowing carFollowing = CarFollowing::Inherit;  // vehicles: their model where the lane sets none
    // Walkers: the time gap they keep to the body in their way, s (the headway rule,
    // steering/Headway.h; 1.06 s in Seyfried's single-file data). 0 = no such rule.
    float timeGapS = 0.0f;
    bool operator==(const AgentType&) const = default;
};

struct Agent {
    std::uint32_t id = 0;       // stable AgentId, unique in the scene, > 0
    std::string type;
    glm::vec3 position{0.0f};
    float headingDeg = 0.0f;    // degrees, 0 = +x, counter-clockwise seen from above
    std::string goal;           // optional goal name
    std::string path;           // optional path name
    std::uint32_t leader = 0;   // optional AgentId pursued, evaded or followed; 0 = none
    std::string brain;          // optional brain in Scene::brains; empty = the type's brain
    std::string group;          // optional name of a set of agents (the assign brush, the outliner)
    // Per-agent variation set by hand (the variation brush); unset = drawn per agent id
    // from the type's Variation.
    int look = -1;              // index into the type's looks, -1 = drawn
    int tint = -1;              // index into the type's tints, -1 = drawn
    float heightScale = 0.0f;   // > 0 fixes the height scale, 0 = drawn from the type's range
    bool operator==(const Agent&) const = default;
};

enum class AreaShape { Rect, Circle, Polygon };

// The shape a group's formation holds while it moves (Formations.h): its members side by
// side (line), in rows behind the anchor (column), or in rows widening behind it (wedge, an
// arrow with the anchor at the tip).
enum class FormationShape { None, Line, Column, Wedge };

struct GroupFormation {
    FormationShape shape = FormationShape::None;
    float spacingM = 1.0f;    // between neighbouring slots' centres, m, >= the members' diameter
    std::uint32_t width = 2;  // Column: members abreast in each row, >= 1
    bool operator==(const GroupFormation&) const = default;
};

struct SpawnGroup {
    std::string name;
    std::string type;
    std::uint32_t count = 0;
    AreaShape shape = AreaShape::Rect;
    glm::vec2 min{0.0f}, max{0.0f};  // Rect: corners (x, z)
    glm::vec2 center{0.0f};          // Circle
    float radiusM = 0.0f;            // Circle, > 0
    std::string goal;
    std::string path;
    std::uint32_t leader = 0;        // AgentId the members pursue, evade or follow; 0 = none
    glm::vec2 altitudeM{0.0f};       // fliers: spawn height range [min, max] in m; ground agents ignore it
    std::vector<glm::vec2> points{}; // Polygon: corners (x, z) in order, >= 3, not crossing itself
    // Exit goals the members choose among, each the one it expects to leave by soonest
    // (ExitChoice.h); instead of goal, path and leader. Empty = none.
    std::vector<std::string> exits{};
    // Members hold a formation round an anchor (the leader, else the member at the front).
    GroupFormation formation{};
    // Members walk in small groups of companions, [min, max] walkers each (families,
    // friends; Formations.h): abreast where there is room, waiting for each other. 0 = none.
    glm::uvec2 companions{0u};
    bool operator==(const SpawnGroup&) const = default;
};

struct Path {
    std::string name;
    std::vector<glm::vec2> points;  // >= 2 points
    float radiusM = 1.0f;           // > 0
    bool closed = false;
    // plan: astar: `points` are waypoints, and the World follows the shortest way between
    // each and the next round walls and obstacles (planned on the navigation grid at load,
    // smoothed to its corners), keeping clearanceM from them.
    bool planned = false;
    float clearanceM = 1.0f;        // m, > 0; planned paths only
    // An open path's end is an exit: a walker that reaches it (within radiusM of its last
    // point) leaves the scene there, as through an exit goal.
    bool exit = false;
    bool operator==(const Path&) const = default;
};

struct Wall {
    std::string name;
    std::vector<glm::vec2> points;  // polyline, >= 2 points
    float heightM = 2.5f;           // m, > 0: how high the 3D view and the exported set stand it
    bool operator==(const Wall&) const = default;
};

enum class ObstacleShape { Circle, Box };

struct Obstacle {
    std::string name;
    ObstacleShape shape = ObstacleShape::Circle;
    glm::vec2 center{0.0f};
    float radiusM = 0.5f;         // Circle, > 0
    glm::vec2 size{1.0f};         // Box: full width (x) and depth (z), > 0
    float angleDeg = 0.0f;        // Box rotation about y
    bool operator==(const Obstacle&) const = default;
};

struct Goal {
    std::string name;
    glm::vec2 position{0.0f};
    float radiusM = 1.0f;  // arrival tolerance, > 0
    bool exit = false;     // agents reaching it leave the simulation; door width = 2 radiusM
    bool operator==(const Goal&) const = default;
};

struct Terrain {
    glm::vec2 origin{0.0f};      // (x, z) of height sample (0, 0)
    float cellM = 1.0f;          // spacing between samples, > 0
    std::uint32_t cols = 0, rows = 0;
    std::vector<float> heights;  // rows * cols, row-major along x; empty terrain = flat ground
    bool operator==(const Terrain&) const = default;
};

struct FlowStroke {
    std::vector<glm::vec2> points;  // direction of travel = order of points, >= 2
    float widthM = 2.0f;            // influence width, > 0
    bool operator==(const FlowStroke&) const = default;
};

struct Lane {
    std::string name;
    std::vector<glm::vec2> points;  // direction of travel = order of points, >= 2
    float widthM = 3.5f;            // > 0
    float speedLimit = 13.9f;       // m/s, > 0
    bool loop = true;               // vehicles reaching the end restart at the start
    CarFollowing carFollowing = CarFollowing::Inherit;  // the model of every vehicle on the lane
    bool operator==(const Lane&) const = default;
};

struct Crosswalk {
    std::string name;
    glm::vec2 from{0.0f}, to{0.0f};  // centre line, pedestrians cross from one end to the other
    float widthM = 3.0f;             // > 0
    bool operator==(const Crosswalk&) const = default;
};

struct StopLine {
    std::string lane;       // either a lane and a distance along it...
    float atM = 0.0f;       // m along the lane, >= 0
    std::string crosswalk;  // ...or a crosswalk whose ends are the pedestrians' stop lines
    bool operator==(const StopLine&) const = default;
};

struct TrafficLight {
    std::string name;
    float greenS = 20.0f, yellowS = 3.0f, redS = 23.0f;  // phase durations, >= 0, sum > 0
    float offsetS = 0.0f;                                // cycle offset, s
    glm::vec2 position{0.0f};                            // where the signal head stands
    std::vector<StopLine> stopLines;
    bool operator==(const TrafficLight&) const = default;
};

struct Vehicle {
    std::uint32_t id = 0;   // AgentId shared with agents' id space
    std::string type;       // an agent type of kind vehicle
    std::string lane;
    float atM = 0.0f;       // start distance along the lane, >= 0
    float speed = 0.0f;     // initial speed, m/s, >= 0
    bool operator==(const Vehicle&) const = default;
};

struct Keyframe {
    float timeS = 0.0f;
    glm::vec3 position{0.0f};
    bool operator==(const Keyframe&) const = default;
};

struct Hero {
    std::uint32_t id = 0;       // AgentId
    std::string name;
    std::string type;
    float clearanceM = 2.0f;    // others are pushed out of this radius, >= 0
    std::string keyframesFile;  // optional: one "x y z" line per frame, relative to the scene
    std::vector<Keyframe> keyframes;  // strictly increasing times
    bool operator==(const Hero&) const = default;
};

// A fixed sound beacon (a bell, a busker, a loudspeaker) heard on its channel.
struct SoundSource {
    std::string name;
    std::string channel;
    glm::vec2 position{0.0f};  // (x, z)
    float strength = 1.0f;     // loudness at the source, > 0 (1 = full)
    float radiusM = 20.0f;     // heard up to this distance, m, > 0
    bool operator==(const SoundSource&) const = default;
};

// A place where walkers stop and act (Musse's action points: a shop window, a ticket
// machine, a bench). A walker of one of `types` (every walker when empty) whose centre
// enters the disk stops there with the probability `chance`, turns to face `facingDeg`
// (when `faces`; else it keeps the heading it came with), plays `action` for `durationS`
// and goes on to its goal or along its path. It stops once per visit: again only after
// it has left the disk.
struct ActionPoint {
    std::string name;
    glm::vec2 position{0.0f};            // (x, z)
    float radiusM = 1.0f;                // > 0
    std::string action = "look_around";  // an action's name (Clip.h): not idle, walk or run
    float durationS = 4.0f;              // > 0
    bool faces = false;
    float facingDeg = 0.0f;              // degrees, 0 = +x, counter-clockwise seen from above
    float chance = 1.0f;                 // in [0, 1]
    std::vector<std::string> types;      // agent type names; empty = every walker
    bool operator==(const ActionPoint&) const = default;
};

// Where a source lets its agents in: along a line, or over a rectangle.
enum class SourceShape { Line, Rect };
// How a source spaces its arrivals: evenly at its rate, or as a seeded Poisson process.
enum class Arrivals { Steady, Poisson };

struct SourceType {
    std::string type;     // an agent type's name
    float weight = 1.0f;  // > 0: its share of the arrivals, against the others' weights
    bool operator==(const SourceType&) const = default;
};

// A stream of agents that enter the scene during the run (the World's SourcePhase): at
// `rate` a second, evenly or as Poisson arrivals, within `windows` (or the whole run), up
// to `cap`, each on a seeded place of the line or rectangle, of a type drawn by weight,
// bound for `goal`, along `path`, or for the one of `exits` it chooses.
struct Source {
    std::string name;
    std::vector<SourceType> types;   // >= 1
    SourceShape shape = SourceShape::Line;
    glm::vec2 from{0.0f}, to{0.0f};  // Line: its ends (x, z)
    glm::vec2 min{0.0f}, max{0.0f};  // Rect: its corners (x, z)
    float rate = 1.0f;               // agents a second, > 0
    Arrivals arrivals = Arrivals::Steady;
    std::vector<glm::vec2> windows;  // [start, end) in s, in order, not overlapping; empty: the whole run
    std::string goal;
    std::string path;
    std::uint32_t cap = 0;           // most agents it lets in over the run; 0: as many as its rate gives
    bool headed = false;             // heading given; else each faces its goal or its path's first point
    float headingDeg = 0.0f;         // degrees, 0 = +x, counter-clockwise seen from above
    // Exit goals its agents choose among as they enter (ExitChoice.h); instead of goal and path.
    std::vector<std::string> exits{};
    bool operator==(const Source&) const = default;
};

// What a measurement records (RunAnalysis.h): the walkers crossing a line, or the
// density and speed of those inside an area.
enum class MeasurementShape { Line, Area };

// A researcher's measurement place: it changes nothing in the run, the analysis of the
// recorded frames reads it (flow over a line, speed against density in an area).
struct Measurement {
    std::string name;
    MeasurementShape shape = MeasurementShape::Line;
    // Line: its two ends (x, z); a crossing counts as forward when it moves along
    // (z1 - z0, x0 - x1), the line's direction turned a quarter. Area: the corners (x, z)
    // of a simple polygon, >= 3.
    std::vector<glm::vec2> points;
    bool operator==(const Measurement&) const = default;
};

struct Scene {
    static constexpr int kFormatVersion = 1;
    Settings settings;
    TrafficSettings traffic;
    std::vector<AgentType> agentTypes;
    std::vector<Agent> agents;
    std::vector<SpawnGroup> groups;
    std::vector<Path> paths;
    std::vector<Wall> walls;
    std::vector<Obstacle> obstacles;
    std::vector<Goal> goals;
    Terrain terrain;
    std::vector<FlowStroke> flowStrokes;
    std::vector<Lane> lanes;
    std::vector<Crosswalk> crosswalks;
    std::vector<TrafficLight> trafficLights;
    std::vector<Vehicle> vehicles;
    std::vector<Hero> heroes;
    std::vector<SoundSource> soundSources;
    std::vector<ActionPoint> actionPoints;
    std::vector<Source> sources;
    std::vector<Measurement> measurements;
    std::vector<BrainGraph> brains;
    LayoutLayer layout;  // edits to the recorded crowd, applied after the simulation (issue 29)
    bool operator==(const Scene&) const = default;

    const AgentType* findAgentType(const std::string& name) const;
    const Goal* findGoal(const std::string& name) const;
    const Path* findPath(const std::string& name) const;
    const Lane* findLane(const std::string& name) const;
    const Crosswalk* findCrosswalk(const std::string& name) const;
    const BrainGraph* findBrain(const std::string& name) const;
    // Whether agent type `type`'s brain (or a macro brain it uses) picks the agent's goal
    // (an output.goal node): then the brain, not an exit choice, sends its agents.
    bool brainPicksGoals(const std::string& type) const;
};

// The id of the first agent spawn groups create in a World: after every id the scene's
// agents, vehicles and heroes use. Group g's members take the next groups[g].count ids,
// group after group, so the ids of group g are [first + sum of earlier counts, + count).
std::uint32_t firstSpawnedId(const Scene& scene);

// Names that may appear in AgentType::behaviours (Reynolds 1999 and boids 1987), from
// kBehaviourTable (BehaviourTable.h).
const std::vector<std::string>& behaviourNames();
// Built-in characters that export can generate without a file.
const std::vector<std::string>& builtinCharacters();

const char* toString(AgentKind kind);
const char* toString(Navigation navigation);
const char* toString(AreaShape shape);
const char* toString(Arrivals arrivals);
const char* toString(MeasurementShape shape);  // "line", "area"
const char* toString(FormationShape shape);    // "none", "line", "column", "wedge"
const char* toString(ObstacleShape shape);
const char* toString(CarFollowing model);  // "inherit", "idm", "gap_time", "fuzzy"
// The model a vehicle of `type` on `lane` follows (either may be null): the lane's, the
// type's, else the scene's default.
CarFollowing carFollowingOf(const Scene& scene, const Lane* lane, const AgentType* type);

}  // namespace throng::sim
