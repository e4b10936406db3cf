#pragma once
// A letter typed on a combo box picks its item (Qt's keyboard search) instead of firing
// the editor's tool shortcut of that letter (G for the goal tool, S for ...) while the
// combo box has focus. Used by the properties panel and the tool options.

class QComboBox;

namespace throng::editor {

// Makes `combo` keep the plain printable keys typed on it (an event filter owned by it).
void keepTypedLetters(QComboBox* combo);

}  // namespace throng::editor
