#pragma once
// The points of the selected paths, walls, lanes or polygon groups as a table (x, z per
// row): a cell edit moves a point, "Add point" inserts one after the selected row (halfway
// to the next, or one segment on past the end) and "Remove point" takes the selected row
// out while more than the minimum remain. Each edit is one undo step through the
// PropertyForm, over every selected item when their points are the same; differing points
// show "(mixed)". An edit the shape's check refuses changes nothing.

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
    // Why an item may not take these points (a polygon that would cross itself), or empty.
    using Check = std::function<QString(const Points&)>;
    PointTable(PropertyForm& form, PropertyForm::Locate<Points> locate, QWidget* parent = nullptr);

    // A polyline keeps 2 points, a polygon 3; the default is 2.
    void setMinPoints(std::size_t minPoints) { m_minPoints = minPoints; }
    // A measurement line keeps exactly 2: "Add point" is refused at the maximum.
    void setMaxPoints(std::size_t maxPoints) { m_maxPoints = maxPoints; }
    void setCheck(Check check) { m_check = std::move(check); }

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
    std::size_t m_minPoints = 2;  // the scene check's minimum for a polyline
    std::size_t m_maxPoints = std::size_t(-1);
    Check m_check;
    int m_serial = 0;  // each edit its own undo step
};

}  // namespace throng::editor
