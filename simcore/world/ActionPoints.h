#pragma once
// The action point phase (Scene.h, ActionPoint; Musse's action points): at the end of each
// step, on the positions it ended at, a walker whose centre entered an action point stops
// there with the point's chance. While it plays the point's action it is held like one
// that has arrived (stopped: the move phase leaves it where it stands and the others go
// round it), turns to the point's facing at kTurnDegPerS, and after the point's duration
// it is let go to its goal or path. It stops at a point once per visit: again only after
// its centre has left the disk. Each agent reads and writes only its own columns, so the
// result is the same for any thread count; durations count in steps of the World's dt,
// so a frame rate changes when an agent goes on by less than a frame.

#include "simcore/scene/Clip.h"
#include "simcore/world/AgentColumns.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace throng::sim {

struct Scene;
struct StaticSet;
struct StepView;

// How fast an agent at an action point turns to its facing, degrees/s.
inline constexpr float kActionTurnDegPerS = 180.0f;

// One action point as a World plays it, in the World's coordinates.
struct ActionPlace {
    glm::vec2 position{0.0f};
    float radiusM = 1.0f;
    Clip clip = Clip::LookAround;
    float durationS = 1.0f;
    bool faces = false;
    glm::vec3 facing{1.0f, 0.0f, 0.0f};  // unit, on the ground
    float chance = 1.0f;
    std::vector<std::uint8_t> forType;  // per agent type: 1 = its walkers stop here
};

// The scene's action points for a World of it: type names resolved, actions to clips.
std::vector<ActionPlace> actionPlaces(const Scene& scene);

// The step's action point phase. Writes agents' pointAt, pointLeftS, pointLast, stopped,
// and for an agent at a point its vel, fwd and side.
void playActionPoints(const StepView& v, AgentColumns& agents);

// The clip agent i plays at its action point, else `otherwise`.
inline Clip actionPointClip(const std::vector<ActionPlace>& places, const AgentColumns& agents, std::size_t i,
                            Clip otherwise)
{
    const std::int32_t p = agents.pointAt.empty() ? -1 : agents.pointAt[i];
    return p >= 0 ? places[std::size_t(p)].clip : otherwise;
}

}  // namespace throng::sim
