#include "report/HtmlReport.h"

#include "report/AnalysisCharts.h"
#include "report/ChartImage.h"
#include "report/GroundPlot.h"
#include "report/ReportFigures.h"

#include <QBuffer>
#include <QByteArray>

#include <cstdio>
#include <set>
#include <sstream>

namespace throng::report {

namespace {

std::string escaped(const std::string& text)
{
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

// JSON string contents: quotes, backslashes and control characters escaped; "</" broken up
// so a name cannot close the script element the JSON sits in.
std::string jsonText(const std::string& text)
{
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", unsigned(c));
            out += buf;
        } else if (c == '/' && i > 0 && text[i - 1] == '<') {
            out += "\\/";
        } else {
            out += c;
        }
    }
    return out;
}

std::string num(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

template <typename T>
std::string list(const std::vector<T>& values)
{
    std::string out = "[";
    for (std::size_t k = 0; k < values.size(); ++k) {
        if (k > 0)
            out += ',';
        out += num(double(values[k]));
    }
    out += ']';
    return out;
}

std::string pngDataUri(const QImage& image)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return "data:image/png;base64," + bytes.toBase64().toStdString();
}

void figure(std::ostringstream& html, const QImage& image, const std::string& alt)
{
    html << "<figure><img alt=\"" << escaped(alt) << "\" width=\"" << image.width() << "\" height=\""
         << image.height() << "\" src=\"" << pngDataUri(image) << "\"></figure>\n";
}

}  // namespace

std::string analysisJson(const sim::RunAnalysis& a)
{
    std::ostringstream j;
    const sim::Occupancy& o = a.occupancy;
    std::vector<std::uint32_t> inEachSecond, outEachSecond;
    for (std::size_t f = 0; f < o.inScene.size(); f += std::max<std::size_t>(1, std::size_t(a.fps + 0.5f))) {
        inEachSecond.push_back(o.inScene[f]);
        outEachSecond.push_back(o.out[f]);
    }
    std::set<std::uint32_t> drawn;  // the walkers the trajectory plan draws (a gap splits one in two)
    for (const sim::Trajectory& t : a.trajectories)
        drawn.insert(t.agent);
    j << "{\"fps\": " << num(a.fps) << ", \"frames\": " << a.frames << ", \"walkers\": " << a.walkers
      << ", \"walkers_drawn\": " << drawn.size()
      << ", \"evacuation_s\": " << num(o.evacuationS) << ", \"in_scene_each_second\": " << list(inEachSecond)
      << ", \"out_each_second\": " << list(outEachSecond) << ", \"flow_bin_s\": " << num(a.flowBinS)
      << ",\n \"lines\": [";
    for (std::size_t l = 0; l < a.lines.size(); ++l)
        j << (l ? ", " : "") << "{\"name\": \"" << jsonText(a.lines[l].name)
          << "\", \"forward\": " << a.lines[l].forward
          << ", \"backward\": " << a.lines[l].backward << ", \"flow_per_s\": " << list(a.lineFlowPerSecond[l]) << "}";
    j << "],\n \"exits\": [";
    for (std::size_t e = 0; e < o.exits.size(); ++e)
        j << (e ? ", " : "") << "{\"name\": \"" << jsonText(o.exits[e].exit)
          << "\", \"out\": " << o.exits[e].agentsOut()
          << ", \"flow_per_s\": " << list(exitFlowPerSecond(o.exits[e], a.fps, a.frames, a.flowBinS)) << "}";
    j << "],\n \"areas\": [";
    for (std::size_t k = 0; k < a.speedDensity.size(); ++k) {
        const sim::AreaSpeedDensity& area = a.speedDensity[k];
        std::vector<double> density, speed;
        for (const sim::SpeedDensitySample& s : area.samples) {
            density.push_back(s.densityPerM2);
            speed.push_back(s.speedMps);
        }
        j << (k ? ", " : "") << "{\"name\": \"" << jsonText(area.name) << "\", \"area_m2\": " << num(area.areaM2)
          << ", \"density\": " << list(density) << ", \"speed\": " << list(speed) << "}";
    }
    const sim::DensityMap& d = a.density;
    j << "],\n \"density_map\": {\"min\": [" << num(d.min.x) << ", " << num(d.min.y)
      << "], \"cell_m\": " << num(d.cellM)
      << ", \"cols\": " << d.cols << ", \"rows\": " << d.rows << ", \"frames\": " << d.frames
      << ", \"total_persons\": " << num(d.totalPersons()) << ", \"peak_density\": " << num(d.peakDensity()) << "}}";
    return j.str();
}

