#include "export/character/StrideMaths.h"
#include "export/character/PoseMaths.h"

#include <algorithm>
#include <cmath>

namespace throng::exporting {

glm::vec2 footTarget(const FootPath& g, float s, float groundM)
{
    const float d = g.duty, stride = g.strideM;
    if (s < d)
        return {stride * (0.5f * d - s), groundM};
    const float u = (s - d) / (1.0f - d);
    const float lift = groundM + g.liftM * std::sin(kPi * u);
    if (g.landingSpeedShare > 0.0f) {
        // Cubic Hermite from -d/2 to +d/2 strides with that share of the stance's slope
        // (-1 stride per cycle, -(1 - d) per unit of u) at both ends.
        const float m = -(1.0f - d) * g.landingSpeedShare, u2 = u * u, u3 = u2 * u;
        const float x = (2.0f * u3 - 3.0f * u2 + 1.0f) * (-0.5f * d) + (u3 - 2.0f * u2 + u) * m +
                        (-2.0f * u3 + 3.0f * u2) * (0.5f * d) + (u3 - u2) * m;
        return {stride * x, lift};
    }
    const float ease = u - std::sin(2.0f * kPi * u) / (2.0f * kPi);
    return {stride * (-0.5f * d + d * ease), lift};
}

std::pair<float, float> legAngles(glm::vec2 toFoot, float upper, float lower, bool bendForward)
{
    const float d =
        std::clamp(std::hypot(toFoot.x, toFoot.y), std::abs(upper - lower) + 1e-4f, (upper + lower) * 0.9999f);
    const float cosBend = std::clamp((d * d - upper * upper - lower * lower) / (2.0f * upper * lower), -1.0f, 1.0f);
    const float bend = bendForward ? std::acos(cosBend) : -std::acos(cosBend);
    const float towardFoot = std::atan2(toFoot.x, -toFoot.y);
    const float offset = std::atan2(lower * std::sin(bend), upper + lower * std::cos(bend));
    return {towardFoot - offset, bend};
}

}  // namespace throng::exporting
