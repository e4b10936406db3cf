#pragma once
// Runs numbered jobs in forked child processes, so a job that aborts, segfaults or hangs
// is reported by its number instead of taking the test down. A child runs jobs one after
// another until one dies or overruns its time; the next child starts after it. POSIX
// only; test-only. The parent runs no job and no OpenMP region of its own.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace throng::test {

struct IsolatedFailure {
    std::size_t job = 0;
    std::string what;
};

// job(i) returns an empty string when job i is fine, else what went wrong. A job that has
// used limitS seconds of processor time, or waited 5 * limitS seconds, is killed and
// reported as hung: processor time, because on a machine busy with other work a job that
// needs 9 s of it took over 20 s; waiting too, for a job that hangs without computing.
std::vector<IsolatedFailure> runIsolated(std::size_t jobs, const std::function<std::string(std::size_t)>& job,
                                         double limitS);

}  // namespace throng::test
