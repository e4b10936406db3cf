#pragma once
// The set's colours (linear 0..1 RGBA) as the exports write them and the editor's 3D view
// draws them (its palette takes these), so a shot looks the same in both.

#include <glm/vec4.hpp>

namespace throng::exporting::setcolours {

inline constexpr glm::vec4 kGround{0.212f, 0.224f, 0.239f, 1.0f};
inline constexpr glm::vec4 kWall{0.925f, 0.890f, 0.800f, 1.0f};
inline constexpr glm::vec4 kObstacle{0.640f, 0.570f, 0.490f, 1.0f};
inline constexpr glm::vec4 kLane{0.165f, 0.173f, 0.184f, 1.0f};
inline constexpr glm::vec4 kLaneCentre{0.860f, 0.760f, 0.330f, 1.0f};
inline constexpr glm::vec4 kCrosswalkStripe{0.880f, 0.880f, 0.870f, 1.0f};
inline constexpr glm::vec4 kLightHousing{0.080f, 0.085f, 0.090f, 1.0f};
inline constexpr glm::vec4 kLightPole{0.420f, 0.440f, 0.460f, 1.0f};
inline constexpr glm::vec4 kLightGreen{0.240f, 0.860f, 0.420f, 1.0f};
inline constexpr glm::vec4 kLightYellow{1.000f, 0.780f, 0.200f, 1.0f};
inline constexpr glm::vec4 kLightRed{1.000f, 0.300f, 0.300f, 1.0f};
inline constexpr glm::vec4 kLightUnknown{0.500f, 0.500f, 0.500f, 1.0f};

}  // namespace throng::exporting::setcolours
