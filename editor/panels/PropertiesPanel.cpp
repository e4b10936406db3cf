#include "editor/panels/PropertiesPanel.h"

#include "editor/SceneDocument.h"
#include "editor/panels/PropertyForm.h"
#include "editor/panels/PropertyRows.h"

#include <QFormLayout>
#include <QLabel>
#include <QScrollArea>
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
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    column->addWidget(scroll, 1);
    m_fields = new QWidget(scroll);
    scroll->setWidget(m_fields);
    auto* fieldColumn = new QVBoxLayout(m_fields);
    m_form = new QFormLayout;
    // A narrow panel puts a label above its field instead of scrolling sideways.
    m_form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    fieldColumn->addLayout(m_form);
    fieldColumn->addStretch(1);
    connect(&m_document, &SceneDocument::selectionChanged, this, &PropertiesPanel::rebuild);
    connect(&m_document, &SceneDocument::sceneChanged, this, &PropertiesPanel::refreshValues);
    connect(&m_document, &SceneDocument::sceneReset, this, &PropertiesPanel::rebuild);
    rebuild();
}

void PropertiesPanel::rebuild()
{
    while (m_form->rowCount() > 0)
        m_form->removeRow(0);
    delete m_rows;
    m_rows = nullptr;
    const Selection& selection = m_document.selection();
    if (selection.empty()) {
        m_title->setText(tr("Nothing selected. Pick items in the outliner or with the Select tool (Q)."));
        return;
    }
    const ItemKind kind = selection.front().kind;
    if (selection.front().index >= itemCount(m_document.scene(), kind)) {
        m_title->setText(QString());
        return;
    }
    m_title->setText(selection.size() == 1 ? itemLabel(m_document.scene(), selection.front())
                                           : tr("%1 items of %2").arg(selection.size()).arg(kindTitle(kind)));
    m_rows = new PropertyForm(m_document, m_form, m_fields);
    connect(m_rows, &PropertyForm::problem, this, &PropertiesPanel::problem);
    addPropertyRows(*m_rows);
    m_rows->refresh();
}

void PropertiesPanel::refreshValues()
{
    if (!m_rows)
        return;
    // An undone rename or delete can leave the selection pointing past the lists.
    for (const SceneItem& item : m_document.selection())
        if (item.index >= itemCount(m_document.scene(), item.kind)) {
            rebuild();
            return;
        }
    m_title->setText(m_document.selection().size() == 1 ? itemLabel(m_document.scene(), m_document.selection().front())
                                                        : m_title->text());
    m_rows->refresh();
}

}  // namespace throng::editor
