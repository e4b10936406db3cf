#pragma once
// Collision layers and priorities of agent types: who avoids whom, and who makes way.
// A horse does not yield to a child; a crowd parts for an ambulance. Plain data and pure
// functions, read by the World's sense, steer and collide phases; never reads the World.

#include "simcore/scene/Scene.h"

#include <cstdint>

namespace throng::sim {

struct TypeCollision {
    float priority = 0.0f;                // higher = others make way for it
    std::uint32_t layerBit = 1u;          // 1 << layer
    std::uint32_t collidesWith = 0xffffffffu;  // bit k set = avoids agents on layer k

    static TypeCollision of(const AgentType& t)
    {
        return {t.priority, 1u << (t.layer & 31u), t.collidesWith};
    }
};

// Two agents perceive, avoid and push each other only when each one's mask holds the
// other's layer; otherwise they pass through each other.
inline bool collide(const TypeCollision& a, const TypeCollision& b)
{
    return (a.collidesWith & b.layerBit) != 0u && (b.collidesWith & a.layerBit) != 0u;
}

// The share of the avoidance between `self` and `other` that `self` takes, in [0, 1]
// (ORCA's responsibility split, generalised): all of it against a body that has stopped
// for good or one of higher priority, none against one of lower priority, half between
// equals (the reciprocal case, as before priorities existed).
inline float avoidanceShare(const TypeCollision& self, const TypeCollision& other, bool otherStopped)
{
    if (otherStopped || other.priority > self.priority)
        return 1.0f;
    if (other.priority < self.priority)
        return 0.0f;
    return 0.5f;
}

}  // namespace throng::sim
