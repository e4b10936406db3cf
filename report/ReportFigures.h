#pragma once
// The figures of a run's analysis as rows of label and value text, grouped in sections
// (the run, each exit, each measurement line, each area): what the report's tables and
// the Analysis dock's figures show. Formats numbers; computes nothing new.

#include "simcore/analysis/RunAnalysis.h"

#include <string>
#include <vector>

namespace throng::report {

struct FigureRow {
    std::string label, value;
};

struct FigureSection {
    std::string title;
    std::vector<FigureRow> rows;
};

std::vector<FigureSection> reportFigures(const sim::RunAnalysis& analysis);

// Persons per second out of one exit over time bins of binS seconds (as flowPerSecond).
std::vector<double> exitFlowPerSecond(const sim::ExitOutflow& exit, float fps, std::size_t frameCount, double binS);

}  // namespace throng::report
