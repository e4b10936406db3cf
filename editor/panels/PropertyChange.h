#pragma once
// What a property edit in the properties panel changes: the field of the item that a
// property key ("x", "tint", "points/3") stands for, per kind of item. Plain functions
// of the key; they read no scene.

#include "editor/SceneChange.h"

#include <QString>

#include <cstddef>
#include <vector>

namespace throng::editor {

// The field property `key` of an item of `kind` is; a key not listed is Parameters (read
// by the simulation).
SceneField propertyField(ItemKind kind, const QString& key);
// Property `key` of the items `indices` of `kind`.
SceneChange propertyChange(ItemKind kind, const QString& key, std::vector<std::size_t> indices);

}  // namespace throng::editor
