#pragma once
// The editable number fields of each kind of scene item: label, unit range and where the
// value lives. Plain data used by the properties panel; edits nothing itself.

#include "editor/SceneItem.h"

#include <QString>

#include <functional>
#include <vector>

namespace throng::editor {

struct PropertyField {
    QString key;      // stable id, also the spin box's object name ("radius")
    QString label;    // "Radius (m)"
    double min = 0.0, max = 1e6, step = 0.1;
    int decimals = 2;
    // The value of item `index` in the scene.
    std::function<float&(sim::Scene&, std::size_t index)> locate;
    // Why item `index` may not take `value` (a crosswalk whose ends would meet), or empty.
    std::function<QString(const sim::Scene&, std::size_t index, float value)> refusal = {};
    // Whether the row applies to item `index` (a box's size, not a circle's); empty = always.
    // The row shows while it applies to any selected item.
    std::function<bool(const sim::Scene&, std::size_t index)> shown = {};
};

const std::vector<PropertyField>& propertyFields(ItemKind kind);

}  // namespace throng::editor
