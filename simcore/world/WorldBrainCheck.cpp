// The scene check for brains: compiles every brain of a scene and reports compiler
// errors and sensors the World cannot fill as file:line:col diagnostics; and the table
// from a sensor's name to the column the World fills for it.
#include "simcore/world/WorldBrain.h"

#include "simcore/brain/BrainCompiler.h"
#include "simcore/world/detail/WorldBrains.h"

#include <algorithm>
#include <map>

namespace throng::sim {

using detail::SensorFill;

namespace detail {

std::optional<SensorFill> sensorFillFor(const BrainSensorUse& use)
{
    static const std::map<std::string, SensorFill> plain{
        {"speed", SensorFill::Speed}, {"goal_bearing", SensorFill::GoalBearing},
        {"goal_distance", SensorFill::GoalDistance}, {"path_offset", SensorFill::PathOffset},
        {"flow_bearing", SensorFill::FlowBearing}, {"neighbour_count", SensorFill::NeighbourCount},
        {"neighbour_density", SensorFill::NeighbourDensity}, {"nearest_distance", SensorFill::NearestDistance},
        {"nearest_bearing", SensorFill::NearestBearing}, {"vision_left", SensorFill::VisionLeft},
        {"vision_centre", SensorFill::VisionCentre}, {"vision_right", SensorFill::VisionRight},
        {"feeler_left", SensorFill::FeelerLeft}, {"feeler_centre", SensorFill::FeelerCentre},
        {"feeler_right", SensorFill::FeelerRight}, {"wall_distance", SensorFill::WallDistance},
        {"light_state", SensorFill::LightState}, {"stop_line_distance", SensorFill::StopLineDistance},
        {"hero_distance", SensorFill::HeroDistance}, {"hero_bearing", SensorFill::HeroBearing},
        {"terrain_slope", SensorFill::TerrainSlope}, {"time", SensorFill::Time},
        {"neighbour_distance", SensorFill::NeighbourDistance}, {"neighbour_bearing", SensorFill::NeighbourBearing},
        {"neighbour_speed", SensorFill::NeighbourSpeed}, {"neighbour_heading", SensorFill::NeighbourHeading},
        {"neighbour_tag", SensorFill::NeighbourTag}, {"sound_bearing", SensorFill::SoundBearing},
        {"sound_distance", SensorFill::SoundDistance}, {"sound_strength", SensorFill::SoundStrength},
        {"sound_source_bearing", SensorFill::SoundSourceBearing},
        {"sound_source_distance", SensorFill::SoundSourceDistance},
        {"sound_source_strength", SensorFill::SoundSourceStrength},
        {"action_point_distance", SensorFill::ActionPointDistance},
        {"action_point_bearing", SensorFill::ActionPointBearing}, {"action_point_time", SensorFill::ActionPointTime},
    };
    static const std::map<std::string, SensorFill> attributes{
        {"max_speed", SensorFill::AttrMaxSpeed}, {"radius", SensorFill::AttrRadius},
        {"mass", SensorFill::AttrMass}, {"max_force", SensorFill::AttrMaxForce},
        {"perception", SensorFill::AttrPerception}, {"speed_factor", SensorFill::AttrSpeedFactor},
    };
    const auto& table = use.sensor == "attribute" ? attributes : plain;
    const auto it = table.find(use.sensor == "attribute" ? use.argument : use.sensor);
    if (it == table.end())
        return std::nullopt;
    return it->second;
}

}  // namespace detail

namespace {

// The input node that reads `use`, for the message's position.
const BrainNode* inputNodeFor(const BrainGraph& g, const BrainSensorUse& use)
{
    for (const BrainNode& n : g.nodes) {
        if (n.type != "input")
            continue;
        std::string sensor, argument;
        for (const BrainParam& p : n.params) {
            if (p.key == "sensor")
                sensor = p.text;
            else if (p.key == "channel" || p.key == "name" || p.key == "tag")
                argument = p.text;
        }
        if (sensor == use.sensor && argument == use.argument)
            return &n;
    }
    return nullptr;
}

// Whether anything in the scene sounds on `channel`: a sound source or an emitting type.
bool heardInScene(const Scene& scene, const std::string& channel)
{
    for (const SoundSource& s : scene.soundSources)
        if (s.channel == channel)
            return true;
    for (const AgentType& t : scene.agentTypes)
        if (t.emits.channel == channel)
            return true;
    return false;
}

bool usedByAType(const Scene& scene, const std::string& brain)
{
    for (const AgentType& t : scene.agentTypes)
        if (t.brain == brain)
            return true;
    return false;
}

// Whether the World compiles `brain`: a type's or a placed agent's brain (BrainPhase::build).
bool runByTheWorld(const Scene& scene, const std::string& brain)
{
    if (usedByAType(scene, brain))
        return true;
    for (const Agent& a : scene.agents)
        if (a.brain == brain)
            return true;
    return false;
}

}  // namespace

std::string worldSensorProblem(const BrainSensorUse& use, const Scene& /*scene*/)
{
    if (use.sensor == "attribute" && !detail::sensorFillFor(use))
        return "attribute '" + use.argument +
               "' is not an agent attribute (max_speed, radius, mass, max_force, perception, speed_factor)";
    if (!detail::sensorFillFor(use))
        return "sensor '" + use.sensor + "' is not provided by the World";
    return {};
}

std::vector<Diagnostic> checkSceneBrains(const Scene& scene)
{
    std::vector<Diagnostic> out;
    for (std::size_t b = 0; b < scene.brains.size(); ++b) {
        const BrainGraph& g = scene.brains[b];
        const std::string key = "brains[" + std::to_string(b) + "]";
        const BrainCompileResult r = compileBrain(g, scene.brains);
        // `run` compiles only the brains agents run (a macro inside one is compiled with it),
        // so a broken brain nobody runs is news, not a reason to refuse the scene.
        const bool runs = runByTheWorld(scene, g.name);
        const Severity severity = runs ? Severity::Error : Severity::Warning;
        const std::string idle =
            runs ? std::string() : "brain '" + g.name + "' is run by no agent, so a run ignores this: ";
        for (const BrainError& e : r.errors)
            out.push_back({severity, e.file, e.line, e.column, key, idle + e.message});
        if (!r.ok())
            continue;
        std::vector<std::string> silent;  // channels already warned about
        for (const BrainSensorUse& use : r.program->sensors) {
            const BrainNode* n = inputNodeFor(g, use);
            const BrainSourcePos pos = n ? g.source.node(n->id) : BrainSourcePos{};
            const std::string who = n ? "node " + std::to_string(n->id) + " (input): " : std::string();
            if (const std::string why = worldSensorProblem(use, scene); !why.empty()) {
                out.push_back({severity, g.source.file, pos.line, pos.column, key, idle + who + why});
                continue;
            }
            // A brain some type runs that listens where nothing sounds hears silence forever.
            if (use.sensor.starts_with("sound") && usedByAType(scene, g.name) && !heardInScene(scene, use.argument) &&
                std::find(silent.begin(), silent.end(), use.argument) == silent.end()) {
                silent.push_back(use.argument);
                out.push_back({Severity::Warning, g.source.file, pos.line, pos.column, key,
                               who + "nothing is heard on channel '" + use.argument +
                                   "' (no sound source is on it and no agent type emits on it)"});
            }
        }
    }
    return out;
}

}  // namespace throng::sim
