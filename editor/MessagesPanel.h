#pragma once
// The "Messages" list: what the last load reported, one "file:line:col: message" row
// per diagnostic, errors marked as such; activating a row that names an item (by its key)
// asks for that item to be selected. Shows messages; never reads files itself.

#include "editor/SceneItem.h"
#include "simcore/base/Diagnostic.h"

#include <QListWidget>

#include <vector>

namespace throng::editor {

class MessagesPanel : public QListWidget {
    Q_OBJECT

public:
    explicit MessagesPanel(QWidget* parent = nullptr);

    // Replaces the list with `diagnostics`, after a first row saying what was done.
    void showDiagnostics(const QString& headline, const std::vector<sim::Diagnostic>& diagnostics);
    // Replaces the list with one informational row.
    void showNote(const QString& note);

    // A few rows high, so the dock leaves the viewport most of the window.
    QSize sizeHint() const override;

signals:
    // The user activated (double-clicked, Enter) a message about this item.
    void itemRequested(SceneItem item);
};

}  // namespace throng::editor
