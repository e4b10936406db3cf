#pragma once
// Thresholds of the steering functions that the fused kernels (world/WalkKernel.cpp,
// world/BoidKernel.cpp) repeat inline; one definition, so kernel and function cannot part.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

namespace throng::sim::detail {

// Below this speed (m/s) the velocity no longer says where the agent faces (VehicleModel.cpp).
constexpr float kStoppedSpeed = 1e-3f;
// Below this lateral offset (m) a threat counts as dead ahead and the agent passes on its
// right (UnalignedCollisionAvoidance.cpp).
constexpr float kDeadAheadM = 1e-3f;

}  // namespace throng::sim::detail
