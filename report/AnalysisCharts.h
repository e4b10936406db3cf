#pragma once
// Builds the Qt Charts of a run's analysis: agents in the scene and out over time, flow
// over each measurement line and out of each exit over time, and speed against density
// in the measurement areas with Weidmann's curve. The caller owns each chart (to show in
// a QChartView or render to an image); building never changes the analysis.

#include "simcore/analysis/RunAnalysis.h"

#include <QtCharts/QChart>

#include <memory>

namespace throng::report {

std::unique_ptr<QChart> occupancyChart(const sim::RunAnalysis& analysis);
std::unique_ptr<QChart> flowChart(const sim::RunAnalysis& analysis);
std::unique_ptr<QChart> speedDensityChart(const sim::RunAnalysis& analysis);

}  // namespace throng::report
