#include "editor/viewport/AgentColours.h"

#include "editor/viewport/DensityHeatmap.h"
#include "editor/viewport/ViewportPalette.h"
#include "export/character/AgentVariation.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace throng::editor {

const char* colourByName(ColourBy by)
{
    switch (by) {
    case ColourBy::Tint: return "Tint";
    case ColourBy::Type: return "Type";
    case ColourBy::Group: return "Group";
    case ColourBy::Goal: return "Goal";
    case ColourBy::Path: return "Path";
    case ColourBy::Brain: return "Brain";
    case ColourBy::Speed: return "Speed";
    case ColourBy::Density: return "Density";
    }
    return "Tint";
}

namespace {

AgentCategories::Key categoryKey(ColourBy by)
{
    switch (by) {
    case ColourBy::Goal: return AgentCategories::Key::Goal;
    case ColourBy::Path: return AgentCategories::Key::Path;
    case ColourBy::Brain: return AgentCategories::Key::Brain;
    default: return AgentCategories::Key::Group;
    }
}

std::string number(float v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(v));
    return text;
}

}  // namespace

glm::vec3 AgentColours::categoryColour(int index)
{
    // Tableau 10: distinct at a glance, repeating after ten.
    static constexpr std::array<glm::vec3, kCategoryColours> kColours{{
        {0.306f, 0.475f, 0.655f},
        {0.949f, 0.557f, 0.169f},
        {0.882f, 0.341f, 0.349f},
        {0.463f, 0.718f, 0.698f},
        {0.349f, 0.631f, 0.310f},
        {0.929f, 0.788f, 0.282f},
        {0.690f, 0.478f, 0.631f},
        {1.000f, 0.616f, 0.655f},
        {0.612f, 0.459f, 0.373f},
        {0.729f, 0.690f, 0.675f},
    }};
    return index < 0 ? kNoCategory : kColours[std::size_t(index) % kColours.size()];
}

glm::vec3 AgentColours::gradientColour(float t)
{
    static constexpr std::array<glm::vec3, 5> kStops{{
        {0.231f, 0.298f, 0.753f},  // blue: standing
        {0.200f, 0.700f, 0.850f},  // cyan
        {0.300f, 0.780f, 0.350f},  // green
        {0.950f, 0.820f, 0.200f},  // yellow
        {0.880f, 0.200f, 0.170f},  // red: flat out
    }};
    const float x = std::clamp(std::isfinite(t) ? t : 0.0f, 0.0f, 1.0f) * float(kStops.size() - 1);
    const std::size_t k = std::min(std::size_t(x), kStops.size() - 2);
    return glm::mix(kStops[k], kStops[k + 1], x - float(k));
}

void AgentColours::setScene(const sim::Scene& scene)
{
    m_variations.clear();
    m_typeNames.clear();
    m_typeTopSpeed.clear();
    for (const sim::AgentType& t : scene.agentTypes) {
        m_variations.push_back(t.variation);
        m_typeNames.push_back(t.name);
        m_typeTopSpeed.push_back(t.maxSpeed * std::max(1.0f, t.variation.speedFactor.y));
    }
    m_handTint.clear();
    for (const sim::Agent& a : scene.agents)
        if (a.tint >= 0)
            m_handTint[a.id] = a.tint;
    m_seed = scene.settings.seed;
    m_categories.setScene(scene);
    m_cachedFor.clear();
    m_colours.clear();
}

void AgentColours::setColourBy(ColourBy by)
{
    m_by = by;
}

glm::vec3 AgentColours::tint(const sim::AgentInfo& agent) const
{
    const std::size_t type = agent.typeIndex;
    const std::vector<glm::vec3>* tints = type < m_variations.size() ? &m_variations[type].tints : nullptr;
    if (!tints || tints->empty())
        return glm::vec3(palette::agentColour(type));
    const auto hand = m_handTint.find(agent.id);
    int index = hand != m_handTint.end() ? hand->second
                                          : exporting::drawVariation(m_variations[type], m_seed, agent.id, 1).tint;
    // A layout layer's swap shows another tint (or none: the type's own colour).
    if (agent.tint == -1)
        return glm::vec3(palette::agentColour(type));
    if (agent.tint >= 0 && std::size_t(agent.tint) < tints->size())
        index = agent.tint;
    index = std::clamp(index, 0, int(tints->size()) - 1);
    return (*tints)[std::size_t(index)];
}

