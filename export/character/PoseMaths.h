#pragma once
// The pieces the built-in characters and their motion are made of: pi, a smooth step, a
// rotation about one axis of the joint's frame, and a skeleton's joint as a builder lists
// it. Shared by Humanoid*.cpp, Horse.cpp, Vehicles.cpp, Gait.cpp and the maths under them,
// so each is written once.

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <algorithm>

namespace throng::exporting {

inline constexpr float kPi = 3.14159265358979f;

// 0 below lo, 1 above hi, and Hermite's smooth step between (a step at hi when hi <= lo).
inline float smoothstep(float lo, float hi, float x)
{
    if (!(hi > lo))
        return x >= hi ? 1.0f : 0.0f;
    const float t = std::clamp((x - lo) / (hi - lo), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

inline glm::quat aboutX(float a) { return glm::angleAxis(a, glm::vec3(1.0f, 0.0f, 0.0f)); }
inline glm::quat aboutY(float a) { return glm::angleAxis(a, glm::vec3(0.0f, 1.0f, 0.0f)); }
inline glm::quat aboutZ(float a) { return glm::angleAxis(a, glm::vec3(0.0f, 0.0f, 1.0f)); }

// One joint of a built-in skeleton: its name, its parent's index (-1 for the root) and its
// offset from the parent in m (at scale 1 where the builder scales).
struct JointSpec {
    const char* name;
    int parent;
    glm::vec3 offset;
};

}  // namespace throng::exporting
