#include "simcore/io/SceneIO.h"

#include "simcore/base/AtomicFile.h"
#include "simcore/io/detail/SceneReader.h"
#include "simcore/io/detail/YamlWriter.h"
#include "simcore/scene/WalkingAge.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace throng::sim {

namespace detail {
void writeSceneSet(YamlWriter& w, const Scene& s);
void writeSceneTraffic(YamlWriter& w, const Scene& s);
void writeSceneSound(YamlWriter& w, const Scene& s);
void writeEmission(YamlWriter& w, const SoundEmission& e);
void writeSceneActionPoints(YamlWriter& w, const Scene& s);
void writeSceneSources(YamlWriter& w, const Scene& s);
void writeSceneMeasurements(YamlWriter& w, const Scene& s);
void writeSceneLayout(YamlWriter& w, const Scene& s);
}  // namespace detail

namespace {

// Below this many placed agents the readable list form is written; above it, the table.
constexpr std::size_t kAgentTableThreshold = 64;

using detail::num;
using Writer = detail::YamlWriter;

// A parameter: a number, a list of numbers, or text. Brain text is always quoted so it
// reads back as text even when it looks like a number; behaviour words are plain.
void writeParam(Writer& w, const BrainParam& p, bool quoteText = false)
{
    YAML::Emitter& o = w.out;
    o << YAML::Key << p.key << YAML::Value;
    if (!p.text.empty() || p.numbers.empty()) {
        if (quoteText)
            o << YAML::DoubleQuoted;
        o << p.text;
    } else if (p.numbers.size() == 1) {
        o << num(p.numbers[0]);
    } else {
        o << YAML::Flow << YAML::BeginSeq;
        for (float v : p.numbers)
            o << num(v);
        o << YAML::EndSeq;
    }
}

void writeBrainBody(Writer& w, const BrainGraph& b)
{
    YAML::Emitter& o = w.out;
    w.key("nodes");
    o << YAML::BeginSeq;
    for (const BrainNode& n : b.nodes) {
        o << YAML::Flow << YAML::BeginMap;
        w.kv("id", std::to_string(n.id));
        w.kv("type", n.type);
        if (!n.label.empty())
            o << YAML::Key << "label" << YAML::Value << YAML::DoubleQuoted << n.label;
        w.key("position");
        w.vec2(n.position);
        if (!n.params.empty()) {
            w.key("params");
            o << YAML::Flow << YAML::BeginMap;
            for (const BrainParam& p : n.params)
                writeParam(w, p, true);
            o << YAML::EndMap;
        }
        o << YAML::EndMap;
    }
    o << YAML::EndSeq;
    w.key("links");
    o << YAML::BeginSeq;
    for (const BrainLink& l : b.links) {
        o << YAML::Flow << YAML::BeginMap;
        w.key("from");
        o << YAML::Flow << YAML::BeginSeq << l.fromNode << l.fromPort << YAML::EndSeq;
        w.key("to");
        o << YAML::Flow << YAML::BeginSeq << l.toNode << l.toPort << YAML::EndSeq;
        o << YAML::EndMap;
    }
    o << YAML::EndSeq;
}

void writeAgentTypes(Writer& w, const Scene& s)
{
    YAML::Emitter& o = w.out;
    w.key("agent_types");
    o << YAML::BeginSeq;
    for (const AgentType& t : s.agentTypes) {
        o << YAML::BeginMap;
        w.kv("name", t.name);
        w.kv("kind", toString(t.kind));
        w.kvf("radius", t.radiusM);
        w.kvf("max_speed", t.maxSpeed);
        w.kvf("max_force", t.maxForce);
        w.kvf("mass", t.mass);
        w.kvf("perception", t.perceptionM);
        w.kvf("view_angle", t.viewAngleDeg);
        w.kvOpt("brain", t.brain);
        w.kvOpt("character", t.character);
        if (t.clips != CharacterClips{}) {
            w.key("clips");
            o << YAML::BeginMap;
            w.kvOpt("idle", t.clips.idle);
            w.kvOpt("walk", t.clips.walk);
            w.kvOpt("run", t.clips.run);
            for (const auto& [action, clip] : t.clips.actions)
                w.kvOpt(action.c_str(), clip);
            o << YAML::EndMap;
        }
        w.key("variation");
        o << YAML::BeginMap;
        if (!t.variation.looks.empty()) {
            w.key("looks");
            o << YAML::Flow << t.variation.looks;
        }
        if (!t.variation.tints.empty()) {
            w.key("tints");
            o << YAML::Flow << YAML::BeginSeq;
            for (const glm::vec3& c : t.variation.tints)
                w.vec3(c);
            o << YAML::EndSeq;
        }
        w.key("height");
        w.vec2(t.variation.heightScale);
        w.key("speed");
        w.vec2(t.variation.speedFactor);
        w.key("phase");
        w.vec2(t.variation.phaseOffset);
        if (t.variation.reactionS != glm::vec2(0.0f)) {
            w.key("reaction");
            w.vec2(t.variation.reactionS);
        }
        if (hasAge(t.variation.ageYears)) {
            w.key("age");
            w.vec2(t.variation.ageYears);
        }
        o << YAML::EndMap;
        if (!t.behaviours.empty()) {
            w.key("behaviours");
            o << YAML::BeginMap;
            for (const BehaviourWeight& b : t.behaviours) {
                if (b.params.empty()) {
                    w.kvf(b.behaviour.c_str(), b.weight);
                    continue;
                }
                w.key(b.behaviour.c_str());
                o << YAML::Flow << YAML::BeginMap;
                w.kvf("weight", b.weight);
                for (const BrainParam& p : b.params)
                    writeParam(w, p);
                o << YAML::EndMap;
            }
            o << YAML::EndMap;
        }
        if (t.priorityCombination)
            w.kv("combination", "priority");
        if (t.minSpeed != 0.0f)
            w.kvf("min_speed", t.minSpeed);
        if (t.banking != 0.0f)
            w.kvf("banking", t.banking);
        if (t.actionBlendS >= 0.0f)
            w.kvf("action_blend", t.actionBlendS);
        if (t.timeGapS > 0.0f)
            w.kvf("time_gap", t.timeGapS);
        detail::writeEmission(w, t.emits);
        if (t.priority != 0.0f)
            w.kvf("priority", t.priority);
        if (t.layer != 0)
            w.kv("layer", std::to_string(t.layer));
        if (t.collidesWith != 0xffffffffu) {
            w.key("collides_with");
            o << YAML::Flow << YAML::BeginSeq;
            for (unsigned l = 0; l < 32; ++l)
                if (t.collidesWith & (1u << l))
                    o << l;
            o << YAML::EndSeq;
        }
        if (t.navigation != Navigation::Direct)
            w.kv("navigation", toString(t.navigation));
        if (t.carFollowing != CarFollowing::Inherit)
            w.kv("car_following", toString(t.carFollowing));
        o << YAML::EndMap;
    }
    o << YAML::EndSeq;
}

void writeAgents(Writer& w, const Scene& s)
{
    YAML::Emitter& o = w.out;
    w.key("agents");
    if (s.agents.size() < kAgentTableThreshold) {
        o << YAML::BeginSeq;
        for (const Agent& a : s.agents) {
            o << YAML::Flow << YAML::BeginMap;
            w.kv("id", std::to_string(a.id));
            w.kv("type", a.type);
            w.key("position");
            w.vec3(a.position);
            w.kvf("heading", a.headingDeg);
            w.kvOpt("goal", a.goal);
            w.kvOpt("path", a.path);
            if (a.leader != 0)
                w.kv("leader", std::to_string(a.leader));
            w.kvOpt("brain", a.brain);
            w.kvOpt("group", a.group);
            if (a.look >= 0)
                w.kv("look", std::to_string(a.look));
            if (a.tint >= 0)
                w.kv("tint", std::to_string(a.tint));
            if (a.heightScale > 0.0f)
                w.kvf("height", a.heightScale);
            o << YAML::EndMap;
        }
        o << YAML::EndSeq;
        return;
    }
    const bool leaders = std::any_of(s.agents.begin(), s.agents.end(), [](const Agent& a) { return a.leader != 0; });
    const bool varied = std::any_of(s.agents.begin(), s.agents.end(),
                                    [](const Agent& a) { return a.look >= 0 || a.tint >= 0 || a.heightScale > 0.0f; });
    const bool brains = std::any_of(s.agents.begin(), s.agents.end(), [](const Agent& a) { return !a.brain.empty(); });
    const bool groups = std::any_of(s.agents.begin(), s.agents.end(), [](const Agent& a) { return !a.group.empty(); });
    std::string rows;
    rows.reserve(s.agents.size() * 48);
    for (const Agent& a : s.agents) {
        rows += std::to_string(a.id) + ' ' + a.type + ' ' + num(a.position.x) + ' ' + num(a.position.y) + ' ' +
                num(a.position.z) + ' ' + num(a.headingDeg) + ' ' + (a.goal.empty() ? "-" : a.goal) + ' ' +
                (a.path.empty() ? "-" : a.path);
        if (leaders)
            rows += ' ' + (a.leader ? std::to_string(a.leader) : std::string("-"));
        if (varied) {
            rows += ' ' + (a.look >= 0 ? std::to_string(a.look) : std::string("-"));
            rows += ' ' + (a.tint >= 0 ? std::to_string(a.tint) : std::string("-"));
            rows += ' ' + (a.heightScale > 0.0f ? num(a.heightScale) : std::string("-"));
        }
        if (brains)
            rows += ' ' + (a.brain.empty() ? std::string("-") : a.brain);
        if (groups)
            rows += ' ' + (a.group.empty() ? std::string("-") : a.group);
        rows += '\n';
    }
    std::vector<std::string> columns{"id", "type", "x", "y", "z", "heading", "goal", "path"};
    if (leaders)
        columns.push_back("leader");
    if (varied)
        columns.insert(columns.end(), {"look", "tint", "height"});
    if (brains)
        columns.push_back("brain");
    if (groups)
        columns.push_back("group");
    o << YAML::BeginMap;
    w.key("columns");
    o << YAML::Flow << columns;
    w.key("rows");
    o << YAML::Literal << rows;
    o << YAML::EndMap;
}

}  // namespace

