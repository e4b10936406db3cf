#include "export/detail/StagingDirectory.h"

#include "simcore/base/AtomicFile.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace throng::exporting::detail {

StagingDirectory::StagingDirectory(std::string targetPath) : m_target(std::move(targetPath)) {}

StagingDirectory::~StagingDirectory()
{
    if (!m_dir.empty()) {
        std::error_code ec;
        std::filesystem::remove_all(m_dir, ec);
    }
}

bool StagingDirectory::create()
{
    for (int attempt = 0; attempt < 100; ++attempt) {
        std::string dir = sim::uniqueSiblingPath(m_target);
        if (::mkdir(dir.c_str(), 0777) == 0) {
            m_dir = std::move(dir);
            return true;
        }
        if (errno != EEXIST) {
            m_error = "cannot write '" + m_target + "': " + std::strerror(errno);
            return false;
        }
    }
    m_error = "cannot write '" + m_target + "': no free temporary name beside it";
    return false;
}

std::string StagingDirectory::filePath(const std::string& name) const { return m_dir + "/" + name; }

bool StagingDirectory::syncToDisk()
{
    // One syncfs for the whole directory: an fsync per file costs milliseconds each,
    // which adds up to minutes for a per-agent cache of a big crowd.
    const int fd = ::open(m_dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    const bool synced = fd >= 0 && ::syncfs(fd) == 0;
    if (fd >= 0)
        ::close(fd);
    if (!synced)
        m_error = "could not write all of '" + m_target + "' (disk full?)";
    return synced;
}

bool StagingDirectory::publish(const std::string& name, const std::string& targetPath)
{
    std::error_code ec;
    std::filesystem::rename(filePath(name), targetPath, ec);
    if (ec) {
        m_error = "cannot replace '" + targetPath + "': " + ec.message();
        return false;
    }
    return true;
}

}  // namespace throng::exporting::detail
