#pragma once
// Drives the real main window as a user does in the UI tests: shows it, opens a copy of
// a scene, clicks tool buttons and clicks or drags on the viewport at ground points.

#include "editor/MainWindow.h"

#include <glm/vec2.hpp>

#include <QString>
#include <QTemporaryDir>

#include <vector>

namespace throng::editor::test {

// Shows the window, waits until it is exposed and active, opens a copy of
// resources/scenes/<name> in `dir`/scenes (beside a copy of resources/brains in
// `dir`/brains), waits for frame 0 of its crowd (the simulation's thread makes it) and
// frames it. False when any step fails.
bool showWithScene(MainWindow& window, const QTemporaryDir& dir, const QString& name);
// Shows the window as showWithScene does, opening the scene file at `path`.
bool showWithSceneFile(MainWindow& window, const QString& path);
// The widget pixel of a ground point (x, z).
QPoint pixelOf(MainWindow& window, glm::vec2 ground);
// Clicks the tool bar button of the tool with this key ("crowdBrush").
bool clickToolButton(MainWindow& window, const QString& key);
// Clicks the tab titled `title` among the docks' tab bars ("Analysis"); false when no
// shown tab bar has it.
bool clickDockTab(MainWindow& window, const QString& title);
// A left drag on the viewport through these ground points, with moves between them.
void dragOnGround(MainWindow& window, const std::vector<glm::vec2>& points);
void clickOnGround(MainWindow& window, glm::vec2 point);

}  // namespace throng::editor::test
