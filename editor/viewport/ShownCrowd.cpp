#include "editor/viewport/ShownCrowd.h"

#include <algorithm>

namespace throng::editor {

namespace {
constexpr float kFallbackRadiusM = 0.3f;
}  // namespace

void ShownCrowd::setScene(const sim::Scene& scene, const std::string& sceneDirectory)
{
    m_colours.setScene(scene);
    m_changed.characters = m_characters.setScene(scene, sceneDirectory) || m_changed.characters;
    m_typeRadiusM.clear();
    m_typeKind.clear();
    m_typeNames.clear();
    for (const sim::AgentType& t : scene.agentTypes) {
        m_typeRadiusM.push_back(t.radiusM);
        m_typeKind.push_back(t.kind == sim::AgentKind::Vehicle ? Vehicles
                             : t.kind == sim::AgentKind::Flier ? Fliers
                                                               : Walkers);
        m_typeNames.push_back(t.name);
    }
}

float ShownCrowd::radiusOf(std::size_t type) const
{
    return type < m_typeRadiusM.size() ? m_typeRadiusM[type] : kFallbackRadiusM;
}

ShownCrowd::Kind ShownCrowd::kindOf(std::size_t type) const
{
    return type < m_typeKind.size() ? m_typeKind[type] : Walkers;
}

void ShownCrowd::keep(std::span<const sim::AgentFrame> frames, std::span<const sim::AgentInfo> agents)
{
    const std::size_t n = std::min(frames.size(), agents.size());
    if (frames.data() == m_frames.data() && n == m_frames.size())
        return;
    m_frames.assign(frames.begin(), frames.begin() + std::ptrdiff_t(n));
    m_agents.assign(agents.begin(), agents.begin() + std::ptrdiff_t(n));
}

void ShownCrowd::build(std::span<const float> density, double timeS, const sim::FrameCache* cache,
                       std::size_t frameIndex)
{
    const std::size_t n = m_frames.size();
    const std::vector<glm::vec3>& colours = m_colours.coloursFor(m_frames, m_agents, density);
    // A one-shot (a fall) runs from the frame its agent switched to it: the cache says which.
    // And the legs cycle, and a horse changes gait, as the export's do (from the recording).
    m_clipSinceS.clear();
    m_gait.clear();
    if (cache && frameIndex < cache->frameCount() && cache->agentCount() == n) {
        clipSinceS(*cache, frameIndex, m_clipSinceS);
        m_characters.gaitAt(*cache, frameIndex, m_gait);
    }
    m_characters.posesFor(m_frames, m_agents, timeS, m_framePoses, m_clipSinceS, m_gait);
    for (std::size_t k = 0; k < kKinds; ++k) {
        m_glyphs[k].clear();
        m_poses[k].clear();
    }
    m_glyphs[Walkers].reserve(n);
    m_extent = {};
    std::vector<std::size_t> perType(m_typeNames.size(), 0);
    m_counts = {};
    m_shown.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const sim::AgentFrame& f = m_frames[i];
        const std::size_t type = m_agents[i].typeIndex;
        const float radius = radiusOf(type);
        // Not there on this frame (an edit added or removed it), or left through an exit.
        const bool drawn = f.present && !f.out;
        // Picking and the agents' rings follow them from frame to frame.
        m_shown.set(i, m_agents[i].id, f.position, radius, drawn);
        if (!f.present)
            continue;
        m_counts.arrived += f.arrived ? 1 : 0;
        m_counts.out += f.out ? 1 : 0;
        if (!drawn)
            continue;
        ++m_counts.shown;
        if (type < perType.size())
            ++perType[type];
        const Kind kind = kindOf(type);
        m_glyphs[kind].push_back({f.position, f.headingRad, radius, colours[i]});
        m_poses[kind].push_back(m_framePoses[i]);
        m_extent.include({f.position.x, f.position.z}, radius);
    }
    for (std::size_t t = 0; t < perType.size(); ++t)
        if (perType[t] > 0)
            m_counts.perType.emplace_back(m_typeNames[t], perType[t]);
    m_changed.glyphs = true;
}

std::size_t ShownCrowd::glyphCount() const
{
    std::size_t count = 0;
    for (const std::vector<AgentGlyph>& glyphs : m_glyphs)
        count += glyphs.size();
    return count;
}

ShownCrowd::Changed ShownCrowd::takeChanged()
{
    const Changed changed = m_changed;
    m_changed = {};
    return changed;
}

}  // namespace throng::editor
