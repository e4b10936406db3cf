#pragma once
// The Help menu: the user guide (docs/editor.md, built into the program), a sheet of
// every keyboard shortcut the window's actions have plus the viewport's mouse keys,
// and About. Shows information only.

#include <QObject>

class QAction;
class QDialog;
class QMainWindow;

namespace throng::editor {

class HelpMenu : public QObject {
    Q_OBJECT

public:
    explicit HelpMenu(QMainWindow& window);

    // Opens (or raises) the sheet of shortcuts, built from the window's actions as they
    // are now, and returns it.
    QDialog* showShortcuts();
    QDialog* showGuide();

private:
    QMainWindow& m_window;
    QDialog* m_shortcuts = nullptr;
    QDialog* m_guide = nullptr;
};

}  // namespace throng::editor
