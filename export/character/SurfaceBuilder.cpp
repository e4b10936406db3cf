#include "export/character/SurfaceBuilder.h"
#include "export/character/PoseMaths.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::exporting {

namespace {

constexpr float kHalfPi = 1.57079632679f;

struct LodShape {
    int segments, subdivisions, domeRings;
};

LodShape shapeOf(Lod lod)
{
    switch (lod) {
    case Lod::Near: return {14, 2, 3};
    case Lod::Mid: return {8, 1, 1};
    case Lod::Far: return {6, 0, 1};
    }
    return {14, 2, 3};
}

// Catmull-Rom through p1 (t = 0) and p2 (t = 1).
template <typename T>
T catmullRom(const T& p0, const T& p1, const T& p2, const T& p3, float t)
{
    const float t2 = t * t, t3 = t2 * t;
    return 0.5f * ((2.0f * p1) + (p2 - p0) * t + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t2 +
                   (3.0f * p1 - p0 - 3.0f * p2 + p3) * t3);
}

}  // namespace

SurfaceBuilder::SurfaceBuilder(CharacterMesh& mesh, Lod lod) : m_mesh(mesh), m_far(lod == Lod::Far)
{
    const LodShape shape = shapeOf(lod);
    m_segments = shape.segments;
    m_subdivisions = shape.subdivisions;
    m_domeRings = shape.domeRings;
    m_share.fill(1.0f);
}

std::vector<SurfaceBuilder::Ring> SurfaceBuilder::rings(const Tube& tube, std::vector<float>& sectionS) const
{
    const std::vector<TubeSection>& k = tube.sections;
    const int n = static_cast<int>(k.size());
    const int sub = tube.small ? 0 : m_subdivisions;
    auto at = [&](int i) { return k[static_cast<std::size_t>(std::clamp(i, 0, n - 1))]; };
    std::vector<Ring> out;
    for (int i = 0; i + 1 < n; ++i)
        for (int step = 0; step <= sub; ++step) {
            const float t = static_cast<float>(step) / static_cast<float>(sub + 1);
            Ring r{};
            r.centre = catmullRom(at(i - 1).centre, at(i).centre, at(i + 1).centre, at(i + 2).centre, t);
            r.depth = std::max(1e-4f, catmullRom(at(i - 1).depth, at(i).depth, at(i + 1).depth, at(i + 2).depth, t));
            r.width = std::max(1e-4f, catmullRom(at(i - 1).width, at(i).width, at(i + 1).width, at(i + 2).width, t));
            r.slot = at(i).slot;
            out.push_back(r);
        }
    out.push_back(Ring{k.back().centre, {}, {}, k.back().depth, k.back().width, 0.0f, k.back().slot});
    for (std::size_t r = 1; r < out.size(); ++r)
        out[r].s = out[r - 1].s + glm::length(out[r].centre - out[r - 1].centre);
    sectionS.clear();
    for (int i = 0; i < n; ++i)
        sectionS.push_back(out[static_cast<std::size_t>(i * (sub + 1))].s);
    for (std::size_t r = 0; r < out.size(); ++r) {
        const glm::vec3 ahead = out[std::min(r + 1, out.size() - 1)].centre, behind = out[r > 0 ? r - 1 : 0].centre;
        glm::vec3 axis = ahead - behind;
        axis = glm::length(axis) > 1e-9f ? glm::normalize(axis) : glm::vec3(0.0f, 1.0f, 0.0f);
        glm::vec3 u = tube.forward - glm::dot(tube.forward, axis) * axis;
        u = glm::length(u) > 1e-6f ? glm::normalize(u) : glm::normalize(glm::cross(axis, glm::vec3(0.0f, 0.0f, 1.0f)));
        out[r].u = u;
        out[r].v = glm::cross(axis, u);
    }
    return out;
}

