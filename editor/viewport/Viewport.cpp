#include "editor/viewport/Viewport.h"

#include "editor/viewport/GroundRay.h"
#include "editor/viewport/SetGeometryBuilder.h"
#include "export/set/SetSolids.h"
#include "editor/viewport/ToolOverlay.h"
#include "editor/viewport/TrailBuilder.h"
#include "editor/viewport/ViewportPalette.h"
#include "simcore/world/World.h"

#include <QDebug>
#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace throng::editor {

namespace {
constexpr float kFallbackRadiusM = 0.3f;

// Whether OpenGL here is a software rasteriser (Mesa's llvmpipe or softpipe: virtual
// machines, remote desktops, CI). There 4x multisampling triples the cost of a frame
// full of small agents, so the viewport goes without it. Asked once, with a throwaway
// context; needs the application object.
bool softwareOpenGl()
{
    static const bool software = [] {
        QOpenGLContext context;
        QOffscreenSurface surface;
        surface.create();
        if (!context.create() || !context.makeCurrent(&surface))
            return false;
        const auto* renderer = reinterpret_cast<const char*>(context.functions()->glGetString(GL_RENDERER));
        const QString name = renderer ? QString::fromLatin1(renderer) : QString();
        context.doneCurrent();
        return name.contains("llvmpipe") || name.contains("softpipe") || name.contains("swrast");
    }();
    return software;
}
}  // namespace

Viewport::Viewport(QWidget* parent) : QOpenGLWidget(parent)
{
    setFormat(surfaceFormat());
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 120);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setToolTip(tr("Orbit (3D): Alt+left or right drag. Pan: Alt+middle or middle drag. Zoom: wheel (towards "
                  "the cursor) or Alt+right drag. Frame the selection: F. Frame all: A."));
    setMouseTracking(true);
    m_overlay = new ToolOverlay(this);
    m_overlay->resize(size());
    m_hud = new ViewportHud(this);
    m_hud->resize(size());
    m_hud->setVisible(m_layers.settings().hud);
}

void Viewport::setTool(ViewportTool* tool)
{
    if (tool == m_tool)
        return;
    if (m_tool) {
        m_tool->deactivate();
        disconnect(m_tool, nullptr, m_overlay, nullptr);
    }
    m_tool = tool;
    m_toolDragging = false;
    if (m_tool) {
        m_tool->activate();
        connect(m_tool, &ViewportTool::overlayChanged, m_overlay, qOverload<>(&QWidget::update));
    }
    m_overlay->setTool(m_tool);
}

void Viewport::updateScene(const sim::Scene& scene)
{
    const bool frameOnNextPaint = m_frameOnNextPaint, movedByUser = m_cameraMovedByUser;
    setSet(scene);
    m_frameOnNextPaint = frameOnNextPaint;
    m_cameraMovedByUser = movedByUser;
    // The shown agents again, coloured and sized by the edited types.
    setAgents(m_frames, m_agents, m_timeS, m_frameIndex);
}

std::optional<glm::vec3> Viewport::pixelToGround(QPointF pixel) const
{
    return castToGround(renderView().viewProjection, size(), pixel, m_terrain);
}

RenderView Viewport::renderView() const
{
    CameraRig camera = m_camera;
    camera.setViewportSize(size());
    return camera.renderView();
}

Viewport::~Viewport()
{
    // ~QOpenGLWidget destroys the context after this object is gone: stop listening first.
    if (context())
        disconnect(context(), nullptr, this, nullptr);
    makeCurrent();
    releaseGl();
    doneCurrent();
}

QSurfaceFormat Viewport::surfaceFormat()
{
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    // THRONG_MSAA=N sets the samples; else 4, or none under software OpenGL.
    bool set = false;
    const int samples = qEnvironmentVariableIntValue("THRONG_MSAA", &set);
    if (set)
        format.setSamples(std::max(0, samples));
    else
        format.setSamples(QGuiApplication::instance() && softwareOpenGl() ? 0 : 4);
    return format;
}

void Viewport::setScene(const sim::Scene& scene)
{
    setSet(scene);
    m_cache = nullptr;
    // The lights show their phase at the start; the agents come with frame 0.
    setAgents({}, {}, 0.0, 0);
    m_frameWhenAgentsCome = true;
}

