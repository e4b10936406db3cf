#pragma once
// The editor's icon set: hand-drawn SVGs compiled in from resources/icons (every SVG there),
// looked up by key ("tool-select", "action-play"). Draws nothing itself and never falls
// back to another icon, so a misspelt key shows up as a missing icon rather than a wrong one.

#include <QIcon>
#include <QString>
#include <QStringList>

namespace throng::editor {

// The icon for `key`; a null QIcon (and a warning) when the set has no such icon.
QIcon themeIcon(const QString& key);

// Every key the set holds, sorted.
QStringList iconKeys();

}  // namespace throng::editor
