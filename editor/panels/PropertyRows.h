#pragma once
// Which rows the properties panel shows for each kind of item: one small builder per
// kind adds its fields to a PropertyForm (names, combo boxes of the scene's types,
// brains, groups, paths and goals, check boxes, counts, number fields, read-only info).

#include "simcore/scene/Scene.h"

#include <QStringList>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace throng::editor {

class PropertyForm;

// Adds the rows of the form's kind (the selection's) to `form`.
void addPropertyRows(PropertyForm& form);

// The builders, per kind.
void addAgentRows(PropertyForm& form);
void addAgentTypeRows(PropertyForm& form);
void addGroupRows(PropertyForm& form);
void addSetRows(PropertyForm& form);  // paths, walls, obstacles, goals, lanes, lights, heroes, settings
void addCrosswalkRows(PropertyForm& form);  // PropertyRowsTraffic.cpp
void addSourceRows(PropertyForm& form);     // PropertyRowsSource.cpp
void addVehicleRows(PropertyForm& form);
// PropertyRowsAgent.cpp: the leader (an agent id, "(none)" = 0; `agents`: the selection
// is placed agents, which may not lead themselves), and an agent's look, tint and height.
void addLeaderRow(PropertyForm& form, std::function<std::uint32_t&(sim::Scene&, std::size_t)> locate, bool agents);
void addAgentVariationRows(PropertyForm& form);
// PropertyRowsType.cpp: a type's looks, tints and character; its walkers' ages; its
// collision layers.
void addAgentTypeLookRows(PropertyForm& form);
// The walkers' age range, typed as two numbers ("20 to 80"; empty for none).
void addAgentTypeAgeRow(PropertyForm& form);
// PropertyRowsExits.cpp: the exits a group's or source's agents choose among (ExitChoice.h),
// typed as a list; `apply` sets the checked names (and clears the item's other route), and
// the rows named in routeRows (its goal, path, leader) hide while the item chooses.
void addExitsRow(PropertyForm& form, std::function<std::vector<std::string>&(sim::Scene&, std::size_t)> exits,
                 std::function<void(const std::vector<std::string>&)> apply, const QStringList& routeRows);
void addAgentTypeCollisionRows(PropertyForm& form);
// PropertyRowsKeep.cpp: how a group's members keep together: a formation (shape, spacing,
// column width) or companions (small groups' sizes), Formations.h.
void addKeepTogetherRows(PropertyForm& form);
// PropertyRowsLayout.cpp: a layout operation's kind, switch, agents, frames and amount.
void addLayoutOpRows(PropertyForm& form);

}  // namespace throng::editor
