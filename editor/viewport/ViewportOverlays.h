#pragma once
// What the viewport draws besides the set and the agents: the HUD, trails behind the
// followed agents, the watched agents' steering, the flow strokes' sketched (RBF) field,
// a goal's flow field, and the crowd's density. A view setting, never saved in the scene.

namespace throng::editor {

struct ViewportOverlays {
    bool hud = true;
    bool trails = false;
    bool steering = false;
    bool sketchField = false;
    bool goalField = false;
    bool density = false;
    float trailSeconds = 4.0f;  // s of walking behind each followed agent, > 0
    bool operator==(const ViewportOverlays&) const = default;
};

}  // namespace throng::editor