void SurfaceBuilder::tube(const Tube& tube)
{
    if (tube.small && m_far)
        return;
    std::vector<float> sectionS;
    const std::vector<Ring> main = rings(tube, sectionS);
    const int segments = tube.small ? std::max(4, m_segments / 2) : m_segments;
    const int domeRings = tube.small ? 1 : m_domeRings;

    // Rows from the start pole to the end pole: a ring of `segments` points, or one point.
    struct Row {
        std::vector<glm::vec3> points;
        float s;
        MaterialSlot slot;  // of the band from this row to the next
    };
    std::vector<Row> rows;
    // Point j where the ellipse's normal points 360 j / segments degrees round: every
    // segment turns the surface by the same angle, however flat the section.
    auto ringPoints = [&](const Ring& r, float scale, const glm::vec3& shift) {
        std::vector<glm::vec3> points;
        for (int j = 0; j < segments; ++j) {
            const float a = 4.0f * kHalfPi * static_cast<float>(j) / static_cast<float>(segments);
            const float c = r.depth * std::cos(a), s = r.width * std::sin(a), l = std::sqrt(c * c + s * s);
            points.push_back(r.centre + shift + scale * (r.depth * (c / l) * r.u + r.width * (s / l) * r.v));
        }
        return points;
    };
    auto cap = [&](const Ring& r, float capM, float outward, bool start) {
        const float d = capM < 0.0f ? std::min(r.depth, r.width) : capM;
        const glm::vec3 axis = outward * glm::cross(r.u, r.v);
        const int count = d > 0.0f ? domeRings : 0;
        std::vector<Row> made;
        for (int q = 1; q <= count; ++q) {
            const float phi = kHalfPi * static_cast<float>(q) / static_cast<float>(count + 1);
            made.push_back({ringPoints(r, std::cos(phi), d * std::sin(phi) * axis), r.s, r.slot});
        }
        made.push_back({{r.centre + d * axis}, r.s, r.slot});
        if (start)
            std::reverse(made.begin(), made.end());
        return made;
    };
    for (Row& row : cap(main.front(), tube.startCapM, -1.0f, true))
        rows.push_back(std::move(row));
    for (const Ring& r : main)
        rows.push_back({ringPoints(r, 1.0f, glm::vec3(0.0f)), r.s, r.slot});
    for (Row& row : cap(main.back(), tube.endCapM, 1.0f, false))
        rows.push_back(std::move(row));

    // Local vertices, triangles (with their slot) and area-weighted normals.
    std::vector<glm::vec3> positions;
    std::vector<float> s;
    std::vector<std::uint32_t> first;
    for (const Row& row : rows) {
        first.push_back(static_cast<std::uint32_t>(positions.size()));
        for (const glm::vec3& p : row.points) {
            positions.push_back(p);
            s.push_back(row.s);
        }
    }
    struct Triangle {
        std::uint32_t a, b, c;
        MaterialSlot slot;
    };
    std::vector<Triangle> triangles;
    for (std::size_t r = 0; r + 1 < rows.size(); ++r) {
        const std::uint32_t a0 = first[r], b0 = first[r + 1];
        const bool aPole = rows[r].points.size() == 1, bPole = rows[r + 1].points.size() == 1;
        const MaterialSlot slot = rows[r].slot;
        for (int j = 0; j < segments; ++j) {
            const auto jn = static_cast<std::uint32_t>((j + 1) % segments), jc = static_cast<std::uint32_t>(j);
            if (aPole) {
                triangles.push_back({a0, b0 + jn, b0 + jc, slot});
            } else if (bPole) {
                triangles.push_back({a0 + jc, a0 + jn, b0, slot});
            } else {
                triangles.push_back({a0 + jc, a0 + jn, b0 + jc, slot});
                triangles.push_back({a0 + jn, b0 + jn, b0 + jc, slot});
            }
        }
    }
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
    for (const Triangle& t : triangles) {
        const glm::vec3 n = glm::cross(positions[t.b] - positions[t.a], positions[t.c] - positions[t.a]);
        normals[t.a] += n;
        normals[t.b] += n;
        normals[t.c] += n;
    }

    // Skin weights from arc length: each bone from its start, blended across it.
    std::vector<float> boneS;
    for (const TubeBone& bone : tube.bones) {
        const float at = std::clamp(bone.at, 0.0f, static_cast<float>(sectionS.size() - 1));
        const auto i = std::min(static_cast<std::size_t>(at), sectionS.size() - 1);
        const float f = at - static_cast<float>(i);
        boneS.push_back(i + 1 < sectionS.size() ? sectionS[i] + f * (sectionS[i + 1] - sectionS[i]) : sectionS[i]);
    }
    auto influences = [&](float arc, std::array<std::uint16_t, 4>& joints, glm::vec4& weights) {
        joints = {0, 0, 0, 0};
        weights = glm::vec4(0.0f);
        int used = 0;
        for (std::size_t b = 0; b < tube.bones.size(); ++b) {
            const float in = b == 0 ? 1.0f : smoothstep(boneS[b] - tube.blendM, boneS[b] + tube.blendM, arc);
            const float out = b + 1 < tube.bones.size()
                                  ? smoothstep(boneS[b + 1] - tube.blendM, boneS[b + 1] + tube.blendM, arc)
                                  : 0.0f;
            const float w = in * (1.0f - out);
            if (w > 1e-5f && used < 4) {
                joints[static_cast<std::size_t>(used)] = static_cast<std::uint16_t>(tube.bones[b].joint);
                weights[used++] = w;
            }
        }
        normaliseInfluences(joints, weights);
    };

    // Written once per slot that uses a vertex, so each part owns its vertices.
    std::vector<std::int64_t> written(positions.size() * kMaterialSlotCount, -1);
    auto emit = [&](std::uint32_t local, MaterialSlot slot) {
        std::int64_t& out = written[local * kMaterialSlotCount + static_cast<std::size_t>(slot)];
        if (out < 0) {
            out = static_cast<std::int64_t>(m_mesh.positions.size());
            m_mesh.positions.push_back(positions[local]);
            const float length = glm::length(normals[local]);
            m_mesh.normals.push_back(length > 0.0f ? normals[local] / length : glm::vec3(0.0f, 1.0f, 0.0f));
            std::array<std::uint16_t, 4> joints{};
            glm::vec4 weights(0.0f);
            influences(s[local], joints, weights);
            m_mesh.joints.push_back(joints);
            m_mesh.weights.push_back(weights);
        }
        return static_cast<std::uint32_t>(out);
    };
    for (const Triangle& t : triangles) {
        std::vector<std::uint32_t>& list = m_triangles[static_cast<std::size_t>(t.slot)];
        list.push_back(emit(t.a, t.slot));
        list.push_back(emit(t.b, t.slot));
        list.push_back(emit(t.c, t.slot));
    }
}

void SurfaceBuilder::finish()
{
    for (int slot = 0; slot < kMaterialSlotCount; ++slot) {
        const std::vector<std::uint32_t>& list = m_triangles[static_cast<std::size_t>(slot)];
        if (list.empty())
            continue;
        MeshPart part;
        part.slot = static_cast<MaterialSlot>(slot);
        part.firstIndex = static_cast<std::uint32_t>(m_mesh.indices.size());
        part.indexCount = static_cast<std::uint32_t>(list.size());
        part.wornShare = m_share[static_cast<std::size_t>(slot)];
        m_mesh.indices.insert(m_mesh.indices.end(), list.begin(), list.end());
        m_mesh.parts.push_back(part);
    }
    for (auto& list : m_triangles)
        list.clear();
}

}  // namespace throng::exporting
