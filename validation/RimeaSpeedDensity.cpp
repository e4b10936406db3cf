// RiMEA tests 4 and 16 (RimeaSpeedDensity.h): speed against density, in a corridor and in
// single file round a ring, measured in the scene's measurement area by the classical method.
#include "validation/RimeaSpeedDensity.h"

#include "simcore/analysis/SpeedDensity.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/World.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace throng::validation {

namespace {

// The mean density (persons/m²) and speed in the scene's first measurement area, by the
// classical method (simcore/analysis), over the frames from fromS to toS of a run of
// `scene`; n is the frames with somebody inside (0: nobody ever was).
struct AreaMeans {
    double densityPerM2 = 0.0, speedMps = 0.0, areaM2 = 0.0;
    std::size_t n = 0;
};

AreaMeans meansInFirstArea(const sim::Scene& scene, double fromS, double toS)
{
    sim::World world(scene);
    sim::FrameCache cache;
    world.startRecording(cache);
    std::vector<sim::AgentFrame> frame;
    while (world.timeS() < toS - 1e-9) {
        world.step();
        world.snapshot(frame);
        cache.append(frame);
    }
    const std::vector<sim::AreaSpeedDensity> areas = sim::measureSpeedDensity(scene, cache, 1);
    AreaMeans m;
    if (areas.empty())
        return m;
    m.areaM2 = areas[0].areaM2;
    for (const sim::SpeedDensitySample& s : areas[0].samples)
        if (double(s.frame) / double(cache.fps()) >= fromS) {
            m.densityPerM2 += s.densityPerM2;
            m.speedMps += s.speedMps;
            ++m.n;
        }
    if (m.n > 0) {
        m.densityPerM2 /= double(m.n);
        m.speedMps /= double(m.n);
    }
    return m;
}

// Where `count` walkers stand evenly spaced round the closed polyline `ring` (x, z), each
// facing along it (the heading as Agent::headingDeg counts it).
std::vector<std::pair<glm::vec2, float>> evenlyRound(const std::vector<glm::vec2>& ring, std::size_t count)
{
    std::vector<double> ends{0.0};  // the arc length at each corner, the first again at the end
    for (std::size_t k = 0; k < ring.size(); ++k)
        ends.push_back(ends.back() + double(glm::distance(ring[k], ring[(k + 1) % ring.size()])));
    std::vector<std::pair<glm::vec2, float>> places;
    std::size_t seg = 0;
    for (std::size_t n = 0; n < count; ++n) {
        const double at = ends.back() * double(n) / double(count);
        while (ends[seg + 1] < at)
            ++seg;
        const glm::vec2 a = ring[seg], b = ring[(seg + 1) % ring.size()];
        const float t = float((at - ends[seg]) / (ends[seg + 1] - ends[seg]));
        const glm::vec2 way = glm::normalize(b - a);
        places.emplace_back(a + (b - a) * t, glm::degrees(std::atan2(-way.y, way.x)));
    }
    return places;
}

}  // namespace

// Test 4: the fundamental diagram. The corridor filled at each density; in its middle
// (the scene's measurement area), from 10 s to 25 s, the walkers' density and mean speed
// by the classical method (simcore/analysis), set against Weidmann's curve at the density
// measured.
Outcome fundamentalDiagram(const std::vector<sim::Scene>& scenes)
{
    constexpr std::array<double, 6> kDensities{0.5, 1.0, 2.0, 3.0, 4.0, 5.0};
    constexpr double kFromS = 10.0, kToS = 25.0, kToleranceMps = 0.15;
    Outcome out;
    out.pass = !scenes[0].groups.empty() && !scenes[0].measurements.empty();
    double lastSpeed = 1e9;
    for (const double rho : kDensities) {
        sim::Scene scene = scenes[0];
        if (!out.pass)
            break;
        sim::SpawnGroup& crowd = scene.groups[0];
        const glm::vec2 size = crowd.max - crowd.min;
        crowd.count = std::uint32_t(std::lround(rho * double(size.x) * double(size.y)));
        const AreaMeans m = meansInFirstArea(scene, kFromS, kToS);
        if (m.n == 0) {
            out.measured += format("%.1f /m2: nobody in the area; ", rho);
            out.pass = false;
            continue;
        }
        const double density = m.densityPerM2, speed = m.speedMps;
        const double weidmann = sim::weidmannSpeed(density);
        out.measured += format("%.2f /m2: %.2f m/s (Weidmann %.2f); ", density, speed, weidmann);
        out.pass = out.pass && std::abs(speed - weidmann) <= kToleranceMps && speed < lastSpeed;
        lastSpeed = speed;
    }
    if (out.measured.size() >= 2)
        out.measured.resize(out.measured.size() - 2);
    return out;
}

