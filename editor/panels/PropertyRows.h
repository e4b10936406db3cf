#pragma once
// Which rows the properties panel shows for each kind of item: one small builder per
// kind adds its fields to a PropertyForm (names, combo boxes of the scene's types,
// brains, groups, paths and goals, check boxes, counts, number fields, read-only info).

namespace throng::editor {

class PropertyForm;

// Adds the rows of the form's kind (the selection's) to `form`.
void addPropertyRows(PropertyForm& form);

// The builders, per kind.
void addAgentRows(PropertyForm& form);
void addAgentTypeRows(PropertyForm& form);
void addGroupRows(PropertyForm& form);
void addSetRows(PropertyForm& form);  // paths, walls, obstacles, goals, lanes, lights, heroes, settings

}  // namespace throng::editor
