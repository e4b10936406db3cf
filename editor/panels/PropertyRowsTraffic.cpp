// The properties panel's rows for the traffic kinds: crosswalks and vehicles.
#include "editor/panels/PropertyRows.h"

#include "editor/panels/PropertyForm.h"

namespace throng::editor {

namespace {

QString tr(const char* text)
{
    return PropertyForm::tr(text);
}

// The agent types a vehicle may be: those of kind vehicle (the scene check refuses others).
QStringList vehicleTypes(const sim::Scene& s)
{
    QStringList out;
    for (const sim::AgentType& t : s.agentTypes)
        if (t.kind == sim::AgentKind::Vehicle)
            out << QString::fromStdString(t.name);
    return out;
}

QStringList laneNames(const sim::Scene& s)
{
    QStringList out;
    for (const sim::Lane& l : s.lanes)
        out << QString::fromStdString(l.name);
    return out;
}

}  // namespace

void addCrosswalkRows(PropertyForm& form)
{
    form.addName();
    form.addNumberFields();  // from x/z, to x/z, width
}

void addVehicleRows(PropertyForm& form)
{
    form.addInfo("id", tr("Id"), [](const sim::Scene& s, std::size_t i) {
        return s.vehicles[i].id == 0 ? tr("assigned at load") : QString::number(s.vehicles[i].id);
    });
    form.addChoice("type", tr("Type"), vehicleTypes,
                   [](sim::Scene& s, std::size_t i) -> auto& { return s.vehicles[i].type; }, false);
    form.addChoice("lane", tr("Lane"), laneNames,
                   [](sim::Scene& s, std::size_t i) -> auto& { return s.vehicles[i].lane; }, false);
    form.addNumberFields();  // start distance, initial speed
}

}  // namespace throng::editor
