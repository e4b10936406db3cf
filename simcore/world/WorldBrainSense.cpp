// The sense phase for brains: fills, for every agent of a brain-driven type, the sensor
// columns its program lists, from the previous state only (positions, velocities, the
// neighbour grid, walls, obstacles, crosswalk and lane lights, heroes, sounds). Agents
// write only their own row.
#include "simcore/world/BrainPhase.h"

#include "simcore/world/StepView.h"

#include "simcore/world/Sense.h"

#include "simcore/world/detail/StepGeometry.h"
#include "simcore/world/detail/WorldBrains.h"
#include "simcore/world/detail/WorldSound.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

constexpr float kNoneM = 1e6f;        // distance reported when there is nothing (no goal, line, hero)
constexpr float kWallReachM = 10.0f;  // wall_distance looks this far at most
constexpr float kStopLineSideM = 1.0f;  // a crosswalk's stop line reaches this far beyond its width
constexpr float kAlongCos = 0.5f;       // wanting to go within 60 degrees of a crosswalk's axis: onto it

// Distance along a ray (unit dir) to segment ab, or `length` when it misses.
float rayToSegment(glm::vec2 o, glm::vec2 dir, float length, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 e = b - a, ao = a - o;
    const float denom = cross(dir, e);
    if (std::fabs(denom) < 1e-9f)
        return length;
    const float t = cross(ao, e) / denom, u = cross(ao, dir) / denom;
    return t >= 0.0f && t < length && u >= 0.0f && u <= 1.0f ? t : length;
}

float rayToCircle(glm::vec2 o, glm::vec2 dir, float length, glm::vec2 c, float r)
{
    const glm::vec2 oc = o - c;
    const float b = glm::dot(oc, dir), q = glm::dot(oc, oc) - r * r;
    if (q <= 0.0f)
        return 0.0f;
    const float disc = b * b - q;
    if (disc < 0.0f)
        return length;
    const float t = -b - std::sqrt(disc);
    return t >= 0.0f && t < length ? t : length;
}

glm::vec2 rotated(glm::vec2 v, float rad)
{
    const float c = std::cos(rad), s = std::sin(rad);
    return {v.x * c + v.y * s, -v.x * s + v.y * c};  // + = toward the left, (f.y, -f.x)
}

}  // namespace

