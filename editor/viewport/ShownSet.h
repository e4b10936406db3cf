#pragma once
// The set of the shown scene as the viewport draws it, kept on the CPU until the next paint
// uploads it: its ground shapes (walls, paths, goals, ...), its 3D solids, and its traffic
// lights and lamps lit as they are at the shown moment; with the ground it stands on and the
// extent a camera frames. Plain scene data and meshes; never touches GL or edits the scene.

#include "editor/viewport/GroundBox.h"
#include "editor/viewport/ShapeMesh.h"
#include "export/set/SolidMesh.h"
#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

#include <optional>

namespace throng::editor {

class ShownSet {
public:
    // The set of `scene`; its lights come with light().
    void setScene(const sim::Scene& scene);
    // The traffic lights and lamps as they are at `timeS` (grey when unknown).
    void light(std::optional<double> timeS);

    const ShapeMesh& shapes() const { return m_shapes; }
    const exporting::SolidMesh& solids() const { return m_solids; }
    const ShapeMesh& lights() const { return m_lights; }
    const exporting::SolidMesh& lamps() const { return m_lamps; }
    const sim::Terrain& terrain() const { return m_terrain; }
    glm::vec2 boundsMin() const { return m_boundsMin; }
    glm::vec2 boundsMax() const { return m_boundsMax; }
    // Everything drawn of the set; empty for an empty scene (setExtent).
    const GroundBox& extent() const { return m_extent; }

    // What changed since the last call: the set (shapes and solids), the lights (and lamps).
    struct Changed {
        bool set = false, lights = false;
    };
    Changed takeChanged();
    // The next takeChanged reports everything (a new GL context has nothing uploaded).
    void markAllChanged() { m_changed = {true, true}; }

private:
    ShapeMesh m_shapes, m_lights;
    exporting::SolidMesh m_solids, m_lamps;
    sim::Scene m_traffic;  // lanes, crosswalks and lights only: relit every frame
    sim::Terrain m_terrain;
    glm::vec2 m_boundsMin{-50.0f}, m_boundsMax{50.0f};
    GroundBox m_extent;
    Changed m_changed{true, true};
};

}  // namespace throng::editor