void AgentColours::colourCategories(std::span<const sim::AgentInfo> agents)
{
    for (std::size_t i = 0; i < agents.size(); ++i) {
        switch (m_by) {
        case ColourBy::Tint: m_colours[i] = tint(agents[i]); break;
        case ColourBy::Type: m_colours[i] = glm::vec3(palette::agentColour(agents[i].typeIndex)); break;
        default: m_colours[i] = categoryColour(m_categories.of(categoryKey(m_by), agents[i].id)); break;
        }
    }
}

const std::vector<glm::vec3>& AgentColours::coloursFor(std::span<const sim::AgentFrame> frames,
                                                       std::span<const sim::AgentInfo> agents,
                                                       std::span<const float> density)
{
    if (perFrame()) {
        m_cachedFor.clear();
        m_colours.resize(agents.size());
        for (std::size_t i = 0; i < agents.size(); ++i) {
            if (m_by == ColourBy::Density) {
                m_colours[i] = glm::vec3(DensityHeatmap::colourFor(i < density.size() ? density[i] : 0.0f));
                continue;
            }
            const std::size_t type = agents[i].typeIndex;
            const float top = type < m_typeTopSpeed.size() && m_typeTopSpeed[type] > 0.0f ? m_typeTopSpeed[type] : 1.4f;
            m_colours[i] = gradientColour(i < frames.size() ? frames[i].speed / top : 0.0f);
        }
        return m_colours;
    }
    const bool same = m_cachedBy == m_by && agents.size() == m_cachedFor.size() &&
                      std::equal(agents.begin(), agents.end(), m_cachedFor.begin(), [](const auto& a, const auto& b) {
                          return a.id == b.id && a.typeIndex == b.typeIndex;
                      });
    if (same)
        return m_colours;
    m_cachedFor.assign(agents.begin(), agents.end());
    m_cachedBy = m_by;
    m_colours.resize(agents.size());
    colourCategories(agents);
    return m_colours;
}

ColourLegend AgentColours::legend() const
{
    ColourLegend legend;
    legend.title = colourByName(m_by);
    auto add = [&](std::string label, glm::vec3 colour) {
        if (legend.entries.size() < kLegendEntries)
            legend.entries.push_back({std::move(label), colour});
        else
            ++legend.more;
    };
    switch (m_by) {
    case ColourBy::Tint:
        legend.title = "Tint (each type's palette)";
        break;
    case ColourBy::Type:
        for (std::size_t t = 0; t < m_typeNames.size(); ++t)
            add(m_typeNames[t], glm::vec3(palette::agentColour(t)));
        break;
    case ColourBy::Speed:
        legend.title = "Speed (of the type's top speed)";
        legend.gradient = true;
        for (int k = 0; k <= 4; ++k)
            legend.entries.push_back({std::to_string(k * 25) + " %", gradientColour(float(k) / 4.0f)});
        break;
    case ColourBy::Density:
        legend.title = "Density (agents per m²)";
        legend.gradient = true;
        for (const DensityHeatmap::ScaleStop& stop : DensityHeatmap::scale())
            legend.entries.push_back({number(stop.density), glm::vec3(stop.colour)});
        legend.entries.back().label += " and more";
        break;
    default: {
        const std::vector<std::string>& names = m_categories.names(categoryKey(m_by));
        for (std::size_t k = 0; k < names.size(); ++k)
            add(names[k], categoryColour(int(k)));
        add("none", kNoCategory);
        break;
    }
    }
    return legend;
}

}  // namespace throng::editor
