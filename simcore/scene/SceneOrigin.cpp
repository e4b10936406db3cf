#include "simcore/scene/SceneOrigin.h"

#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace throng::sim {

namespace {

// Every ground point of a scene, visited once; f(glm::vec2&) for (x, z) pairs and
// g(glm::vec3&) for 3D points whose (x, z) are ground coordinates.
template <class Scn, class F, class G>
void forEachGroundPoint(Scn& s, F&& f, G&& g)
{
    f(s.settings.boundsMin);
    f(s.settings.boundsMax);
    for (auto& a : s.agents) g(a.position);
    for (auto& gr : s.groups) {
        f(gr.min);
        f(gr.max);
        f(gr.center);
        for (auto& q : gr.points) f(q);
    }
    for (auto& p : s.paths)
        for (auto& q : p.points) f(q);
    for (auto& w : s.walls)
        for (auto& q : w.points) f(q);
    for (auto& o : s.obstacles) f(o.center);
    for (auto& goal : s.goals) f(goal.position);
    f(s.terrain.origin);
    for (auto& st : s.flowStrokes)
        for (auto& q : st.points) f(q);
    for (auto& l : s.lanes)
        for (auto& q : l.points) f(q);
    for (auto& c : s.crosswalks) {
        f(c.from);
        f(c.to);
    }
    for (auto& l : s.trafficLights) f(l.position);
    for (auto& h : s.heroes)
        for (auto& k : h.keyframes) g(k.position);
    for (auto& so : s.soundSources) f(so.position);
    for (auto& ap : s.actionPoints) f(ap.position);
    for (auto& so : s.sources) {
        f(so.from);
        f(so.to);
        f(so.min);
        f(so.max);
    }
}

float shifted(float v, double by) { return float(double(v) - by); }

}  // namespace

glm::dvec2 simulationOrigin(const Scene& scene)
{
    const glm::vec2 lo = scene.settings.boundsMin, hi = scene.settings.boundsMax;
    const double reach = std::max({std::fabs(double(lo.x)), std::fabs(double(lo.y)), std::fabs(double(hi.x)),
                                   std::fabs(double(hi.y))});
    if (!(reach > kFarSceneM))
        return glm::dvec2(0.0);
    return glm::dvec2(std::round(0.5 * (double(lo.x) + double(hi.x))), std::round(0.5 * (double(lo.y) + double(hi.y))));
}

Scene shiftedScene(const Scene& scene, glm::dvec2 origin)
{
    Scene out = scene;
    forEachGroundPoint(
        out, [&](glm::vec2& p) { p = {shifted(p.x, origin.x), shifted(p.y, origin.y)}; },
        [&](glm::vec3& p) { p = {shifted(p.x, origin.x), p.y, shifted(p.z, origin.y)}; });
    return out;
}

double coordinateSpacingM(const Scene& scene)
{
    float far = 0.0f;
    forEachGroundPoint(
        scene, [&](const glm::vec2& p) { far = std::max({far, std::fabs(p.x), std::fabs(p.y)}); },
        [&](const glm::vec3& p) { far = std::max({far, std::fabs(p.x), std::fabs(p.z)}); });
    if (!(far > 0.0f) || !std::isfinite(far))
        return 0.0;
    return double(std::nextafter(far, std::numeric_limits<float>::infinity()) - far);
}

}  // namespace throng::sim
