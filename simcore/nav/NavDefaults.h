#pragma once
// How the World lays out the grid its walkers navigate and when a sketched field steers
// them, for whoever must show the same grid and field (the editor's field arrows).

namespace throng::sim {

inline constexpr float kNavClearanceM = 0.15f;     // kept beyond the body radius when inflating the set
inline constexpr float kNavDefaultRadiusM = 0.3f;  // a walker's body, for a grid only flow strokes need
inline constexpr float kSketchMinStrength = 0.2f;  // weaker sketched field than this: no flow there

}  // namespace throng::sim