void Viewport::setScene(const sim::Scene& scene, const sim::World& state)
{
    std::vector<sim::AgentFrame> frames;
    state.snapshot(frames);
    sim::addOrigin(frames, state.origin());
    setSet(scene);
    m_cache = nullptr;
    setAgents(frames, state.agentInfo(), state.timeS(), std::size_t(state.stepIndex()));
    m_frameWhenAgentsCome = false;
}

void Viewport::showFrame(const sim::FrameCache& cache, std::size_t frame)
{
    // A run without agents records no frames: its frame 0 shows nobody.
    if (frame == 0 && cache.agentCount() == 0) {
        m_cache = &cache;
        setAgents({}, {}, 0.0, 0);
        return;
    }
    if (frame >= cache.frameCount())
        return;
    m_cache = &cache;
    setAgents(cache.frame(frame), cache.agentsAt(frame), double(frame) / double(cache.fps()), frame);
    // A scene just opened is framed with its crowd, as it would have been had the agents
    // been there at once, unless the user has moved the camera since.
    if (m_frameWhenAgentsCome && !cache.frame(frame).empty()) {
        m_frameWhenAgentsCome = false;
        if (!m_cameraMovedByUser)
            m_frameOnNextPaint = true;
    }
}

void Viewport::setSet(const sim::Scene& scene)
{
    m_setMesh.clear();
    SetGeometryBuilder::addSet(scene, m_setMesh);
    m_solidMesh.clear();
    exporting::SetSolids::addSet(scene, m_solidMesh);
    m_setChanged = true;
    m_traffic = {};
    m_traffic.lanes = scene.lanes;
    m_traffic.crosswalks = scene.crosswalks;
    m_traffic.trafficLights = scene.trafficLights;
    m_terrain = scene.terrain;
    m_agentColours.setScene(scene);
    m_fps = scene.settings.fps;
    m_typeNames.clear();
    for (const sim::AgentType& t : scene.agentTypes)
        m_typeNames.push_back(t.name);
    m_charactersChanged = m_agentCharacters.setScene(scene, m_sceneDirectory) || m_charactersChanged;
    m_typeRadiusM.clear();
    m_typeIsVehicle.clear();
    m_typeIsFlier.clear();
    for (const sim::AgentType& t : scene.agentTypes) {
        m_typeRadiusM.push_back(t.radiusM);
        m_typeIsVehicle.push_back(t.kind == sim::AgentKind::Vehicle);
        m_typeIsFlier.push_back(t.kind == sim::AgentKind::Flier);
    }
    m_boundsMin = scene.settings.boundsMin;
    m_boundsMax = scene.settings.boundsMax;
    m_layers.setScene(scene);
    update();
    m_grid.setBounds(m_boundsMin, m_boundsMax);
    m_setBox = setExtent(scene);
    m_frameOnNextPaint = true;
    m_cameraMovedByUser = false;
}

