#include "editor/viewport/Viewport.h"

#include "editor/viewport/GroundRay.h"
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
    // An edit is made in the view as it stands: the agents it brings (a new scene's first
    // spawn group or brush stroke) must not pull the camera away from where the user works.
    m_frameWhenAgentsCome = false;
    // The shown agents again, coloured and sized by the edited types.
    setAgents(m_crowd.frames(), m_crowd.agents(), m_timeS, m_frameIndex);
}

std::optional<glm::vec3> Viewport::pixelToGround(QPointF pixel) const
{
    return castToGround(renderView().viewProjection, size(), pixel, m_set.terrain());
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
    m_set.setScene(scene);
    m_crowd.setScene(scene, m_sceneDirectory);
    m_fps = scene.settings.fps;
    m_layers.setScene(scene);
    update();
    m_grid.setBounds(m_set.boundsMin(), m_set.boundsMax());
    m_frameOnNextPaint = true;
    m_cameraMovedByUser = false;
}

void Viewport::setAgents(std::span<const sim::AgentFrame> frames, std::span<const sim::AgentInfo> agents,
                         std::optional<double> timeS, std::size_t frameIndex)
{
    // Kept for colouring again (setColourBy).
    m_crowd.keep(frames, agents);
    m_layers.rebuildDensity(m_crowd.frames(), m_crowd.colourBy() == ColourBy::Density);
    m_crowd.build(m_layers.density(), timeS.value_or(0.0), m_cache, frameIndex);
    m_timeS = timeS;
    m_frameIndex = frameIndex;
    m_marks.showFrame(frameIndex);
    if (m_marks.followsAgents())
        rebuildHighlight();
    if (m_layers.settings().trails)
        rebuildOverlay();
    m_overlay->update();  // the select tool's circles follow the agents too
    m_set.light(m_timeS);
    updateHud();
    emit agentsChanged();
    update();
}

void Viewport::setOverlays(const ViewportOverlays& overlays)
{
    if (!m_layers.setSettings(overlays, m_crowd.frames(), m_crowd.colourBy() == ColourBy::Density))
        return;
    m_hud->setVisible(overlays.hud);
    rebuildOverlay();
    updateHud();
}

void Viewport::setColourBy(ColourBy by)
{
    if (by == m_crowd.colourBy())
        return;
    m_crowd.setColourBy(by);
    setAgents(m_crowd.frames(), m_crowd.agents(), m_timeS, m_frameIndex);
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
    std::vector<std::size_t> followed;
    if (m_layers.settings().trails)
        followed = m_marks.followed(m_crowd.shown(), TrailBuilder::kMaxTrails);
    m_layers.rebuildLines(m_cache, m_frameIndex, followed, m_fps);
    update();
}

void Viewport::updateHud()
{
    if (!m_layers.settings().hud)
        return;
    HudFigures figures;
    const ShownCrowd::Counts& counts = m_crowd.counts();
    figures.shown = counts.shown;
    figures.arrived = counts.arrived;
    figures.out = counts.out;
    figures.perType = counts.perType;
    figures.layoutOverlaps = m_layoutOverlaps;
    figures.layoutWallCrossings = m_layoutWallCrossings;
    figures.frame = m_frameIndex;
    figures.timeS = m_timeS;
    figures.fps = double(m_fps);
    figures.stepsPerSecond = m_stepsPerSecond;
    figures.layoutFlagged = m_marks.flaggedCount();
    ColourLegend colouring = m_crowd.legend();
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
    m_layoutOverlaps = check.overlaps.size();
    m_layoutWallCrossings = check.wallCrossings.size();
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
    m_marks.build(m_crowd.shown(), m_highlightMesh);
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
    GroundBox box = m_set.extent();
    box.include(m_crowd.extent());
    if (box.empty) {
        box.include(m_set.boundsMin());
        box.include(m_set.boundsMax());
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
    const GroundBox box = m_marks.extent(m_crowd.shown(), kAgentRoomM);
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
    m_set.markAllChanged();
    m_crowd.markAllChanged();
    m_highlightChanged = true;
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
    const ShownSet::Changed set = m_set.takeChanged();
    if (set.set) {
        m_setRenderer.upload(*this, m_set.shapes());
        m_solidRenderer.upload(*this, m_set.solids());
    }
    if (set.lights) {
        m_lightRenderer.upload(*this, m_set.lights());
        m_lampRenderer.upload(*this, m_set.lamps());
    }
    const ShownCrowd::Changed crowd = m_crowd.takeChanged();
    if (crowd.characters)
        m_agentRenderer.setCharacters(*this, m_crowd.poseTables(), AgentCharacters::kLevels);
    if (crowd.glyphs)
        m_agentRenderer.upload(*this, m_crowd.batch(ShownCrowd::Walkers), m_crowd.batch(ShownCrowd::Vehicles),
                               m_crowd.batch(ShownCrowd::Fliers));
    if (m_highlightChanged)
        m_highlightRenderer.upload(*this, m_highlightMesh);
    m_highlightChanged = false;
    const OverlayLayers::Changed layers = m_layers.takeChanged();
    if (layers.lines)
        m_overlayRenderer.upload(*this, m_layers.lines());
    if (layers.fields)
        m_fieldRenderer.upload(*this, m_layers.fields());
    if (layers.heat)
        m_heatRenderer.upload(*this, m_layers.heat());
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
