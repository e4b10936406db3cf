#pragma once
// Two one-liners the lane network, its barriers and the traffic step all use: the left-hand
// normal of a lane's direction and a closed-interval test. Written once here.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include <glm/vec2.hpp>

namespace throng::sim::detail {

// The left-hand normal of planar direction t (x, z): +x heading gives (0, -1).
inline glm::vec2 leftOf(glm::vec2 t) { return {t.y, -t.x}; }

inline bool inRange(float x, float lo, float hi) { return x >= lo && x <= hi; }

}  // namespace throng::sim::detail
