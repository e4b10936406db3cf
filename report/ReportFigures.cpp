#include "report/ReportFigures.h"

#include "simcore/world/NavStats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace throng::report {

namespace {

std::string number(double v, int decimals)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string seconds(double s) { return s < 0.0 ? "not reached" : number(s, 1) + " s"; }

}  // namespace

std::vector<double> exitFlowPerSecond(const sim::ExitOutflow& exit, float fps, std::size_t frameCount, double binS)
{
    sim::LineFlow asLine;
    for (std::size_t f : exit.frames)
        asLine.crossings.push_back({f, 0, true});
    return sim::flowPerSecond(asLine, fps, frameCount, binS);
}

std::vector<FigureSection> reportFigures(const sim::RunAnalysis& a)
{
    std::vector<FigureSection> sections;
    const sim::Occupancy& o = a.occupancy;
    FigureSection run{"Run", {}};
    run.rows.push_back({"Recorded", std::to_string(a.frames) + " frames at " + number(a.fps, 0) + " fps (" +
                                        number(a.durationS, 1) + " s)"});
    run.rows.push_back({"Walkers", std::to_string(a.walkers)});
    run.rows.push_back({"Most agents in the scene at once", std::to_string(o.peakInScene)});
    run.rows.push_back({"Agents out through exits", std::to_string(o.out.empty() ? 0 : o.out.back())});
    run.rows.push_back({"Agents in the scene at the end", std::to_string(o.inScene.empty() ? 0 : o.inScene.back())});
    run.rows.push_back({"Time to evacuate", seconds(o.evacuationS)});
    run.rows.push_back({"Peak density (mean over the run, " + number(a.density.cellM, 1) + " m cells)",
                        number(a.density.peakDensity(), 2) + " persons/m²"});
    sections.push_back(std::move(run));

    for (const sim::ExitOutflow& e : o.exits) {
        FigureSection s{"Exit " + e.exit, {}};
        s.rows.push_back({"Agents out", std::to_string(e.agentsOut())});
        if (!e.frames.empty()) {
            s.rows.push_back({"First out", seconds(double(e.frames.front()) / a.fps)});
            s.rows.push_back({"Last out", seconds(double(e.frames.back()) / a.fps)});
            std::vector<float> times;
            for (std::size_t f : e.frames)
                times.push_back(float(double(f) / a.fps));
            const double steady = sim::steadyOutflowPerSecond(times);
            s.rows.push_back({"Steady outflow (10th to 90th percentile)",
                              steady < 0.0 ? "too few agents" : number(steady, 2) + " persons/s"});
        }
        sections.push_back(std::move(s));
    }
    for (std::size_t l = 0; l < a.lines.size(); ++l) {
        const sim::LineFlow& line = a.lines[l];
        FigureSection s{"Measurement line " + line.name, {}};
        s.rows.push_back({"Length", number(line.lengthM, 2) + " m"});
        s.rows.push_back({"Crossings forward", std::to_string(line.forward)});
        s.rows.push_back({"Crossings backward", std::to_string(line.backward)});
        const std::vector<double>& flow = a.lineFlowPerSecond[l];
        const double peak = flow.empty() ? 0.0 : *std::max_element(flow.begin(), flow.end());
        s.rows.push_back({"Peak flow (" + number(a.flowBinS, 1) + " s bins)",
                          number(peak, 2) + " persons/s (" + number(line.lengthM > 0 ? peak / line.lengthM : 0.0, 2) +
                              " persons/m/s)"});
        sections.push_back(std::move(s));
    }
    for (const sim::AreaSpeedDensity& area : a.speedDensity) {
        FigureSection s{"Measurement area " + area.name, {}};
        s.rows.push_back({"Area", number(area.areaM2, 2) + " m²"});
        s.rows.push_back({"Frames with walkers inside", std::to_string(area.samples.size())});
        if (!area.samples.empty()) {
            double density = 0.0, speed = 0.0, peak = 0.0;
            for (const sim::SpeedDensitySample& x : area.samples) {
                density += x.densityPerM2;
                speed += x.speedMps;
                peak = std::max(peak, x.densityPerM2);
            }
            const double n = double(area.samples.size());
            s.rows.push_back({"Mean density while occupied", number(density / n, 2) + " persons/m²"});
            s.rows.push_back({"Highest density", number(peak, 2) + " persons/m²"});
            s.rows.push_back({"Mean speed while occupied", number(speed / n, 2) + " m/s (Weidmann at that density: " +
                                                               number(sim::weidmannSpeed(density / n), 2) + " m/s)"});
        }
        sections.push_back(std::move(s));
    }
    return sections;
}

}  // namespace throng::report
