// Agent types (`agent_types`): see TypeReader.h.
#include "simcore/io/detail/TypeReader.h"

#include "simcore/io/detail/SceneReader.h"
#include "simcore/io/detail/SetReader.h"
#include "simcore/io/detail/TrafficReader.h"
#include "simcore/scene/Clip.h"
#include "simcore/scene/WalkingAge.h"
#include "simcore/world/TypeSteering.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>

namespace throng::sim::detail {

bool TypeReader::readBehaviour(const YAML::Node& node, const std::string& key, BehaviourWeight& out)
{
    if (!node.IsMap())
        return m_f.toFloat(node, key, out.weight, Range::NonNegative);
    m_f.checkDuplicateKeys(node, key);
    if (!m_f.readFloat(node, "weight", key, out.weight, false, Range::NonNegative))
        return false;
    bool ok = true;
    std::set<std::string> seen;
    for (auto it = node.begin(); it != node.end(); ++it) {
        BrainParam p;
        p.key = it->first.Scalar();
        if (p.key == "weight" || !seen.insert(p.key).second)
            continue;
        const YAML::Node v = it->second;
        const std::string pk = key + "." + p.key;
        if (v.IsSequence()) {
            p.numbers.resize(v.size());
            for (std::size_t i = 0; ok && i < v.size(); ++i)
                ok = m_f.toFloat(v[i], indexKey(pk, i), p.numbers[i], Range::Any);
        } else if (v.IsScalar()) {
            float number = 0.0f;
            std::string why;
            if (parseFiniteFloat(v.Scalar(), number, why))
                p.numbers = {number};
            else
                p.text = v.Scalar();
        } else {
            m_f.error(v.Mark(), pk, "must be a number, a list of numbers or a word");
            ok = false;
            continue;
        }
        if (const std::string problem = checkBehaviourParam(out.behaviour, p); !problem.empty()) {
            m_f.error(it->first.Mark(), pk, problem);
            ok = false;
            continue;
        }
        out.params.push_back(std::move(p));
    }
    return ok;
}

void TypeReader::readVariation(const YAML::Node& node, const std::string& key, Variation& v)
{
    if (!m_f.expectMap(node, key))
        return;
    m_f.checkKeys(node, key, {"looks", "tints", "height", "speed", "phase", "reaction", "age"});
    m_f.readStringList(node, "looks", key, v.looks, false);
    if (YAML::Node tints = node["tints"]; tints.IsDefined() && m_f.expectSequence(tints, key + ".tints")) {
        v.tints.clear();
        for (std::size_t i = 0; i < tints.size(); ++i) {
            const YAML::Node t = tints[i];
            const std::string tk = indexKey(key + ".tints", i);
            glm::vec3 c;
            bool ok = t.IsSequence() && t.size() == 3;
            for (std::size_t j = 0; ok && j < 3; ++j)
                ok = m_f.toFloat(t[j], indexKey(tk, j), c[int(j)], Range::Unit);
            if (!t.IsSequence() || t.size() != 3)
                m_f.error(t.Mark(), tk, "a tint must be [r, g, b] with each in 0..1");
            if (ok)
                v.tints.push_back(c);
        }
    }
    auto range = [&](const char* name, glm::vec2& r, Range kind) {
        if (m_f.readVec2(node, name, key, r, false, kind) && r.x > r.y)
            m_f.error(node[name].Mark(), childKey(key, name), "range [min, max] has min greater than max");
    };
    range("height", v.heightScale, Range::Positive);
    range("speed", v.speedFactor, Range::Positive);
    range("phase", v.phaseOffset, Range::Unit);
    range("reaction", v.reactionS, Range::NonNegative);
    if (node["age"].IsDefined() && m_f.readVec2(node, "age", key, v.ageYears, false, Range::NonNegative)) {
        if (v.ageYears.x > v.ageYears.y)
            m_f.error(node["age"].Mark(), childKey(key, "age"), "range [min, max] has min greater than max");
        else if (v.ageYears.x < kWalkingAgeMinYears || v.ageYears.y > kWalkingAgeMaxYears)
            m_f.error(node["age"].Mark(), childKey(key, "age"),
                      "ages must lie within 10 to 80 years, where Weidmann's walking speeds are known");
    }
}

void TypeReader::read(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "agent_types"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("agent_types", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"name", "kind", "radius", "max_speed", "max_force", "mass", "perception",
                                  "view_angle", "brain", "character", "clips", "variation", "behaviours", "combination",
                                  "min_speed", "banking", "emits", "priority", "layer", "collides_with",
                                  "navigation", "action_blend", "car_following", "time_gap"});
        AgentType t;
        if (!m_f.readName(item, "name", key, t.name, true))
            continue;
        m_names.claim(item, key, t.name, "agent type");
        std::string kind = "pedestrian";
        if (m_f.readString(item, "kind", key, kind, false)) {
            if (kind == "pedestrian") t.kind = AgentKind::Pedestrian;
            else if (kind == "vehicle") t.kind = AgentKind::Vehicle;
            else if (kind == "flier") t.kind = AgentKind::Flier;
            else
                m_f.error(item["kind"].Mark(), key + ".kind",
                          "must be pedestrian, vehicle or flier, got '" + kind + "'");
        }
        if (t.kind == AgentKind::Vehicle) {
            t.radiusM = 1.0f;
            t.maxSpeed = 13.9f;
            t.maxForce = 4000.0f;
            t.mass = 1200.0f;
        }
        m_f.readFloat(item, "radius", key, t.radiusM, false, Range::Positive);
        m_f.readFloat(item, "max_speed", key, t.maxSpeed, false, Range::NonNegative);
        m_f.readFloat(item, "max_force", key, t.maxForce, false, Range::NonNegative);
        m_f.readFloat(item, "mass", key, t.mass, false, Range::Positive);
        m_f.readFloat(item, "perception", key, t.perceptionM, false, Range::Positive);
        if (m_f.readFloat(item, "view_angle", key, t.viewAngleDeg, false, Range::Positive) && t.viewAngleDeg > 360.0f)
            m_f.error(item["view_angle"].Mark(), key + ".view_angle", "must be at most 360 degrees");
        if (m_f.readName(item, "brain", key, t.brain, false) && !t.brain.empty())
            m_names.checkKnown(item, "brain", key, t.brain, "brain");
        if (m_f.readString(item, "character", key, t.character, false) && !t.character.empty()) {
            const auto& builtins = builtinCharacters();
            const bool builtin = std::find(builtins.begin(), builtins.end(), t.character) != builtins.end();
            const bool isFile = t.character.ends_with(".glb") || t.character.ends_with(".gltf");
            if (!builtin && !isFile)
                m_f.error(item["character"].Mark(), key + ".character",
                          "'" + t.character + "' is neither a built-in character (man, woman, tall_man, child, "
                          "elderly, car, bird) nor a .glb/.gltf file");
            else if (isFile && !std::filesystem::exists(resolvePath(m_baseDir, t.character)))
                m_f.error(item["character"].Mark(), key + ".character",
                          "character file '" + resolvePath(m_baseDir, t.character) + "' does not exist");
        }
        if (YAML::Node c = item["clips"]; c.IsDefined() && m_f.expectMap(c, key + ".clips")) {
            std::array<const char*, kClipCount> clipKeys{};  // every clip's name (Clip.h)
            for (int k = 0; k < kClipCount; ++k)
                clipKeys[std::size_t(k)] = toString(Clip(k));
            m_f.checkKeys(c, key + ".clips", clipKeys);
            m_f.readString(c, "idle", key + ".clips", t.clips.idle, false);
            m_f.readString(c, "walk", key + ".clips", t.clips.walk, false);
            m_f.readString(c, "run", key + ".clips", t.clips.run, false);
            // The actions a file's clips play, in the file's order (Clip.h's names).
            for (const auto& entry : c) {
                const std::string name = entry.first.as<std::string>("");
                const std::optional<Clip> clip = clipFromName(name);
                std::string file;
                if (clip && isAction(*clip) && m_f.readString(c, name.c_str(), key + ".clips", file, false) &&
                    !file.empty())
                    t.clips.actions.emplace_back(name, file);
            }
        }
        if (YAML::Node v = item["variation"]; v.IsDefined())
            readVariation(v, key + ".variation", t.variation);
        std::string combination = "blend";
        if (m_f.readString(item, "combination", key, combination, false)) {
            if (combination == "priority") t.priorityCombination = true;
            else if (combination != "blend")
                m_f.error(item["combination"].Mark(), key + ".combination",
                          "must be blend or priority, got '" + combination + "'");
        }
        if (m_f.readFloat(item, "min_speed", key, t.minSpeed, false, Range::NonNegative) && t.minSpeed > t.maxSpeed)
            m_f.error(item["min_speed"].Mark(), key + ".min_speed", "is above max_speed");
        m_f.readFloat(item, "banking", key, t.banking, false, Range::NonNegative);
        m_f.readFloat(item, "action_blend", key, t.actionBlendS, false, Range::NonNegative);
        if (m_f.readFloat(item, "time_gap", key, t.timeGapS, false, Range::NonNegative) &&
            t.kind != AgentKind::Pedestrian && t.timeGapS > 0.0f) {
            m_f.warning(item["time_gap"].Mark(), key + ".time_gap", "only walkers keep a time gap; ignored here");
            t.timeGapS = 0.0f;
        }
        if (YAML::Node e = item["emits"]; e.IsDefined())
            readEmission(m_f, e, key + ".emits", t.emits);
        std::string navigation = "direct";
        if (m_f.readString(item, "navigation", key, navigation, false)) {
            if (navigation == "astar") t.navigation = Navigation::AStar;
            else if (navigation == "flow_field") t.navigation = Navigation::FlowField;
            else if (navigation != "direct")
                m_f.error(item["navigation"].Mark(), key + ".navigation",
                          "must be direct, astar or flow_field, got '" + navigation + "'");
            if (t.kind != AgentKind::Pedestrian && t.navigation != Navigation::Direct)
                m_f.warning(item["navigation"].Mark(), key + ".navigation", "only walkers navigate; ignored here");
        }
        readCarFollowing(m_f, item, key, t.carFollowing, true);
        if (t.kind != AgentKind::Vehicle && item["car_following"].IsDefined())
            m_f.warning(item["car_following"].Mark(), key + ".car_following",
                        "only vehicle types follow cars; ignored here");
        for (const char* walkerOnly : {"reaction", "age"})
            if (const YAML::Node v = item["variation"];
                t.kind != AgentKind::Pedestrian && v.IsDefined() && v.IsMap() && v[walkerOnly].IsDefined())
                m_f.warning(v[walkerOnly].Mark(), key + ".variation." + walkerOnly,
                            std::string("'") + walkerOnly + "' only affects walkers and is ignored here");
        for (const char* flierOnly : {"min_speed", "banking"})
            if (t.kind != AgentKind::Flier && item[flierOnly].IsDefined())
                m_f.warning(item[flierOnly].Mark(), key + "." + flierOnly,
                            std::string("'") + flierOnly + "' only affects fliers and is ignored here");
        readCollision(item, key, t);
        if (YAML::Node b = item["behaviours"]; b.IsDefined() && m_f.expectMap(b, key + ".behaviours")) {
            const auto& known = behaviourNames();
            m_f.checkDuplicateKeys(b, key + ".behaviours");
            std::set<std::string> seen;
            for (auto it = b.begin(); it != b.end(); ++it) {
                const std::string name = it->first.Scalar();
                const std::string bk = key + ".behaviours." + name;
                if (!seen.insert(name).second)
                    continue;  // checkKeys reported the duplicate
                if (std::find(known.begin(), known.end(), name) == known.end()) {
                    m_f.error(it->first.Mark(), bk, "unknown steering behaviour '" + name + "'");
                    continue;
                }
                BehaviourWeight w{name, 1.0f, {}};
                if (readBehaviour(it->second, bk, w))
                    t.behaviours.push_back(std::move(w));
            }
        }
        scene.agentTypes.push_back(std::move(t));
    }
}

// Making way: priority, collision layer and the layers the type collides with.
void TypeReader::readCollision(const YAML::Node& item, const std::string& key, AgentType& t)
{
    m_f.readFloat(item, "priority", key, t.priority, false, Range::Any);
    if (m_f.readU32(item, "layer", key, t.layer, false) && t.layer > 31)
        m_f.error(item["layer"].Mark(), key + ".layer", "must be a layer from 0 to 31");
    std::vector<float> layers;
    if (item["collides_with"].IsDefined() && m_f.readFloatList(item, "collides_with", key, layers, false)) {
        t.collidesWith = 0;
        for (float l : layers) {
            if (l < 0.0f || l > 31.0f || l != std::floor(l)) {
                m_f.error(item["collides_with"].Mark(), key + ".collides_with",
                          "layers are whole numbers from 0 to 31");
                break;
            }
            t.collidesWith |= 1u << unsigned(l);
        }
    }
}

}  // namespace throng::sim::detail
