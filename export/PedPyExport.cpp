#include "export/PedPyExport.h"

#include "simcore/base/AtomicFile.h"
#include "simcore/nav/NavShapes.h"
#include "simcore/traffic/LaneNetwork.h"
#include "simcore/traffic/WalkerBarriers.h"
#include "export/detail/ExportCancel.h"
#include "export/detail/TextFields.h"

#include <cmath>
#include <filesystem>
#include <numbers>

namespace throng::exporting {

namespace {

constexpr int kCircleCorners = 32;

// -v, with +0 for 0 (never "-0").
float negated(float v)
{
    return 0.0f - v;
}

// A ground point (x, z) of the scene in PedPy's axes: "x y" with y = -z.
void appendPoint(std::string& out, glm::vec2 p)
{
    detail::appendFloat(out, p.x);
    out += ' ';
    detail::appendFloat(out, negated(p.y));
}

void appendLine(std::string& out, glm::vec2 a, glm::vec2 b)
{
    out += ", LINESTRING (";
    appendPoint(out, a);
    out += ", ";
    appendPoint(out, b);
    out += ')';
}

// A closed ring (the first corner repeated at the end, as WKT wants).
void appendPolygon(std::string& out, const std::vector<glm::vec2>& corners)
{
    out += ", POLYGON ((";
    for (std::size_t k = 0; k <= corners.size(); ++k) {
        if (k > 0)
            out += ", ";
        appendPoint(out, corners[k % corners.size()]);
    }
    out += "))";
}

std::string geometryText(const sim::Scene& scene)
{
    const glm::vec2 lo = scene.settings.boundsMin, hi = scene.settings.boundsMax;
    std::string out = "GEOMETRYCOLLECTION (POLYGON ((";
    const glm::vec2 outline[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
    for (int k = 0; k <= 4; ++k) {
        if (k > 0)
            out += ", ";
        appendPoint(out, outline[k % 4]);
    }
    out += "))";
    for (const sim::Wall& w : scene.walls) {
        out += ", LINESTRING (";
        for (std::size_t k = 0; k < w.points.size(); ++k) {
            if (k > 0)
                out += ", ";
            appendPoint(out, w.points[k]);
        }
        out += ')';
    }
    if (!scene.lanes.empty())
        for (const sim::BarrierSegment& b : sim::walkerBarriers(sim::LaneNetwork(scene)))
            appendLine(out, b.a, b.b);
    const sim::NavShapes shapes = sim::navShapes(scene);
    for (const sim::NavCircle& c : shapes.circles) {
        std::vector<glm::vec2> corners;
        for (int k = 0; k < kCircleCorners; ++k) {
            const double a = 2.0 * std::numbers::pi * double(k) / kCircleCorners;
            corners.push_back(c.centre + c.radiusM * glm::vec2(float(std::cos(a)), float(std::sin(a))));
        }
        appendPolygon(out, corners);
    }
    for (const sim::NavBox& box : shapes.boxes) {
        sim::Segment sides[4];
        sim::boxSides(box, sides);
        appendPolygon(out, {sides[0].a, sides[1].a, sides[2].a, sides[3].a});
    }
    out += ")\n";
    return out;
}

}  // namespace

std::string pedPyGeometryPath(const std::string& path)
{
    return std::filesystem::path(path).replace_extension(".wkt").string();
}

ExportResult writePedPyTrajectories(const sim::Scene& scene, const sim::FrameCache& cache, const std::string& path,
                                    const ProgressFn& progress)
{
    ExportResult result;
    const std::string geometryPath = pedPyGeometryPath(path);
    if (geometryPath == path) {
        result.error = "PedPy trajectories '" + path + "': the path must not end in .wkt (the set is written there)";
        return result;
    }
    sim::AtomicFile trajectories(path), geometry(geometryPath);
    if (!trajectories.open()) {
        result.error = trajectories.error();
        return result;
    }
    if (!geometry.open()) {
        result.error = geometry.error();
        return result;
    }
    char fps[32];
    std::snprintf(fps, sizeof fps, "%g", double(scene.settings.fps));
    std::string text = "# Throng trajectories for PedPy: pedpy.load_trajectory_from_txt reads this file\n"
                       "# framerate: " + std::string(fps) + "\n"
                       "# unit: x/m y/m z/m; x east, y north (Throng's -z), z up\n"
                       "# the set: " + std::filesystem::path(geometryPath).filename().string() + " (WKT)\n"
                       "# id frame x y z\n";
    text.reserve(detail::kFlushBytes + 256);
    const auto& agents = cache.agents();
    std::vector<char> walker(agents.size(), 0);
    for (std::size_t i = 0; i < agents.size(); ++i)
        walker[i] = agents[i].typeIndex < scene.agentTypes.size() &&
                    scene.agentTypes[agents[i].typeIndex].kind == sim::AgentKind::Pedestrian;
    const glm::dvec3 origin = cache.origin();
    const std::size_t frames = cache.frameCount();
    for (std::size_t f = 0; f < frames; ++f) {
        if (detail::cancelledAt(progress, static_cast<float>(f) / static_cast<float>(frames)))
            return detail::cancelledExport(path);
        for (std::size_t i = 0; i < agents.size(); ++i) {
            const sim::AgentFrame& a = cache.at(f, i);
            if (!walker[i] || a.out || !a.present)
                continue;
            detail::appendUnsigned(text, agents[i].id);
            text += ' ';
            detail::appendUnsigned(text, f);
            text += ' ';
            detail::appendCoordinate(text, a.position.x, origin.x);
            text += ' ';
            detail::appendCoordinate(text, negated(a.position.z), 0.0 - origin.z);
            text += ' ';
            detail::appendCoordinate(text, a.position.y, origin.y);
            text += '\n';
            if (text.size() >= detail::kFlushBytes) {
                trajectories.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
                text.clear();
            }
        }
    }
    trajectories.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
    geometry.stream() << geometryText(scene);
    if (!trajectories.commit()) {
        result.error = trajectories.error();
        return result;
    }
    if (!geometry.commit()) {
        result.error = geometry.error();
        return result;
    }
    result.writtenPaths = {path, geometryPath};
    if (progress)
        progress(1.0f);
    return result;
}

}  // namespace throng::exporting
