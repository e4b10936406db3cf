#pragma once
// The heads-up display over the viewport: the shown frame and its time, the agents shown
// per type, how many arrived and left, the simulation's steps per second, the view's
// frames per second, and the legend of the agents' colouring. Shows the figures it is
// given; lets every mouse event through.

#include "editor/viewport/AgentColours.h"

#include <QElapsedTimer>
#include <QStringList>
#include <QWidget>

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace throng::editor {

struct HudFigures {
    std::size_t frame = 0;
    std::optional<double> timeS;
    double fps = 24.0;  // the scene's
    std::size_t shown = 0, arrived = 0, out = 0;
    std::vector<std::pair<std::string, std::size_t>> perType;  // type name, agents shown
    double stepsPerSecond = 0.0;  // the simulation's, 0 while idle
    // What the layout check found over the recording, and the agents it flags on this frame.
    std::size_t layoutOverlaps = 0, layoutWallCrossings = 0, layoutFlagged = 0;
    // The agents' colouring first, then what the overlays show (a watched agent's forces).
    std::vector<ColourLegend> legends;
};

class ViewportHud : public QWidget {
    Q_OBJECT

public:
    // Types listed one per line; the rest are summed on one more.
    static constexpr std::size_t kTypeLines = 6;

    explicit ViewportHud(QWidget* parent);
    void setFigures(HudFigures figures);
    const HudFigures& figures() const { return m_figures; }
    // The view drew a frame: counts towards viewFps().
    void framePainted();
    // Frames the view drew in the last second (0 when it has been still for longer).
    double viewFps() const;
    // The text it shows, line by line (a legend's entries as "■ label").
    QStringList lines() const;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    HudFigures m_figures;
    QElapsedTimer m_clock;
    std::deque<qint64> m_paints;  // ms on m_clock of the paints in the last second
};

}  // namespace throng::editor
