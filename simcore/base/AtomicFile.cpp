#include "simcore/base/AtomicFile.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace throng::sim {

namespace {

std::atomic<unsigned> g_tempCounter{0};

std::string inQuotes(const std::string& path) { return "'" + path + "'"; }

bool syncFileToDisk(const std::string& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return false;
    const bool synced = ::fsync(fd) == 0;
    return (::close(fd) == 0) && synced;
}

}  // namespace

std::string uniqueSiblingPath(const std::string& targetPath)
{
    return targetPath + ".throng-tmp-" + std::to_string(::getpid()) + "-" + std::to_string(g_tempCounter.fetch_add(1));
}

AtomicFile::AtomicFile(std::string targetPath) : m_target(std::move(targetPath)) {}

AtomicFile::~AtomicFile() { discard(); }

bool AtomicFile::open()
{
    discard();
    m_error.clear();
    // O_EXCL: two exports racing for the same target must never share a temporary file.
    for (int attempt = 0; attempt < 100; ++attempt) {
        m_temp = uniqueSiblingPath(m_target);
        const int fd = ::open(m_temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            break;
        }
        const int err = errno;
        m_temp.clear();
        if (err != EEXIST) {
            m_error = "cannot write " + inQuotes(m_target) + ": " + std::strerror(err);
            return false;
        }
    }
    if (m_temp.empty()) {
        m_error = "cannot write " + inQuotes(m_target) + ": no free temporary name beside it";
        return false;
    }
    m_out.open(m_temp, std::ios::binary | std::ios::trunc);
    if (!m_out) {
        m_error = "cannot write " + inQuotes(m_target) + ": cannot open temporary file " + inQuotes(m_temp);
        std::remove(m_temp.c_str());
        m_temp.clear();
        return false;
    }
    return true;
}

bool AtomicFile::commit()
{
    if (m_temp.empty()) {
        m_error = "cannot write " + inQuotes(m_target) + ": the file was not opened";
        return false;
    }
    m_out.flush();
    const bool wrote = m_out.good();
    m_out.close();
    if (!wrote || m_out.fail() || !syncFileToDisk(m_temp)) {
        m_error = "could not write all of " + inQuotes(m_target) + " (disk full?)";
        discard();
        return false;
    }
    std::error_code ec;
    std::filesystem::rename(m_temp, m_target, ec);
    if (ec) {
        m_error = "cannot replace " + inQuotes(m_target) + ": " + ec.message();
        discard();
        return false;
    }
    m_temp.clear();
    return true;
}

void AtomicFile::discard()
{
    if (m_out.is_open())
        m_out.close();
    if (!m_temp.empty()) {
        std::remove(m_temp.c_str());
        m_temp.clear();
    }
}

}  // namespace throng::sim
