// The collide phase (Collide.h): the collide pass's per-agent step, the agent's proposed
// position nudged out of the bodies it overlaps, capped at its max speed, and for walkers
// kept out of walls and obstacles; then the contact rounds, which part the ground bodies
// that still overlap.
#include "simcore/world/Collide.h"

#include "simcore/world/BrainPhase.h"
#include "simcore/world/Constraints.h"
#include "simcore/world/StepView.h"
#include "simcore/world/WorldPriority.h"

#include "simcore/base/Rng.h"
#include "simcore/world/detail/StepConstants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>

namespace throng::sim {

namespace {

// contactMoved's bits. kContactMoved: the contact rounds moved the agent this step.
// kClearOfContact: the collide pass found the agent's listed neighbours far enough apart
// that the first round cannot part it from any (resolveCollision). kMovedInRound: moved in
// the round of that parity (the rounds after the first look at the last one's, and write
// their own, which other agents' rounds do not read).
constexpr std::uint8_t kContactMoved = 1, kClearOfContact = 2;
constexpr std::uint8_t kMovedInRound[2] = {4, 8};
// m: how far the collide pass may move any body from its proposed place (planar) for
// kClearOfContact to hold; a pass that moved one farther (a wall's push, a brain's hold
// at a low frame rate) sends every agent through the first round (collide, below). Two
// of a walker's pushes at 1.4 m/s and 24 fps come to under 0.06 m.
constexpr float kClearMarginM = 0.1f;

std::uint8_t loadFlags(const AgentColumns& agents, std::size_t i)
{
    // Other agents' rounds write their own flags meanwhile, but never the bits read here.
    return std::atomic_ref<const std::uint8_t>(agents.contactMoved[i]).load(std::memory_order_relaxed);
}

void storeFlags(AgentColumns& agents, std::size_t i, std::uint8_t flags)
{
    std::atomic_ref<std::uint8_t>(agents.contactMoved[i]).store(flags, std::memory_order_relaxed);
}

// The way agent i parts from j, `d` (their offset) apart at distance `dist`.
glm::vec3 partingDirection(const StepView& v, std::size_t i, std::size_t j, glm::vec3 d, float dist)
{
    if (dist > 1e-6f)
        return d / dist;
    // Coincident bodies part along a direction both derive from their ids, in opposite
    // senses, so the pair never moves together.
    const AgentId a = v.agents.info[i].id, b = v.agents.info[j].id;
    const AgentId lo = std::min(a, b), hi = std::max(a, b);
    const float angle = float(rngUniform(lo, hi, 0, 77)) * 6.2831853f;
    return glm::vec3(std::cos(angle), 0.0f, std::sin(angle)) * (a == lo ? 1.0f : -1.0f);
}

// The share of a pair's overlap agent i takes (WorldPriority.h).
float contactShare(const StepView& v, std::size_t i, std::size_t j)
{
    // A standing neighbour, or one of higher priority, does not give way, so this agent
    // takes the whole overlap; against one of lower priority it takes none.
    float share = avoidanceShare(v.collision(i), v.collision(j), v.agents.stopped[j] != 0);
    // A walker that the red caught on the road goes first: those waiting at the kerb,
    // where it must get to, make room for it (set by this step's steer phase).
    if (!v.traffic.signal.empty() && v.traffic.signal[i].clearing != v.traffic.signal[j].clearing)
        share = v.traffic.signal[i].clearing ? 0.0f : 1.0f;
    return share;
}

// Agent i's nudge out of the bodies it overlaps at their proposed places. nearest2: the
// squared distance to the nearest listed neighbour (planar for a walker): infinite with
// none, not a number where a distance is not.
glm::vec3 separateBodies(const StepView& v, std::size_t i, float& nearest2)
{
    nearest2 = INFINITY;
    if (v.agents.stopped[i])
        return glm::vec3(0.0f);
    const bool flying = v.types.steering[v.agents.info[i].typeIndex].vehicle.flying;
    glm::vec3 push(0.0f);
    const std::uint32_t* near = &v.agents.nearIndex[i * kMaxNeighbours];
    for (std::size_t k = 0; k < v.agents.nearCount[i]; ++k) {
        const std::uint32_t j = near[k];
        glm::vec3 d = v.agents.nextPos[i] - v.agents.nextPos[j];
        if (!flying)
            d.y = 0.0f;
        const float contact = v.agents.radius[i] + v.agents.radius[j];
        const float d2 = glm::dot(d, d);
        nearest2 = std::isnan(d2) || std::isnan(nearest2) ? NAN : std::min(nearest2, d2);
        if (d2 >= contact * contact)
            continue;
        const float dist = std::sqrt(d2);
        push += partingDirection(v, i, j, d, dist) * ((contact - dist) * contactShare(v, i, j));
    }
    // Cap the correction so a squeezed agent is nudged, never thrown: at most half its
    // body and half what it could walk in the step.
    const float cap = std::min(0.5f * v.agents.radius[i], 0.5f * v.agents.maxSpeed[i] * v.clock.dt);
    const float len = glm::length(push);
    return len > cap ? push * (cap / len) : push;
}

// Agent i's place after the collide pass, in resolvedPos, and its contact flags
// (kClearOfContact where it holds). False when the pass moved it farther than
// kClearMarginM from its proposed place (or to a place that is not a number).
bool resolveCollision(const StepView& v, const BrainPhase& brains, AgentColumns& agents, std::size_t i,
                      bool collideFree, bool hasStatics)
{
    agents.contactMoved[i] = 0;
    if (agents.stopped[i]) {  // frozen where it stands
        agents.resolvedPos[i] = agents.nextPos[i];
        return true;
    }
    float nearest2 = NAN;  // unknown where the kernel's proof stands in for the search
    glm::vec3 p = agents.nextPos[i] + (collideFree ? glm::vec3(0.0f) : separateBodies(v, i, nearest2));
    const bool flying = v.types.steering[agents.info[i].typeIndex].vehicle.flying;
    // Nobody moves faster than its max speed, nudges included, so what the viewer
    // sees and the gait it is animated with always agree. A brain's lower speed holds
    // back only the walker's progress: pushes may move it aside or back, so a walker
    // its brain stops still gives way, but never on past where its brain holds it.
    glm::vec3 move = p - agents.pos[i];
    if (brains.active()) {
        if (const glm::vec3 held = brains.limited(v, i, move, agents.maxSpeed[i], v.clock.dt); held != move) {
            move = held;
            p = agents.pos[i] + move;
        }
    }
    const float maxMove = agents.maxSpeed[i] * v.clock.dt, moved = glm::length(move);
    if (moved > maxMove && moved > 0.0f)
        p = agents.pos[i] + move * (maxMove / moved);
    if (!flying) {
        if (hasStatics)
            constrain(agents, v.set, v.clock.dt, i, agents.pos[i], p);
        p.y = agents.nextPos[i].y;
        // A walker's velocity is the move it made (nobody reads another's in this pass).
        agents.nextVel[i] = (p - agents.pos[i]) / v.clock.dt;
        agents.nextVel[i].y = 0.0f;
    }
    agents.resolvedPos[i] = p;
    // Clear of contact: each listed neighbour j lay at least sqrt(nearest2) away at the
    // proposed places, and the pass moved this agent `shifted` and j at most the margin
    // (collide checks that it did), so their places lie at least `apart` apart, beyond any
    // pair's contact less the slop (with room for the rounding of coordinates this far
    // out). Then the first contact round finds no pair to part (settleRound) and may pass
    // this agent by.
    const glm::vec2 shift(p.x - agents.nextPos[i].x, p.z - agents.nextPos[i].z);
    const float shifted = glm::length(shift);
    const float rounding = 1e-3f + 1e-6f * (std::fabs(p.x) + std::fabs(p.z));
    const float apart = std::sqrt(nearest2) - shifted - kClearMarginM - rounding;
    if (!flying && apart >= agents.radius[i] + v.maxRadius - detail::kContactSlopM)
        agents.contactMoved[i] = kClearOfContact;
    return shifted <= kClearMarginM;
}

// Whether the contact rounds move agent i: a walking ground body (not one that stands,
// has left, flies, is driven along a lane, walks out of an obstacle or waits off stage).
bool settles(const StepView& v, std::size_t i)
{
    return !v.agents.stopped[i] && !v.agents.out[i] && !v.types.steering[v.agents.info[i].typeIndex].vehicle.flying &&
           !v.traffic.isDriven(i) && !v.agents.escaping[i] && !(v.traffic.anyOffStage && v.traffic.offStage[i]);
}

// Whether round `round` can pass agent i by: in the first, the collide pass found it clear
// of contact (when `clearHolds`); in later ones, neither it nor any listed neighbour moved
// in the round before, so it would find what it found there (and it did not move).
bool unchangedForRound(const AgentColumns& agents, std::size_t i, int round, bool clearHolds)
{
    // (A neighbour that does not settle never moves: its bits stay clear.)
    const std::uint8_t flags = loadFlags(agents, i);
    if (round == 0)
        return clearHolds && (flags & kClearOfContact) != 0;
    const std::uint8_t before = kMovedInRound[(round + 1) & 1];
    if (flags & before)
        return false;
    const std::uint32_t* near = &agents.nearIndex[i * kMaxNeighbours];
    std::uint8_t any = 0;
    for (std::size_t k = 0; k < agents.nearCount[i]; ++k)
        any |= loadFlags(agents, near[k]);
    return (any & before) == 0;
}

// Agent i in contact round `round`: parted from the listed neighbours it presses into at
// the last round's places (resolvedPos), its new place in nextPos. Whether it moved; in
// `passedBy`, whether the shortcut passed it by (unchangedForRound).
bool settleRound(const StepView& v, AgentColumns& agents, std::size_t i, int round, bool shortcut, bool clearHolds,
                 bool hasStatics, bool& passedBy)
{
    const glm::vec3 p = agents.resolvedPos[i];
    agents.nextPos[i] = p;
    const std::uint8_t flags = loadFlags(agents, i) & std::uint8_t(~kMovedInRound[round & 1]);
    storeFlags(agents, i, flags);  // not moved in this round, unless it moves below
    passedBy = shortcut && unchangedForRound(agents, i, round, clearHolds);
    if (passedBy || !settles(v, i))
        return false;
    glm::vec3 push(0.0f);
    const std::uint32_t* near = &agents.nearIndex[i * kMaxNeighbours];
    for (std::size_t k = 0; k < agents.nearCount[i]; ++k) {
        const std::uint32_t j = near[k];
        if (v.traffic.anyOffStage && v.traffic.offStage[j])
            continue;
        glm::vec3 d = p - agents.resolvedPos[j];
        d.y = 0.0f;
        const float contact = agents.radius[i] + agents.radius[j], d2 = glm::dot(d, d);
        const float slop = contact - detail::kContactSlopM;
        if (!(d2 < slop * slop))
            continue;
        float share = contactShare(v, i, j);
        if (share > 0.0f && !settles(v, j))
            share = 1.0f;  // it will not move: this one takes the whole overlap
        const float dist = std::sqrt(d2);
        push += partingDirection(v, i, j, d, dist) * ((contact - dist) * share);
    }
    if (push == glm::vec3(0.0f))
        return false;
    glm::vec3 q = p + push;
    if (hasStatics)
        constrain(agents, v.set, v.clock.dt, i, p, q);
    q.y = p.y;
    if (q == p)
        return false;
    agents.nextPos[i] = q;
    storeFlags(agents, i, flags | kContactMoved | kMovedInRound[round & 1]);
    return true;
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
// A round passes by the agents it would leave where they are (unchangedForRound): those
// the collide pass found clear of contact, then those round whom nothing moved; most of
// a crowd in each round, and in a spread-out one all (`cross`: about 300 of 10,000 move
// in a round). The result is the same as with every agent worked out in every round.
// clearHolds: the collide pass moved no body farther than kClearMarginM. `rounds` says
// whether to take the shortcut, and counts what it passed by.
void settleContacts(const StepView& v, const BrainPhase& brains, AgentColumns& agents, bool clearHolds,
                    bool hasStatics, ContactRounds& rounds)
{
    const std::size_t n = agents.pos.size();
    bool anyMoved = false;
    std::atomic<std::uint64_t> passedByAll{0};
    rounds.marginBroken += !clearHolds;
    for (int round = 0; round < detail::kContactRounds; ++round) {
        const std::uint64_t moved = v.team.sumChunks(n, 256, [&](std::size_t begin, std::size_t end, int) {
            std::uint64_t count = 0, passed = 0;
            for (std::size_t i = begin; i < end; ++i) {
                bool passedBy = false;
                count += settleRound(v, agents, i, round, rounds.shortcut, clearHolds, hasStatics, passedBy);
                passed += passedBy;
            }
            passedByAll.fetch_add(passed, std::memory_order_relaxed);
            return count;
        });
        rounds.agents += n;
        std::swap(agents.nextPos, agents.resolvedPos);  // the round's places are the resolved ones
        if (moved == 0)
            break;
        anyMoved = true;
    }
    rounds.passedBy += passedByAll.load();
    if (!anyMoved)
        return;
    v.team.forEach(n, 256, [&](std::size_t i) {
        if (!(agents.contactMoved[i] & kContactMoved))
            return;
        glm::vec3 p = agents.resolvedPos[i], move = p - agents.pos[i];
        if (brains.active())
            move = brains.limited(v, i, move, agents.maxSpeed[i], v.clock.dt);
        const float maxMove = agents.maxSpeed[i] * v.clock.dt, moved = glm::length(move);
        if (moved > maxMove && moved > 0.0f)
            move *= maxMove / moved;
        if (move != p - agents.pos[i]) {
            p = agents.pos[i] + move;
            if (hasStatics)
                constrain(agents, v.set, v.clock.dt, i, agents.pos[i], p);
        }
        p.y = v.set.groundHeight(p.x, p.z);
        agents.resolvedPos[i] = p;
        agents.nextVel[i] = (p - agents.pos[i]) / v.clock.dt;
        agents.nextVel[i].y = 0.0f;
    });
}

}  // namespace

void collide(const StepView& v, const BrainPhase& brains, AgentColumns& agents,
             std::span<const std::uint8_t> collideFree, float boidSlackM, bool hasStatics, ContactRounds& rounds)
{
    // Collide: bodies still overlapping after steering move apart, each by its share of
    // the overlap (DetourCrowd's collision handling, done Jacobi-style: every agent reads
    // the others' proposed positions and moves only itself). Walls stay hard. Boids the
    // kernel found collide-free skip the search for overlaps (it would find none) once
    // every agent is seen to lie within the kernel's slack of its old velocity's reach;
    // should one not, the pass runs again in full, so the result is the same either way.
    const std::size_t n = agents.pos.size();
    agents.contactMoved.resize(n);
    const bool trustKernel = boidSlackM > 0.0f && collideFree.size() == n;
    const float slack2 = boidSlackM * boidSlackM;
    std::atomic<bool> marginKept{true};  // every agent within kClearMarginM of its proposed place
    const std::uint64_t slackBroken = v.team.sumChunks(n, 256, [&](std::size_t begin, std::size_t end, int) {
        std::uint64_t broken = 0;
        bool kept = true;
        for (std::size_t i = begin; i < end; ++i) {
            bool trusted = false;
            if (trustKernel) {
                const glm::vec3 drift = agents.nextPos[i] - (agents.pos[i] + agents.vel[i] * v.clock.dt);
                broken += glm::dot(drift, drift) > slack2;
                trusted = (collideFree[i] & kCollideFree) != 0;
            }
            kept = resolveCollision(v, brains, agents, i, trusted, hasStatics) && kept;
        }
        if (!kept)
            marginKept.store(false, std::memory_order_relaxed);
        return broken;
    });
    if (trustKernel && slackBroken > 0) {
        marginKept.store(true);
        v.team.forEach(n, 256, [&](std::size_t i) {
            if (!resolveCollision(v, brains, agents, i, false, hasStatics))
                marginKept.store(false, std::memory_order_relaxed);
        });
    }
    // Contact rounds: on each decision (every step at 24 fps and below), the bodies that
    // still overlap are parted (settleContacts, above); between decisions the collide pass
    // keeps what they parted apart.
    if (v.clock.decide && !v.allFliers)
        settleContacts(v, brains, agents, marginKept.load(), hasStatics, rounds);
    // The resolved positions are the next ones (the pass wrote every agent's).
    std::swap(agents.nextPos, agents.resolvedPos);
}

}  // namespace throng::sim
