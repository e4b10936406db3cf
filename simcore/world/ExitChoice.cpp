#include "simcore/world/ExitChoice.h"

#include "simcore/base/detail/PlanarSegments.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace throng::sim {

namespace {

// Whether agent i is in the scene and still on its way: not off stage, out or arrived.
bool onItsWay(const AgentColumns& a, std::size_t i)
{
    return !a.offstage[i] && !a.out[i] && !a.arrived[i];
}

}  // namespace

void ExitChoice::build(std::vector<std::int32_t> setOf, std::vector<std::vector<std::int32_t>> sets)
{
    m_setOf = std::move(setOf);
    m_sets = std::move(sets);
}

std::vector<std::int32_t> ExitChoice::goals() const
{
    std::vector<std::int32_t> out;
    for (const std::vector<std::int32_t>& set : m_sets)
        out.insert(out.end(), set.begin(), set.end());
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

float ExitChoice::distanceM(const StepView& v, std::size_t i, std::int32_t g) const
{
    const glm::vec2 p = detail::xz(v.agents.pos[i]);
    const std::size_t goal = std::size_t(g);
    if (v.nav.active && goal < v.nav.hasField.size() && v.nav.hasField[goal]) {
        const FlowField& field = v.nav.fields[goal];
        const NavCell c = field.grid().nearestWalkable(field.grid().cellOf(p));
        if (!field.grid().walkable(c) || !field.reachable(c))
            return std::numeric_limits<float>::infinity();
        return field.distanceM(c) + glm::distance(p, field.grid().centre(c));
    }
    return glm::distance(p, v.set.goals[goal].position);
}

namespace {

// How long agent i expects to take to leave exit g: its walk there, or the queue ahead of it.
float expectedS(const StepView& v, std::size_t i, std::int32_t g, float distanceM, std::size_t ahead)
{
    const float capacity = kExitFlowPerMetre * 2.0f * v.set.goals[std::size_t(g)].radiusM;
    return std::max(distanceM / std::max(v.agents.maxSpeed[i], 0.01f), float(ahead) / capacity);
}

}  // namespace

std::vector<ExitChoice::Switch> ExitChoice::first(const StepView& v) const
{
    const std::size_t n = v.agents.pos.size();
    const std::vector<std::int32_t> exits = goals();
    // The others bound for each exit (placed walkers, other groups): their distances.
    std::vector<std::vector<float>> others(v.set.goals.size());
    for (std::size_t i = 0; i < n; ++i)
        if (setOf(i) < 0 && onItsWay(v.agents, i) && v.agents.goal[i] >= 0 &&
            std::binary_search(exits.begin(), exits.end(), v.agents.goal[i]))
            others[std::size_t(v.agents.goal[i])].push_back(distanceM(v, i, v.agents.goal[i]));
    for (std::vector<float>& d : others)
        std::sort(d.begin(), d.end());
    // The choosers, nearest to an exit first.
    std::vector<std::uint32_t> order;
    std::vector<float> nearest(n, std::numeric_limits<float>::infinity());
    for (std::size_t i = 0; i < n; ++i) {
        if (setOf(i) < 0 || !onItsWay(v.agents, i))
            continue;
        order.push_back(std::uint32_t(i));
        for (std::int32_t g : m_sets[std::size_t(setOf(i))])
            nearest[i] = std::min(nearest[i], distanceM(v, i, g));
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return nearest[a] < nearest[b]; });
    std::vector<std::size_t> chosen(v.set.goals.size(), 0);
    std::vector<Switch> out;
    for (const std::uint32_t i : order) {
        std::int32_t best = -1;
        float bestS = std::numeric_limits<float>::infinity();
        for (std::int32_t g : m_sets[std::size_t(setOf(i))]) {
            const float d = distanceM(v, i, g);
            const std::vector<float>& o = others[std::size_t(g)];
            const std::size_t othersAhead = std::size_t(std::lower_bound(o.begin(), o.end(), d) - o.begin());
            const std::size_t ahead = chosen[std::size_t(g)] + othersAhead;
            const float s = expectedS(v, i, g, d, ahead);
            if (best < 0 || s < bestS) {
                best = g;
                bestS = s;
            }
        }
        ++chosen[std::size_t(best)];
        out.push_back({i, best});
    }
    return out;
}

