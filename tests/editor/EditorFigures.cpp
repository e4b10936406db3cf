// editor_figures: the editor's figures as JSON on stdout (never a test; timings are not
// asserted anywhere). Start-up time to a shown window with the crossroads demo, viewport
// frame time with 10,000 and 100,000 agents (top, 3D, 3D close-up; level of detail off
// and on in one run), the frame time during playback with and without the HUD and the
// overlays, crowd-brush stroke latency per mouse move, and the 3D frame time with near
// agents as characters against glyphs.
// Run under a display: xvfb-run -a -s "-screen 0 1920x1080x24" editor_figures [WINDOW.png]
// (`editor_figures --characters`: the characters-against-glyphs figures only).
#include "EditorUiDriver.h"
#include "ShowInitialState.h"

#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <QWheelEvent>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <vector>

using namespace throng;
using namespace throng::editor;

namespace {

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// A square crowd of `count` placed agents, 1 m apart, in bounds that hold them.
sim::Scene crowdOf(std::size_t count)
{
    sim::Scene s;
    sim::AgentType walker;
    walker.name = "walker";
    s.agentTypes.push_back(walker);
    const auto side = std::size_t(std::ceil(std::sqrt(double(count))));
    const float half = float(side) * 0.5f + 2.0f;
    s.settings.boundsMin = glm::vec2(-half);
    s.settings.boundsMax = glm::vec2(half);
    for (std::size_t i = 0; i < count; ++i) {
        sim::Agent a;
        a.id = std::uint32_t(i + 1);
        a.type = "walker";
        a.position = {float(i % side) - half + 2.0f, 0.0f, float(i / side) - half + 2.0f};
        a.headingDeg = float(i % 360);
        s.agents.push_back(a);
    }
    return s;
}

double repaintMs(Viewport& viewport)
{
    QElapsedTimer t;
    t.start();
    viewport.repaint();
    viewport.makeCurrent();
    viewport.context()->functions()->glFinish();
    viewport.doneCurrent();
    return double(t.nsecsElapsed()) / 1e6;
}

// Median milliseconds per synchronous repaint with level of detail off (every agent of
// the crowd with one shape, as before) and on, frames of the two taken in turn so that
// the load of a shared machine weighs on both alike. `zoomSteps` wheel clicks in after
// framing all (0: the whole crowd in view).
struct FrameTimes {
    double fullMs = 0.0, lodMs = 0.0;
    std::array<int, kAgentDetailLevels> drawn{};
};

FrameTimes frameTimes(Viewport& viewport, ViewMode mode, int zoomSteps, int frames)
{
    viewport.setViewMode(mode);
    viewport.frameAll();
    for (int k = 0; k < zoomSteps; ++k) {
        const QPointF centre(viewport.width() / 2.0, viewport.height() / 2.0);
        QWheelEvent wheel(centre, viewport.mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(&viewport, &wheel);
    }
    std::vector<double> full, lod;
    for (int i = 0; i <= frames; ++i) {
        viewport.setAgentLevelOfDetail(false);
        const double f = repaintMs(viewport);
        viewport.setAgentLevelOfDetail(true);
        const double l = repaintMs(viewport);
        if (i > 0) {  // the first of each warms caches and compiles shader variants
            full.push_back(f);
            lod.push_back(l);
        }
    }
    return {median(full), median(lod), viewport.agentsDrawnByDetail()};
}

// Median milliseconds per repaint in 3D with level of detail, agents as glyphs and as
// characters, frames of the two taken in turn.
struct CharacterTimes {
    double glyphsMs = 0.0, charactersMs = 0.0;
    int characters = 0;
};

CharacterTimes characterTimes(Viewport& viewport, int zoomSteps, int frames)
{
    viewport.setViewMode(ViewMode::Orbit);
    viewport.setAgentLevelOfDetail(true);
    viewport.frameAll();
    for (int k = 0; k < zoomSteps; ++k) {
        const QPointF centre(viewport.width() / 2.0, viewport.height() / 2.0);
        QWheelEvent wheel(centre, viewport.mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(&viewport, &wheel);
    }
    std::vector<double> glyphs, characters;
    int drawn = 0;
    for (int i = 0; i <= frames; ++i) {
        viewport.setAgentsAsCharacters(false);
        const double g = repaintMs(viewport);
        viewport.setAgentsAsCharacters(true);
        const double c = repaintMs(viewport);
        drawn = viewport.charactersDrawn();
        if (i > 0) {
            glyphs.push_back(g);
            characters.push_back(c);
        }
    }
    viewport.setAgentsAsCharacters(false);
    return {median(glyphs), median(characters), drawn};
}

// A recording of `scene`'s placed agents all walking east at 1.4 m/s for `frames` frames.
sim::FrameCache walkingCache(const sim::Scene& scene, std::size_t frames)
{
    std::vector<sim::AgentInfo> info;
    for (const sim::Agent& a : scene.agents)
        info.push_back({a.id, 0});
    sim::FrameCache cache;
    cache.reset(info, 24.0f);
    std::vector<sim::AgentFrame> frame(info.size());
    for (std::size_t f = 0; f < frames; ++f) {
        for (std::size_t i = 0; i < info.size(); ++i) {
            frame[i].position = scene.agents[i].position + glm::vec3(1.4f * float(f) / 24.0f, 0.0f, 0.0f);
            frame[i].speed = 1.4f;
            frame[i].clip = sim::Clip::Walk;
        }
        cache.append(frame);
    }
    return cache;
}

// The steering of one agent as a watched walker in a crowd publishes it.
sim::AgentDebug steeringOf(const sim::Scene& scene, std::size_t i)
{
    sim::AgentDebug a;
    a.id = scene.agents[i].id;
    a.position = scene.agents[i].position;
    a.velocity = {1.4f, 0.0f, 0.0f};
    a.rangeM = 4.0f;
    a.viewAngleRad = 4.71f;
    for (int k = 0; k < 8; ++k)
        a.neighbours.push_back({a.id + 1, a.position + glm::vec3(std::cos(float(k)), 0.0f, std::sin(float(k)))});
    for (int k = 0; k < 6; ++k) {
        a.forces.push_back({sim::Behaviour(k), glm::vec3(std::cos(float(k)), 0.0f, std::sin(float(k))), 1.0f});
        a.feelers.push_back({a.position, a.position + glm::vec3(1.5f, 0.0f, 0.3f * float(k - 3))});
    }
    for (int k = 0; k < 10; ++k)
        a.path.push_back(a.position + glm::vec3(float(k), 0.0f, 0.5f * float(k % 2)));
    a.steering = {1.0f, 0.0f, 0.2f};
    return a;
}

// Median milliseconds per frame shown (showFrame, then a synchronous repaint) during
// playback, with nothing over the agents (as before the HUD), with the HUD alone, and
// with the HUD, agents coloured by speed, the density map, trails behind 256 selected
// agents and the steering of 8 (fields off: the crowd has no strokes or goals), frames
// of the three taken in turn.
struct OverlayTimes {
    double plainMs = 0.0, hudMs = 0.0, overlaysMs = 0.0;
};

OverlayTimes overlayTimes(Viewport& viewport, const sim::Scene& scene, const sim::FrameCache& cache, ViewMode mode,
                          int frames)
{
    viewport.setViewMode(mode);
    viewport.setAgentLevelOfDetail(true);
    viewport.frameAll();
    Selection selected;
    const std::size_t step = std::max<std::size_t>(1, scene.agents.size() / 256);
    for (std::size_t k = 0; k < 256 && k * step < scene.agents.size(); ++k)
        selected.push_back({ItemKind::Agent, k * step});
    std::vector<sim::AgentDebug> steering;
    for (std::size_t k = 0; k < 8 && k * step < scene.agents.size(); ++k)
        steering.push_back(steeringOf(scene, k * step));
    ViewportOverlays plain;
    plain.hud = false;
    const ViewportOverlays hudOnly;
    ViewportOverlays all;
    all.trails = all.steering = all.density = true;
    std::vector<double> without, hud, with;
    for (int i = 0; i <= frames; ++i) {
        const std::size_t frame = 24 + std::size_t(i) % (cache.frameCount() - 24);
        for (const int level : {0, 1, 2}) {
            const bool on = level == 2;
            viewport.setOverlays(level == 0 ? plain : level == 1 ? hudOnly : all);
            viewport.setColourBy(on ? ColourBy::Speed : ColourBy::Tint);
            viewport.setHighlight(scene, on ? selected : Selection{});
            viewport.setSteering(on ? steering : std::vector<sim::AgentDebug>{});
            QElapsedTimer t;
            t.start();
            viewport.showFrame(cache, frame);
            const double showMs = double(t.nsecsElapsed()) / 1e6;
            const double ms = showMs + repaintMs(viewport);
            if (i > 0)
                (level == 0 ? without : level == 1 ? hud : with).push_back(ms);
        }
    }
    viewport.setOverlays(ViewportOverlays{});
    viewport.setColourBy(ColourBy::Tint);
    viewport.setHighlight(scene, {});
    return {median(without), median(hud), median(with)};
}

void printOverlayTimes(const char* name, const OverlayTimes& t, bool last)
{
    std::cout << "    \"" << name << "\": {\"plain_ms\": " << t.plainMs << ", \"hud_ms\": " << t.hudMs
              << ", \"overlays_ms\": " << t.overlaysMs
              << ", \"overlays_over_plain\": " << (t.plainMs > 0.0 ? t.overlaysMs / t.plainMs : 0.0) << "}"
              << (last ? "\n" : ",\n");
}

void printCharacterTimes(const char* name, const CharacterTimes& t, bool last)
{
    std::cout << "    \"" << name << "\": {\"glyphs_ms\": " << t.glyphsMs << ", \"characters_ms\": " << t.charactersMs
              << ", \"drawn_as_characters\": " << t.characters << "}" << (last ? "\n" : ",\n");
}

void printTimes(const char* name, const FrameTimes& t, bool last)
{
    std::cout << "    \"" << name << "\": {\"full_ms\": " << t.fullMs << ", \"lod_ms\": " << t.lodMs
              << ", \"full_over_lod\": " << (t.lodMs > 0.0 ? t.fullMs / t.lodMs : 0.0) << ", \"drawn_detailed\": "
              << t.drawn[0] << ", \"drawn_coarse\": " << t.drawn[1] << ", \"drawn_impostor\": " << t.drawn[2] << "}"
              << (last ? "\n" : ",\n");
}

}  // namespace

int main(int argc, char** argv)
{
    QElapsedTimer sinceStart;
    sinceStart.start();
    QSurfaceFormat::setDefaultFormat(Viewport::surfaceFormat());
    QApplication app(argc, argv);
    QApplication::setOrganizationName("ThrongFigures");
    QTemporaryDir dir;
    const bool charactersOnly = argc > 1 && QByteArray(argv[1]) == "--characters";
    if (charactersOnly) {
        Viewport viewport;
        viewport.resize(1280, 720);
        viewport.show();
        if (!QTest::qWaitForWindowExposed(&viewport))
            return 1;
        std::cout << "{\n";
        for (std::size_t n : {std::size_t(10000), std::size_t(100000)}) {
            test::showInitialState(viewport, crowdOf(n));
            std::cout << "  \"agents_" << n << "\": {\n";
            printCharacterTimes("3d", characterTimes(viewport, 0, 3), false);
            printCharacterTimes("3d_close", characterTimes(viewport, 15, 3), true);
            std::cout << "  }" << (n == 100000 ? "\n" : ",\n");
        }
        std::cout << "}\n";
        return 0;
    }

    // Start-up: QApplication to a shown, exposed window with the crossroads demo open.
    auto* window = new MainWindow;
    if (!test::showWithScene(*window, dir, "crossroads.yaml")) {
        std::cerr << "editor_figures: cannot show the window\n";
        return 1;
    }
    QApplication::processEvents();
    const double startupMs = double(sinceStart.nsecsElapsed()) / 1e6;
    window->viewport().makeCurrent();
    const std::string gl = reinterpret_cast<const char*>(window->viewport().context()->functions()->glGetString(GL_RENDERER));
    window->viewport().doneCurrent();

    // Brush latency: each mouse move of a stroke, dab and command included, then the
    // refresh of the viewport and the simulation that follows the burst.
    test::clickToolButton(*window, "crowdBrush");
    QWidget* vp = &window->viewport();
    std::vector<double> moveMs;
    QTest::mousePress(vp, Qt::LeftButton, Qt::NoModifier, test::pixelOf(*window, {-35, -25}));
    for (int k = 1; k <= 40; ++k) {
        QElapsedTimer t;
        t.start();
        QTest::mouseMove(vp, test::pixelOf(*window, {-35.0f + 0.5f * float(k), -25.0f}));
        QApplication::processEvents();  // the deferred refresh of viewport and simulation
        window->viewport().repaint();
        moveMs.push_back(double(t.nsecsElapsed()) / 1e6);
    }
    QTest::mouseRelease(vp, Qt::LeftButton, Qt::NoModifier, test::pixelOf(*window, {-15, -25}));
    const std::size_t painted = window->document().scene().agents.size();
    if (argc > 1)
        window->grab().save(QString::fromLocal8Bit(argv[1]));
    delete window;

    std::cout << "{\n  \"renderer\": \"" << gl << "\",\n"
              << "  \"startup_to_shown_window_ms\": " << startupMs << ",\n"
              << "  \"brush_move_latency_ms_median\": " << median(moveMs) << ",\n"
              << "  \"brush_move_latency_ms_max\": " << *std::max_element(moveMs.begin(), moveMs.end()) << ",\n"
              << "  \"brush_stroke_agents\": " << painted << ",\n";
    Viewport viewport;
    viewport.resize(1280, 720);
    viewport.show();
    if (!QTest::qWaitForWindowExposed(&viewport))
        return 1;
    // 0 agents: the cost of the ground, grid and window alone. The 3D close-up is 15
    // wheel clicks (9x) in from framing all: near agents large, much of the crowd out of view.
    const std::size_t counts[] = {0, 10000, 100000};
    for (std::size_t n : counts) {
        QElapsedTimer t;
        t.start();
        const sim::Scene scene = crowdOf(n);
        test::showInitialState(viewport, scene);
        const double setMs = double(t.nsecsElapsed()) / 1e6;
        const int frames = n >= 100000 ? 5 : 9;
        std::cout << "  \"agents_" << n << "\": {\n    \"set_scene_ms\": " << setMs << ",\n";
        printTimes("top", frameTimes(viewport, ViewMode::Top, 0, frames), false);
        printTimes("3d", frameTimes(viewport, ViewMode::Orbit, 0, frames), false);
        printTimes("3d_close", frameTimes(viewport, ViewMode::Orbit, 15, frames), n == 0);
        if (n > 0) {
            const sim::FrameCache cache = walkingCache(scene, 48);
            printOverlayTimes("top_playback", overlayTimes(viewport, scene, cache, ViewMode::Top, frames), false);
            printOverlayTimes("3d_playback", overlayTimes(viewport, scene, cache, ViewMode::Orbit, frames), true);
            test::showInitialState(viewport, scene);
        }
        std::cout << "  }" << (n == counts[2] ? "\n" : ",\n");
    }
    std::cout << "}\n";
    return 0;
}