void Viewport::setAgents(std::span<const sim::AgentFrame> frames, std::span<const sim::AgentInfo> agents,
                         std::optional<double> timeS, std::size_t frameIndex)
{
    const std::size_t n = std::min(frames.size(), agents.size());
    // Kept for colouring again (setColourBy), unless it is the kept frame itself.
    if (frames.data() != m_frames.data()) {
        m_frames.assign(frames.begin(), frames.begin() + std::ptrdiff_t(n));
        m_agents.assign(agents.begin(), agents.begin() + std::ptrdiff_t(n));
    }
    m_layers.rebuildDensity(frames.first(n), m_agentColours.colourBy() == ColourBy::Density);
    const std::vector<glm::vec3>& colours =
        m_agentColours.coloursFor(frames.first(n), agents.first(n), m_layers.density());
    // A one-shot (a fall) runs from the frame its agent switched to it: the cache says which.
    // And the legs cycle, and a horse changes gait, as the export's do (from the recording).
    m_clipSinceS.clear();
    m_shownGait.clear();
    if (m_cache && frameIndex < m_cache->frameCount() && m_cache->agentCount() == n) {
        clipSinceS(*m_cache, frameIndex, m_clipSinceS);
        m_agentCharacters.gaitAt(*m_cache, frameIndex, m_shownGait);
    }
    m_agentCharacters.posesFor(frames.first(n), agents.first(n), timeS.value_or(0.0), m_shownPoses, m_clipSinceS,
                               m_shownGait);
    m_glyphs.clear();
    m_carGlyphs.clear();
    m_birdGlyphs.clear();
    m_glyphPoses.clear();
    m_carPoses.clear();
    m_birdPoses.clear();
    m_glyphs.reserve(n);
    m_agentBox = {};
    std::vector<std::size_t> perType(m_typeNames.size(), 0);
    std::size_t shown = 0, arrived = 0, out = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!frames[i].present)
            continue;  // not there on this frame (an edit added or removed it)
        arrived += frames[i].arrived ? 1 : 0;
        if (frames[i].out) {
            ++out;
            continue;  // left through an exit
        }
        const std::size_t type = agents[i].typeIndex;
        ++shown;
        if (type < perType.size())
            ++perType[type];
        const float radius = type < m_typeRadiusM.size() ? m_typeRadiusM[type] : kFallbackRadiusM;
        const bool car = type < m_typeIsVehicle.size() && m_typeIsVehicle[type];
        const bool bird = type < m_typeIsFlier.size() && m_typeIsFlier[type];
        (car ? m_carGlyphs : bird ? m_birdGlyphs : m_glyphs)
            .push_back({frames[i].position, frames[i].headingRad, radius, colours[i]});
        (car ? m_carPoses : bird ? m_birdPoses : m_glyphPoses).push_back(m_shownPoses[i]);
        m_agentBox.include({frames[i].position.x, frames[i].position.z}, radius);
    }
    m_hudCounts.shown = shown;
    m_hudCounts.arrived = arrived;
    m_hudCounts.out = out;
    m_hudCounts.perType.clear();
    for (std::size_t t = 0; t < perType.size(); ++t)
        if (perType[t] > 0)
            m_hudCounts.perType.emplace_back(m_typeNames[t], perType[t]);
    m_agentsChanged = true;
    m_timeS = timeS;
    m_frameIndex = frameIndex;
    // Picking and the agents' rings follow them from frame to frame.
    m_shown.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t type = agents[i].typeIndex;
        const bool drawn = frames[i].present && !frames[i].out;
        m_shown.set(i, agents[i].id, frames[i].position, type < m_typeRadiusM.size() ? m_typeRadiusM[type] : kFallbackRadiusM,
                    drawn);
    }
    m_marks.showFrame(frameIndex);
    if (m_marks.followsAgents())
        rebuildHighlight();
    if (m_layers.settings().trails)
        rebuildOverlay();
    m_overlay->update();  // the select tool's circles follow the agents too
    rebuildLights();
    updateHud();
    emit agentsChanged();
    update();
}

void Viewport::rebuildLights()
{
    m_lightMesh.clear();
    SetGeometryBuilder::addLights(m_traffic, m_timeS, m_lightMesh);
    m_lampMesh.clear();
    exporting::SetSolids::addLamps(m_traffic.trafficLights, m_terrain, m_timeS, m_lampMesh);
    m_lightsChanged = true;
}

void Viewport::setOverlays(const ViewportOverlays& overlays)
{
    if (!m_layers.setSettings(overlays, m_frames, m_agentColours.colourBy() == ColourBy::Density))
        return;
    m_hud->setVisible(overlays.hud);
    rebuildOverlay();
    updateHud();
}

void Viewport::setColourBy(ColourBy by)
{
    if (by == m_agentColours.colourBy())
        return;
    m_agentColours.setColourBy(by);
    setAgents(m_frames, m_agents, m_timeS, m_frameIndex);
}

void Viewport::setSteering(std::vector<sim::AgentDebug> agents)
{
    m_layers.setSteering(std::move(agents));
    if (m_layers.settings().steering) {
        rebuildOverlay();
        updateHud();
    }
}

void Viewport::setSimulationRate(double stepsPerSecond)
{
    m_stepsPerSecond = stepsPerSecond;
}

void Viewport::rebuildOverlay()
{
    const std::vector<std::size_t> followed =
        m_layers.settings().trails ? m_marks.followed(m_shown, TrailBuilder::kMaxTrails) : std::vector<std::size_t>{};
    m_layers.rebuildLines(m_cache, m_frameIndex, followed, m_fps);
    update();
}

