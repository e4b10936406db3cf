#include "editor/AgentTypePresets.h"

#include <QCoreApplication>

#include <algorithm>

namespace throng::editor {

namespace {

bool nameUsed(const sim::Scene& scene, const std::string& name)
{
    return std::any_of(scene.agentTypes.begin(), scene.agentTypes.end(),
                       [&](const sim::AgentType& t) { return t.name == name; });
}

std::string freeName(const sim::Scene& scene, const std::string& stem)
{
    if (!nameUsed(scene, stem))
        return stem;
    for (int n = 2;; ++n)
        if (const std::string name = stem + "_" + std::to_string(n); !nameUsed(scene, name))
            return name;
}

QString tr(const char* text)
{
    return QCoreApplication::translate("AgentTypePresets", text);
}

// The crowd palette of the crossroads demo: varied builds and clothes from the start.
sim::Variation walkerVariation()
{
    sim::Variation v;
    v.looks = {"man", "woman", "tall_man", "child", "elderly"};
    v.tints = {{0.8f, 0.25f, 0.2f}, {0.2f, 0.45f, 0.8f}, {0.9f, 0.75f, 0.3f}, {0.3f, 0.65f, 0.35f}, {0.6f, 0.6f, 0.65f}};
    v.heightScale = {0.92f, 1.08f};
    return v;
}

}  // namespace

QString presetLabel(TypePreset preset)
{
    switch (preset) {
    case TypePreset::Pedestrian: return tr("Pedestrian");
    case TypePreset::Runner: return tr("Runner");
    case TypePreset::Car: return tr("Car");
    case TypePreset::Bird: return tr("Bird");
    case TypePreset::Rider: return tr("Rider");
    }
    return {};
}

QString presetDescription(TypePreset preset)
{
    switch (preset) {
    case TypePreset::Pedestrian: return tr("Walkers at 1.4 m/s, 0.3 m bodies, varied looks and clothes");
    case TypePreset::Runner: return tr("Joggers at 3.5 m/s");
    case TypePreset::Car: return tr("Cars at 13.9 m/s (50 km/h) that drive along lanes");
    case TypePreset::Bird: return tr("Fliers that flock: 5 to 12 m/s, banking into turns");
    case TypePreset::Rider: return tr("Horsemen at 8.4 m/s, 0.6 m bodies");
    }
    return {};
}

sim::AgentType makeTypePreset(TypePreset preset, const sim::Scene& scene)
{
    sim::AgentType t;
    t.character = "man";
    switch (preset) {
    case TypePreset::Pedestrian:
        t.name = "pedestrian";
        t.maxForce = 6.0f;
        t.variation = walkerVariation();
        break;
    case TypePreset::Runner:
        t.name = "runner";
        t.maxSpeed = 3.5f;
        t.maxForce = 10.0f;
        t.variation = walkerVariation();
        break;
    case TypePreset::Car:
        t.name = "car";
        t.kind = sim::AgentKind::Vehicle;
        t.radiusM = 1.1f;
        t.maxSpeed = 13.9f;
        t.maxForce = 5000.0f;
        t.mass = 1200.0f;
        t.perceptionM = 45.0f;
        t.viewAngleDeg = 90.0f;
        t.character = "car";
        break;
    case TypePreset::Bird:
        t.name = "bird";
        t.kind = sim::AgentKind::Flier;
        t.radiusM = 0.2f;
        t.maxSpeed = 12.0f;
        t.minSpeed = 5.0f;
        t.maxForce = 20.0f;
        t.perceptionM = 2.0f;
        t.viewAngleDeg = 300.0f;
        t.banking = 0.05f;
        t.character = "bird";
        t.variation.speedFactor = {0.9f, 1.1f};
        break;
    case TypePreset::Rider:
        t.name = "rider";
        t.radiusM = 0.6f;
        t.maxSpeed = 8.4f;
        t.maxForce = 30.0f;
        t.perceptionM = 3.0f;
        t.variation.speedFactor = {0.9f, 1.0f};
        break;
    }
    t.name = freeName(scene, t.name);
    return t;
}

sim::AgentType duplicateType(const sim::AgentType& type, const sim::Scene& scene)
{
    sim::AgentType copy = type;
    copy.name = freeName(scene, type.name + "_copy");
    return copy;
}

sim::Scene newSceneTemplate()
{
    sim::Scene scene;
    scene.agentTypes.push_back(makeTypePreset(TypePreset::Pedestrian, scene));
    return scene;
}

}  // namespace throng::editor
