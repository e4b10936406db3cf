#pragma once
// The random streams a World draws each agent's own values from (Rng.h, keyed by the
// agent's id): each use of randomness has its own, so adding one never shifts another.
// New streams go at the end. World.cpp and WorldStarts.cpp draw from them; the exports
// draw the speed factor, the phase offset and the age from the same streams
// (AgentVariation.cpp, WalkingAge.h).
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/scene/WalkingAge.h"

#include <cstdint>

namespace throng::sim::detail {

enum AgentStream : std::uint64_t {
    kSpawnX = 1, kSpawnZ, kSpawnHeading, kSpeedFactor, kPhaseOffset, kStride, kWanderStart, kSpotR, kSpotA, kSpawnY,
    kSpawnPick, kReaction, kAge, kCompanions
};
static_assert(kAge == kAgeStream, "the age's stream is WalkingAge.h's");

}  // namespace throng::sim::detail
