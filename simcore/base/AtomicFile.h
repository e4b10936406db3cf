#pragma once
// Writes one file so that readers see either the old file or the complete new one: the
// bytes go to a temporary file beside the target, which is synced and renamed over it.
// Never leaves the temporary file behind, whether the write fails or is abandoned.

#include <fstream>
#include <string>

namespace throng::sim {

class AtomicFile {
public:
    explicit AtomicFile(std::string targetPath);
    ~AtomicFile();  // discards the temporary file unless commit() succeeded
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    // Creates the temporary file; false with error() naming the target when it cannot.
    bool open();
    // The open temporary file; valid between a successful open() and commit()/discard().
    std::ostream& stream() { return m_out; }
    // Flushes, syncs and renames the temporary file over the target; false with error().
    bool commit();
    // Closes and removes the temporary file; the target is left as it was.
    void discard();

    const std::string& targetPath() const { return m_target; }
    const std::string& error() const { return m_error; }

private:
    std::string m_target;
    std::string m_temp;
    std::string m_error;
    std::ofstream m_out;
};

// A fresh name beside `targetPath` (target + ".throng-tmp-<pid>-<n>"), never returned twice
// by this process; create it exclusively (O_EXCL, mkdir) and ask again if it exists.
std::string uniqueSiblingPath(const std::string& targetPath);

}  // namespace throng::sim
