#include "simcore/world/RunSplit.h"

#include <algorithm>
#include <cmath>

namespace throng::sim {

void RunSplit::prepare(int threads)
{
    const auto t = std::size_t(std::max(threads, 1));
    if (m_end.size() == t)
        return;
    m_end.resize(t);
    for (std::size_t k = 0; k < t; ++k)
        m_end[k] = double(k + 1) / double(t);
    m_busy.assign(t, 0.0);
}

std::pair<std::size_t, std::size_t> RunSplit::range(std::size_t n, int t) const
{
    const auto k = std::size_t(t);
    auto at = [&](double fraction) { return std::min(n, std::size_t(std::llround(fraction * double(n)))); };
    const std::size_t first = k == 0 ? 0 : at(m_end[k - 1]);
    const std::size_t last = k + 1 == m_end.size() ? n : at(m_end[k]);
    return {first, std::max(first, last)};
}

void RunSplit::rebalance()
{
    const std::size_t threads = m_end.size();
    if (threads < 2)
        return;
    double total = 0.0;
    for (std::size_t k = 0; k < threads; ++k) {
        const double share = m_end[k] - (k == 0 ? 0.0 : m_end[k - 1]);
        if (!(m_busy[k] > 0.0) || !(share > 0.0) || !std::isfinite(m_busy[k]))
            return;  // nothing to go by (a clock that did not move, an empty range)
        total += m_busy[k];
    }
    // Each range's cost spreads evenly over it; the new boundary k lies where the cost
    // summed from the start reaches k / threads of the whole.
    std::vector<double>& target = m_target;
    target.assign(threads, 1.0);
    std::size_t seg = 0;
    double costBefore = 0.0;
    for (std::size_t k = 0; k + 1 < threads; ++k) {
        const double want = total * double(k + 1) / double(threads);
        while (seg + 1 < threads && costBefore + m_busy[seg] < want)
            costBefore += m_busy[seg++];
        const double start = seg == 0 ? 0.0 : m_end[seg - 1];
        const double share = m_end[seg] - start;
        target[k] = start + share * std::clamp((want - costBefore) / m_busy[seg], 0.0, 1.0);
    }
    // Halfway, against a noisy clock, and no range below a quarter of an equal share.
    const double least = 0.25 / double(threads);
    double previous = 0.0;
    for (std::size_t k = 0; k + 1 < threads; ++k) {
        const double most = 1.0 - least * double(threads - 1 - k);
        m_end[k] = std::clamp(0.5 * (m_end[k] + target[k]), previous + least, most);
        previous = m_end[k];
    }
    m_end[threads - 1] = 1.0;
}

}  // namespace throng::sim
