#pragma once
// A viewport test's way to show a scene with its agents at once: the viewport builds no
// World of its own (the editor's agents come from the simulation's frame cache), so the
// test builds the scene's initial state and gives it to the viewport.

#include "editor/viewport/Viewport.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/World.h"

#include <QtGlobal>

#include <exception>

namespace throng::editor::test {

// Shows the scene's set and the agents of a World built from it at frame 0; only the set
// when no World can be built.
inline void showInitialState(Viewport& viewport, const sim::Scene& scene)
{
    try {
        const sim::World world(scene);
        viewport.setScene(scene, world);
    } catch (const std::exception& e) {
        qWarning("the test scene has no initial state: %s", e.what());
        viewport.setScene(scene);
    }
}

}  // namespace throng::editor::test
