// The collide pass's per-agent step (World::step calls it for every agent, after the
// steer phase): the agent's proposed position, nudged out of the bodies it overlaps
// (separateBodies, WorldStep.cpp), capped at its max speed, and for walkers kept out of
// walls and obstacles. Then the contact rounds, which part the ground bodies that still
// overlap.
#include "simcore/world/World.h"

#include "simcore/world/Constraints.h"

#include "simcore/world/detail/StepConstants.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>

namespace throng::sim {

void World::resolveCollision(std::size_t i, bool collideFree, bool hasStatics)
{
    if (m_agents.stopped[i]) {  // frozen where it stands
        m_agents.resolvedPos[i] = m_agents.nextPos[i];
        return;
    }
    glm::vec3 p = m_agents.nextPos[i] + (collideFree ? glm::vec3(0.0f) : separateBodies(i));
    const bool flying = m_types.steering[m_agents.info[i].typeIndex].vehicle.flying;
    // Nobody moves faster than its max speed, nudges included, so what the viewer
    // sees and the gait it is animated with always agree. A brain's lower speed holds
    // back only the walker's progress: pushes may move it aside or back, so a walker
    // its brain stops still gives way, but never on past where its brain holds it.
    glm::vec3 move = p - m_agents.pos[i];
    if (m_brains.active()) {
        if (const glm::vec3 held = m_brains.limited(view(), i, move, m_agents.maxSpeed[i], m_clock.dt); held != move) {
            move = held;
            p = m_agents.pos[i] + move;
        }
    }
    const float maxMove = m_agents.maxSpeed[i] * m_clock.dt, moved = glm::length(move);
    if (moved > maxMove && moved > 0.0f)
        p = m_agents.pos[i] + move * (maxMove / moved);
    if (!flying) {
        if (hasStatics)
            constrain(m_agents, m_set, m_clock.dt, i, m_agents.pos[i], p);
        p.y = m_agents.nextPos[i].y;
        // A walker's velocity is the move it made (nobody reads another's in this pass).
        m_agents.nextVel[i] = (p - m_agents.pos[i]) / m_clock.dt;
        m_agents.nextVel[i].y = 0.0f;
    }
    m_agents.resolvedPos[i] = p;
}

// The contact rounds. One collide pass leaves a dense crowd pressed into itself: each
// walker parts from its neighbours' proposed places while they part from its own, and a
// walker squeezed from both sides moves little. In a jam at a door that left pairs
// pressed 5 % into each other in the steady crowd, 12 % at worst (issue 23). Each round
// is the collide pass again on the places the last one left (Jacobi: every agent reads
// the round's places and writes only its own, so any thread count gives the same), with
// walls kept hard, until no pair overlaps by more than kContactSlopM or kContactRounds.
// A walker's move still keeps to its max speed and its brain's hold, and its velocity is
// the move it made. World::step runs the rounds on each decision (StepRate.h), so the
// crowd is parted 24 times a second at any frame rate. Dense crowds at doors 0.8 to 2.4 m
// wide now press 2.5 to 4.5 % into each other at the 95th percentile (TestBottleneckFamily);
// more rounds (8) gained little there and left walkers standing in front of the gaps
// between others who had stopped (TestCrowdSteering's ring: 8 of 120 against 2).
void World::settleContacts(bool hasStatics)
{
    const std::size_t n = m_agents.pos.size();
    m_agents.contactMoved.assign(n, 0);
    bool anyMoved = false;
    for (int round = 0; round < detail::kContactRounds; ++round) {
        const std::uint64_t moved = m_team.sumChunks(n, 256, [&](std::size_t begin, std::size_t end, int) {
            std::uint64_t count = 0;
            for (std::size_t i = begin; i < end; ++i)
                count += settleRound(i, hasStatics);
            return count;
        });
        std::swap(m_agents.nextPos, m_agents.resolvedPos);  // the round's places are the resolved ones
        if (moved == 0)
            break;
        anyMoved = true;
    }
    if (!anyMoved)
        return;
    m_team.forEach(n, 256, [&](std::size_t i) {
        if (!m_agents.contactMoved[i])
            return;
        glm::vec3 p = m_agents.resolvedPos[i], move = p - m_agents.pos[i];
        if (m_brains.active())
            move = m_brains.limited(view(), i, move, m_agents.maxSpeed[i], m_clock.dt);
        const float maxMove = m_agents.maxSpeed[i] * m_clock.dt, moved = glm::length(move);
        if (moved > maxMove && moved > 0.0f)
            move *= maxMove / moved;
        if (move != p - m_agents.pos[i]) {
            p = m_agents.pos[i] + move;
            if (hasStatics)
                constrain(m_agents, m_set, m_clock.dt, i, m_agents.pos[i], p);
        }
        p.y = m_set.groundHeight(p.x, p.z);
        m_agents.resolvedPos[i] = p;
        m_agents.nextVel[i] = (p - m_agents.pos[i]) / m_clock.dt;
        m_agents.nextVel[i].y = 0.0f;
    });
}

// Whether the contact rounds move agent i: a walking ground body (not one that stands,
// has left, flies, is driven along a lane, walks out of an obstacle or waits off stage).
bool World::settles(std::size_t i) const
{
    return !m_agents.stopped[i] && !m_agents.out[i] && !m_types.steering[m_agents.info[i].typeIndex].vehicle.flying && !m_traffic.isDriven(i) &&
           !m_agents.escaping[i] && !(m_traffic.anyOffStage && m_traffic.offStage[i]);
}

bool World::settleRound(std::size_t i, bool hasStatics)
{
    const glm::vec3 p = m_agents.resolvedPos[i];
    m_agents.nextPos[i] = p;
    if (!settles(i))
        return false;
    glm::vec3 push(0.0f);
    const std::uint32_t* near = &m_agents.nearIndex[i * kMaxNeighbours];
    for (std::size_t k = 0; k < m_agents.nearCount[i]; ++k) {
        const std::uint32_t j = near[k];
        if (m_traffic.anyOffStage && m_traffic.offStage[j])
            continue;
        glm::vec3 d = p - m_agents.resolvedPos[j];
        d.y = 0.0f;
        const float contact = m_agents.radius[i] + m_agents.radius[j], d2 = glm::dot(d, d);
        const float slop = contact - detail::kContactSlopM;
        if (!(d2 < slop * slop))
            continue;
        float share = contactShare(i, j);
        if (share > 0.0f && !settles(j))
            share = 1.0f;  // it will not move: this one takes the whole overlap
        const float dist = std::sqrt(d2);
        push += partingDirection(i, j, d, dist) * ((contact - dist) * share);
    }
    if (push == glm::vec3(0.0f))
        return false;
    glm::vec3 q = p + push;
    if (hasStatics)
        constrain(m_agents, m_set, m_clock.dt, i, p, q);
    q.y = p.y;
    if (q == p)
        return false;
    m_agents.nextPos[i] = q;
    m_agents.contactMoved[i] = 1;
    return true;
}

}  // namespace throng::sim
