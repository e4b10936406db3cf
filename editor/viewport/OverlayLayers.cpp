#include "editor/viewport/OverlayLayers.h"

#include "editor/viewport/SteeringOverlay.h"
#include "editor/viewport/TrailBuilder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace throng::editor {

bool OverlayLayers::setSettings(const ViewportOverlays& settings, std::span<const sim::AgentFrame> frames,
                                bool colourByDensity)
{
    if (settings == m_settings)
        return false;
    const bool fieldsChanged =
        settings.sketchField != m_settings.sketchField || settings.goalField != m_settings.goalField;
    const bool densityChanged = settings.density != m_settings.density;
    m_settings = settings;
    if (fieldsChanged)
        rebuildFields();
    if (densityChanged)
        rebuildDensity(frames, colourByDensity);
    return true;
}

void OverlayLayers::setScene(const sim::Scene& scene)
{
    m_boundsMin = scene.settings.boundsMin;
    m_boundsMax = scene.settings.boundsMax;
    m_fieldParts = FieldArrows::partsOf(scene);
    if (m_fieldGoal >= scene.goals.size())
        m_fieldGoal = 0;
    rebuildFields();
}

bool OverlayLayers::showGoal(std::size_t goal)
{
    if (goal == m_fieldGoal)
        return false;
    m_fieldGoal = goal;
    if (m_settings.goalField)
        rebuildFields();
    return true;
}

void OverlayLayers::rebuildFields()
{
    m_fieldMesh.clear();
    m_changed.fields = true;
    if (!m_settings.sketchField && !m_settings.goalField)
        return;
    m_fields.setScene(m_fieldParts);  // builds again only when the parts changed
    constexpr float kWantedSpacingM = 1.0f;
    const float spacing = FieldArrows::spacingFor(m_boundsMin, m_boundsMax, kWantedSpacingM);
    if (m_settings.sketchField)
        m_fields.addSketchArrows(m_fieldMesh, spacing);
    if (m_settings.goalField && m_fieldGoal < m_fields.goalCount())
        m_fields.addGoalArrows(m_fieldGoal, m_fieldMesh, spacing);
}

void OverlayLayers::rebuildDensity(std::span<const sim::AgentFrame> frames, bool colourByDensity)
{
    const bool map = m_settings.density;
    if (!map && !colourByDensity) {
        if (!m_heat.empty()) {
            m_heat.clear();
            m_changed.heat = true;
        }
        return;
    }
    m_heatmap.build(frames, m_boundsMin, m_boundsMax);
    m_density.resize(frames.size());
    for (std::size_t i = 0; i < frames.size(); ++i)
        m_density[i] = m_heatmap.densityAt({frames[i].position.x, frames[i].position.z});
    m_heat.clear();
    if (map)
        m_heatmap.addCells(m_heat);
    m_changed.heat = true;
}

void OverlayLayers::rebuildLines(const sim::FrameCache* cache, std::size_t frame,
                                 const std::vector<std::size_t>& followed, float fps)
{
    m_lines.clear();
    if (m_settings.trails && cache && frame < cache->frameCount()) {
        const auto frames = std::size_t(std::lround(double(m_settings.trailSeconds) * double(fps)));
        TrailBuilder::add(*cache, frame, followed, std::max<std::size_t>(2, frames), m_lines);
    }
    if (m_settings.steering)
        SteeringOverlay::add(m_steering, m_lines);
    m_changed.lines = true;
}

void OverlayLayers::addLegends(HudFigures& figures, bool anyWatched) const
{
    if (m_settings.density) {
        char peak[96];
        std::snprintf(peak, sizeof peak, "Density map (agents per m², peak %.1f)", double(m_heatmap.maxDensity()));
        ColourLegend density{peak, {}, true, 0};
        for (const DensityHeatmap::ScaleStop& stop : DensityHeatmap::scale())
            density.entries.push_back({std::to_string(int(stop.density)), glm::vec3(stop.colour)});
        density.entries.back().label += " and more";
        figures.legends.push_back(std::move(density));
    }
    if (m_settings.sketchField) {
        std::string note = "Sketched field: ";
        if (m_fieldParts.flowStrokes.empty())
            note += "the scene has no flow strokes";
        else if (!m_fields.sketchError().empty())
            note += m_fields.sketchError();
        else
            note += std::to_string(m_fieldParts.flowStrokes.size()) + " strokes";
        figures.legends.push_back({note, {{"arrows", glm::vec3(FieldArrows::kSketchColour)}}, false, 0});
    }
    if (m_settings.goalField)
        figures.legends.push_back({m_fieldGoal < m_fieldParts.goals.size()
                                       ? "Flow field to goal '" + m_fieldParts.goals[m_fieldGoal].name + "'"
                                       : std::string("Flow field: the scene has no goal"),
                                   {{"arrows", glm::vec3(FieldArrows::kGoalColour)}},
                                   false,
                                   0});
    if (m_settings.steering) {
        constexpr std::size_t kDescribed = 2;  // agents whose forces the HUD lists
        for (std::size_t k = 0; k < m_steering.size() && k < kDescribed; ++k)
            figures.legends.push_back(SteeringOverlay::describe(m_steering[k]));
        if (m_steering.empty())
            figures.legends.push_back({anyWatched ? "Steering: computing the shown frame"
                                                  : "Steering: select an agent to see its steering",
                                       {}, false, 0});
    }
}

OverlayLayers::Changed OverlayLayers::takeChanged()
{
    const Changed changed = m_changed;
    m_changed = {false, false, false};
    return changed;
}

}  // namespace throng::editor
