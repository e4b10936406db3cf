#pragma once
// Helpers the editor tests share: scene files written into a temporary folder, the
// viewport rendered offscreen, colour comparisons with a readable failure text, and the
// steps UI tests repeat on the main window (open a scene, play to a frame, pick items
// in the outliner, read the status bar, the scene as it would be saved).

#include "editor/MainWindow.h"
#include "editor/viewport/Viewport.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>

#include <QByteArray>
#include <QImage>
#include <QPointF>
#include <QString>
#include <QTemporaryDir>

namespace throng::editor::test {

// Agents of the crossroads demo as the status bar counts them: 200 spawned walkers, the
// 10-walker shortest-path group, 16 cars and 1 hero.
inline constexpr std::size_t kCrossroadsAgents = 227;

// Writes `yaml` to dir/name and returns the file's path.
QString writeScene(const QTemporaryDir& dir, const QString& name, const QByteArray& yaml);
// Writes yaml as scene.yaml in dir and loads it; a scene that does not load stops the test.
sim::Scene loadTestScene(const QTemporaryDir& dir, const QByteArray& yaml);

// Shows `viewport` offscreen at `sizePx` and returns what it draws.
QImage renderOffscreen(Viewport& viewport, QSize sizePx);

// The image pixel under a logical widget position (rounded).
QRgb pixelAt(const QImage& image, const Viewport& viewport, QPointF widgetPos);

// True when every channel of `pixel` is within `tolerance` (0..255) of `colour`.
bool sameColour(QRgb pixel, glm::vec4 colour, int tolerance = 8);
// How many of `image`'s pixels within `radiusM` of a ground point (x, z), sampled every
// 5 cm, have `colour` (within `tolerance`).
int pixelsOf(MainWindow& window, const QImage& image, glm::vec2 centre, float radiusM, glm::vec4 colour,
             int tolerance);
QString describe(QRgb pixel);
QString describe(glm::vec4 colour);

// Writes `yaml` as dir/name and opens it in the shown main window (EditorUiDriver's
// showWithSceneFile). False when any step fails.
bool showWithYaml(MainWindow& window, const QTemporaryDir& dir, const QString& name, const QByteArray& yaml);
// Clicks the button with this object name ("playButton", "stepButton").
bool clickButton(MainWindow& window, const QString& objectName);
// Presses Play, waits until the viewport shows frame `frame` or later, presses Pause.
// False when the frame was not reached within `timeoutMs`.
bool playToFrame(MainWindow& window, std::size_t frame, int timeoutMs = 30000);
// Presses Play, waits until frame `last` is recorded, presses Pause. False when it was
// not recorded within `timeoutMs` or playback did not stop.
bool playUntilRecorded(MainWindow& window, std::size_t last, int timeoutMs = 90000);
// Scrubs to `frame` with the keyboard on the timeline's scrub bar (Home, then Right).
// False unless the simulation and the viewport then show that frame.
bool scrubWithKeys(MainWindow& window, std::size_t frame);
// The hash of a recording's first `frames` frames (agent sets included).
std::uint64_t hashOfFirst(const sim::FrameCache& cache, std::size_t frames);
// The status bar's texts: "Frame 12", "227 agents".
QString frameText(MainWindow& window);
QString agentCountText(MainWindow& window);
// Clicks the outliner rows of `items` (Ctrl held from the second on), expanding headings.
void selectInOutliner(MainWindow& window, const Selection& items);
// The scene as Save would write it.
QByteArray sceneYaml(MainWindow& window);

// The properties panel driven like a user.
// The panel's widget of this type and object name ("width", "brain"); null when none.
template <class Widget>
Widget* field(MainWindow& window, const QString& name)
{
    return window.findChild<QWidget*>("properties")->findChild<Widget*>(name);
}
// Waits until `widget` is laid out in the panel (rows added to a shown panel are laid out
// on the next event loop pass) and scrolls the panel to it.
void showInPanel(MainWindow& window, QWidget* widget);
// Whether pick() first scrolls the panel to the combo box.
enum class Scroll { No, ToWidget };
// Picks `text` in the panel's combo box `name` with the keyboard, as a user does.
void pick(MainWindow& window, const QString& name, const QString& text, Scroll scroll = Scroll::No);
// Types `text` over all that a spin box or line edit shows and presses Return.
void typeInto(QWidget* widget, const QString& text);
// The same, after scrolling the panel to the widget (showInPanel).
void typeInto(MainWindow& window, QWidget* widget, const QString& text);
// Clicks the panel's push button `name`, scrolled into view.
void press(MainWindow& window, const QString& name);
// Ctrl+Z on the viewport.
void undo(MainWindow& window);
// Shows the window at 1400 x 900 on the scene it starts with (File > New's) and waits
// until it is exposed and active.
void showNewWindow(MainWindow& window);
// Clicks the item `text` (mnemonic '&' ignored) of the open popup menu; false when no
// menu is open or it has no such item.
bool clickPopupItem(const QString& text);
// Runs `answer` on the next modal dialog or popup menu that opens (polling every 20 ms, as
// the dialog's exec() blocks the caller, until it returns true or 5 s have passed).
void whenShown(std::function<bool()> answer);

// The newest line of the messages panel; empty when there is none.
QString lastMessage(MainWindow& window);

}  // namespace throng::editor::test
