#include "editor/viewport/ShownSet.h"

#include "editor/viewport/SetGeometryBuilder.h"
#include "export/set/SetSolids.h"

namespace throng::editor {

void ShownSet::setScene(const sim::Scene& scene)
{
    m_shapes.clear();
    SetGeometryBuilder::addSet(scene, m_shapes);
    m_solids.clear();
    exporting::SetSolids::addSet(scene, m_solids);
    m_changed.set = true;
    m_traffic = {};
    m_traffic.lanes = scene.lanes;
    m_traffic.crosswalks = scene.crosswalks;
    m_traffic.trafficLights = scene.trafficLights;
    m_terrain = scene.terrain;
    m_boundsMin = scene.settings.boundsMin;
    m_boundsMax = scene.settings.boundsMax;
    m_extent = setExtent(scene);
}

void ShownSet::light(std::optional<double> timeS)
{
    m_lights.clear();
    SetGeometryBuilder::addLights(m_traffic, timeS, m_lights);
    m_lamps.clear();
    exporting::SetSolids::addLamps(m_traffic.trafficLights, m_terrain, timeS, m_lamps);
    m_changed.lights = true;
}

ShownSet::Changed ShownSet::takeChanged()
{
    const Changed changed = m_changed;
    m_changed = {};
    return changed;
}

}  // namespace throng::editor