void BrainPhase::sense(const StepView& view, AgentColumns& agents, TypeBrain& tb) const
{
    bool needNeighbours = false, needFeelers = false;
    for (SensorFill f : tb.fills) {
        needNeighbours = needNeighbours || (f >= SensorFill::NeighbourCount && f <= SensorFill::VisionRight) ||
                         (f >= SensorFill::NeighbourDistance && f <= SensorFill::NeighbourTag);
        needFeelers = needFeelers || (f >= SensorFill::FeelerLeft && f <= SensorFill::FeelerRight);
    }
    tb.gathersNeighbours = needNeighbours;
    const std::size_t n = tb.agents.size(), sensors = tb.fills.size();
    const float time = float(view.clock.timeS());
    const float third = tb.viewDeg / 6.0f;
    view.team.forEach(n, 256, [&](std::size_t k) {
        const std::size_t i = tb.agents[k];
        const TypeParams& type = view.types.params[view.agents.info[i].typeIndex];
        const TypeSteering& steering = view.types.steering[view.agents.info[i].typeIndex];
        const glm::vec2 p = xz(view.agents.pos[i]);
        glm::vec2 f = xz(view.agents.fwd[i]);
        f = glm::dot(f, f) > 1e-12f ? glm::normalize(f) : glm::vec2(1.0f, 0.0f);
        const float speed = glm::length(view.agents.vel[i]);
        // The neighbours go into the agent's own view.agents.nearIndex row, where the steer phase
        // of this step finds them instead of querying the grid a second time; the sensors read
        // from it only what they need of each.
        const std::uint32_t* near = &agents.nearIndex[i * kMaxNeighbours];
        const std::size_t count =
            needNeighbours ? gatherNeighbours(view, i, nullptr, &agents.nearIndex[i * kMaxNeighbours]) : 0;
        auto nearPos = [&](std::size_t j) { return xz(view.agents.pos[near[j]]); };
        if (needNeighbours)
            agents.nearCount[i] = std::uint8_t(count);
        tb.neighbourCount[k] = std::uint8_t(std::min<std::size_t>(count, kBrainNeighbours));
        // The neighbours' bearings (bearingDeg) and distances (glm::distance: the square
        // root of the same sum of squares), four at a time, once for every sensor that
        // reads them.
        std::array<float, kMaxNeighbours> nearBearing, nearDistance;
        bool geometryFound = false;
        auto findGeometry = [&] {
            if (geometryFound)
                return;
            for (std::size_t j = 0; j < count; j += 4) {
                simd::F4 dx, dy;
                for (std::size_t l = 0; l < 4; ++l) {
                    const glm::vec2 d = j + l < count ? nearPos(j + l) - p : glm::vec2(0.0f);
                    dx[l] = d.x;
                    dy[l] = d.y;
                }
                const simd::F4 b = bearingsDeg(f, dx, dy), d = simd::sqrtOf(dx * dx + dy * dy);
                for (std::size_t l = 0; l < 4 && j + l < count; ++l) {
                    nearBearing[j + l] = b[l];
                    nearDistance[j + l] = d[l];
                }
            }
            geometryFound = true;
        };
        auto bearings = [&]() -> const std::array<float, kMaxNeighbours>& {
            findGeometry();
            return nearBearing;
        };
        auto distances = [&]() -> const std::array<float, kMaxNeighbours>& {
            findGeometry();
            return nearDistance;
        };
        // The stop line ahead and its light (both sensors' answer, found once).
        float stopGap = kNoneM, stopLight = 0.0f;
        bool stopLineFound = false;
        std::array<float, 3> feeler{};  // left, centre, right
        if (needFeelers) {
            const float length = steering.obstacles.minLengthM + steering.obstacles.lookaheadS * speed;
            const float angles[3] = {steering.obstacles.whiskerAngleRad, 0.0f, -steering.obstacles.whiskerAngleRad};
            for (int s = 0; s < 3; ++s) {
                const glm::vec2 dir = rotated(f, angles[s]);
                float t = length;
                view.set.walls.forEachNear(p + dir * (0.5f * length), 0.5f * length, [&](std::uint32_t w) {
                    const Segment& seg = view.set.walls.segment(w);
                    t = std::min(t, rayToSegment(p, dir, length, seg.a, seg.b));
                });
                view.set.obstacleGrid.forEachNear(p + dir * (0.5f * length), 0.5f * length, [&](std::uint32_t o) {
                    if (o < view.set.circles.size())
                        t = std::min(
                            t, rayToCircle(p, dir, length, xz(view.set.circles[o].centre), view.set.circles[o].radius));
                });
                feeler[std::size_t(s)] = t;
            }
        }
        for (std::size_t s = 0; s < sensors; ++s) {
            float* column = tb.columns[s].data();
            float& v = column[tb.fills[s] >= SensorFill::NeighbourDistance ? k * kBrainNeighbours : k];
            switch (tb.fills[s]) {
            case SensorFill::Speed: v = speed; break;
            case SensorFill::GoalBearing:
            case SensorFill::GoalDistance: {
                bool has = false;
                glm::vec2 target(0.0f);
                if (view.agents.path[i] >= 0 && !view.set.paths[std::size_t(view.agents.path[i])].closed) {
                    has = true;
                    target = view.set.paths[std::size_t(view.agents.path[i])].points.back();
                } else if (view.agents.path[i] < 0 && view.agents.goal[i] >= 0) {
                    has = true;
                    target = view.agents.goalSpot[i];
                }
                if (tb.fills[s] == SensorFill::GoalDistance)
                    v = has ? glm::distance(p, target) : kNoneM;
                else
                    v = has ? bearingDeg(f, target - p) : 0.0f;
                break;
            }
            case SensorFill::PathOffset: {
                v = 0.0f;
                if (view.agents.path[i] < 0)
                    break;
                const std::vector<glm::vec2>& pts = view.set.paths[std::size_t(view.agents.path[i])].points;
                float best = INFINITY;
                for (std::size_t q = 0; q + 1 < pts.size(); ++q) {
                    const glm::vec2 c = closestOnSegment(p, pts[q], pts[q + 1]);
                    const float d = glm::distance(p, c);
                    const glm::vec2 along = pts[q + 1] - pts[q];
                    if (d < best && glm::dot(along, along) > 0.0f) {
                        best = d;
                        const glm::vec2 dir = glm::normalize(along);
                        v = glm::dot(p - c, glm::vec2(dir.y, -dir.x));
                    }
                }
                break;
            }
            case SensorFill::FlowBearing: {
                const glm::vec2 d = xz(flowDirection(view, view.agents.pos[i]));
                v = glm::dot(d, d) > 0.0f ? bearingDeg(f, d) : 0.0f;
                break;
            }
            case SensorFill::NeighbourCount: v = float(count); break;
            case SensorFill::NeighbourDensity:
                v = float(count) / (3.14159265f * type.perception * type.perception * tb.viewDeg / 360.0f);
                break;
            case SensorFill::NearestDistance: v = count ? distances()[0] : type.perception; break;
            case SensorFill::NearestBearing: v = count ? bearings()[0] : 0.0f; break;
            case SensorFill::VisionLeft:
            case SensorFill::VisionCentre:
            case SensorFill::VisionRight: {
                int seen[3] = {0, 0, 0};
                for (std::size_t j = 0; j < count; ++j) {
                    const float b = bearings()[j];
                    ++seen[b > third ? 0 : (b < -third ? 2 : 1)];
                }
                v = float(seen[int(tb.fills[s]) - int(SensorFill::VisionLeft)]);
                break;
            }
            case SensorFill::FeelerLeft: v = feeler[0]; break;
            case SensorFill::FeelerCentre: v = feeler[1]; break;
            case SensorFill::FeelerRight: v = feeler[2]; break;
            case SensorFill::WallDistance: {
                v = kWallReachM;
                view.set.walls.forEachNear(p, kWallReachM, [&](std::uint32_t w) {
                    const Segment& seg = view.set.walls.segment(w);
                    v = std::min(v, glm::distance(p, closestOnSegment(p, seg.a, seg.b)));
                });
                break;
            }
            case SensorFill::LightState:
            case SensorFill::StopLineDistance: {
                if (stopLineFound) {
                    v = tb.fills[s] == SensorFill::LightState ? stopLight : stopGap;
                    break;
                }
                float gap = kNoneM, light = 0.0f;
                if (const std::int32_t vehicle = m_brains->vehicleOf[i]; vehicle >= 0) {
                    // A vehicle's stop line is the next one on its lane, from its front.
                    const VehicleStopLine line = view.traffic.system->stopLineAhead(std::size_t(vehicle));
                    if (line.found) {
                        gap = line.distanceM;
                        light = 0.5f * float(int(line.phase));
                    }
                } else {
                    // The stop line ahead: an end of a lit crosswalk this agent walks toward
                    // and has not passed; its light, and the gap from the body to the line.
                    // "Toward" as the traffic signal has it: the way it wants to go (its path
                    // or goal, not its facing, which wobbles while it waits) within 60
                    // degrees of the crosswalk's axis, so a walker passing the end of a
                    // crosswalk along the sidewalk is not held at it.
                    // The way it wants to go, worked out only where a lit crosswalk is near.
                    glm::vec2 w(0.0f);
                    bool wanted = false;
                    for (const CrosswalkBox& c : view.set.crosswalks) {
                        if (c.light < 0)
                            continue;
                        const glm::vec2 ab = c.b - c.a;
                        const float len = glm::length(ab);
                        if (len <= 0.0f)
                            continue;
                        const glm::vec2 dir = ab / len;
                        const float along = glm::dot(p - c.a, dir), across = std::fabs(cross(dir, p - c.a));
                        if (across > c.halfWidth + kStopLineSideM)
                            continue;
                        if (!wanted) {
                            w = wantedHeading(view, i);
                            w = glm::dot(w, w) > 1e-12f ? glm::normalize(w) : f;
                            wanted = true;
                        }
                        float d = kNoneM;
                        if (along < 0.0f && glm::dot(w, dir) > kAlongCos)
                            d = -along - view.agents.radius[i];
                        else if (along > len && glm::dot(w, dir) < -kAlongCos)
                            d = along - len - view.agents.radius[i];
                        if (d < gap) {
                            gap = d;
                            light = 0.5f * float(view.lightState(std::size_t(c.light)));
                        }
                    }
                }
                stopGap = gap;
                stopLight = light;
                stopLineFound = true;
                v = tb.fills[s] == SensorFill::LightState ? light : gap;
                break;
            }
            case SensorFill::HeroDistance:
            case SensorFill::HeroBearing: {
                // The nearest hero other than the agent itself, where it stood at the step's start.
                float best = kNoneM, bearing = 0.0f;
                for (const std::uint32_t h : view.traffic.heroAgent) {
                    const glm::vec2 d = xz(view.agents.pos[h]) - p;
                    const float dist = glm::length(d);
                    if (h != i && dist < best) {
                        best = dist;
                        bearing = dist > 0.0f ? bearingDeg(f, d) : 0.0f;
                    }
                }
                v = tb.fills[s] == SensorFill::HeroDistance ? best : bearing;
                break;
            }
            case SensorFill::ActionPointDistance:
            case SensorFill::ActionPointBearing: {
                // The nearest action point the agent's type stops at, by the distance to its edge.
                float best = kNoneM, bearing = 0.0f;
                for (const ActionPlace& place : view.set.actionPoints) {
                    const glm::vec2 d = place.position - p;
                    const float centre = glm::length(d), edge = std::max(0.0f, centre - place.radiusM);
                    if (place.forType[view.agents.info[i].typeIndex] && edge < best) {
                        best = edge;
                        bearing = centre > 0.0f ? bearingDeg(f, d) : 0.0f;
                    }
                }
                v = tb.fills[s] == SensorFill::ActionPointDistance ? best : bearing;
                break;
            }
            case SensorFill::ActionPointTime: v = view.agents.pointAt[i] >= 0 ? view.agents.pointLeftS[i] : 0.0f; break;
            case SensorFill::TerrainSlope: {
                const float h0 = view.set.groundHeight(p.x, p.y),
                            h1 = view.set.groundHeight(p.x + 0.5f * f.x, p.y + 0.5f * f.y);
                v = glm::degrees(std::atan((h1 - h0) / 0.5f));
                break;
            }
            case SensorFill::Time: v = time; break;
            case SensorFill::AttrMaxSpeed: v = view.agents.maxSpeed[i]; break;
            case SensorFill::AttrRadius: v = view.agents.radius[i]; break;
            case SensorFill::AttrMass: v = type.mass; break;
            case SensorFill::AttrMaxForce: v = type.maxForce; break;
            case SensorFill::AttrPerception: v = type.perception; break;
            case SensorFill::AttrSpeedFactor:
                v = type.maxSpeed > 0.0f ? view.agents.maxSpeed[i] / type.maxSpeed : 1.0f;
                break;
            case SensorFill::SoundBearing:
            case SensorFill::SoundDistance:
            case SensorFill::SoundStrength:
            case SensorFill::SoundSourceBearing:
            case SensorFill::SoundSourceDistance:
            case SensorFill::SoundSourceStrength: break;  // below, once per channel
            case SensorFill::NeighbourDistance:
            case SensorFill::NeighbourBearing:
            case SensorFill::NeighbourSpeed:
            case SensorFill::NeighbourHeading:
            case SensorFill::NeighbourTag:
                for (std::size_t j = 0; j < kBrainNeighbours; ++j) {
                    float x = 0.0f;
                    if (j < count) {
                        switch (tb.fills[s]) {
                        case SensorFill::NeighbourDistance: x = distances()[j]; break;
                        case SensorFill::NeighbourBearing: x = bearings()[j]; break;
                        case SensorFill::NeighbourSpeed: x = glm::length(view.agents.vel[near[j]]); break;
                        case SensorFill::NeighbourTag:
                            x = m_brains->tagValues[tb.fillTag[s]][near[j]];
                            break;
                        default: x = bearingDeg(f, xz(view.agents.fwd[near[j]])); break;
                        }
                    }
                    (&v)[j] = x;
                }
                break;
            }
        }
        // Sound: each channel the type hears once, then every sensor reading it.
        for (const std::uint32_t c : tb.hears) {
            HeardList heard;
            const std::size_t loud = hearChannel(*m_brains, c, view.grid, view.agents.info, view.agents.pos,
                                                 view.agents.out, i, p, f, heard);
            for (std::size_t s = 0; s < sensors; ++s) {
                const SensorFill fill = tb.fills[s];
                if (!isSoundFill(fill) || tb.fillTag[s] != c)
                    continue;
                float* column = tb.columns[s].data();
                switch (fill) {
                case SensorFill::SoundBearing: column[k] = loud ? heard[0].bearingDeg : 0.0f; break;
                case SensorFill::SoundDistance: column[k] = loud ? heard[0].distanceM : kNoneM; break;
                case SensorFill::SoundStrength: column[k] = loud ? heard[0].strength : 0.0f; break;
                default:
                    for (std::size_t j = 0; j < kMaxHeard; ++j) {
                        const Heard h = j < loud ? heard[j] : Heard{};
                        column[k * kMaxHeard + j] = fill == SensorFill::SoundSourceBearing    ? h.bearingDeg
                                                    : fill == SensorFill::SoundSourceDistance ? h.distanceM
                                                                                              : h.strength;
                    }
                }
            }
            for (std::size_t set = 0; set < tb.itemCounts.size(); ++set)
                if (tb.itemSetChannel[set] == std::int32_t(c))
                    tb.itemCounts[set][k] = std::uint8_t(loud);
        }
    });
}

}  // namespace throng::sim
