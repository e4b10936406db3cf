#pragma once
// Writes a run's analysis as one self-contained HTML file: the figures as tables, every
// plot as an embedded PNG, and the data behind the plots as embedded JSON, with nothing
// fetched from anywhere. Needs a QApplication (ensureApplication); never simulates.

#include "simcore/analysis/RunAnalysis.h"
#include "simcore/io/SceneIO.h"
#include "simcore/scene/Scene.h"

#include <string>

namespace throng::report {

struct ReportHeading {
    std::string sceneName;  // shown as the title, e.g. the scene file's name
    std::uint64_t seed = 0;
};

// Needs a QApplication (ensureApplication).
std::string reportHtml(const sim::Scene& scene, const sim::RunAnalysis& analysis, const ReportHeading& heading);
// Builds the report and writes it atomically to `path`. An error, and nothing written, where
// the program already runs an application that cannot draw (see ensureApplication).
sim::SaveResult writeReport(const std::string& path, const sim::Scene& scene, const sim::RunAnalysis& analysis,
                            const ReportHeading& heading);

// The embedded data as JSON: series per second and per bin, per line, exit and area.
std::string analysisJson(const sim::RunAnalysis& analysis);

}  // namespace throng::report
