#include "export/character/MeshBuilder.h"
#include "export/character/PoseMaths.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace throng::exporting {

void MeshBuilder::polygon(int joint, const std::vector<glm::vec3>& ring)
{
    // Convex, planar, counter-clockwise from outside: a fan with one flat normal.
    const glm::vec3 normal = glm::normalize(glm::cross(ring[1] - ring[0], ring[2] - ring[0]));
    const auto first = static_cast<std::uint32_t>(m_mesh.positions.size());
    for (const glm::vec3& p : ring) {
        m_mesh.positions.push_back(p);
        m_mesh.normals.push_back(normal);
        m_mesh.joints.push_back({static_cast<std::uint16_t>(joint), 0, 0, 0});
        m_mesh.weights.push_back({1.0f, 0.0f, 0.0f, 0.0f});
    }
    for (std::uint32_t i = 1; i + 1 < ring.size(); ++i) {
        m_mesh.indices.push_back(first);
        m_mesh.indices.push_back(first + i);
        m_mesh.indices.push_back(first + i + 1);
    }
}

void MeshBuilder::quad(int joint, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d)
{
    polygon(joint, {a, b, c, d});
}

void MeshBuilder::box(int joint, glm::vec3 lo, glm::vec3 hi, glm::vec2 topScale)
{
    const float cx = 0.5f * (lo.x + hi.x), cz = 0.5f * (lo.z + hi.z);
    auto top = [&](float x, float z) {
        return glm::vec3(cx + (x - cx) * topScale.x, hi.y, cz + (z - cz) * topScale.y);
    };
    // Corners: b = bottom, t = top; 0..3 counter-clockwise seen from above (+y).
    const glm::vec3 b0(lo.x, lo.y, lo.z), b1(lo.x, lo.y, hi.z), b2(hi.x, lo.y, hi.z), b3(hi.x, lo.y, lo.z);
    const glm::vec3 t0 = top(lo.x, lo.z), t1 = top(lo.x, hi.z), t2 = top(hi.x, hi.z), t3 = top(hi.x, lo.z);
    quad(joint, t0, t1, t2, t3);  // top, facing +y
    quad(joint, b0, b3, b2, b1);  // bottom, facing -y
    quad(joint, b0, b1, t1, t0);  // -x
    quad(joint, b2, b3, t3, t2);  // +x
    quad(joint, b1, b2, t2, t1);  // +z
    quad(joint, b3, b0, t0, t3);  // -z
}

void MeshBuilder::prism(int joint, glm::vec3 centre, int axis, float radius, float halfLength, int sides)
{
    // A frame (u, v, w) with w along the axis and u x v = w, so rings run counter-clockwise about w.
    glm::vec3 w(0.0f), u(0.0f), v(0.0f);
    w[axis] = 1.0f;
    u[(axis + 1) % 3] = 1.0f;
    v[(axis + 2) % 3] = 1.0f;
    std::vector<glm::vec3> lowRing, highRing;
    for (int s = 0; s < sides; ++s) {
        const float a = 2.0f * kPi * (static_cast<float>(s) + 0.5f) / static_cast<float>(sides);
        const glm::vec3 r = radius * (std::cos(a) * u + std::sin(a) * v);
        lowRing.push_back(centre + r - halfLength * w);
        highRing.push_back(centre + r + halfLength * w);
    }
    polygon(joint, highRing);
    polygon(joint, std::vector<glm::vec3>(lowRing.rbegin(), lowRing.rend()));
    for (int s = 0; s < sides; ++s) {
        const int n = (s + 1) % sides;
        quad(joint, lowRing[s], lowRing[n], highRing[n], highRing[s]);
    }
}

}  // namespace throng::exporting