std::string brainToYaml(const BrainGraph& brain)
{
    Writer w;
    w.out << YAML::BeginMap;
    w.kv("throng_brain", "1");
    writeBrainBody(w, brain);
    w.out << YAML::EndMap;
    return std::string(w.out.c_str()) + "\n";
}

std::string sceneToYaml(const Scene& s)
{
    Writer w;
    YAML::Emitter& o = w.out;
    o << YAML::BeginMap;
    w.kv("throng", std::to_string(Scene::kFormatVersion));
    w.key("settings");
    o << YAML::BeginMap;
    w.kvf("fps", s.settings.fps);
    w.kvf("duration", s.settings.durationS);
    w.kv("seed", std::to_string(s.settings.seed));
    w.key("bounds");
    o << YAML::Flow << YAML::BeginMap;
    w.key("min");
    w.vec2(s.settings.boundsMin);
    w.key("max");
    w.vec2(s.settings.boundsMax);
    o << YAML::EndMap;
    if (s.settings.navCellM != Settings{}.navCellM)
        w.kvf("nav_cell", s.settings.navCellM);
    o << YAML::EndMap;

    if (!s.brains.empty()) {
        w.key("brains");
        o << YAML::BeginSeq;
        for (const BrainGraph& b : s.brains) {
            o << YAML::BeginMap;
            w.kv("name", b.name);
            if (!b.file.empty())
                w.kv("file", b.file);
            else
                writeBrainBody(w, b);
            o << YAML::EndMap;
        }
        o << YAML::EndSeq;
    }
    writeAgentTypes(w, s);
    detail::writeSceneSet(w, s);
    detail::writeSceneTraffic(w, s);
    detail::writeSceneSound(w, s);
    detail::writeSceneActionPoints(w, s);
    detail::writeSceneSources(w, s);
    detail::writeSceneMeasurements(w, s);
    writeAgents(w, s);
    detail::writeSceneLayout(w, s);
    o << YAML::EndMap;
    return std::string(o.c_str()) + "\n";
}

