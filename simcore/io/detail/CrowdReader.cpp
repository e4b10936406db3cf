// Placed agents (`agents` as a list of maps; the table form is CrowdReaderTable.cpp) and
// heroes with their keyframes.
#include "simcore/io/detail/CrowdReader.h"

#include "simcore/io/detail/SceneReader.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace throng::sim::detail {

void CrowdReader::readAgents(const YAML::Node& node, Scene& scene)
{
    if (node.IsMap()) {
        readAgentTable(node, "agents", scene);
        return;
    }
    if (!m_f.expectSequence(node, "agents"))
        return;
    scene.agents.reserve(scene.agents.size() + node.size());
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("agents", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"id", "type", "position", "heading", "goal", "path", "leader", "brain", "group",
                                  "look", "tint", "height"});
        Agent a;
        if (YAML::Node id = item["id"]; id.IsDefined() && m_f.readU32(item, "id", key, a.id, false))
            m_names.claimId(id, key + ".id", a.id);
        if (m_f.readName(item, "type", key, a.type, true))
            m_names.checkKnown(item, "type", key, a.type, "agent type");
        m_f.readPoint3(item, "position", key, a.position, true);
        m_f.readFloat(item, "heading", key, a.headingDeg, false);
        if (m_f.readName(item, "goal", key, a.goal, false) && !a.goal.empty())
            m_names.checkKnown(item, "goal", key, a.goal, "goal");
        if (m_f.readName(item, "path", key, a.path, false) && !a.path.empty())
            m_names.checkKnown(item, "path", key, a.path, "path");
        if (m_f.readName(item, "brain", key, a.brain, false) && !a.brain.empty())
            m_names.checkKnown(item, "brain", key, a.brain, "brain");
        m_f.readName(item, "group", key, a.group, false);
        if (m_f.readU32(item, "leader", key, a.leader, false) && item["leader"].IsDefined()) {
            if (a.id != 0 && a.leader == a.id)
                m_f.error(item["leader"].Mark(), key + ".leader", "an agent cannot lead itself");
            m_names.leads(item["leader"].Mark(), key + ".leader", a.leader);
        }
        readAgentVariation(item, key, scene, a);
        scene.agents.push_back(std::move(a));
    }
}

void CrowdReader::readAgentVariation(const YAML::Node& item, const std::string& key, const Scene& scene, Agent& a)
{
    const AgentType* type = scene.findAgentType(a.type);
    const std::string known = type ? a.type : std::string();
    m_f.readIndexOfType(item, "look", key, a.look, type ? std::max<std::size_t>(1, type->variation.looks.size()) : 0,
                        known);
    m_f.readIndexOfType(item, "tint", key, a.tint, type ? type->variation.tints.size() : 0, known);
    m_f.readFloat(item, "height", key, a.heightScale, false, Range::Positive);
}

void CrowdReader::readHeroes(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "heroes"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("heroes", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"id", "name", "type", "clearance", "keyframes", "keyframes_file"});
        Hero h;
        if (YAML::Node id = item["id"]; id.IsDefined() && m_f.readU32(item, "id", key, h.id, false))
            m_names.claimId(id, key + ".id", h.id);
        if (m_f.readName(item, "name", key, h.name, true))
            m_names.claim(item, key, h.name, "hero");
        if (m_f.readName(item, "type", key, h.type, true))
            m_names.checkRef(item, "type", key, h.type, scene.findAgentType(h.type) != nullptr, "agent type");
        m_f.readFloat(item, "clearance", key, h.clearanceM, false, Range::NonNegative);
        const YAML::Node keys = item["keyframes"];
        const YAML::Node file = item["keyframes_file"];
        if (keys.IsDefined() == file.IsDefined()) {
            m_f.error(item.Mark(), key, "give exactly one of 'keyframes' or 'keyframes_file'");
        } else if (file.IsDefined()) {
            if (m_f.readString(item, "keyframes_file", key, h.keyframesFile, true))
                readHeroKeyframesFile(file, key + ".keyframes_file", scene.settings.fps, h);
        } else if (m_f.expectSequence(keys, key + ".keyframes")) {
            for (std::size_t j = 0; j < keys.size(); ++j) {
                const std::string kk = indexKey(key + ".keyframes", j);
                const YAML::Node k = keys[j];
                if (!m_f.expectMap(k, kk))
                    continue;
                m_f.checkKeys(k, kk, {"time", "position"});
                Keyframe kf;
                if (!m_f.readFloat(k, "time", kk, kf.timeS, true, Range::NonNegative) ||
                    !m_f.readPoint3(k, "position", kk, kf.position, true))
                    continue;
                if (!h.keyframes.empty() && kf.timeS <= h.keyframes.back().timeS)
                    m_f.error(k["time"].Mark(), kk + ".time", "keyframe times must increase");
                h.keyframes.push_back(kf);
            }
            if (h.keyframes.empty())
                m_f.error(keys.Mark(), key + ".keyframes", "a hero needs at least one keyframe");
        }
        scene.heroes.push_back(std::move(h));
    }
}

void CrowdReader::readHeroKeyframesFile(const YAML::Node& at, const std::string& key, float fps, Hero& hero)
{
    // One "x y z" line per frame, as Maya writes it: frame n is at time n / fps.
    const std::string full = resolvePath(m_baseDir, hero.keyframesFile);
    std::ifstream in(full);
    if (!in) {
        m_f.error(at.Mark(), key, "cannot open keyframes file '" + full + "'");
        return;
    }
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#')
            continue;
        std::istringstream ss(line);
        std::string tok[3], extra;
        ss >> tok[0] >> tok[1] >> tok[2];
        glm::vec3 p;
        std::string why;
        bool ok = !tok[2].empty() && !(ss >> extra);
        for (int c = 0; ok && c < 3; ++c)
            ok = parseFiniteFloat(tok[c], p[c], why);
        if (!ok) {
            std::vector<Diagnostic> sub;
            sub.push_back({Severity::Error, full, lineNo, 1, "", why.empty() ? "expected 'x y z'" : why});
            m_f.error(at.Mark(), key, "in keyframes file: " + sub[0].format());
            return;
        }
        hero.keyframes.push_back({float(double(hero.keyframes.size()) / fps), p});
    }
    if (hero.keyframes.empty())
        m_f.error(at.Mark(), key, "keyframes file '" + full + "' has no keyframes");
}

}  // namespace throng::sim::detail
