#include "simcore/world/Sources.h"

#include "simcore/base/Rng.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace throng::sim {

namespace {

// Random streams of a source's arrivals, keyed by (source, arrival).
enum SourceStream : std::uint64_t { kSourceGap = 1, kSourceType, kSourceU, kSourceV };

std::uint64_t sourceArrivalKey(std::size_t source, std::uint64_t k)
{
    return (std::uint64_t(source + 1) << 40) | k;
}

// The type of a draw u in [0, 1) over the weights.
std::uint16_t sourceTypeOf(const Scene& scene, const Source& s, float u)
{
    float total = 0.0f;
    for (const SourceType& t : s.types)
        total += t.weight;
    float at = u * total;
    const SourceType* pick = &s.types.back();
    for (const SourceType& t : s.types) {
        if (at < t.weight) {
            pick = &t;
            break;
        }
        at -= t.weight;
    }
    for (std::size_t k = 0; k < scene.agentTypes.size(); ++k)
        if (scene.agentTypes[k].name == pick->type)
            return std::uint16_t(k);
    return 0;
}

// Where an arrival faces: the source's heading, else its goal (its first exit) or its path's
// first point.
float sourceHeadingOf(const Scene& scene, const Source& s, glm::vec2 place)
{
    if (s.headed)
        return glm::radians(s.headingDeg);
    glm::vec2 to = place;
    const std::string& goal = s.goal.empty() && !s.exits.empty() ? s.exits.front() : s.goal;
    if (const Goal* g = goal.empty() ? nullptr : scene.findGoal(goal))
        to = g->position;
    else if (const Path* p = s.path.empty() ? nullptr : scene.findPath(s.path); p && !p->points.empty())
        to = p->points.front();
    const glm::vec2 d = to - place;
    // Forward is (cos h, -sin h) on (x, z).
    return glm::length(d) > 1e-6f ? std::atan2(-d.y, d.x) : 0.0f;
}

}  // namespace

std::vector<SourceArrival> sourceArrivals(const Scene& scene, std::size_t index, std::uint64_t seed)
{
    const Source& s = scene.sources[index];
    std::vector<SourceArrival> out;
    if (s.types.empty() || !(s.rate > 0.0f))
        return out;
    const double end = double(scene.settings.durationS);
    std::vector<glm::dvec2> windows;
    if (s.windows.empty())
        windows.push_back({0.0, end});
    for (const glm::vec2& w : s.windows)
        if (double(w.x) < end)
            windows.push_back({double(w.x), std::min(double(w.y), end)});
    const double gap = 1.0 / double(s.rate);
    std::uint64_t k = 0;
    double poissonT = 0.0;  // a Poisson source's clock runs over its windows' time only
    std::size_t window = 0;
    double windowStart = 0.0;  // of the window `window`, on the Poisson clock
    auto full = [&] { return s.cap != 0 && out.size() >= s.cap; };
    auto add = [&](double t) {
        const std::uint64_t key = sourceArrivalKey(index, k);
        SourceArrival a;
        a.timeS = t;
        a.source = std::uint32_t(index);
        a.type = sourceTypeOf(scene, s, rngUniform(seed, key, 0, kSourceType));
        const float u = rngUniform(seed, key, 0, kSourceU), v = rngUniform(seed, key, 0, kSourceV);
        a.place = s.shape == SourceShape::Line ? s.from + (s.to - s.from) * u
                                               : s.min + (s.max - s.min) * glm::vec2(u, v);
        a.headingRad = sourceHeadingOf(scene, s, a.place);
        out.push_back(a);
        ++k;
    };
    if (s.arrivals == Arrivals::Steady) {
        for (const glm::dvec2& w : windows)
            for (double n = 0.0; !full(); n += 1.0) {
                const double t = w.x + n * gap;
                if (t >= w.y)
                    break;
                add(t);
            }
        return out;
    }
    while (!full() && window < windows.size()) {
        // Exponential gaps with mean 1 / rate; u in [0, 1), so 1 - u in (0, 1].
        poissonT += -std::log(1.0 - double(rngUniform(seed, sourceArrivalKey(index, k), 0, kSourceGap))) * gap;
        while (window < windows.size() && poissonT - windowStart >= windows[window].y - windows[window].x) {
            windowStart += windows[window].y - windows[window].x;
            ++window;
        }
        if (window < windows.size())
            add(windows[window].x + (poissonT - windowStart));
    }
    return out;
}

