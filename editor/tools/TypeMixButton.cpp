#include "editor/tools/TypeMixButton.h"

#include "editor/tools/TypeMixTable.h"

#include <QStringList>

namespace throng::editor {

TypeMixButton::TypeMixButton(std::vector<TypeShare> mix, TypeList types, Fallback fallback, QWidget* parent)
    : QToolButton(parent), m_mix(std::move(mix)), m_types(std::move(types)), m_fallback(std::move(fallback)),
      m_table(new TypeMixTable(this))
{
    setObjectName("brushMix");
    setToolTip(tr("The agent types the brush paints and their weights"));
    // A popup closes itself on a click outside, like a menu, and does not block.
    m_table->setWindowFlags(Qt::Popup);
    connect(this, &QToolButton::clicked, this, &TypeMixButton::openTable);
    connect(m_table, &TypeMixTable::mixChanged, this, [this](const std::vector<TypeShare>& m) {
        m_mix = m;
        showSummary();
        emit mixChanged(m_mix);
    });
    showSummary();
}

void TypeMixButton::openTable()
{
    m_table->setTypes(m_types(), m_mix, m_fallback());
    m_table->move(mapToGlobal(QPoint(0, height())));
    m_table->show();
    m_table->raise();
}

void TypeMixButton::showSummary()
{
    QStringList parts;
    for (const TypeShare& s : m_mix)
        parts << QStringLiteral("%1 %2").arg(QString::fromStdString(s.type)).arg(double(s.weight));
    const QString fallback = QString::fromStdString(m_fallback());
    setText(parts.isEmpty() ? (fallback.isEmpty() ? tr("(no type)") : fallback) : parts.join(QStringLiteral(" : ")));
}

}  // namespace throng::editor
