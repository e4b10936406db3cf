#include "editor/panels/TintTable.h"

#include <QColorDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

namespace throng::editor {

namespace {

PropertyForm::Locate<TintTable::Tints> tintsOf()
{
    return [](sim::Scene& s, std::size_t i) -> TintTable::Tints& { return s.agentTypes[i].variation.tints; };
}

QColor toColour(glm::vec3 c)
{
    return QColor::fromRgbF(c.r, c.g, c.b);
}

}  // namespace

TintTable::TintTable(PropertyForm& form, QWidget* parent) : QWidget(parent), m_form(form)
{
    setObjectName("tintTable");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    m_note = new QLabel(tr("(mixed)"), this);
    column->addWidget(m_note);
    m_table = new QTableWidget(0, 1, this);
    m_table->setObjectName("tints");
    m_table->setHorizontalHeaderLabels({tr("Colour")});
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setMinimumHeight(100);
    column->addWidget(m_table);
    auto* buttons = new QHBoxLayout;
    m_add = new QPushButton(tr("Add tint"), this);
    m_add->setObjectName("addTint");
    m_pick = new QPushButton(tr("Pick colour..."), this);
    m_pick->setObjectName("pickTint");
    m_pick->setToolTip(tr("Choose the selected tint's colour in a colour dialog"));
    m_remove = new QPushButton(tr("Remove tint"), this);
    m_remove->setObjectName("removeTint");
    buttons->addWidget(m_add);
    buttons->addWidget(m_pick);
    buttons->addWidget(m_remove);
    column->addLayout(buttons);

    connect(m_table, &QTableWidget::cellChanged, this, &TintTable::cellEdited, Qt::QueuedConnection);
    connect(m_add, &QPushButton::clicked, this, [this] {
        change(tr("add a tint"), [](Tints& tints) { tints.emplace_back(1.0f); });
        m_table->setCurrentCell(m_table->rowCount() - 1, 0);  // the new one, ready for Pick colour
    });
    connect(m_pick, &QPushButton::clicked, this, [this] {
        const int row = m_table->currentRow();
        if (row < 0 || !m_table->item(row, 0))
            return;
        if (!m_dialog) {
            m_dialog = new QColorDialog(this);
            m_dialog->setObjectName("tintDialog");
            m_dialog->setOption(QColorDialog::DontUseNativeDialog);  // the same dialog everywhere
        }
        m_dialog->disconnect(this);
        m_dialog->setCurrentColor(QColor(m_table->item(row, 0)->text()));
        connect(m_dialog, &QColorDialog::colorSelected, this, [this, row](const QColor& c) { setTint(row, c); });
        m_dialog->open();
    });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        const int row = m_table->currentRow();
        if (row < 0)
            return;
        // Agents that fixed a tint index at or past the removed one would lose or change it.
        const sim::Scene& s = m_form.scene();
        for (std::size_t t : m_form.indices())
            for (const sim::Agent& a : s.agents)
                if (a.type == s.agentTypes[t].name && a.tint >= row) {
                    m_form.refuse(m_remove, tr("Agent %1 uses tint %2 of %3: no tint removed. Set its tint to "
                                               "(drawn) first.")
                                                .arg(a.id)
                                                .arg(a.tint + 1)
                                                .arg(QString::fromStdString(a.type)));
                    return;
                }
        change(tr("remove tint %1").arg(row + 1), [row](Tints& tints) {
            if (std::size_t(row) < tints.size())
                tints.erase(tints.begin() + row);
        });
    });
}

void TintTable::change(const QString& what, const std::function<void(Tints&)>& edit)
{
    m_form.applyEach<Tints>(QStringLiteral("tints/%1").arg(++m_serial), what, tintsOf(), [&](const Tints& now) {
        Tints next = now;
        edit(next);
        return next;
    });
}

void TintTable::refresh()
{
    const std::optional<Tints> tints = m_form.common(tintsOf());
    const int current = m_table->currentRow();
    const QSignalBlocker block(m_table);
    m_note->setVisible(!tints);
    for (QWidget* w : std::initializer_list<QWidget*>{m_table, m_add, m_pick, m_remove})
        w->setEnabled(bool(tints));
    m_table->setRowCount(tints ? int(tints->size()) : 0);
    for (std::size_t r = 0; tints && r < tints->size(); ++r) {
        const QColor colour = toColour((*tints)[r]);
        auto* cell = new QTableWidgetItem(colour.name());
        cell->setData(Qt::DecorationRole, colour);
        m_table->setItem(int(r), 0, cell);
    }
    if (current >= 0 && current < m_table->rowCount())
        m_table->setCurrentCell(current, 0);
}

void TintTable::cellEdited(int row, int column)
{
    const QTableWidgetItem* cell = m_table->item(row, column);
    if (!cell)
        return;
    const QColor colour(cell->text().trimmed());
    if (!colour.isValid()) {
        m_form.refuse(m_table, tr("\"%1\" is not a colour (#rrggbb); the tint stays as it was.").arg(cell->text()));
        return;
    }
    setTint(row, colour);
}

void TintTable::setTint(int row, const QColor& colour)
{
    if (!colour.isValid())
        return;
    const glm::vec3 rgb(float(colour.redF()), float(colour.greenF()), float(colour.blueF()));
    change(tr("tint %1").arg(row + 1), [row, rgb](Tints& tints) {
        if (std::size_t(row) < tints.size())
            tints[std::size_t(row)] = rgb;
    });
}

}  // namespace throng::editor