void Viewport::updateHud()
{
    if (!m_layers.settings().hud)
        return;
    HudFigures figures = m_hudCounts;
    figures.frame = m_frameIndex;
    figures.timeS = m_timeS;
    figures.fps = double(m_fps);
    figures.stepsPerSecond = m_stepsPerSecond;
    figures.layoutFlagged = m_marks.flaggedCount();
    ColourLegend colouring = m_agentColours.legend();
    colouring.title = "Colour by " + colouring.title;
    figures.legends.push_back(std::move(colouring));
    m_layers.addLegends(figures, !m_marks.watchedIds().empty());
    m_hud->setFigures(std::move(figures));
}

void Viewport::setHighlight(const sim::Scene& scene, const Selection& selection)
{
    const std::vector<sim::AgentId> watched = m_marks.watchedIds();
    m_marks.setSelection(scene, selection);
    for (const SceneItem& item : selection)
        if (item.kind == ItemKind::Goal && item.index < scene.goals.size() && m_layers.showGoal(item.index)) {
            update();
            updateHud();
            break;
        }
    marksChanged(watched);
}

void Viewport::setFocusedAgent(sim::AgentId id)
{
    const std::vector<sim::AgentId> watched = m_marks.watchedIds();
    m_marks.setFocusedAgent(id);
    marksChanged(watched);
    if (id != 0)
        emit agentPicked(id);
}

void Viewport::setInspectedAgent(sim::AgentId id)
{
    if (id == m_marks.inspectedAgent())
        return;
    const std::vector<sim::AgentId> watched = m_marks.watchedIds();
    m_marks.setInspectedAgent(id);
    marksChanged(watched);
}

void Viewport::setLayoutCheck(const sim::LayoutCheck& check)
{
    m_marks.setLayoutClashes(check);
    m_marks.showFrame(m_frameIndex);
    m_hudCounts.layoutOverlaps = check.overlaps.size();
    m_hudCounts.layoutWallCrossings = check.wallCrossings.size();
    rebuildHighlight();
    updateHud();
}

void Viewport::marksChanged(const std::vector<sim::AgentId>& watchedBefore)
{
    rebuildHighlight();
    if (m_layers.settings().trails || m_layers.settings().steering)
        rebuildOverlay();
    if (m_marks.watchedIds() != watchedBefore)
        emit watchedAgentsChanged();
}

void Viewport::rebuildHighlight()
{
    m_marks.build(m_shown, m_highlightMesh);
    m_highlightChanged = true;
    update();
}

void Viewport::setAgentLevelOfDetail(bool on)
{
    m_agentRenderer.setLevelOfDetail(on);
    update();
}

void Viewport::setAgentsAsCharacters(bool on)
{
    m_agentRenderer.setAgentsAsCharacters(on);
    update();
}

void Viewport::setViewMode(ViewMode mode)
{
    if (mode == m_camera.mode())
        return;
    m_camera.setMode(mode);
    emit viewModeChanged(mode);
    update();
}

GroundBox Viewport::framingBox() const
{
    GroundBox box = m_setBox;
    box.include(m_agentBox);
    if (box.empty) {
        box.include(m_boundsMin);
        box.include(m_boundsMax);
    }
    return box;
}

void Viewport::frameAll()
{
    m_camera.setViewportSize(size());
    m_camera.frame(framingBox());
    m_frameOnNextPaint = false;
    m_cameraMovedByUser = false;
    update();
}

void Viewport::frameSelection()
{
    // A lone agent fills no view: frame it with some ground round it.
    constexpr float kAgentRoomM = 3.0f;
    const GroundBox box = m_marks.extent(m_shown, kAgentRoomM);
    if (box.empty) {
        frameAll();
        return;
    }
    m_camera.setViewportSize(size());
    m_camera.frame(box);
    m_frameOnNextPaint = false;
    m_cameraMovedByUser = true;
    update();
}

QPointF Viewport::worldToPixel(glm::vec3 point) const
{
    const glm::vec4 clip = renderView().viewProjection * glm::vec4(point, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(0.5 + 0.5 * double(ndc.x)) * width(), (0.5 - 0.5 * double(ndc.y)) * height()};
}

