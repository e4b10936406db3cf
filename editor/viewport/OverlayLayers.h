#pragma once
// The overlays over the set on the CPU side: which the user turned on (ViewportOverlays)
// and their meshes, rebuilt when what they show changes and flagged until the viewport
// uploads them: the trails and the watched agents' steering (lines), the sketched and
// goal fields' arrows (fields), the density map (heat). Also the HUD's legends for them.
// Owns no GL and never edits the scene.

#include "editor/viewport/DensityHeatmap.h"
#include "editor/viewport/FieldArrows.h"
#include "editor/viewport/ShapeMesh.h"
#include "editor/viewport/ViewportHud.h"
#include "editor/viewport/ViewportOverlays.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/DebugSink.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace throng::editor {

class OverlayLayers {
public:
    const ViewportOverlays& settings() const { return m_settings; }
    // Turns overlays on and off; the fields and the density map (of `frames`) are rebuilt
    // when theirs changed. colourByDensity: the agents are coloured by density, so the
    // density is needed even without its map. False when nothing changed.
    bool setSettings(const ViewportOverlays& settings, std::span<const sim::AgentFrame> frames, bool colourByDensity);
    // A new or edited scene: the fields' parts and the set's bounds.
    void setScene(const sim::Scene& scene);
    // The goal whose flow field the goal field shows; false when it already was.
    bool showGoal(std::size_t goal);
    // The density map of the shown frame and each of its agents' density (agents per m²),
    // when the map is on or colourByDensity; else the map is cleared.
    void rebuildDensity(std::span<const sim::AgentFrame> frames, bool colourByDensity);
    const std::vector<float>& density() const { return m_density; }
    // The watched agents' steering annotations on the shown frame.
    void setSteering(std::vector<sim::AgentDebug> agents) { m_steering = std::move(agents); }
    const std::vector<sim::AgentDebug>& steering() const { return m_steering; }
    // The trails (the `followed` agents' last trailSeconds before `frame` of `cache`, at
    // fps frames a second; none without a cache) and the steering annotations.
    void rebuildLines(const sim::FrameCache* cache, std::size_t frame, const std::vector<std::size_t>& followed,
                      float fps);
    // The legends of the overlays that are on. anyWatched: an agent is selected, focused
    // or inspected (the steering legend says what to do when none is).
    void addLegends(HudFigures& figures, bool anyWatched) const;

    // The meshes and whether each changed since the last upload (takeChanged clears it).
    const ShapeMesh& lines() const { return m_lines; }
    const ShapeMesh& fields() const { return m_fieldMesh; }
    const ShapeMesh& heat() const { return m_heat; }
    struct Changed {
        bool lines, fields, heat;
    };
    Changed takeChanged();
    // After the GL objects were made again: every mesh must be uploaded.
    void markAllChanged() { m_changed = {true, true, true}; }

private:
    void rebuildFields();

    ViewportOverlays m_settings;
    std::vector<sim::AgentDebug> m_steering;
    FieldArrows m_fields;
    sim::Scene m_fieldParts;  // what the fields are built from (FieldArrows::partsOf)
    std::size_t m_fieldGoal = 0;  // the selected goal, else the first
    glm::vec2 m_boundsMin{-50.0f}, m_boundsMax{50.0f};
    DensityHeatmap m_heatmap;
    std::vector<float> m_density;  // agents per m² where each shown agent stands
    ShapeMesh m_lines, m_fieldMesh, m_heat;
    Changed m_changed{true, true, true};
};

}  // namespace throng::editor
