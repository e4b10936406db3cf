#pragma once
// A hero's keyframed root motion: position, velocity and heading at any time, passing
// exactly through every keyframe, and the push that clears a walker out of the hero's
// room. The hero is never pushed: nothing here changes a track after construction.

#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace throng::sim {

enum class HeroInterpolation {
    Linear,      // straight between keyframes (velocity jumps at each keyframe)
    CatmullRom,  // cubic Hermite with Catmull-Rom tangents over non-uniform times (smooth)
};

class HeroTrack {
public:
    HeroTrack() = default;
    // From a hero of the scene (a keyframes file is already keyed at frame / fps by the
    // loader). Catmull-Rom is the default.
    explicit HeroTrack(const Hero& hero, HeroInterpolation mode = HeroInterpolation::CatmullRom);
    // keys: at least one, strictly increasing times (as the scene loader guarantees).
    HeroTrack(std::vector<Keyframe> keys, float clearanceM, HeroInterpolation mode = HeroInterpolation::CatmullRom);

    // Keyframes from one position per frame, frame n at n / fps (the "x y z" file form).
    static std::vector<Keyframe> fromFrames(const std::vector<glm::vec3>& positions, float fps);

    // Before the first keyframe the hero waits at it, after the last it stays there.
    // Within 10 microseconds of a keyframe's time the result is that keyframe, bit for bit.
    glm::vec3 positionAt(double timeS) const;
    glm::vec3 velocityAt(double timeS) const;  // m/s; zero outside the keyed range
    // Ground direction (x, z) of travel, unit; while standing, the last one it moved in
    // (or the next one, before it first moves; +x for a hero that never moves).
    glm::vec2 forwardAt(double timeS) const;
    // Heading in the scene's convention: degrees, 0 = +x, counter-clockwise from above.
    float headingDegAt(double timeS) const;

    float clearanceM() const { return m_clearanceM; }
    HeroInterpolation mode() const { return m_mode; }
    const std::vector<Keyframe>& keyframes() const { return m_keys; }
    double startS() const { return m_keys.empty() ? 0.0 : double(m_keys.front().timeS); }
    double endS() const { return m_keys.empty() ? 0.0 : double(m_keys.back().timeS); }

private:
    std::size_t segmentAt(double timeS) const;  // k with t_k <= t < t_k+1
    glm::vec3 tangent(std::size_t k) const;      // dp/dt at keyframe k

    std::vector<Keyframe> m_keys;
    float m_clearanceM = 2.0f;
    HeroInterpolation m_mode = HeroInterpolation::CatmullRom;
};

// How a walker makes room for a hero (ground plane).
struct HeroPush {
    bool inside = false;         // the walker's body reaches into the hero's clearance
    glm::vec2 displacement{0.0f};// m: moves the walker's centre to clearance + radius from the hero
    glm::vec2 velocity{0.0f};    // m/s: a make-room velocity (sideways off the hero's line when it moves)
};

// The push for a walker at walkerPos (body radius walkerRadiusM) near a hero at heroPos
// moving with heroVelocity and keeping clearanceM free. Only the walker moves. A walker
// exactly at the hero's centre is sent to a side chosen by walkerId, so two such walkers
// part instead of moving as one.
HeroPush heroPush(glm::vec2 heroPos, glm::vec2 heroVelocity, float clearanceM, glm::vec2 walkerPos,
                  float walkerRadiusM, std::uint32_t walkerId);

}  // namespace throng::sim