SaveResult writeFileAtomically(const std::string& path, const std::string& text)
{
    AtomicFile file(path);
    if (!file.open())
        return {false, file.error()};
    file.stream().write(text.data(), std::streamsize(text.size()));
    if (!file.commit())
        return {false, file.error()};
    return {true, {}};
}

namespace {

// A file the scene refers to (a brain, keyframes), written where the reference points
// from the scene's new folder. Its folder is made if missing: a demo's "../brains/" does
// not exist beside a Save As into a fresh folder. (The scene's own folder must exist.)
SaveResult writeReferencedFile(const std::string& path, const std::string& text)
{
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
    return writeFileAtomically(path, text);  // reports the folder if it could not be made
}

}  // namespace

SaveResult saveScene(const Scene& scene, const std::string& path)
{
    const std::string baseDir = std::filesystem::path(path).parent_path().string();
    for (const BrainGraph& b : scene.brains) {
        if (b.file.empty())
            continue;
        SaveResult r = writeReferencedFile(detail::resolvePath(baseDir, b.file), brainToYaml(b));
        if (!r.ok)
            return r;
    }
    // Keyframe files hold one "x y z" line per frame; rewriting them beside the scene
    // keeps a Save As into another folder complete.
    for (const Hero& h : scene.heroes) {
        if (h.keyframesFile.empty())
            continue;
        std::string text;
        for (const Keyframe& k : h.keyframes)
            text += num(k.position.x) + ' ' + num(k.position.y) + ' ' + num(k.position.z) + '\n';
        SaveResult r = writeReferencedFile(detail::resolvePath(baseDir, h.keyframesFile), text);
        if (!r.ok)
            return r;
    }
    return writeFileAtomically(path, sceneToYaml(scene));
}

}  // namespace throng::sim
