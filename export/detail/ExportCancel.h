#pragma once
// What every exporter does when its progress callback asks it to stop.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/ExportResult.h"

#include <string>

namespace throng::exporting::detail {

// Whether `progress` (when set) cancels at `fraction` done.
inline bool cancelledAt(const ProgressFn& progress, float fraction)
{
    return progress && !progress(fraction);
}

// The result of an export to `path` that was cancelled.
inline ExportResult cancelledExport(const std::string& path)
{
    ExportResult result;
    result.cancelled = true;
    result.error = "export to '" + path + "' cancelled";
    return result;
}

}  // namespace throng::exporting::detail
