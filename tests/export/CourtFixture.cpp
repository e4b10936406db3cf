#include "CourtFixture.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QtGlobal>

#include <fstream>
#include <sstream>

namespace throng::test {

namespace {

std::string courtYaml(double shift)
{
    auto at = [&](double x, double z) {
        std::ostringstream s;
        s.precision(12);
        s << "[" << x + shift << ", " << z + shift << "]";
        return s.str();
    };
    std::ostringstream y;
    y << "throng: 1\nsettings: {fps: 12, duration: 10, seed: 3, bounds: {min: " << at(-20, -15) << ", max: "
      << at(20, 15) << "}}\n"
      << "agent_types:\n  - {name: walker, radius: 0.3}\n"
      << "  - {name: visitor, radius: 0.3, variation: {tints: [[0.9, 0.1, 0.1], [0.1, 0.2, 0.9]]}}\n"
      << "walls:\n  - {name: back, height: 2.5, points: [" << at(-12, -8) << ", " << at(12, -8) << "]}\n"
      << "obstacles:\n  - {name: post, shape: circle, center: " << at(0, 4) << ", radius: 0.4}\n"
      << "lanes:\n  - {name: road, points: [" << at(-18, 12) << ", " << at(18, 12) << "], width: 3.5}\n"
      << "crosswalks:\n  - {name: zebra, from: " << at(-8, 10) << ", to: " << at(-8, 14) << ", width: 3}\n"
      << "traffic_lights:\n  - {name: signal, green: 3, yellow: 1, red: 3, position: " << at(-10, 9) << "}\n"
      << "goals:\n  - {name: door, position: " << at(8, 0) << ", radius: 1.5, exit: true}\n"
      << "  - {name: bench, position: " << at(-8, 0) << ", radius: 1}\n"
      << "groups:\n  - {name: leaving, type: walker, count: 8, rect: {min: " << at(-4, -3) << ", max: " << at(0, 3)
      << "}, goal: door}\n"
      << "  - {name: staying, type: visitor, count: 4, rect: {min: " << at(-3, -6) << ", max: " << at(1, -4)
      << "}, goal: bench}\n";
    return y.str();
}

}  // namespace

CourtShot recordCourt(double shift)
{
    CourtShot r;
    const sim::LoadResult loaded = sim::parseScene(courtYaml(shift), "court.yaml", "");
    if (!loaded.ok() || !loaded.diagnostics.empty())
        qFatal("%s", loaded.diagnostics[0].format().c_str());
    r.scene = loaded.scene;
    sim::World world(r.scene);
    world.startRecording(r.cache);
    std::vector<sim::AgentFrame> frame;
    for (int f = 1; f < 120; ++f) {
        world.step();
        world.snapshot(frame);
        r.cache.append(frame);
    }
    return r;
}

std::map<int, std::map<int, glm::dvec3>> readTrajectoryRows(const std::string& csvPath)
{
    std::map<int, std::map<int, glm::dvec3>> rows;
    std::ifstream in(csvPath);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string field[5];
        for (std::string& f : field)
            std::getline(s, f, ',');
        rows[std::stoi(field[1])][std::stoi(field[0])] = {std::stod(field[2]), std::stod(field[3]),
                                                          std::stod(field[4])};
    }
    return rows;
}

std::map<int, std::map<int, double>> readTrajectoryHeadings(const std::string& csvPath)
{
    std::map<int, std::map<int, double>> rows;
    std::ifstream in(csvPath);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string field[6];
        for (std::string& f : field)
            std::getline(s, f, ',');
        rows[std::stoi(field[1])][std::stoi(field[0])] = std::stod(field[5]) * 3.14159265358979 / 180.0;
    }
    return rows;
}

}  // namespace throng::test
