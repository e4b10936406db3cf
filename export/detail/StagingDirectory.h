#pragma once
// A private directory beside an export's target where several files are written in full
// before any of them is renamed into place. Never renames a file before it is synced, and
// removes itself with whatever is still inside when it goes out of scope.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include <string>

namespace throng::exporting::detail {

class StagingDirectory {
public:
    // The directory will be created beside `targetPath` (same filesystem, so renames are atomic).
    explicit StagingDirectory(std::string targetPath);
    ~StagingDirectory();
    StagingDirectory(const StagingDirectory&) = delete;
    StagingDirectory& operator=(const StagingDirectory&) = delete;

    // Creates the directory; false with error() naming the target when it cannot.
    bool create();
    // Where to write the staged file `name` (a plain file name).
    std::string filePath(const std::string& name) const;
    // Flushes every staged file to disk at once; call before publishing any of them.
    bool syncToDisk();
    // Renames the staged file `name` over `targetPath`; false with error().
    bool publish(const std::string& name, const std::string& targetPath);

    const std::string& error() const { return m_error; }

private:
    std::string m_target;
    std::string m_dir;
    std::string m_error;
};

}  // namespace throng::exporting::detail
