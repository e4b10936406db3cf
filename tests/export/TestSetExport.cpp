// The set travels with the crowd (issue 28): the glTF export holds the ground over the
// bounds, the lanes, the crosswalks' bars, the walls extruded to their height, the
// obstacles and the traffic lights, each where the scene puts it (read back from the
// file's accessors), and each lamp lit on exactly the frames the light's phase shows it;
// --no-set (includeSet false) leaves all of it out and the agents as they were; a scene
// at map coordinates gets the same set as at the origin, under scene_origin.
#include "GltfReadBack.h"
#include "TestRegistry.h"

#include "export/GltfExporter.h"
#include "simcore/io/SceneIO.h"
#include "simcore/scene/SceneOrigin.h"
#include "simcore/traffic/LightPhase.h"
#include "simcore/world/World.h"

#include <QTemporaryDir>
#include <QTest>

#include <glm/common.hpp>

#include <cmath>
#include <sstream>

using namespace throng;

namespace {

// A walled yard of 40 m x 30 m with a bent lane, a crosswalk, two obstacles, a light
// (green 4 s, yellow 1, red 5) and four walkers, everything shifted by `shift` metres.
std::string yard(double shift)
{
    auto at = [&](double x, double z) {
        std::ostringstream s;
        s.precision(12);
        s << "[" << x + shift << ", " << z + shift << "]";
        return s.str();
    };
    std::ostringstream y;
    y << "throng: 1\nsettings: {fps: 10, duration: 12, seed: 5, bounds: {min: " << at(-20, -15) << ", max: "
      << at(20, 15) << "}}\n"
      << "agent_types: [{name: walker, radius: 0.3}]\n"
      << "walls:\n  - {name: yard, height: 3, points: [" << at(-10, -5) << ", " << at(10, -5) << ", " << at(10, 8)
      << "]}\n"
      << "obstacles:\n  - {name: post, shape: circle, center: " << at(0, 0) << ", radius: 0.5}\n"
      << "  - {name: kiosk, shape: box, center: " << at(-6, 4) << ", size: [2, 1], angle: 0}\n"
      << "lanes:\n  - {name: road, points: [" << at(-18, 12) << ", " << at(0, 12) << ", " << at(15, 2)
      << "], width: 3.5}\n"
      << "crosswalks:\n  - {name: zebra, from: " << at(-8, 10) << ", to: " << at(-8, 14) << ", width: 3}\n"
      << "traffic_lights:\n  - {name: signal, green: 4, yellow: 1, red: 5, position: " << at(-10, 9) << "}\n"
      << "groups:\n  - {name: crowd, type: walker, count: 4, rect: {min: " << at(-5, -2) << ", max: " << at(5, 2)
      << "}}\n";
    return y.str();
}

struct Exported {
    sim::Scene scene;
    tinygltf::Model model;
};

Exported exportYard(const QTemporaryDir& dir, double shift, bool includeSet, std::size_t firstFrame = 0)
{
    Exported e;
    const sim::LoadResult loaded = sim::parseScene(yard(shift), "yard.yaml", "");
    if (!loaded.ok() || !loaded.diagnostics.empty())
        qFatal("%s", loaded.diagnostics[0].format().c_str());
    e.scene = loaded.scene;
    sim::World world(e.scene);
    sim::FrameCache cache;
    world.startRecording(cache);
    std::vector<sim::AgentFrame> frame;
    for (int f = 1; f < 120; ++f) {
        world.step();
        world.snapshot(frame);
        cache.append(frame);
    }
    exporting::GltfOptions options;
    options.path = dir.filePath(includeSet ? "set.glb" : "bare.glb").toStdString();
    options.mode = exporting::GltfMode::Compact;
    options.includeSet = includeSet;
    options.firstFrame = firstFrame;
    const exporting::ExportResult r = exporting::exportGltf(e.scene, cache, options);
    if (!r.ok())
        qFatal("%s", r.error.c_str());
    std::string error;
    if (!test::loadGltf(options.path, e.model, error))
        qFatal("%s", error.c_str());
    return e;
}

// The bounds (min, max) of every POSITION of the node's mesh.
std::pair<glm::vec3, glm::vec3> meshBounds(const tinygltf::Model& model, int node)
{
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const tinygltf::Primitive& p : model.meshes[std::size_t(model.nodes[std::size_t(node)].mesh)].primitives) {
        const std::vector<float> v = test::accessorFloats(model, p.attributes.at("POSITION"));
        for (std::size_t k = 0; k + 2 < v.size(); k += 3) {
            lo = glm::min(lo, glm::vec3(v[k], v[k + 1], v[k + 2]));
            hi = glm::max(hi, glm::vec3(v[k], v[k + 1], v[k + 2]));
        }
    }
    return {lo, hi};
}

