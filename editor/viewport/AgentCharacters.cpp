#include "editor/viewport/AgentCharacters.h"

#include "export/character/AgentVariation.h"
#include "export/character/CharacterLibrary.h"

#include <QDebug>

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {

// m/s: at or above this an agent with an action walks on while it plays it (World's idle
// threshold for a walker).
constexpr float kMovingMps = 0.1f;

// What the characters depend on: each type's kind, character, clips and looks.
std::string signatureOf(const sim::Scene& scene, const std::string& sceneDirectory)
{
    std::string s = sceneDirectory;
    for (const sim::AgentType& t : scene.agentTypes) {
        s += '\n' + std::to_string(int(t.kind)) + '|' + t.character + '|' + t.clips.idle + '|' + t.clips.walk + '|' +
             t.clips.run;
        for (const auto& [action, clip] : t.clips.actions)
            s += '|' + action + '=' + clip;
        for (const std::string& look : t.variation.looks)
            s += '|' + look;
    }
    return s;
}

}  // namespace

bool AgentCharacters::setScene(const sim::Scene& scene, const std::string& sceneDirectory)
{
    m_variations.clear();
    for (const sim::AgentType& t : scene.agentTypes)
        m_variations.push_back(t.variation);
    m_handSet.clear();
    for (const sim::Agent& a : scene.agents)
        if (a.look >= 0 || a.heightScale > 0.0f)
            m_handSet.emplace(a.id, a);
    m_seed = scene.settings.seed;
    m_cachedFor.clear();
    m_looks.clear();
    m_walkersFor.clear();
    m_walkers.clear();
    m_gait.forget();

    const std::string signature = signatureOf(scene, sceneDirectory);
    if (signature == m_signature && m_looksOfType.size() == scene.agentTypes.size())
        return false;
    m_signature = signature;
    m_tables.clear();
    m_problems.clear();
    m_looksOfType.assign(scene.agentTypes.size(), {});
    // Every type on its own: one type's missing file must not take the others' characters.
    // Near agents wear the middle level of detail, far ones the lightest (a software
    // renderer pays for every triangle); a character file, loaded once, serves both.
    const std::size_t types = scene.agentTypes.size();
    exporting::CharacterLibrary library;
    library.setLod(exporting::Lod::Mid);
    const std::vector<std::string> errors = library.resolveEach(scene, sceneDirectory, std::vector<bool>(types, true));
    std::vector<bool> resolvable(types, false);
    for (std::size_t t = 0; t < types; ++t) {
        resolvable[t] = errors[t].empty();
        if (!errors[t].empty())
            m_problems += (m_problems.empty() ? "" : "\n") + errors[t];
    }
    const exporting::CharacterLibrary farLibrary = library.atLod(exporting::Lod::Far);
    m_parts.clear();
    m_gaitCharacters.clear();
    for (std::size_t c = 0; c < library.characterCount(); ++c) {
        m_gaitCharacters.push_back(library.character(c));
        m_gaitCharacters.back().mesh = {};
        m_tables.push_back(buildPoseTable(library.character(c)));
        // A character from a file has one level: its far table is its near one.
        m_tables.push_back(library.fromFile(c) ? m_tables.back() : buildPoseTable(farLibrary.character(c)));
        m_parts.push_back(exporting::partsOf(library.character(c).mesh));
    }
    for (std::size_t t = 0; t < types; ++t)
        if (resolvable[t])
            for (std::size_t c : library.looksOf(t))
                m_looksOfType[t].push_back(int(c));
    if (!m_problems.empty())
        qWarning().noquote() << "throng: these agent types are drawn as glyphs:" << QString::fromStdString(m_problems);
    return true;
}

namespace {

bool sameAgents(std::span<const sim::AgentInfo> a, const std::vector<sim::AgentInfo>& b)
{
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](const auto& x, const auto& y) {
               return x.id == y.id && x.typeIndex == y.typeIndex;
           });
}

}  // namespace

