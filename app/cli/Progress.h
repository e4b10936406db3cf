#pragma once
// Progress of a long run on stderr: a redrawn bar on a terminal, a line every 10 % in a
// log. Silent when disabled (--quiet) or when the work is short.

#include <cstdint>
#include <iosfwd>
#include <string>

namespace throng::cli {

class Progress {
public:
    Progress(std::ostream& err, std::string label, std::uint64_t total, bool enabled);
    void update(std::uint64_t done);
    void finish();
    // Ends the bar where it stands (work stopped short): on a terminal, the next message
    // starts on a line of its own.
    void stop();

private:
    std::ostream& m_err;
    std::string m_label;
    std::uint64_t m_total;
    bool m_enabled, m_tty;
    int m_lastShown = -1;
};

}  // namespace throng::cli
