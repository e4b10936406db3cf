#pragma once
// Runs a loop's chunks on a fixed number of threads: the calling thread and helpers that
// take chunks as they come free (oneTBB's work stealing). A helper the operating system
// does not run, on a machine busy with other work, delays nobody: the caller takes its
// chunks. It never decides a result: chunk boundaries depend only on the loop's length and
// grain, never on the thread count or on which thread runs a chunk.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

namespace throng::sim {

class ThreadTeam {
public:
    // threads <= 0: one per core this process may run on (its affinity mask).
    explicit ThreadTeam(int threads = 0);
    ~ThreadTeam();
    ThreadTeam(const ThreadTeam&) = delete;
    ThreadTeam& operator=(const ThreadTeam&) = delete;

    int size() const { return m_size; }

    // fn(begin, end, slot) for each chunk [begin, end) of [0, n), `grain` items long (the
    // last may be shorter); slot in [0, size()) is the running thread's, for scratch that
    // must not be shared. Chunks may run in any order and on any thread, at once.
    template <typename Fn>
    void forChunks(std::size_t n, std::size_t grain, Fn&& fn) const
    {
        if (n == 0)
            return;
        grain = grain == 0 ? 1 : grain;
        if (m_size == 1 || n <= grain) {
            for (std::size_t begin = 0; begin < n; begin += grain)
                fn(begin, std::min(n, begin + grain), 0);
            noteCallerRan((n + grain - 1) / grain);
            return;
        }
        auto call = [](void* context, std::size_t begin, std::size_t end, int slot) {
            (*static_cast<std::remove_reference_t<Fn>*>(context))(begin, end, slot);
        };
        run(n, grain, call, const_cast<void*>(static_cast<const void*>(&fn)));
    }

    // fn(i) for each i in [0, n), in chunks of `grain`.
    template <typename Fn>
    void forEach(std::size_t n, std::size_t grain, Fn&& fn) const
    {
        forChunks(n, grain, [&fn](std::size_t begin, std::size_t end, int) {
            for (std::size_t i = begin; i < end; ++i)
                fn(i);
        });
    }

    // The sum of fn(begin, end, slot) over the chunks (whole numbers: the same sum in any
    // order).
    template <typename Fn>
    std::uint64_t sumChunks(std::size_t n, std::size_t grain, Fn&& fn) const
    {
        std::atomic<std::uint64_t> total{0};
        forChunks(n, grain, [&](std::size_t begin, std::size_t end, int slot) {
            total.fetch_add(std::uint64_t(fn(begin, end, slot)), std::memory_order_relaxed);
        });
        return total.load(std::memory_order_relaxed);
    }

    // Chunks each slot has run since the team was made (tests assert every thread worked).
    std::vector<std::uint64_t> chunksRun() const;

    // Threads a team of `threads` (<= 0: the default) would have.
    static int resolve(int threads);

private:
    using ChunkFn = void (*)(void* context, std::size_t begin, std::size_t end, int slot);
    void run(std::size_t n, std::size_t grain, ChunkFn fn, void* context) const;
    void noteCallerRan(std::size_t chunks) const;

    struct Impl;
    int m_size = 1;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace throng::sim
