#pragma once
// The points of the selected paths, walls or lanes as a table (x, z per row): a cell edit
// moves a point, "Add point" inserts one after the selected row (halfway to the next, or
// one segment on past the end) and "Remove point" takes the selected row out while more
// than two remain. Each edit is one undo step through the PropertyForm, over every
// selected item when their points are the same; differing points show "(mixed)".

#include "editor/panels/PropertyForm.h"

#include <glm/vec2.hpp>

#include <QWidget>

#include <functional>
#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace throng::editor {

class PointTable : public QWidget {
    Q_OBJECT

public:
    using Points = std::vector<glm::vec2>;
    PointTable(PropertyForm& form, PropertyForm::Locate<Points> locate, QWidget* parent = nullptr);

    // Re-reads the selection's points.
    void refresh();
    QTableWidget* table() const { return m_table; }

private:
    void cellEdited(int row, int column);
    void addPoint();
    void removePoint();
    // Applies `edit` to the points of every selected item as one undo step.
    void change(const QString& what, const std::function<void(Points&)>& edit);

    PropertyForm& m_form;
    PropertyForm::Locate<Points> m_locate;
    QTableWidget* m_table = nullptr;
    QLabel* m_note = nullptr;
    QPushButton* m_add = nullptr;
    QPushButton* m_remove = nullptr;
    int m_serial = 0;  // each edit its own undo step
};

}  // namespace throng::editor
