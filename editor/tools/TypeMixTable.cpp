#include "editor/tools/TypeMixTable.h"

#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace throng::editor {

TypeMixTable::TypeMixTable(QWidget* parent) : QFrame(parent), m_table(new QTableWidget(0, 2, this))
{
    setObjectName("typeMixTable");
    setFrameShape(QFrame::StyledPanel);
    m_table->setObjectName("typeMix");
    m_table->setHorizontalHeaderLabels({tr("Type"), tr("Weight")});
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->setToolTip(tr("The brush paints each type in proportion to its weight; all 0 paints the first "
                           "pedestrian type"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(m_table);
}

void TypeMixTable::setTypes(const std::vector<std::string>& names, const std::vector<TypeShare>& mix,
                            const std::string& fallback)
{
    // The table deletes replaced cell widgets later: until then they must not answer to
    // their names or report a mix.
    for (int row = 0; row < m_table->rowCount(); ++row)
        if (QWidget* old = m_table->cellWidget(row, 1)) {
            old->blockSignals(true);
            old->setObjectName(QString());
        }
    m_table->setRowCount(0);
    m_table->setRowCount(int(names.size()));
    for (int row = 0; row < int(names.size()); ++row) {
        const std::string& name = names[std::size_t(row)];
        auto* item = new QTableWidgetItem(QString::fromStdString(name));
        m_table->setItem(row, 0, item);
        auto it = std::find_if(mix.begin(), mix.end(), [&](const TypeShare& s) { return s.type == name; });
        const double weight = it != mix.end() ? double(it->weight) : mix.empty() && name == fallback ? 1.0 : 0.0;
        auto* spin = new QDoubleSpinBox(m_table);
        spin->setObjectName(QStringLiteral("mixWeight_%1").arg(QString::fromStdString(name)));
        spin->setRange(0.0, 1000.0);
        spin->setDecimals(1);
        spin->setValue(weight);
        spin->setKeyboardTracking(false);
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this] { emit mixChanged(this->mix()); });
        m_table->setCellWidget(row, 1, spin);
    }
    m_table->resizeRowsToContents();
    const int rowsHeight = m_table->verticalHeader()->length() + m_table->horizontalHeader()->height();
    m_table->setMinimumHeight(std::min(rowsHeight + 4, 320));
    m_table->setMinimumWidth(260);
    adjustSize();
}

std::vector<TypeShare> TypeMixTable::mix() const
{
    std::vector<TypeShare> out;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const auto* spin = qobject_cast<const QDoubleSpinBox*>(m_table->cellWidget(row, 1));
        if (spin && spin->value() > 0.0)
            out.push_back({m_table->item(row, 0)->text().toStdString(), float(spin->value())});
    }
    return out;
}

}  // namespace throng::editor
