#include "editor/panels/PointTable.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace throng::editor {

namespace {
constexpr double kLimitM = 1e5;  // the panel's coordinate range, as the number fields
}  // namespace

PointTable::PointTable(PropertyForm& form, PropertyForm::Locate<Points> locate, QWidget* parent)
    : QWidget(parent), m_form(form), m_locate(std::move(locate))
{
    setObjectName("pointTable");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    m_note = new QLabel(tr("(mixed)"), this);
    column->addWidget(m_note);
    m_table = new QTableWidget(0, 2, this);
    m_table->setObjectName("points");
    m_table->setHorizontalHeaderLabels({tr("X (m)"), tr("Z (m)")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setMinimumHeight(140);
    column->addWidget(m_table);
    auto* buttons = new QHBoxLayout;
    m_add = new QPushButton(tr("Add point"), this);
    m_add->setObjectName("addPoint");
    m_add->setToolTip(tr("Insert a point after the selected one (halfway to the next)"));
    m_remove = new QPushButton(tr("Remove point"), this);
    m_remove->setObjectName("removePoint");
    m_remove->setToolTip(tr("Remove the selected point (a line keeps two, an area three)"));
    buttons->addWidget(m_add);
    buttons->addWidget(m_remove);
    column->addLayout(buttons);
    // Queued: the edit rebuilds the rows, which must not happen inside the item's own signal.
    connect(m_table, &QTableWidget::cellChanged, this, &PointTable::cellEdited, Qt::QueuedConnection);
    connect(m_add, &QPushButton::clicked, this, &PointTable::addPoint);
    connect(m_remove, &QPushButton::clicked, this, &PointTable::removePoint);
}

void PointTable::change(const QString& what, const std::function<void(Points&)>& edit)
{
    if (m_check) {
        auto& scene = const_cast<sim::Scene&>(m_form.scene());  // read only
        for (std::size_t i : m_form.indices()) {
            Points next = m_locate(scene, i);
            edit(next);
            if (const QString why = m_check(next); !why.isEmpty()) {
                m_form.refuse(m_table, why);
                return;
            }
        }
    }
    m_form.applyEach<Points>(QStringLiteral("points/%1").arg(++m_serial), what, m_locate, [&](const Points& now) {
        Points next = now;
        edit(next);
        return next;
    });
}

void PointTable::refresh()
{
    const std::optional<Points> points = m_form.common(m_locate);
    const int current = m_table->currentRow();
    const QSignalBlocker block(m_table);
    m_note->setVisible(!points);
    m_table->setEnabled(bool(points));
    m_add->setEnabled(bool(points));
    m_remove->setEnabled(bool(points));
    m_table->setRowCount(points ? int(points->size()) : 0);
    for (std::size_t r = 0; points && r < points->size(); ++r)
        for (int c = 0; c < 2; ++c) {
            auto* cell = new QTableWidgetItem;
            cell->setData(Qt::EditRole, double((*points)[r][c]));
            m_table->setItem(int(r), c, cell);
        }
    if (current >= 0 && current < m_table->rowCount())
        m_table->setCurrentCell(current, 0);
}

void PointTable::cellEdited(int row, int column)
{
    const QTableWidgetItem* cell = m_table->item(row, column);
    if (!cell)
        return;
    bool ok = false;
    const double value = cell->data(Qt::EditRole).toDouble(&ok);
    if (!ok || !std::isfinite(value) || std::abs(value) > kLimitM) {
        const QString why = tr("A point's coordinate must be a number from %1 to %2 m; the point stays where it was.")
                                .arg(-kLimitM)
                                .arg(kLimitM);
        m_form.refuse(m_table, why);
        return;
    }
    m_table->setToolTip(QString());
    change(tr("point %1").arg(row + 1), [&](Points& points) {
        if (std::size_t(row) < points.size())
            points[std::size_t(row)][column] = float(value);
    });
}

void PointTable::addPoint()
{
    const int row = m_table->currentRow() >= 0 ? m_table->currentRow() : m_table->rowCount() - 1;
    if (row < 0)
        return;
    if (std::size_t(m_table->rowCount()) >= m_maxPoints) {
        m_form.refuse(m_add, tr("This line has its %1 points, its ends; none was added.").arg(m_maxPoints));
        return;
    }
    change(tr("add a point"), [&](Points& points) {
        const std::size_t at = std::min(std::size_t(row), points.size() - 1);
        const glm::vec2 p = points[at];
        const glm::vec2 next = at + 1 < points.size() ? 0.5f * (p + points[at + 1])
                               : at > 0              ? p + (p - points[at - 1])
                                                     : p + glm::vec2(1.0f, 0.0f);
        points.insert(points.begin() + std::ptrdiff_t(at + 1), next);
    });
    m_table->setCurrentCell(row + 1, 0);
}

void PointTable::removePoint()
{
    const int row = m_table->currentRow();
    if (row < 0)
        return;
    if (std::size_t(m_table->rowCount()) <= m_minPoints) {
        m_form.refuse(m_remove, m_minPoints > 2 ? tr("An area needs at least %1 corners; none was removed.").arg(m_minPoints)
                                                : tr("A line needs at least %1 points; none was removed.").arg(m_minPoints));
        return;
    }
    change(tr("remove point %1").arg(row + 1), [&](Points& points) {
        if (std::size_t(row) < points.size() && points.size() > m_minPoints)
            points.erase(points.begin() + row);
    });
    m_table->setCurrentCell(std::min(row, m_table->rowCount() - 1), 0);
}

}  // namespace throng::editor
