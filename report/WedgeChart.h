#pragma once
// The plot of a wedge (throng-cli wedge collect): one figure of every variant's run as a
// bar, so a TD sees which take is which at a glance. Needs Qt (Charts); never simulates.

#include <optional>
#include <string>
#include <vector>

namespace throng::report {

struct WedgeBar {
    std::string label;            // the variant: its folder, values and seed
    std::optional<double> value;  // none: the variant failed or has no such figure
};

// Writes `path` (PNG): a bar per variant of the figure `metric`, a missing one left empty
// and marked. Creates an offscreen application if the program has none. An empty string,
// or what went wrong naming the file.
std::string writeWedgeChart(const std::string& path, const std::string& metric, const std::vector<WedgeBar>& bars);

}  // namespace throng::report
