#pragma once
// Names each action's shortcut in its tooltip ("Save the scene to its file (Ctrl+S)"),
// so tool buttons and menus teach the keys. Changes tooltips only.

class QWidget;

namespace throng::editor {

// Every QAction under `root` with a shortcut whose tooltip does not name it yet gets it
// appended; run once the actions exist. Tooltips that name it already stay as they are.
void nameShortcutsInToolTips(QWidget& root);

}  // namespace throng::editor