AgentCharacters::Look AgentCharacters::lookOf(const sim::AgentInfo& agent) const
{
    const std::size_t type = agent.typeIndex;
    if (type >= m_looksOfType.size() || m_looksOfType[type].empty())
        return {};
    const std::vector<int>& looks = m_looksOfType[type];
    // As GltfExporter draws and overrides each agent's variation.
    exporting::AgentVariation v = exporting::drawVariation(m_variations[type], m_seed, agent.id, looks.size());
    if (const auto it = m_handSet.find(agent.id); it != m_handSet.end())
        exporting::applyHandSetVariation(v, it->second, looks.size(), m_variations[type].tints.size());
    exporting::applySwappedLook(v, agent, looks.size(), m_variations[type].tints.size());
    const int character = looks[std::min(v.look, looks.size() - 1)];
    std::uint32_t bits = 0;
    for (int slot = 1; slot < exporting::kMaterialSlotCount; ++slot)
        bits |= std::uint32_t(v.colour[std::size_t(slot)] & 7u) << (3 * (slot - 1));
    for (const exporting::MeshPart& part : m_parts[std::size_t(character)])
        if (int(part.slot) >= int(exporting::MaterialSlot::Hat) && exporting::wearsPart(part, m_seed, agent.id))
            bits |= 1u << (24 + int(part.slot) - int(exporting::MaterialSlot::Hat));
    return {character, v.heightScale, bits, v};
}

const std::vector<AgentCharacters::Look>& AgentCharacters::looksFor(std::span<const sim::AgentInfo> agents)
{
    if (sameAgents(agents, m_cachedFor))
        return m_looks;
    m_cachedFor.assign(agents.begin(), agents.end());
    m_looks.resize(agents.size());
    for (std::size_t i = 0; i < agents.size(); ++i)
        m_looks[i] = lookOf(agents[i]);
    return m_looks;
}

void AgentCharacters::gaitAt(const sim::FrameCache& cache, std::size_t frame, std::vector<exporting::GaitFrame>& gait)
{
    // The export walks every agent of the cache in its latest type (FrameCache::agents).
    if (!sameAgents(cache.agents(), m_walkersFor)) {
        m_walkersFor = cache.agents();
        m_walkers.assign(m_walkersFor.size(), GaitPhases::Walker{});
        for (std::size_t i = 0; i < m_walkersFor.size(); ++i) {
            const Look look = lookOf(m_walkersFor[i]);
            if (look.character >= 0)
                m_walkers[i] = {&m_gaitCharacters[std::size_t(look.character)], look.variation};
        }
        m_gait.forget();
    }
    m_gait.gaitAt(cache, frame, m_walkers, gait);
}

void AgentCharacters::posesFor(std::span<const sim::AgentFrame> frames, std::span<const sim::AgentInfo> agents,
                               double timeS, std::vector<AgentPose>& poses, std::span<const float> clipSinceS,
                               std::span<const exporting::GaitFrame> gait)
{
    const std::vector<Look>& looks = looksFor(agents);
    poses.resize(frames.size());
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const Look& look = looks[i];
        poses[i] = {look.character, 0, look.heightScale, look.lookBits};
        if (look.character < 0)
            continue;
        const sim::Clip clip = frames[i].clip;
        const float actionPhase = !sim::isOneShot(clip) ? sim::actionPhase(clip, timeS, agents[i].id)
                                  : i < clipSinceS.size() ? sim::oneShotProgress(clip, double(clipSinceS[i]))
                                                          : 1.0f;
        const bool exported = i < gait.size();
        poses[i].pose = m_tables[std::size_t(look.character) * kLevels].poseFor(
            clip, exported ? float(gait[i].phase - std::floor(gait[i].phase)) : frames[i].phase, actionPhase,
            frames[i].speed >= kMovingMps, frames[i].speed, exported ? gait[i].runWeight : -1.0f);
    }
}

void clipSinceS(const sim::FrameCache& cache, std::size_t frame, std::vector<float>& sinceS)
{
    sinceS.assign(cache.agentCount(), 0.0f);
    if (frame >= cache.frameCount() || !(cache.fps() > 0.0f))
        return;
    for (std::size_t i = 0; i < cache.agentCount(); ++i) {
        const sim::Clip clip = cache.at(frame, i).clip;
        if (!sim::isOneShot(clip))
            continue;
        // Past the clip's length it holds its end: no need to look further back.
        const auto reach = std::size_t(std::ceil(double(sim::clipCycleS(clip)) * double(cache.fps()))) + 1;
        std::size_t back = 0;
        while (back < reach && back < frame && cache.at(frame - back - 1, i).clip == clip)
            ++back;
        sinceS[i] = float(double(back) / double(cache.fps()));
    }
}

}  // namespace throng::editor
