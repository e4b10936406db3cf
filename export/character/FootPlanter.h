#pragma once
// Feet that stay where they land, on the ground under them. Walks one agent's recorded
// motion frame by frame after the gait (gaitPose): while the clip has a foot down, its
// ankle is pinned where it touched down — through walk/run blends, stops, starts and turns
// — and when the clip lifts it, it eases back to the clip over a short release. A standing
// agent's foot that the body has turned or moved away from steps to where the clip wants
// it (a walker's feet lift soon enough by themselves). Each ankle stands on the terrain
// under it, the hips drop as far as the lower leg needs, and a planted sole tilts with the
// slope. A one-shot action (a fall) moves the feet as its clip does. Pure: the same inputs
// give the same poses.

#include "export/character/Gait.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace throng::sim {
struct Terrain;
}

namespace throng::exporting {

// One agent's recorded root motion, one entry per frame (the spans as long as the gait).
struct RootMotion {
    std::span<const glm::vec3> positions;  // m, the root on the ground
    std::span<const glm::quat> yaw;        // the root's turn about +Y
    float heightScale = 1.0f;              // the character's scale
    float fps = 24.0f;
};

class FootPlanter {
public:
    // `terrain` (empty heights: flat ground at each frame's root height) must outlive it.
    FootPlanter(const Character& character, std::span<const GaitFrame> gait, const RootMotion& motion,
                const sim::Terrain& terrain);

    // The next frame's pose (the first call gives frame 0). A character without legs, or a
    // frame past the end, gets gaitPose unchanged.
    Pose next();
    std::size_t frame() const { return m_frame; }

    // Lengths in m at scale 1 (times the agent's height scale), times in s.
    static constexpr float kDownM = 0.015f;       // a clip's ankle this near its planted height is down
    static constexpr float kReleaseS = 0.2f;      // a lifted foot eases back to the clip over this
    static constexpr float kStepLiftM = 0.05f;    // a standing foot's re-step lifts it this high
    static constexpr float kMaxDriftM = 0.3f;     // a planted foot this far from the clip's re-steps
    static constexpr float kMaxTwistRad = 0.6f;   // ... or when the body turned this far over it
    static constexpr float kMaxDropM = 0.3f;      // the hips drop at most this far
    static constexpr float kKeepM = 2e-4f;        // an ankle or the hips this near keep the clip's joints

private:
    struct Foot {
        bool locked = false;
        bool stepping = false;      // released to re-step (lifted on its way)
        glm::vec2 lock{0.0f};       // world (x, z) of the planted ankle
        float lockHeadingRad = 0.0f;
        glm::vec2 offset{0.0f};     // at release: the ankle's (x, z) minus the clip's
        float sinceReleaseS = 1e9f;
    };

    float groundAt(glm::vec2 p, const glm::vec3& root) const;
    glm::vec3 groundNormalAt(glm::vec2 p) const;

    const Character& m_character;
    std::span<const GaitFrame> m_gait;
    RootMotion m_motion;
    const sim::Terrain& m_terrain;
    std::vector<Foot> m_feet;
    std::size_t m_frame = 0;
    std::vector<std::uint8_t> m_legJoints;  // the legs' joints and their ancestors
    std::vector<glm::mat4> m_globals;       // scratch: the legs' joint transforms this frame
    std::vector<glm::vec3> m_targets;       // scratch: per leg, where its ankle goes
    std::vector<float> m_stance;            // scratch: per leg, how far it stands
};

}  // namespace throng::exporting
