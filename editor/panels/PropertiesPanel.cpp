#include "editor/panels/PropertiesPanel.h"

#include "editor/SceneDocument.h"
#include "editor/commands/ChangeValueCommand.h"
#include "editor/panels/PropertyFields.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace throng::editor {

PropertiesPanel::PropertiesPanel(SceneDocument& document, QWidget* parent) : QWidget(parent), m_document(document)
{
    setObjectName("properties");
    auto* column = new QVBoxLayout(this);
    m_title = new QLabel(this);
    m_title->setObjectName("propertiesTitle");
    m_title->setWordWrap(true);
    column->addWidget(m_title);
    m_form = new QFormLayout;
    column->addLayout(m_form);
    column->addStretch(1);
    connect(&m_document, &SceneDocument::selectionChanged, this, &PropertiesPanel::rebuild);
    connect(&m_document, &SceneDocument::sceneChanged, this, &PropertiesPanel::refreshValues);
    connect(&m_document, &SceneDocument::sceneReset, this, &PropertiesPanel::rebuild);
    rebuild();
}

void PropertiesPanel::rebuild()
{
    while (m_form->rowCount() > 0)
        m_form->removeRow(0);
    const Selection& selection = m_document.selection();
    if (selection.empty()) {
        m_title->setText(tr("Nothing selected. Pick items in the outliner or with the Select tool (Q)."));
        return;
    }
    const ItemKind kind = selection.front().kind;
    m_title->setText(selection.size() == 1 ? itemLabel(m_document.scene(), selection.front())
                                           : tr("%1 items of %2").arg(selection.size()).arg(kindTitle(kind)));
    const std::vector<PropertyField>& fields = propertyFields(kind);
    for (std::size_t f = 0; f < fields.size(); ++f) {
        auto* spin = new QDoubleSpinBox(this);
        spin->setObjectName(fields[f].key);
        spin->setRange(fields[f].min, fields[f].max);
        spin->setSingleStep(fields[f].step);
        spin->setDecimals(fields[f].decimals);
        spin->setKeyboardTracking(false);
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, f](double v) { apply(f, v); });
        m_form->addRow(fields[f].label, spin);
    }
    refreshValues();
}

void PropertiesPanel::refreshValues()
{
    const Selection& selection = m_document.selection();
    if (selection.empty() || m_applying)
        return;
    const std::vector<PropertyField>& fields = propertyFields(selection.front().kind);
    for (int row = 0; row < m_form->rowCount() && std::size_t(row) < fields.size(); ++row) {
        auto* spin = qobject_cast<QDoubleSpinBox*>(m_form->itemAt(row, QFormLayout::FieldRole)->widget());
        const QSignalBlocker block(spin);
        // Read only: locate() hands out a reference, nothing is written through it.
        auto& scene = const_cast<sim::Scene&>(m_document.scene());
        spin->setValue(double(fields[std::size_t(row)].locate(scene, selection.front().index)));
    }
}

void PropertiesPanel::apply(std::size_t field, double value)
{
    const Selection selection = m_document.selection();
    if (selection.empty())
        return;
    const PropertyField& f = propertyFields(selection.front().kind)[field];
    QUndoStack* stack = m_document.undoStack();
    m_applying = true;
    const QString text = tr("Change %1").arg(f.label);
    if (selection.size() > 1)
        stack->beginMacro(text);
    for (const SceneItem& item : selection) {
        if (item.kind != selection.front().kind)
            continue;
        const std::size_t i = item.index;
        auto locate = [i, loc = f.locate](sim::Scene& s) -> float& { return loc(s, i); };
        const QString key = QStringLiteral("property/%1/%2/%3").arg(int(item.kind)).arg(i).arg(f.key);
        stack->push(new ChangeValueCommand<float>(m_document, key, locate, float(value), text));
    }
    if (selection.size() > 1)
        stack->endMacro();
    m_applying = false;
}

}  // namespace throng::editor