bool near(glm::vec3 a, glm::vec3 b, float tolerance) { return glm::all(glm::lessThan(glm::abs(a - b), glm::vec3(tolerance))); }

QString text(glm::vec3 v) { return QString("(%1, %2, %3)").arg(v.x).arg(v.y).arg(v.z); }

}  // namespace

class TestSetExport : public QObject {
    Q_OBJECT
private slots:
    void theSetIsWhereTheSceneHasIt()
    {
        QTemporaryDir dir;
        const Exported e = exportYard(dir, 0.0, true);
        const tinygltf::Model& m = e.model;
        const int set = test::nodeNamed(m, "set");
        QVERIFY(set >= 0);
        QCOMPARE(m.nodes[std::size_t(set)].children.size(), std::size_t(6 + 3));
        // The ground: the bounds, flat.
        auto [lo, hi] = meshBounds(m, test::nodeNamed(m, "set_ground"));
        QVERIFY2(near(lo, {-20, 0, -15}, 1e-4f) && near(hi, {20, 0, 15}, 1e-4f), qPrintable(text(lo) + text(hi)));
        // The wall: its two legs 0.2 m thick, 3 m high.
        std::tie(lo, hi) = meshBounds(m, test::nodeNamed(m, "set_walls"));
        QVERIFY2(near(lo, {-10, 0, -5.1f}, 1e-4f) && near(hi, {10.1f, 3, 8}, 1e-4f), qPrintable(text(lo) + text(hi)));
        // The obstacles: the post (radius 0.5 round the origin) and the kiosk, 1 m high.
        std::tie(lo, hi) = meshBounds(m, test::nodeNamed(m, "set_obstacles"));
        QVERIFY2(near(lo, {-7, 0, -0.5f}, 1e-3f) && near(hi, {0.5f, 1, 4.5f}, 1e-3f), qPrintable(text(lo) + text(hi)));
        // The lane 3.5 m wide, a little above the ground, round at its bend.
        std::tie(lo, hi) = meshBounds(m, test::nodeNamed(m, "set_lanes"));
        QVERIFY2(lo.x < -17.9f && hi.x > 15.0f && hi.z > 13.7f && lo.z < 2.5f, qPrintable(text(lo) + text(hi)));
        QVERIFY2(lo.y > 0.0f && hi.y <= 0.03f, qPrintable(text(lo) + text(hi)));
        // The crosswalk's 3 bars across its 3 m, along its 4 m.
        std::tie(lo, hi) = meshBounds(m, test::nodeNamed(m, "set_crosswalks"));
        QVERIFY2(near(lo, {-9.25f, 0.02f, 10}, 1e-4f) && near(hi, {-6.75f, 0.02f, 14}, 1e-4f),
                 qPrintable(text(lo) + text(hi)));
        // The light's pole and head at (-10, 9), 3.35 m tall.
        std::tie(lo, hi) = meshBounds(m, test::nodeNamed(m, "set_lights"));
        QVERIFY2(std::abs(0.5f * (lo.x + hi.x) + 10.0f) < 1e-3f && std::abs(0.5f * (lo.z + hi.z) - 9.0f) < 1e-3f &&
                     std::abs(hi.y - 3.35f) < 0.01f,
                 qPrintable(text(lo) + text(hi)));
        // Every part has a material; lamps glow.
        for (const tinygltf::Mesh& mesh : m.meshes)
            for (const tinygltf::Primitive& p : mesh.primitives)
                QVERIFY(p.material >= 0);
        QCOMPARE(m.asset.extras.Get("set").Get<bool>(), true);
    }

