#pragma once
// The View menu's display actions: the HUD, Colour By (a choice per colouring and a key
// that cycles them), trails, steering, the sketched field, the goal flow field and the
// density map. Remembered across sessions (QSettings "viewport/…"), applied to the
// viewport; while steering is shown, the simulation watches the viewport's selected
// agents and their annotations follow the shown frame.

#include <QObject>

class QAction;
class QActionGroup;
class QMenu;

namespace throng::editor {

class SimulationController;
class Viewport;

class ViewportDisplayActions : public QObject {
    Q_OBJECT

public:
    ViewportDisplayActions(Viewport& viewport, SimulationController& simulation, QObject* parent);
    void addTo(QMenu& viewMenu);

private:
    QAction* toggle(const QString& text, const char* name, const char* icon, const QKeySequence& key,
                    const QString& tip, bool on);
    void apply();
    void watch();
    void showSteering();

    Viewport& m_viewport;
    SimulationController& m_simulation;
    QAction* m_hud = nullptr;
    QAction* m_trails = nullptr;
    QAction* m_steering = nullptr;
    QAction* m_sketchField = nullptr;
    QAction* m_goalField = nullptr;
    QAction* m_density = nullptr;
    QAction* m_nextColour = nullptr;
    QActionGroup* m_colourBy = nullptr;
};

}  // namespace throng::editor
