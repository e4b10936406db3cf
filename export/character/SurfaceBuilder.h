#pragma once
// Appends smooth, closed, skinned surfaces to a CharacterMesh: tubes lofted through
// elliptical sections, with rounded or flat ends, for limbs, torso, head, hair and
// accessories. Normals are averaged over each surface; skin weights blend from one joint
// to the next along a tube, so a bent elbow or knee stays one surface. How fine the
// surfaces are comes from the level of detail. Geometry only; never knows a character.

#include "export/character/Character.h"

#include <array>
#include <vector>

namespace throng::exporting {

// A key section of a tube: an ellipse about `centre` with radius `depth` along the tube's
// forward reference and `width` across it. `slot` is the material of the stretch from
// this section to the next (the last section's: its end cap's).
struct TubeSection {
    glm::vec3 centre{0.0f};
    float depth = 0.0f, width = 0.0f;  // m
    MaterialSlot slot = MaterialSlot::Skin;
};

// The joint a tube follows from `at` on, `at` counted in sections (1.5: halfway from the
// second section to the third); the first bone starts at 0.
struct TubeBone {
    int joint = 0;
    float at = 0.0f;
};

struct Tube {
    std::vector<TubeSection> sections;   // at least 2, in order along the tube
    glm::vec3 forward{1.0f, 0.0f, 0.0f};  // what `depth` measures along (made square to the axis)
    std::vector<TubeBone> bones;          // at least one; weights blend over +-blendM at each start
    float blendM = 0.05f;
    float startCapM = -1.0f, endCapM = -1.0f;  // depth of the end domes, m; 0 = flat; < 0 = the smaller radius
    bool small = false;                        // a small feature: fewer segments, and none at Lod::Far
};

class SurfaceBuilder {
public:
    SurfaceBuilder(CharacterMesh& mesh, Lod lod);

    // Appends one closed tube. Its vertices are bound to at most two joints each.
    void tube(const Tube& tube);
    // The share of agents that wear the parts of `slot` (accessories); 1 by default.
    void setWornShare(MaterialSlot slot, float share) { m_share[static_cast<std::size_t>(slot)] = share; }
    // Writes the triangles into the mesh's indices, grouped into one part per slot used.
    void finish();

private:
    struct Ring {
        glm::vec3 centre, u, v;  // u along depth, v along width, both square to the axis
        float depth, width, s;   // s: arc length along the tube, m
        MaterialSlot slot;
    };
    std::vector<Ring> rings(const Tube& tube, std::vector<float>& sectionS) const;

    CharacterMesh& m_mesh;
    int m_segments, m_subdivisions, m_domeRings;
    bool m_far;
    std::array<std::vector<std::uint32_t>, kMaterialSlotCount> m_triangles;
    std::array<float, kMaterialSlotCount> m_share;
};

}  // namespace throng::exporting