// Test 16: single file. Walkers placed evenly round the ring (its one closed path) at each
// density per metre, each following the path; on the stretch the scene's measurement area
// covers (it runs along x), from 20 s to 60 s, their density per metre and mean speed by
// the classical method, set against Seyfried et al.'s relation (2005) at the density
// measured: each walker needs 0.36 m standing and 1.06 s of headway more per m/s.
Outcome singleFile(const std::vector<sim::Scene>& scenes)
{
    constexpr std::array<double, 4> kPerMetre{0.5, 1.0, 1.5, 2.0};
    constexpr double kFromS = 20.0, kToS = 60.0, kToleranceMps = 0.1;
    constexpr double kStandingM = 0.36, kHeadwayS = 1.06;
    const sim::Scene& base = scenes[0];
    Outcome out;
    out.pass = base.paths.size() == 1 && base.paths[0].closed && base.groups.size() == 1 &&
               !base.measurements.empty() && base.measurements[0].shape == sim::MeasurementShape::Area;
    if (!out.pass) {
        out.measured = "the scene needs one closed path, one group and a measurement area";
        return out;
    }
    float fromX = 1e30f, toX = -1e30f;
    for (const glm::vec2 q : base.measurements[0].points) {
        fromX = std::min(fromX, q.x);
        toX = std::max(toX, q.x);
    }
    const sim::SpawnGroup walkers = base.groups[0];
    double ringM = 0.0;
    const std::vector<glm::vec2>& ring = base.paths[0].points;
    for (std::size_t k = 0; k < ring.size(); ++k)
        ringM += double(glm::distance(ring[k], ring[(k + 1) % ring.size()]));
    double lastSpeed = 1e9;
    for (const double perMetre : kPerMetre) {
        sim::Scene scene = base;
        scene.groups.clear();
        std::uint32_t id = 0;
        for (const auto& [place, headingDeg] : evenlyRound(ring, std::size_t(std::lround(perMetre * ringM)))) {
            sim::Agent a;
            a.id = ++id;
            a.type = walkers.type;
            a.position = glm::vec3(place.x, 0.0f, place.y);
            a.headingDeg = headingDeg;
            a.path = walkers.path;
            scene.agents.push_back(a);
        }
        const AreaMeans m = meansInFirstArea(scene, kFromS, kToS);
        if (m.n == 0) {
            out.measured += format("%.1f /m: nobody on the stretch; ", perMetre);
            out.pass = false;
            continue;
        }
        const double density = m.densityPerM2 * m.areaM2 / double(toX - fromX);  // persons per metre
        const double speed = m.speedMps;
        const double freeSpeed = double(scene.agentTypes[0].maxSpeed);
        const double seyfried = std::clamp((1.0 / density - kStandingM) / kHeadwayS, 0.0, freeSpeed);
        out.measured += format("%.2f /m: %.2f m/s (Seyfried %.2f); ", density, speed, seyfried);
        out.pass = out.pass && std::abs(speed - seyfried) <= kToleranceMps && speed < lastSpeed;
        lastSpeed = speed;
    }
    if (out.measured.size() >= 2)
        out.measured.resize(out.measured.size() - 2);
    return out;
}

}  // namespace throng::validation
