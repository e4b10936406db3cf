// Measurements (`measurements`): lines and areas the analysis of a run reads (Scene.h,
// Measurement); they change nothing in the simulation.
#include "simcore/io/detail/SetReader.h"

#include "simcore/scene/GroundPolygon.h"

namespace throng::sim::detail {

void SetReader::readMeasurements(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "measurements"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("measurements", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"name", "line", "area"});
        Measurement m;
        if (m_f.readName(item, "name", key, m.name, true))
            m_names.claim(item, key, m.name, "measurement");
        const YAML::Node line = item["line"], area = item["area"];
        if (line.IsDefined() == area.IsDefined()) {
            m_f.error(item.Mark(), key, "give a 'line: [[x, z], [x, z]]' or an 'area: [[x, z], [x, z], [x, z], ...]'");
            continue;
        }
        if (line.IsDefined()) {
            m.shape = MeasurementShape::Line;
            if (!m_f.readPolyline(item, "line", key, m.points, true, 2))
                continue;
            if (m.points.size() != 2) {
                m_f.error(line.Mark(), key + ".line", "a measurement line has two points, its ends");
                continue;
            }
            if (m.points[0] == m.points[1]) {
                m_f.error(line.Mark(), key + ".line", "the line's ends are the same point");
                continue;
            }
        } else {
            m.shape = MeasurementShape::Area;
            if (!m_f.readPolyline(item, "area", key, m.points, true, 3))
                continue;
            // Corners on one line fold back over each other, so this also refuses an empty area.
            if (polygonSelfCrossing(m.points)) {
                m_f.error(area.Mark(), key + ".area", "the area's outline crosses itself");
                continue;
            }
        }
        scene.measurements.push_back(std::move(m));
    }
}

}  // namespace throng::sim::detail