std::vector<std::uint32_t> sourceCounts(const Scene& scene, std::uint64_t seed)
{
    std::vector<std::uint32_t> counts;
    for (std::size_t s = 0; s < scene.sources.size(); ++s)
        counts.push_back(std::uint32_t(sourceArrivals(scene, s, seed).size()));
    return counts;
}

void SourcePhase::build(std::vector<std::uint32_t> agents, std::vector<double> timesS,
                        std::vector<std::uint32_t> sources)
{
    std::vector<std::size_t> order(agents.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return timesS[a] != timesS[b] ? timesS[a] < timesS[b] : agents[a] < agents[b];
    });
    m_agent.clear();
    m_timeS.clear();
    m_source.clear();
    std::uint32_t sourceCount = 0;
    for (std::size_t k : order) {
        m_agent.push_back(agents[k]);
        m_timeS.push_back(timesS[k]);
        m_source.push_back(sources[k]);
        sourceCount = std::max(sourceCount, sources[k] + 1);
    }
    m_blocked.assign(sourceCount, 0);
    m_done = 0;
}

void SourcePhase::sendOffstage(AgentColumns& agents) const
{
    for (std::uint32_t i : m_agent)
        agents.offstage[i] = agents.out[i] = agents.stopped[i] = 1;
}

bool SourcePhase::fits(std::size_t i, const AgentColumns& agents, const NeighbourGrid& grid,
                       float largestRadiusM) const
{
    // The bodies near the arrival's place from the grid, not every agent: an arrival
    // checked against all N agents made a stream into a crowd cost O(N) each (issue 26).
    const glm::vec3 p = agents.pos[i];
    bool clear = true;
    auto overlaps = [&](std::size_t j) {
        if (j == i || agents.out[j])
            return;
        const float reach = agents.radius[i] + agents.radius[j];
        const glm::vec3 d = agents.pos[j] - p;
        clear = clear && !(d.x * d.x + d.z * d.z < reach * reach);
    };
    grid.forEachNear(glm::vec2(p.x, p.z), agents.radius[i] + largestRadiusM, [&](std::uint32_t j) { overlaps(j); });
    for (const std::uint32_t j : m_enteredNow)
        overlaps(j);
    return clear;
}

std::size_t SourcePhase::enter(double timeS, AgentColumns& agents, const NeighbourGrid& grid, float largestRadiusM,
                               std::vector<std::uint32_t>* entered)
{
    if (entered)
        entered->clear();
    m_enteredNow.clear();
    // Small slack: a due time that is a whole number of steps enters on that step.
    const double now = timeS + 1e-9;
    std::fill(m_blocked.begin(), m_blocked.end(), std::uint8_t(0));
    std::size_t count = 0;
    while (m_done < m_agent.size() && !agents.offstage[m_agent[m_done]])
        ++m_done;
    for (std::size_t k = m_done; k < m_agent.size() && m_timeS[k] <= now; ++k) {
        const std::uint32_t i = m_agent[k];
        if (!agents.offstage[i] || m_blocked[m_source[k]])
            continue;
        if (!fits(i, agents, grid, largestRadiusM)) {
            m_blocked[m_source[k]] = 1;  // those after it from its source wait behind it
            continue;
        }
        agents.offstage[i] = 0;
        agents.out[i] = 0;
        agents.stopped[i] = 0;
        agents.stoppedBefore[i] = 0;
        agents.nextPos[i] = agents.pos[i];
        agents.resolvedPos[i] = agents.pos[i];
        m_enteredNow.push_back(i);
        if (entered)
            entered->push_back(i);
        ++count;
    }
    return count;
}

std::size_t SourcePhase::offstage(const AgentColumns& agents) const
{
    std::size_t n = 0;
    for (std::uint32_t i : m_agent)
        n += agents.offstage[i];
    return n;
}

}  // namespace throng::sim
