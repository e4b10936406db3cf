#include "IsolatedRuns.h"

#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>

namespace throng::test {

namespace {

struct Progress {  // shared with the child: which job it is on, since when (wall and processor time)
    std::atomic<std::uint64_t> job;
    std::atomic<std::int64_t> startedNs;
    std::atomic<std::int64_t> startedCpuNs;
};

std::int64_t nowNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// Processor time of process `clock` (CLOCK_PROCESS_CPUTIME_ID for this one); -1 when unknown.
std::int64_t cpuNs(clockid_t clock)
{
    timespec t{};
    if (clock_gettime(clock, &t) != 0)
        return -1;
    return std::int64_t(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}

void writeAll(int fd, const std::string& s)
{
    std::size_t done = 0;
    while (done < s.size()) {
        const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
        if (n <= 0)
            return;
        done += std::size_t(n);
    }
}

// Failures travel as "job\twhat\n" with newlines in `what` flattened.
void parse(std::string& buffer, std::vector<IsolatedFailure>& out)
{
    std::size_t end;
    while ((end = buffer.find('\n')) != std::string::npos) {
        const std::string line = buffer.substr(0, end);
        buffer.erase(0, end + 1);
        const std::size_t tab = line.find('\t');
        if (tab != std::string::npos)
            out.push_back({std::size_t(std::stoull(line.substr(0, tab))), line.substr(tab + 1)});
    }
}

}  // namespace

std::vector<IsolatedFailure> runIsolated(std::size_t jobs, const std::function<std::string(std::size_t)>& job,
                                         double limitS)
{
    std::vector<IsolatedFailure> failures;
    void* shared = mmap(nullptr, sizeof(Progress), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (shared == MAP_FAILED)
        return {{0, "cannot map shared memory for the children"}};
    Progress* progress = new (shared) Progress{};
    std::size_t next = 0;
    while (next < jobs) {
        int fds[2];
        if (pipe(fds) != 0)
            return {{next, "cannot open a pipe to the child"}};
        progress->job = next;
        progress->startedNs = nowNs();
        progress->startedCpuNs = 0;
        const pid_t child = fork();
        if (child == 0) {
            ::close(fds[0]);
            for (std::size_t i = next; i < jobs; ++i) {
                progress->job = i;
                progress->startedCpuNs = cpuNs(CLOCK_PROCESS_CPUTIME_ID);
                progress->startedNs = nowNs();
                std::string what = job(i);
                if (!what.empty()) {
                    for (char& c : what)
                        if (c == '\n' || c == '\t')
                            c = ' ';
                    writeAll(fds[1], std::to_string(i) + "\t" + what + "\n");
                }
            }
            ::close(fds[1]);
            _exit(0);
        }
        ::close(fds[1]);
        clockid_t childClock{};
        const bool cpuKnown = clock_getcpuclockid(child, &childClock) == 0;
        std::string buffer;
        int status = 0;
        bool killed = false, exited = false;
        const char* hungFor = "";
        while (!exited) {
            pollfd p{fds[0], POLLIN, 0};
            if (poll(&p, 1, 100) > 0) {
                char chunk[4096];
                const ssize_t n = ::read(fds[0], chunk, sizeof chunk);
                if (n > 0)
                    buffer.append(chunk, std::size_t(n));
                parse(buffer, failures);
            }
            if (waitpid(child, &status, WNOHANG) == child) {
                exited = true;
                break;
            }
            const double waitedS = double(nowNs() - progress->startedNs.load()) * 1e-9;
            const std::int64_t cpu = cpuKnown ? cpuNs(childClock) : -1;
            const double usedS = cpu >= 0 ? double(cpu - progress->startedCpuNs.load()) * 1e-9 : waitedS;
            if (!killed && (usedS > limitS || waitedS > 5.0 * limitS)) {
                hungFor = usedS > limitS ? "processor time" : "waiting";
                kill(child, SIGKILL);
                killed = true;
            }
        }
        char chunk[4096];
        ssize_t n;
        while ((n = ::read(fds[0], chunk, sizeof chunk)) > 0)
            buffer.append(chunk, std::size_t(n));
        parse(buffer, failures);
        ::close(fds[0]);
        const std::size_t at = std::size_t(progress->job.load());
        if (killed) {
            char what[96];
            std::snprintf(what, sizeof what, "hung: still running after %g s of %s",
                          hungFor[0] == 'w' ? 5.0 * limitS : limitS, hungFor);
            failures.push_back({at, what});
            next = at + 1;
        } else if (WIFSIGNALED(status)) {
            failures.push_back({at, std::string("crashed: ") + strsignal(WTERMSIG(status))});
            next = at + 1;
        } else if (WIFEXITED(status) && WEXITSTATUS(status) != 0) {
            failures.push_back({at, "exited with status " + std::to_string(WEXITSTATUS(status))});
            next = at + 1;
        } else {
            next = jobs;
        }
    }
    munmap(shared, sizeof(Progress));
    return failures;
}

}  // namespace throng::test
