#pragma once
// One contiguous range of a run of work items per thread, with boundaries that move from
// step to step so that the threads take equally long: each range's share follows how long
// its thread took last time for it. The step walks the grid's order this way (a run per
// thread keeps each thread's writes in its own region of space), and a crowd that gathers
// in one part of that order makes halves by count uneven. Which thread steps an agent
// never changes its result, so the split changes only the speed.

#include <cstddef>
#include <utility>
#include <vector>

namespace throng::sim {

class RunSplit {
public:
    // Sets the number of threads; a new number starts from equal ranges.
    void prepare(int threads);
    // Thread t's range of n items, [first, second). The ranges of all threads cover 0..n.
    std::pair<std::size_t, std::size_t> range(std::size_t n, int t) const;
    // Thread t's seconds for its range this step (each thread writes only its own).
    void record(int t, double seconds) { m_busy[std::size_t(t)] = seconds; }
    // After every thread recorded: moves the boundaries halfway to where each thread's
    // last time per item predicts equal times, keeping every range at least a quarter
    // of an equal share.
    void rebalance();

private:
    std::vector<double> m_end;   // per thread: where its range ends, as a fraction of the run
    std::vector<double> m_busy;  // per thread: seconds for its range in the last step
    std::vector<double> m_target;  // rebalance's scratch: where each boundary would go
};

}  // namespace throng::sim
