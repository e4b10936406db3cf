#include "simcore/base/ThreadTeam.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>

namespace throng::sim {

// Why oneTBB and not OpenMP: OpenMP's threads meet at a barrier after every loop, so a
// thread that another process holds off its core stalls the whole team; with libgomp's
// default spinning, 2 threads ran 39 times slower than 1 on a machine with one core busy,
// and sleeping waiters (OMP_WAIT_POLICY=passive) cost a third on a quiet one. Here the
// caller runs whatever chunks no helper has taken, and an idle helper spins only briefly.
struct ThreadTeam::Impl {
    tbb::task_arena arena;
    std::vector<std::atomic<std::uint64_t>> chunks;
    explicit Impl(int threads) : arena(threads, 1), chunks(std::size_t(threads)) {}
};

int ThreadTeam::resolve(int threads)
{
    return threads > 0 ? threads : std::max(1, tbb::info::default_concurrency());
}

ThreadTeam::ThreadTeam(int threads) : m_size(resolve(threads)), m_impl(std::make_unique<Impl>(m_size)) {}

ThreadTeam::~ThreadTeam() = default;

void ThreadTeam::run(std::size_t n, std::size_t grain, ChunkFn fn, void* context) const
{
    const std::size_t chunks = (n + grain - 1) / grain;
    Impl& impl = *m_impl;
    impl.arena.execute([&] {
        // simple_partitioner: each leaf is exactly one chunk, whatever the threads do.
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, chunks, 1),
            [&](const tbb::blocked_range<std::size_t>& r) {
                const int slot = std::clamp(tbb::this_task_arena::current_thread_index(), 0, m_size - 1);
                for (std::size_t c = r.begin(); c != r.end(); ++c)
                    fn(context, c * grain, std::min(n, (c + 1) * grain), slot);
                impl.chunks[std::size_t(slot)].fetch_add(r.size(), std::memory_order_relaxed);
            },
            tbb::simple_partitioner());
    });
}

void ThreadTeam::noteCallerRan(std::size_t chunks) const
{
    m_impl->chunks[0].fetch_add(chunks, std::memory_order_relaxed);
}

std::vector<std::uint64_t> ThreadTeam::chunksRun() const
{
    std::vector<std::uint64_t> out(std::size_t(m_size), 0);
    for (std::size_t s = 0; s < out.size(); ++s)
        out[s] = m_impl->chunks[s].load(std::memory_order_relaxed);
    return out;
}

}  // namespace throng::sim
