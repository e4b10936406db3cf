#pragma once
// The behaviours of the selected agent types as a small table: behaviour, weight and
// parameters ("slowing_distance=2; range=0.2"), with a combo box to add a behaviour and
// a button to remove one. Every edit goes to all selected types as one undo step
// through the PropertyForm; invalid text is refused with a message and nothing changes.

#include "simcore/scene/Scene.h"

#include <QString>

#include <functional>
#include <string>
#include <vector>
#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace throng::editor {

class PropertyForm;

class BehaviourTable : public QWidget {
    Q_OBJECT

public:
    BehaviourTable(PropertyForm& form, QWidget* parent = nullptr);

    // Re-reads the first selected type's behaviours.
    void refresh();
    QTableWidget* table() const { return m_table; }

    // "key=1; key2=a b" for these parameters, and back; parse returns why text is bad.
    static QString paramsText(const std::vector<sim::BrainParam>& params);
    static QString parseParams(const std::string& behaviour, const QString& text, std::vector<sim::BrainParam>& out);

private:
    void cellEdited(int row, int column);
    // Applies `change` to each selected type's behaviour list as one step.
    void change(const QString& what, const std::function<void(std::vector<sim::BehaviourWeight>&)>& edit);

    PropertyForm& m_form;
    QTableWidget* m_table = nullptr;
    QLabel* m_note = nullptr;
    QComboBox* m_add = nullptr;
    QPushButton* m_remove = nullptr;
};

}  // namespace throng::editor
