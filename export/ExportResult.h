#pragma once
// What every exporter returns: the files it wrote, or why it wrote nothing; plus the
// progress callback they all accept. Plain data, never touches the disk itself.

#include <functional>
#include <string>
#include <vector>

namespace throng::exporting {

// Called now and then with the fraction done in [0, 1], on the exporting thread.
// Return false to cancel: the exporter stops and leaves no file of this export behind.
using ProgressFn = std::function<bool(float fraction)>;

struct ExportResult {
    std::vector<std::string> writtenPaths;  // files now on disk, complete; empty on failure
    std::string error;                      // empty on success; names the file on failure
    bool cancelled = false;                 // stopped by the progress callback (error says so)
    bool ok() const { return error.empty(); }
};

}  // namespace throng::exporting
