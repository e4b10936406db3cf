#include "Progress.h"

#include <ostream>
#include <unistd.h>

namespace throng::cli {

Progress::Progress(std::ostream& err, std::string label, std::uint64_t total, bool enabled)
    : m_err(err), m_label(std::move(label)), m_total(total), m_enabled(enabled && total > 0),
      m_tty(::isatty(STDERR_FILENO) != 0)
{
}

void Progress::update(std::uint64_t done)
{
    if (!m_enabled)
        return;
    const int percent = int(done * 100 / m_total);
    const int step = m_tty ? 1 : 10;
    if (percent / step == m_lastShown / step && m_lastShown >= 0)
        return;
    m_lastShown = percent;
    if (m_tty) {
        const int width = 30, filled = percent * width / 100;
        m_err << '\r' << m_label << " [" << std::string(std::size_t(filled), '#')
              << std::string(std::size_t(width - filled), ' ') << "] " << percent << "%" << std::flush;
    } else {
        m_err << m_label << ": " << percent << "%\n" << std::flush;
    }
}

void Progress::finish()
{
    if (!m_enabled)
        return;
    update(m_total);
    if (m_tty)
        m_err << '\n' << std::flush;
}

void Progress::stop()
{
    if (m_enabled && m_tty && m_lastShown >= 0)
        m_err << '\n' << std::flush;
}

}  // namespace throng::cli
