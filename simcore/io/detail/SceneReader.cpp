#include "simcore/io/detail/SceneReader.h"

#include "simcore/io/detail/CrowdReader.h"
#include "simcore/io/detail/LayoutReader.h"
#include "simcore/io/detail/SceneSizeCheck.h"
#include "simcore/io/detail/SetReader.h"
#include "simcore/io/detail/TrafficReader.h"
#include "simcore/io/detail/TypeReader.h"
#include "simcore/io/detail/YamlDocument.h"

#include <filesystem>

namespace throng::sim::detail {

std::string resolvePath(const std::string& baseDir, const std::string& path)
{
    std::filesystem::path p(path);
    if (p.is_absolute() || baseDir.empty())
        return p.lexically_normal().string();
    return (std::filesystem::path(baseDir) / p).lexically_normal().string();
}

void SceneReader::read(const YAML::Node& root, Scene& scene)
{
    m_f.checkKeys(root, "", {"throng", "settings", "brains", "agent_types", "agents", "groups", "paths",
                             "walls", "obstacles", "goals", "terrain", "flow_strokes", "lanes", "crosswalks",
                             "traffic_lights", "vehicles", "heroes", "sound_sources", "action_points", "traffic",
                             "sources", "measurements", "layout"});
    std::uint64_t version = 0;
    if (m_f.readUInt(root, "throng", "", version, true, 1'000'000) && version != Scene::kFormatVersion)
        m_f.error(root["throng"].Mark(), "throng",
                  "unsupported format version " + std::to_string(version) + " (this Throng reads version " +
                      std::to_string(Scene::kFormatVersion) + ")");

    // Sections are read in dependency order, not file order, so references can be
    // checked as soon as they are read.
    auto section = [&](const char* name) { return root[name]; };
    TypeReader types(m_f, m_names, m_baseDir);
    SetReader set(m_f, m_names);
    TrafficReader traffic(m_f, m_names);
    CrowdReader crowd(m_f, m_names, m_baseDir, m_source);
    if (auto n = section("settings"); n.IsDefined())
        readSettings(n, scene.settings);
    if (auto n = section("traffic"); n.IsDefined())
        traffic.readTraffic(n, scene.traffic);
    if (auto n = section("brains"); n.IsDefined())
        readBrains(n, scene);
    if (auto n = section("agent_types"); n.IsDefined())
        types.read(n, scene);
    if (auto n = section("goals"); n.IsDefined())
        set.readGoals(n, scene);
    if (auto n = section("paths"); n.IsDefined())
        set.readPaths(n, scene);
    if (auto n = section("walls"); n.IsDefined())
        set.readWalls(n, scene);
    if (auto n = section("obstacles"); n.IsDefined())
        set.readObstacles(n, scene);
    if (auto n = section("terrain"); n.IsDefined())
        set.readTerrain(n, scene.terrain);
    if (auto n = section("flow_strokes"); n.IsDefined())
        set.readFlowStrokes(n, scene);
    if (auto n = section("lanes"); n.IsDefined())
        traffic.readLanes(n, scene);
    if (auto n = section("crosswalks"); n.IsDefined())
        traffic.readCrosswalks(n, scene);
    if (auto n = section("traffic_lights"); n.IsDefined())
        traffic.readTrafficLights(n, scene);
    if (auto n = section("agents"); n.IsDefined())
        crowd.readAgents(n, scene);
    if (auto n = section("groups"); n.IsDefined())
        crowd.readGroups(n, scene);
    if (auto n = section("vehicles"); n.IsDefined())
        traffic.readVehicles(n, scene);
    if (auto n = section("heroes"); n.IsDefined())
        crowd.readHeroes(n, scene);
    if (auto n = section("sound_sources"); n.IsDefined())
        set.readSoundSources(n, scene);
    if (auto n = section("action_points"); n.IsDefined())
        set.readActionPoints(n, scene);
    if (auto n = section("sources"); n.IsDefined())
        crowd.readSources(n, scene);
    if (auto n = section("measurements"); n.IsDefined())
        set.readMeasurements(n, scene);
    if (auto n = section("layout"); n.IsDefined())
        LayoutReader(m_f).read(n, scene);
    m_names.assignMissingIds(scene);
    // Leaders are checked last: any placed agent, vehicle or hero may lead.
    m_names.checkLeaders(scene);
    checkSceneSizes(m_f, root, scene);
}

void SceneReader::readSettings(const YAML::Node& node, Settings& s)
{
    const std::string key = "settings";
    if (!m_f.expectMap(node, key))
        return;
    m_f.checkKeys(node, key, {"fps", "duration", "seed", "bounds", "nav_cell"});
    m_f.readFloat(node, "nav_cell", key, s.navCellM, false, Range::Positive);
    m_f.readFloat(node, "fps", key, s.fps, false, Range::Positive);
    m_f.readFloat(node, "duration", key, s.durationS, false, Range::Positive);
    m_f.readUInt(node, "seed", key, s.seed, false, UINT64_MAX);
    if (s.fps > 1000.0f)
        m_f.error(node["fps"].Mark(), key + ".fps", "must be at most 1000");
    else if (s.fps > 0.0f && s.fps < 1.0f)  // below a frame a second the sub-steps run away
        m_f.error(node["fps"].Mark(), key + ".fps", "must be at least 1");
    if (YAML::Node b = node["bounds"]; b.IsDefined()) {
        const std::string bk = key + ".bounds";
        if (m_f.expectMap(b, bk)) {
            m_f.checkKeys(b, bk, {"min", "max"});
            m_f.readVec2(b, "min", bk, s.boundsMin, true);
            m_f.readVec2(b, "max", bk, s.boundsMax, true);
            if (s.boundsMin.x >= s.boundsMax.x || s.boundsMin.y >= s.boundsMax.y)
                m_f.error(b.Mark(), bk, "min must be less than max on both axes");
        }
    }
}

void SceneReader::readBrains(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "brains"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("brains", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        BrainGraph brain;
        if (!m_f.readName(item, "name", key, brain.name, true))
            continue;
        m_names.claim(item, key, brain.name, "brain");
        if (YAML::Node file = item["file"]; file.IsDefined()) {
            m_f.checkKeys(item, key, {"name", "file"});
            if (!m_f.readString(item, "file", key, brain.file, true))
                continue;
            const std::string full = resolvePath(m_baseDir, brain.file);
            // Problems inside the brain file are located in that file, and reported at
            // the reference so the scene's reader sees them too.
            std::vector<Diagnostic> sub;
            YamlFields brainFields(full, sub);
            std::string text;
            YAML::Node doc;
            const std::string name = brain.name;
            if (readYamlFile(brainFields, text, doc))
                readBrainGraph(brainFields, doc, "", brain, true);
            brain.name = name;
            for (const Diagnostic& d : sub) {
                if (d.severity == Severity::Error)
                    m_f.error(file.Mark(), key + ".file", "in brain file: " + d.format());
                else
                    m_f.warning(file.Mark(), key + ".file", "in brain file: " + d.format());
            }
        } else {
            readBrainGraph(m_f, item, key, brain, false);
        }
        scene.brains.push_back(std::move(brain));
    }
}

}  // namespace throng::sim::detail
