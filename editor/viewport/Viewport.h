#pragma once
// The OpenGL 3.3 core view of a scene: ground grid, the set (walls, paths, obstacles,
// lanes, lights, ...) and the agents of one moment, through a top or orbit camera.
// Shows what it is given (plain scene data and agent frames); never edits the scene.

#include "editor/SceneItem.h"
#include "editor/tools/ViewportTool.h"
#include "editor/viewport/AgentRenderer.h"
#include "editor/viewport/CameraDrag.h"
#include "editor/viewport/CameraRig.h"
#include "editor/viewport/GridRenderer.h"
#include "editor/viewport/GroundBox.h"
#include "editor/viewport/OverlayLayers.h"
#include "editor/viewport/SelectionMarks.h"
#include "editor/viewport/ShapeMesh.h"
#include "editor/viewport/ShapeRenderer.h"
#include "editor/viewport/ShownAgents.h"
#include "editor/viewport/ShownCrowd.h"
#include "editor/viewport/ShownSet.h"
#include "editor/viewport/SolidRenderer.h"
#include "editor/viewport/ViewportHud.h"
#include "editor/viewport/ViewportOverlays.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/DebugSink.h"
#include "simcore/world/FrameCache.h"

#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLWidget>
#include <QSurfaceFormat>

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace throng::sim {
class World;
}

namespace throng::editor {

class ToolOverlay;

class Viewport : public QOpenGLWidget, protected QOpenGLFunctions_3_3_Core {
    Q_OBJECT

public:
    explicit Viewport(QWidget* parent = nullptr);
    ~Viewport() override;

    // OpenGL 3.3 core profile, 24-bit depth, 4x multisampling (none under a software
    // rasteriser such as llvmpipe, where it triples the frame time; THRONG_MSAA=N sets it).
    static QSurfaceFormat surfaceFormat();

    // Shows a new scene's set at once, without agents, and frames it on the next paint.
    // The agents come with showFrame (frame 0 from the simulation's cache): building a
    // World here would hold the GUI thread for seconds on a big crowd.
    void setScene(const sim::Scene& scene);
    // Shows the scene's set and the current state of `state`, a World of that scene (the
    // command line's screenshot builds its own).
    void setScene(const sim::Scene& scene, const sim::World& state);
    // The set of the edited scene; the camera stays where the user left it, and the agents
    // shown stay until the simulation brings the frame to show (showFrame).
    void updateScene(const sim::Scene& scene);
    // Shows frame `frame` (< cache.frameCount()) of a recording of the current scene, or
    // nobody for frame 0 of a recording without agents. The trails read the frames
    // before it: the caller keeps `cache` alive while it is shown.
    void showFrame(const sim::FrameCache& cache, std::size_t frame);

    // The HUD, trails, steering annotations, fields and density drawn over the set.
    void setOverlays(const ViewportOverlays& overlays);
    const ViewportOverlays& overlays() const { return m_layers.settings(); }
    void setColourBy(ColourBy by);
    ColourBy colourBy() const { return m_crowd.colourBy(); }
    // The watched agents' steering annotations on the shown frame (steering overlay).
    void setSteering(std::vector<sim::AgentDebug> agents);
    // The simulation's steps per second, for the HUD (0 while idle).
    void setSimulationRate(double stepsPerSecond);
    // The agents whose steering the overlay shows: the focused, the inspected and the
    // selected agents (watchedAgentsChanged() when they change).
    std::vector<sim::AgentId> watchedAgents() const { return m_marks.watchedIds(); }
    const ViewportHud& hud() const { return *m_hud; }

    // Outlines the selected items over the set (drawn below the agents); selected agents'
    // and vehicles' rings follow them in the shown frame. Drops the focused agent when its
    // item (its placed agent, group, vehicle or hero) is no longer selected.
    void setHighlight(const sim::Scene& scene, const Selection& selection);
    // The agent the user last clicked (0 = none): a view state, never saved. It gets a
    // ring of its own, so one member of a selected group can be followed.
    void setFocusedAgent(sim::AgentId id);
    sim::AgentId focusedAgent() const { return m_marks.focusedAgent(); }
    // The agent the brain editor inspects (0 = none): ringed in its own colour.
    void setInspectedAgent(sim::AgentId id);
    // What the layout check found (sim::checkLayout): its count goes to the HUD, and the
    // agents it flags on the shown frame get a ring of their own.
    void setLayoutCheck(const sim::LayoutCheck& check);
    sim::AgentId inspectedAgent() const { return m_marks.inspectedAgent(); }
    // How many agents the layout check flags on the shown frame.
    std::size_t layoutFlaggedCount() const { return m_marks.flaggedCount(); }

    void setViewMode(ViewMode mode);
    ViewMode viewMode() const { return m_camera.mode(); }
    // Fits the set and the shown agents into the view.
    void frameAll();
    // Fits the selected items, and the selected agents and groups' members where the shown
    // frame has them, into the view; everything when nothing selected has a place.
    void frameSelection();

