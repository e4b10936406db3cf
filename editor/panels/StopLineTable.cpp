#include "editor/panels/StopLineTable.h"

#include "editor/ComboTypeAhead.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

namespace throng::editor {

namespace {

PropertyForm::Locate<StopLineTable::Lines> linesOf()
{
    return [](sim::Scene& s, std::size_t i) -> StopLineTable::Lines& { return s.trafficLights[i].stopLines; };
}

template <class List>
QStringList names(const List& list)
{
    QStringList out;
    for (const auto& item : list)
        out << QString::fromStdString(item.name);
    return out;
}

}  // namespace

StopLineTable::StopLineTable(PropertyForm& form, QWidget* parent) : QWidget(parent), m_form(form)
{
    setObjectName("stopLineTable");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    m_note = new QLabel(tr("(mixed)"), this);
    column->addWidget(m_note);
    m_table = new QTableWidget(0, 3, this);
    m_table->setObjectName("stopLines");
    m_table->setHorizontalHeaderLabels({tr("Stops on"), tr("Which"), tr("At (m)")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setMinimumHeight(120);
    column->addWidget(m_table);
    auto* buttons = new QHBoxLayout;
    m_add = new QPushButton(tr("Add stop line"), this);
    m_add->setObjectName("addStopLine");
    m_add->setToolTip(tr("Add a stop line (on the first lane at 0 m, or the first crosswalk)"));
    m_remove = new QPushButton(tr("Remove stop line"), this);
    m_remove->setObjectName("removeStopLine");
    m_remove->setToolTip(tr("Remove the selected stop line"));
    buttons->addWidget(m_add);
    buttons->addWidget(m_remove);
    column->addLayout(buttons);

    connect(m_add, &QPushButton::clicked, this, [this] {
        const sim::Scene& s = m_form.scene();
        if (s.lanes.empty() && s.crosswalks.empty()) {
            m_form.refuse(m_add, tr("There is no lane or crosswalk to stop at; draw one first."));
            return;
        }
        sim::StopLine line;
        if (!s.lanes.empty())
            line.lane = s.lanes.front().name;
        else
            line.crosswalk = s.crosswalks.front().name;
        change(QString(), tr("add a stop line"), [&](Lines& lines) { lines.push_back(line); });
    });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        const int row = m_table->currentRow();
        if (row < 0) {
            m_form.refuse(m_remove, tr("Select the stop line to remove first."));
            return;
        }
        change(QString(), tr("remove stop line %1").arg(row + 1), [&](Lines& lines) {
            if (std::size_t(row) < lines.size())
                lines.erase(lines.begin() + row);
        });
    });
}

void StopLineTable::change(const QString& key, const QString& what, const std::function<void(Lines&)>& edit)
{
    const QString merge = key.isEmpty() ? QStringLiteral("stopLines/%1").arg(++m_serial) : QStringLiteral("stopLines/") + key;
    m_form.applyEach<Lines>(merge, what, linesOf(), [&](const Lines& now) {
        Lines next = now;
        edit(next);
        return next;
    });
}

void StopLineTable::refresh()
{
    const std::optional<Lines> lines = m_form.common(linesOf());
    m_note->setVisible(!lines);
    m_table->setEnabled(bool(lines));
    m_add->setEnabled(bool(lines));
    m_remove->setEnabled(bool(lines));
    std::vector<bool> kinds;
    for (std::size_t r = 0; lines && r < lines->size(); ++r)
        kinds.push_back(!(*lines)[r].lane.empty());
    if (kinds != m_rowIsLane) {  // rebuilt only when the rows' kinds change, so a focused editor stays
        const int current = m_table->currentRow();
        m_rowIsLane = kinds;
        m_table->setRowCount(0);
        m_table->setRowCount(int(kinds.size()));
        for (std::size_t r = 0; r < kinds.size(); ++r)
            buildRow(int(r), (*lines)[r]);
        if (current >= 0 && current < m_table->rowCount())
            m_table->setCurrentCell(current, 0);
    }
    for (std::size_t r = 0; r < kinds.size(); ++r)
        showRow(int(r), (*lines)[r]);
}

void StopLineTable::buildRow(int row, const sim::StopLine& line)
{
    const bool lane = !line.lane.empty();
    auto* kind = new QComboBox;
    kind->setObjectName(QStringLiteral("stopKind%1").arg(row));
    kind->addItems({tr("Lane"), tr("Crosswalk")});
    keepTypedLetters(kind);
    connect(kind, &QComboBox::activated, this, [this, row](int index) { setKind(row, index); });
    auto* target = new QComboBox;
    target->setObjectName(QStringLiteral("stopTarget%1").arg(row));
    keepTypedLetters(target);
    connect(target, &QComboBox::activated, this, [this, row, target](int index) { setTarget(row, target->itemText(index)); });
    m_table->setCellWidget(row, 0, kind);
    m_table->setCellWidget(row, 1, target);
    if (!lane) {
        m_table->setItem(row, 2, new QTableWidgetItem(tr("both ends")));
        m_table->item(row, 2)->setFlags(Qt::ItemIsEnabled);
        return;
    }
    auto* at = new QDoubleSpinBox;
    at->setObjectName(QStringLiteral("stopAt%1").arg(row));
    at->setRange(0.0, 1e5);
    at->setDecimals(1);
    at->setSingleStep(1.0);
    at->setKeyboardTracking(false);
    connect(at, &QDoubleSpinBox::valueChanged, this, [this, row](double v) {
        change(QStringLiteral("at/%1").arg(row), tr("stop line %1 distance").arg(row + 1), [&](Lines& lines) {
            if (std::size_t(row) < lines.size())
                lines[std::size_t(row)].atM = float(v);
        });
    });
    m_table->setCellWidget(row, 2, at);
}

void StopLineTable::showRow(int row, const sim::StopLine& line)
{
    const bool lane = !line.lane.empty();
    auto* kind = static_cast<QComboBox*>(m_table->cellWidget(row, 0));
    auto* target = static_cast<QComboBox*>(m_table->cellWidget(row, 1));
    const QSignalBlocker blockKind(kind), blockTarget(target);
    kind->setCurrentIndex(lane ? 0 : 1);
    target->clear();
    target->addItems(lane ? names(m_form.scene().lanes) : names(m_form.scene().crosswalks));
    const QString name = QString::fromStdString(lane ? line.lane : line.crosswalk);
    if (target->findText(name) < 0)
        target->addItem(name);
    target->setCurrentText(name);
    if (auto* at = qobject_cast<QDoubleSpinBox*>(m_table->cellWidget(row, 2))) {
        const QSignalBlocker blockAt(at);
        at->setValue(line.atM);
    }
}

// A switch of kind takes the first lane or crosswalk: a stop line names exactly one.
void StopLineTable::setKind(int row, int kind)
{
    const sim::Scene& s = m_form.scene();
    const bool lane = kind == 0;
    if (lane ? s.lanes.empty() : s.crosswalks.empty()) {
        m_form.refuse(m_table->cellWidget(row, 0),
                      lane ? tr("There is no lane to stop on; the stop line stays as it is.")
                           : tr("There is no crosswalk to stop at; the stop line stays as it is."));
        return;
    }
    change(QString(), tr("stop line %1 kind").arg(row + 1), [&](Lines& lines) {
        if (std::size_t(row) >= lines.size() || lines[std::size_t(row)].lane.empty() != lane)
            return;
        sim::StopLine& line = lines[std::size_t(row)];
        line = sim::StopLine{};
        (lane ? line.lane : line.crosswalk) = lane ? s.lanes.front().name : s.crosswalks.front().name;
    });
}

void StopLineTable::setTarget(int row, const QString& name)
{
    change(QString(), tr("stop line %1 target").arg(row + 1), [&](Lines& lines) {
        if (std::size_t(row) >= lines.size())
            return;
        sim::StopLine& line = lines[std::size_t(row)];
        (line.lane.empty() ? line.crosswalk : line.lane) = name.toStdString();
    });
}

}  // namespace throng::editor
