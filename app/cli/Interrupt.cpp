#include "Interrupt.h"

#include <csignal>

namespace throng::cli {

namespace {

volatile std::sig_atomic_t g_signal = 0;
struct sigaction g_previous[2];
constexpr int kSignals[2] = {SIGINT, SIGTERM};

extern "C" void onStopSignal(int number)
{
    if (g_signal == number) {
        // Asked twice: stop now, as without the watch.
        std::signal(number, SIG_DFL);
        std::raise(number);
        return;
    }
    g_signal = number;
}

}  // namespace

InterruptWatch::InterruptWatch()
{
    g_signal = 0;
    struct sigaction action = {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0;  // no SA_RESTART: a wait (the wedge's waitpid) returns with EINTR
    for (int k = 0; k < 2; ++k)
        sigaction(kSignals[k], &action, &g_previous[k]);
}

InterruptWatch::~InterruptWatch()
{
    for (int k = 0; k < 2; ++k)
        sigaction(kSignals[k], &g_previous[k], nullptr);
}

int InterruptWatch::signal()
{
    return g_signal;
}

const char* InterruptWatch::signalName()
{
    return g_signal == SIGINT ? "SIGINT (Ctrl-C)" : "SIGTERM";
}

}  // namespace throng::cli
