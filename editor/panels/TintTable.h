#pragma once
// The tints of the selected agent types' variation as a small colour table: each row a
// swatch with its #rrggbb name (typed, or picked with "Pick colour..." in a colour
// dialog), "Add tint" and "Remove tint". Each edit is one undo step through the
// PropertyForm; a tint placed agents still use by index is not removed.

#include "editor/panels/PropertyForm.h"

#include <glm/vec3.hpp>

#include <QWidget>

#include <vector>

class QColorDialog;
class QLabel;
class QPushButton;
class QTableWidget;

namespace throng::editor {

class TintTable : public QWidget {
    Q_OBJECT

public:
    using Tints = std::vector<glm::vec3>;
    TintTable(PropertyForm& form, QWidget* parent = nullptr);

    void refresh();
    QTableWidget* table() const { return m_table; }
    // The colour dialog "Pick colour..." opened (null before).
    QColorDialog* dialog() const { return m_dialog; }

private:
    void cellEdited(int row, int column);
    void setTint(int row, const QColor& colour);
    void change(const QString& what, const std::function<void(Tints&)>& edit);

    PropertyForm& m_form;
    QTableWidget* m_table = nullptr;
    QLabel* m_note = nullptr;
    QPushButton* m_add = nullptr;
    QPushButton* m_remove = nullptr;
    QPushButton* m_pick = nullptr;
    QColorDialog* m_dialog = nullptr;
    int m_serial = 0;
};

}  // namespace throng::editor