    std::size_t agentCount() const { return m_crowd.glyphCount(); }
    std::size_t frameIndex() const { return m_frameIndex; }
    // Simulation time of the shown moment (0 for a scene just set); empty before any scene.
    std::optional<double> timeS() const { return m_timeS; }
    // The widget pixel (logical) where a world point appears through the current camera.
    QPointF worldToPixel(glm::vec3 point) const;
    // The point of the terrain (or the ground plane y = 0) under a widget pixel, found by
    // casting the camera ray; empty when the ray misses the ground.
    std::optional<glm::vec3> pixelToGround(QPointF pixel) const;
    // The current camera at the widget's size.
    RenderView renderView() const;
    // The agents as the shown frame draws them.
    const ShownAgents& shownAgents() const { return m_crowd.shown(); }

    // The tool that receives left-button input and draws the overlay; null = navigation only.
    void setTool(ViewportTool* tool);
    ViewportTool* tool() const { return m_tool; }

    // Level of detail for agents (on by default): culled by cells, far ones as impostors.
    // Off draws every agent with the shape chosen for the whole crowd, as a reference.
    void setAgentLevelOfDetail(bool on);
    bool agentLevelOfDetail() const { return m_agentRenderer.levelOfDetail(); }
    // Agents the last paint drew per AgentDetail (Detailed, Coarse, Impostor), with
    // level of detail on; those not counted were outside the view.
    const std::array<int, kAgentDetailLevels>& agentsDrawnByDetail() const
    {
        return m_agentRenderer.lastDrawnByDetail();
    }

    // On: near agents in 3D wear their type's character (as export dresses them: look,
    // tint, height, posed by their recorded clip and phase). Off (the default, the
    // reference the glyph tests use): glyphs. The main window and screenshots turn it on.
    void setAgentsAsCharacters(bool on);
    bool agentsAsCharacters() const { return m_agentRenderer.agentsAsCharacters(); }
    // Agents the last paint drew as characters.
    int charactersDrawn() const { return m_agentRenderer.lastCharactersDrawn(); }
    // The folder character files named relative to the scene are found in (the scene
    // file's folder); set it before setScene. Empty: the working directory.
    void setSceneDirectory(const QString& directory) { m_sceneDirectory = directory.toStdString(); }

    // False when no OpenGL 3.3 core context could be made; glProblem() says why.
    bool isGlReady() const { return m_glReady; }
    QString glProblem() const { return m_glProblem; }

signals:
    // The shown agents changed: agentCount(), frameIndex() or timeS().
    void agentsChanged();
    void viewModeChanged(ViewMode mode);
    // The user picked agent `id` in the view (setFocusedAgent with an agent).
    void agentPicked(sim::AgentId id);
    // watchedAgents() changed (the selection, the focused or the inspected agent).
    void watchedAgentsChanged();

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    void setSet(const sim::Scene& scene);
    // Shows `frames` of `agents` (the first of the two's length) as frame `frameIndex`, at
    // `timeS`; the kept frame itself may be given again, to show it anew.
    void setAgents(std::span<const sim::AgentFrame> frames, std::span<const sim::AgentInfo> agents,
                   std::optional<double> timeS, std::size_t frameIndex);
    GroundBox framingBox() const;
    void forwardToTool(QMouseEvent* event, void (ViewportTool::*handler)(const ToolMouse&));
    void cameraMovedByUser();
    void uploadChanged();
    void rebuildHighlight();
    // The selection, the focused or the inspected agent changed; `watchedBefore` were the
    // watched agents before.
    void marksChanged(const std::vector<sim::AgentId>& watchedBefore);
    // The trails and steering annotations of the shown frame.
    void rebuildOverlay();
    void updateHud();
    void releaseGl();

    CameraRig m_camera;
    GridRenderer m_grid;
    ShapeRenderer m_setRenderer;
    ShapeRenderer m_lightRenderer;
    ShapeRenderer m_highlightRenderer;
    ShapeRenderer m_overlayRenderer;
    ShapeRenderer m_fieldRenderer;
    ShapeRenderer m_heatRenderer;
    AgentRenderer m_agentRenderer;
    SolidRenderer m_solidRenderer, m_lampRenderer;  // the 3D set, and its lamps relit every frame

    // What is shown, kept on the CPU until the next paint uploads it.
    ShownSet m_set;
    ShownCrowd m_crowd;
    OverlayLayers m_layers;  // trails, steering, fields and density, and what is on
    SelectionMarks m_marks;
    ShapeMesh m_highlightMesh;
    bool m_highlightChanged = true;
    std::string m_sceneDirectory;
    std::optional<double> m_timeS;
    std::size_t m_frameIndex = 0;
    float m_fps = 24.0f;                       // the scene's
    const sim::FrameCache* m_cache = nullptr;  // the recording shown, null for a World's state

    ViewportHud* m_hud = nullptr;
    double m_stepsPerSecond = 0.0;
    std::size_t m_layoutOverlaps = 0, m_layoutWallCrossings = 0;  // what the layout check found

    bool m_frameOnNextPaint = true;     // until the user moves the camera, resizing re-frames
    bool m_frameWhenAgentsCome = false;  // a new scene's first agents have not been shown yet
    bool m_cameraMovedByUser = false;
    CameraDrag m_drag;

    ViewportTool* m_tool = nullptr;
    ToolOverlay* m_overlay = nullptr;
    bool m_toolDragging = false;

    bool m_glReady = false;
    QString m_glProblem;
};

}  // namespace throng::editor