std::string reportHtml(const sim::Scene& scene, const sim::RunAnalysis& a, const ReportHeading& heading)
{
    std::ostringstream html;
    const std::string title = "Throng run report: " + heading.sceneName;
    html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << escaped(title)
         << "</title>\n<style>\nbody{font-family:sans-serif;margin:2em auto;max-width:980px;color:#222}\n"
            "table{border-collapse:collapse;margin:0 0 1.2em}\ntd,th{border:1px solid #ccc;padding:3px 10px;"
            "text-align:left}\nth{background:#f0f0f0}\nfigure{margin:1em 0}\nimg{max-width:100%;height:auto}\n"
            "</style>\n</head>\n<body>\n<h1>"
         << escaped(title) << "</h1>\n<p>Seed " << heading.seed << ". Measured from the recorded frames: "
         << "every figure below comes from the agents' positions on each frame.</p>\n";
    html << "<h2>Figures</h2>\n";
    for (const FigureSection& s : reportFigures(a)) {
        html << "<table>\n<tr><th colspan=\"2\">" << escaped(s.title) << "</th></tr>\n";
        for (const FigureRow& r : s.rows)
            html << "<tr><td>" << escaped(r.label) << "</td><td>" << escaped(r.value) << "</td></tr>\n";
        html << "</table>\n";
    }
    const QSize chartSize(900, 420), groundSize(900, 620);
    html << "<h2>Trajectories</h2>\n";
    {
        std::set<std::uint32_t> drawn;
        for (const sim::Trajectory& t : a.trajectories)
            drawn.insert(t.agent);
        if (drawn.size() < a.walkers)
            html << "<p>" << drawn.size() << " of the " << a.walkers << " walkers, picked evenly.</p>\n";
    }
    figure(html, paintGround(scene, a, GroundLayer::Trajectories, groundSize), "Trajectories");
    html << "<h2>Density</h2>\n";
    figure(html, paintGround(scene, a, GroundLayer::Density, groundSize), "Density heatmap");
    html << "<h2>Speed against density</h2>\n";
    figure(html, renderChart(*speedDensityChart(a), chartSize), "Speed against density");
    html << "<h2>Flow</h2>\n";
    figure(html, renderChart(*flowChart(a), chartSize), "Flow over time");
    html << "<h2>Agents in the scene and out</h2>\n";
    figure(html, renderChart(*occupancyChart(a), chartSize), "Agents in the scene and out over time");
    html << "<h2>Data</h2>\n<p>The data behind the plots is in this file as JSON, in the script element "
            "<code>throng-analysis</code>.</p>\n<script type=\"application/json\" id=\"throng-analysis\">\n"
         << analysisJson(a) << "\n</script>\n</body>\n</html>\n";
    return html.str();
}

sim::SaveResult writeReport(const std::string& path, const sim::Scene& scene, const sim::RunAnalysis& analysis,
                            const ReportHeading& heading)
{
    if (!ensureApplication())
        return {false, "report '" + path + "': the program runs no QApplication, which Qt Charts needs to draw"};
    return sim::writeFileAtomically(path, reportHtml(scene, analysis, heading));
}

}  // namespace throng::report