bool ExitChoice::roundAt(double timeS, double dtS)
{
    auto round = [](double t) { return std::floor(t / kChoiceRoundS + 1e-6); };
    return timeS > 0.0 && round(timeS) > round(timeS - dtS);
}

std::vector<std::vector<float>> ExitChoice::boundFor(const StepView& v) const
{
    const std::vector<std::int32_t> exits = goals();
    std::vector<std::vector<float>> bound(v.set.goals.size());
    for (std::size_t i = 0; i < v.agents.pos.size(); ++i)
        if (onItsWay(v.agents, i) && v.agents.goal[i] >= 0 &&
            std::binary_search(exits.begin(), exits.end(), v.agents.goal[i]))
            bound[std::size_t(v.agents.goal[i])].push_back(distanceM(v, i, v.agents.goal[i]));
    for (std::vector<float>& d : bound)
        std::sort(d.begin(), d.end());
    return bound;
}

ExitChoice::Options ExitChoice::options(const StepView& v, std::size_t i,
                                        const std::vector<std::vector<float>>& bound) const
{
    Options o;
    o.bestS = o.currentS = std::numeric_limits<float>::infinity();
    for (std::int32_t g : m_sets[std::size_t(setOf(i))]) {
        const float d = distanceM(v, i, g);
        const std::vector<float>& b = bound[std::size_t(g)];
        // Those nearer than this one; on its own exit, that leaves itself out.
        const std::size_t ahead = std::size_t(std::lower_bound(b.begin(), b.end(), d) - b.begin());
        const float s = expectedS(v, i, g, d, ahead);
        if (g == v.agents.goal[i])
            o.currentS = s;
        if (o.best < 0 || s < o.bestS) {
            o.best = g;
            o.bestS = s;
        }
    }
    return o;
}

std::vector<ExitChoice::Switch> ExitChoice::choose(const StepView& v, double timeS) const
{
    const std::uint64_t round = std::uint64_t(std::floor(timeS / kChoiceRoundS + 1e-6));
    const std::vector<std::vector<float>> bound = boundFor(v);
    std::vector<Switch> out;
    for (std::size_t i = 0; i < v.agents.pos.size(); ++i) {
        if (setOf(i) < 0 || !onItsWay(v.agents, i) || (v.agents.info[i].id + round) % kChoiceRounds != 0)
            continue;
        const std::vector<std::int32_t>& set = m_sets[std::size_t(setOf(i))];
        const std::int32_t current = v.agents.goal[i];
        const Options o = options(v, i, bound);
        const bool inSet = std::find(set.begin(), set.end(), current) != set.end();
        if (o.best >= 0 && o.best != current &&
            (!inSet || (o.bestS < kSwitchShare * o.currentS && o.currentS - o.bestS > kSwitchS)))
            out.push_back({std::uint32_t(i), o.best});
    }
    return out;
}

std::vector<ExitChoice::Switch> ExitChoice::onEntry(const StepView& v, const std::vector<std::uint32_t>& agents) const
{
    std::vector<Switch> out;
    if (std::none_of(agents.begin(), agents.end(), [&](std::uint32_t i) { return setOf(i) >= 0; }))
        return out;
    const std::vector<std::vector<float>> bound = boundFor(v);
    for (const std::uint32_t i : agents)
        if (setOf(i) >= 0)
            if (const Options o = options(v, i, bound); o.best >= 0)
                out.push_back({i, o.best});
    return out;
}

}  // namespace throng::sim
