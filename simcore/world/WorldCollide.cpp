// The collide pass's per-agent step (World::step calls it for every agent, after the
// steer phase): the agent's proposed position, nudged out of the bodies it overlaps
// (separateBodies, WorldStep.cpp), capped at its max speed, and for walkers kept out of
// walls and obstacles.
#include "simcore/world/World.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace throng::sim {

void World::resolveCollision(std::size_t i, bool collideFree, bool hasStatics)
{
    if (m_stopped[i]) {  // frozen where it stands
        m_resolvedPos[i] = m_nextPos[i];
        return;
    }
    glm::vec3 p = m_nextPos[i] + (collideFree ? glm::vec3(0.0f) : separateBodies(i));
    const bool flying = m_steering[m_info[i].typeIndex].vehicle.flying;
    // Nobody moves faster than its max speed, nudges included, so what the viewer
    // sees and the gait it is animated with always agree. A brain's lower speed holds
    // back only the walker's progress: pushes may move it aside or back, so a walker
    // its brain stops still gives way, but never on past where its brain holds it.
    glm::vec3 move = p - m_pos[i];
    if (m_brains) {
        if (const glm::vec3 held = brainLimited(i, move, m_maxSpeed[i], m_dt); held != move) {
            move = held;
            p = m_pos[i] + move;
        }
    }
    const float maxMove = m_maxSpeed[i] * m_dt, moved = glm::length(move);
    if (moved > maxMove && moved > 0.0f)
        p = m_pos[i] + move * (maxMove / moved);
    if (!flying) {
        if (hasStatics)
            constrain(i, m_pos[i], p);
        p.y = m_nextPos[i].y;
        // A walker's velocity is the move it made (nobody reads another's in this pass).
        m_nextVel[i] = (p - m_pos[i]) / m_dt;
        m_nextVel[i].y = 0.0f;
    }
    m_resolvedPos[i] = p;
}

}  // namespace throng::sim
