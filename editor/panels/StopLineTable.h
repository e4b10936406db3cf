#pragma once
// The stop lines of the selected traffic lights as a table: per row the kind (lane or
// crosswalk), which lane or crosswalk, and the distance along the lane; "Add stop line"
// appends one (on the first lane at 0 m, or the first crosswalk), "Remove stop line" takes
// the selected row out. Each edit is one undo step through the PropertyForm, over every
// selected light when their stop lines are the same; differing ones show "(mixed)".

#include "editor/panels/PropertyForm.h"

#include <QWidget>

#include <functional>
#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace throng::editor {

class StopLineTable : public QWidget {
    Q_OBJECT

public:
    using Lines = std::vector<sim::StopLine>;
    StopLineTable(PropertyForm& form, QWidget* parent = nullptr);

    // Re-reads the selection's stop lines.
    void refresh();
    QTableWidget* table() const { return m_table; }

private:
    // Builds the row's widgets (kind, target, distance) for `line`.
    void buildRow(int row, const sim::StopLine& line);
    void showRow(int row, const sim::StopLine& line);
    // Applies `edit` to every selected light's stop lines as one undo step; `key` merges
    // repeated edits of one field (a distance stepped with the arrows).
    void change(const QString& key, const QString& what, const std::function<void(Lines&)>& edit);
    void setKind(int row, int kind);
    void setTarget(int row, const QString& name);

    PropertyForm& m_form;
    QTableWidget* m_table = nullptr;
    QLabel* m_note = nullptr;
    QPushButton* m_add = nullptr;
    QPushButton* m_remove = nullptr;
    std::vector<bool> m_rowIsLane;  // the built rows' kinds: rebuilt when they change
    int m_serial = 0;
};

}  // namespace throng::editor