    // Each lamp is lit (scale 1) on exactly the frames the light's phase shows its colour;
    // an export of frames from 35 on (the editor's range) keeps the recording's time.
    void eachLampIsLitWithItsPhase_data()
    {
        QTest::addColumn<int>("firstFrame");
        QTest::newRow("from frame 0") << 0;
        QTest::newRow("from frame 35") << 35;
    }

    void eachLampIsLitWithItsPhase()
    {
        QFETCH(int, firstFrame);
        QTemporaryDir dir;
        const Exported e = exportYard(dir, 0.0, true, std::size_t(firstFrame));
        const sim::TrafficLight& light = e.scene.trafficLights[0];
        int lit = 0;
        for (const auto& [name, phase] : {std::pair{"red", sim::LightPhase::Red}, {"yellow", sim::LightPhase::Yellow},
                                          {"green", sim::LightPhase::Green}}) {
            const int node = test::nodeNamed(e.model, std::string("set_lamp_signal_") + name);
            QVERIFY2(node >= 0, name);
            const tinygltf::AnimationSampler* sampler = test::samplerFor(e.model, node, "scale");
            QVERIFY2(sampler && sampler->interpolation == "STEP", name);
            const std::vector<float> times = test::accessorFloats(e.model, sampler->input);
            const std::vector<float> scales = test::accessorFloats(e.model, sampler->output);
            for (int f = 0; f < 120; ++f) {
                const float t = float(f) / 10.0f;
                std::size_t k = 0;
                while (k + 1 < times.size() && times[k + 1] <= t + 1e-6f)
                    ++k;
                const bool shown = scales[3 * k] > 0.5f;
                const bool expected = sim::lightPhaseAt(light, double(firstFrame + f) / 10.0) == phase;
                QVERIFY2(shown == expected, qPrintable(QString("%1 lamp at frame %2").arg(name).arg(f)));
                lit += shown ? 1 : 0;
            }
        }
        QCOMPARE(lit, 120);  // one lamp lit on every frame
    }

    // --no-set: the same agents and no set at all.
    void theSetCanBeLeftOut()
    {
        QTemporaryDir dir;
        const Exported with = exportYard(dir, 0.0, true), without = exportYard(dir, 0.0, false);
        QCOMPARE(test::nodeNamed(without.model, "set"), -1);
        for (const tinygltf::Node& n : without.model.nodes)
            QVERIFY2(n.name.rfind("set", 0) != 0, n.name.c_str());
        QCOMPARE(without.model.skins.size(), with.model.skins.size());
        QCOMPARE(without.model.nodes.size() + 1 + 6 + 3, with.model.nodes.size());
        QCOMPARE(without.model.asset.extras.Get("set").Get<bool>(), false);
    }

    // At map coordinates (1e6 m) the set is written relative to scene_origin, as the
    // agents are: the same vertices as at the origin.
    void aFarSetMatchesTheNearOne()
    {
        QTemporaryDir dir;
        const Exported nearYard = exportYard(dir, 0.0, true), farYard = exportYard(dir, 1e6, true);
        const int origin = test::nodeNamed(farYard.model, "scene_origin");
        QVERIFY(origin >= 0);
        const std::vector<double>& t = farYard.model.nodes[std::size_t(origin)].translation;
        QCOMPARE(t[0], 1e6);
        QCOMPARE(t[2], 1e6);
        for (const char* part : {"set_ground", "set_walls", "set_obstacles", "set_lanes", "set_crosswalks", "set_lights"}) {
            const auto [nearLo, nearHi] = meshBounds(nearYard.model, test::nodeNamed(nearYard.model, part));
            const auto [farLo, farHi] = meshBounds(farYard.model, test::nodeNamed(farYard.model, part));
            QVERIFY2(near(nearLo, farLo, 1e-3f) && near(nearHi, farHi, 1e-3f),
                     qPrintable(QString(part) + text(nearLo) + text(farLo)));
        }
    }
};

THRONG_REGISTER_TEST(TestSetExport)
#include "TestSetExport.moc"
