#pragma once
// Ctrl-C (SIGINT) and SIGTERM as a request to stop: while an InterruptWatch lives, either
// signal sets a flag the long commands read between frames and in their exports'
// progress, so they stop, leave no partial file behind, and exit with 128 + the signal.
// The same signal a second time ends the process at once, as it would without the watch.

namespace throng::cli {

class InterruptWatch {
public:
    InterruptWatch();  // installs the handlers; the flag starts clear
    ~InterruptWatch();  // puts the previous handlers back
    InterruptWatch(const InterruptWatch&) = delete;
    InterruptWatch& operator=(const InterruptWatch&) = delete;

    // The signal that asked to stop (SIGINT or SIGTERM), or 0 while none has.
    static int signal();
    static bool requested() { return signal() != 0; }
    // "SIGINT (Ctrl-C)" or "SIGTERM", for messages.
    static const char* signalName();
    // The exit status of a command stopped by it: 128 + the signal, as a shell reports.
    static int exitStatus() { return 128 + signal(); }
};

}  // namespace throng::cli