void Viewport::initializeGL()
{
    m_glReady = false;
    const QSurfaceFormat got = context()->format();
    const bool core33 = got.profile() == QSurfaceFormat::CoreProfile && got.version() >= qMakePair(3, 3);
    if (!core33 || !initializeOpenGLFunctions()) {
        m_glProblem = tr("OpenGL 3.3 core profile is not available (the context is %1.%2%3)")
                          .arg(got.majorVersion())
                          .arg(got.minorVersion())
                          .arg(got.profile() == QSurfaceFormat::CoreProfile ? " core" : "");
        qWarning().noquote() << "throng:" << m_glProblem;
        return;
    }
    if (!m_grid.initialize(*this) || !m_setRenderer.initialize(*this) || !m_lightRenderer.initialize(*this) ||
        !m_highlightRenderer.initialize(*this) || !m_overlayRenderer.initialize(*this) ||
        !m_fieldRenderer.initialize(*this) || !m_heatRenderer.initialize(*this) ||
        !m_agentRenderer.initialize(*this) || !m_solidRenderer.initialize(*this) || !m_lampRenderer.initialize(*this)) {
        m_glProblem = tr("the viewport's shaders did not compile (see the log)");
        return;
    }
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, [this] {
        makeCurrent();
        releaseGl();
        doneCurrent();
    });
    m_setChanged = m_lightsChanged = m_agentsChanged = m_highlightChanged = m_charactersChanged = true;
    m_layers.markAllChanged();
    m_glReady = true;
}

void Viewport::releaseGl()
{
    if (!m_glReady)
        return;
    m_grid.destroy(*this);
    m_setRenderer.destroy(*this);
    m_lightRenderer.destroy(*this);
    m_highlightRenderer.destroy(*this);
    m_overlayRenderer.destroy(*this);
    m_fieldRenderer.destroy(*this);
    m_heatRenderer.destroy(*this);
    m_agentRenderer.destroy(*this);
    m_solidRenderer.destroy(*this);
    m_lampRenderer.destroy(*this);
    m_glReady = false;
}

void Viewport::resizeGL(int, int)
{
    m_camera.setViewportSize(size());
    if (!m_cameraMovedByUser)
        m_frameOnNextPaint = true;
}

void Viewport::uploadChanged()
{
    if (m_setChanged) {
        m_setRenderer.upload(*this, m_setMesh);
        m_solidRenderer.upload(*this, m_solidMesh);
    }
    if (m_lightsChanged) {
        m_lightRenderer.upload(*this, m_lightMesh);
        m_lampRenderer.upload(*this, m_lampMesh);
    }
    if (m_charactersChanged)
        m_agentRenderer.setCharacters(*this, m_agentCharacters.poseTables(), AgentCharacters::kLevels);
    if (m_agentsChanged)
        m_agentRenderer.upload(*this, {m_glyphs, m_glyphPoses}, {m_carGlyphs, m_carPoses}, {m_birdGlyphs, m_birdPoses});
    if (m_highlightChanged)
        m_highlightRenderer.upload(*this, m_highlightMesh);
    const OverlayLayers::Changed layers = m_layers.takeChanged();
    if (layers.lines)
        m_overlayRenderer.upload(*this, m_layers.lines());
    if (layers.fields)
        m_fieldRenderer.upload(*this, m_layers.fields());
    if (layers.heat)
        m_heatRenderer.upload(*this, m_layers.heat());
    m_setChanged = m_lightsChanged = m_agentsChanged = m_highlightChanged = m_charactersChanged = false;
}

void Viewport::paintGL()
{
    const glm::vec4 bg = palette::kBackground;
    glClearColor(bg.r, bg.g, bg.b, bg.a);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!m_glReady)
        return;
    m_camera.setViewportSize(size());
    if (m_frameOnNextPaint) {
        m_camera.frame(framingBox());
        m_frameOnNextPaint = false;
    }
    uploadChanged();
    const RenderView view = m_camera.renderView();

    // The ground layers are flat and drawn back to front; only the 3D set and agents need depth.
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    m_grid.draw(*this, view);
    m_heatRenderer.draw(*this, view);
    m_setRenderer.draw(*this, view);
    m_lightRenderer.draw(*this, view);
    m_fieldRenderer.draw(*this, view);
    m_highlightRenderer.draw(*this, view);
    m_overlayRenderer.draw(*this, view);
    if (view.perspective) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        m_solidRenderer.draw(*this, view);
        m_lampRenderer.draw(*this, view);
    }
    m_agentRenderer.draw(*this, view);
    glDisable(GL_DEPTH_TEST);
    m_hud->framePainted();
}

}  // namespace throng::editor
