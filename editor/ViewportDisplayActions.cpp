#include "editor/ViewportDisplayActions.h"

#include "editor/Icons.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>
#include <QSettings>

namespace throng::editor {

namespace {
const char* settingsKey(ColourBy by)
{
    switch (by) {
    case ColourBy::Tint: return "tint";
    case ColourBy::Type: return "type";
    case ColourBy::Group: return "group";
    case ColourBy::Goal: return "goal";
    case ColourBy::Path: return "path";
    case ColourBy::Brain: return "brain";
    case ColourBy::Speed: return "speed";
    case ColourBy::Density: return "density";
    }
    return "tint";
}
}  // namespace

ViewportDisplayActions::ViewportDisplayActions(Viewport& viewport, SimulationController& simulation, QObject* parent)
    : QObject(parent), m_viewport(viewport), m_simulation(simulation)
{
    const QSettings settings;
    const ViewportOverlays defaults;
    auto saved = [&](const char* key, bool fallback) { return settings.value(QStringLiteral("viewport/") + key, fallback).toBool(); };
    m_hud = toggle(tr("&HUD"), "hudAction", "action-hud", QKeySequence(tr("Shift+H")),
                   tr("Show the frame, time, agents per type, arrivals, and the simulation and view rates over the "
                      "viewport, with the legend of the agents' colours"),
                   saved("hud", defaults.hud));
    m_trails = toggle(tr("&Trails"), "trailsAction", "action-trails", QKeySequence(Qt::Key_T),
                      tr("Draw where the selected agents and groups' members walked over the last %1 s")
                          .arg(double(defaults.trailSeconds)),
                      saved("trails", defaults.trails));
    m_steering = toggle(tr("&Steering"), "steeringAction", "action-steering", QKeySequence(Qt::Key_D),
                        tr("Draw the selected agents' view cone, neighbours, feelers, each behaviour's force, the "
                           "blended steering, velocity and planned way (listed in the HUD)"),
                        saved("steering", defaults.steering));
    m_sketchField = toggle(tr("S&ketched Field"), "sketchFieldAction", "action-sketch-field", QKeySequence(tr("Shift+F")),
                           tr("Draw the field the flow strokes sketch (radial basis functions round the walls) as arrows"),
                           saved("sketchField", defaults.sketchField));
    m_goalField = toggle(tr("&Goal Flow Field"), "goalFieldAction", "action-goal-field", QKeySequence(tr("Shift+G")),
                         tr("Draw the flow field to the selected goal (else the first goal) as arrows"),
                         saved("goalField", defaults.goalField));
    m_density = toggle(tr("&Density Map"), "densityAction", "action-density", QKeySequence(Qt::Key_M),
                       tr("Colour the ground by the crowd's density (agents per m²) in the shown frame"),
                       saved("density", defaults.density));

    m_colourBy = new QActionGroup(this);
    const QString chosen = settings.value("viewport/colourBy", "tint").toString();
    for (int k = 0; k < kColourByCount; ++k) {
        const auto by = ColourBy(k);
        QAction* a = m_colourBy->addAction(tr(colourByName(by)));
        a->setObjectName(QStringLiteral("colourBy%1Action").arg(colourByName(by)));
        a->setCheckable(true);
        a->setData(k);
        a->setChecked(chosen == settingsKey(by));
    }
    if (!m_colourBy->checkedAction())
        m_colourBy->actions().front()->setChecked(true);
    m_nextColour = new QAction(themeIcon("action-colour-by"), tr("&Next Colouring"), this);
    m_nextColour->setObjectName("nextColourAction");
    m_nextColour->setShortcut(QKeySequence(tr("Shift+C")));
    m_nextColour->setToolTip(tr("Colour the agents by the next of tint, type, group, goal, path, brain, speed and density"));
    connect(m_nextColour, &QAction::triggered, this, [this] {
        const QList<QAction*> all = m_colourBy->actions();
        const qsizetype at = all.indexOf(m_colourBy->checkedAction());
        all[(at + 1) % all.size()]->setChecked(true);
        apply();
    });
    connect(m_colourBy, &QActionGroup::triggered, this, [this] { apply(); });

    connect(&m_viewport, &Viewport::watchedAgentsChanged, this, &ViewportDisplayActions::watch);
    connect(&m_simulation, &SimulationController::frameChanged, this, [this] {
        m_viewport.setSimulationRate(m_simulation.stepsPerSecond());
        showSteering();
    });
    connect(&m_simulation, &SimulationController::steeringChanged, this, &ViewportDisplayActions::showSteering);
    apply();
}

QAction* ViewportDisplayActions::toggle(const QString& text, const char* name, const char* icon,
                                        const QKeySequence& key, const QString& tip, bool on)
{
    auto* a = new QAction(themeIcon(icon), text, this);
    a->setObjectName(name);
    a->setCheckable(true);
    a->setChecked(on);
    a->setShortcut(key);
    a->setToolTip(tip);
    connect(a, &QAction::toggled, this, &ViewportDisplayActions::apply);
    return a;
}

void ViewportDisplayActions::addTo(QMenu& viewMenu)
{
    QMenu* colour = viewMenu.addMenu(themeIcon("action-colour-by"), tr("&Colour Agents By"));
    colour->setObjectName("colourByMenu");
    colour->addActions(m_colourBy->actions());
    colour->addSeparator();
    colour->addAction(m_nextColour);
    viewMenu.addActions({m_hud, m_trails, m_steering, m_sketchField, m_goalField, m_density});
}

void ViewportDisplayActions::apply()
{
    ViewportOverlays overlays = m_viewport.overlays();
    overlays.hud = m_hud->isChecked();
    overlays.trails = m_trails->isChecked();
    overlays.steering = m_steering->isChecked();
    overlays.sketchField = m_sketchField->isChecked();
    overlays.goalField = m_goalField->isChecked();
    overlays.density = m_density->isChecked();
    m_viewport.setOverlays(overlays);
    const auto by = ColourBy(m_colourBy->checkedAction()->data().toInt());
    m_viewport.setColourBy(by);
    QSettings settings;
    settings.setValue("viewport/hud", overlays.hud);
    settings.setValue("viewport/trails", overlays.trails);
    settings.setValue("viewport/steering", overlays.steering);
    settings.setValue("viewport/sketchField", overlays.sketchField);
    settings.setValue("viewport/goalField", overlays.goalField);
    settings.setValue("viewport/density", overlays.density);
    settings.setValue("viewport/colourBy", settingsKey(by));
    watch();
}

void ViewportDisplayActions::watch()
{
    m_simulation.watchAgents(m_steering->isChecked() ? m_viewport.watchedAgents() : std::vector<sim::AgentId>{});
    showSteering();
}

void ViewportDisplayActions::showSteering()
{
    m_viewport.setSteering(m_steering->isChecked() ? m_simulation.steering(m_simulation.currentFrame())
                                                   : std::vector<sim::AgentDebug>{});
}

}  // namespace throng::editor
