#include "editor/panels/BehaviourTable.h"

#include "editor/panels/PropertyForm.h"
#include "simcore/world/TypeSteering.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace throng::editor {

namespace {

using Behaviours = std::vector<sim::BehaviourWeight>;

PropertyForm::Locate<Behaviours> behavioursOf()
{
    return [](sim::Scene& s, std::size_t i) -> Behaviours& { return s.agentTypes[i].behaviours; };
}

auto named(Behaviours& list, const std::string& name)
{
    return std::find_if(list.begin(), list.end(), [&](const sim::BehaviourWeight& b) { return b.behaviour == name; });
}

}  // namespace

BehaviourTable::BehaviourTable(PropertyForm& form, QWidget* parent) : QWidget(parent), m_form(form)
{
    setObjectName("behaviours");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    m_note = new QLabel(tr("None listed: the defaults for the kind run."), this);
    m_note->setWordWrap(true);
    column->addWidget(m_note);
    m_table = new QTableWidget(0, 3, this);
    m_table->setObjectName("behaviourTable");
    m_table->setHorizontalHeaderLabels({tr("Behaviour"), tr("Weight"), tr("Parameters")});
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->hide();
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setMinimumHeight(140);
    column->addWidget(m_table);
    auto* buttons = new QHBoxLayout;
    m_add = new QComboBox(this);
    m_add->setObjectName("addBehaviour");
    // Sized by a short name, not the longest behaviour's: Properties fits at 1280 x 800.
    m_add->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_add->setMinimumContentsLength(8);
    m_add->setToolTip(tr("Add a steering behaviour (weight 1) to the selected types"));
    m_remove = new QPushButton(tr("Remove"), this);
    m_remove->setObjectName("removeBehaviour");
    m_remove->setToolTip(tr("Remove the selected behaviour from the selected types"));
    buttons->addWidget(m_add, 1);
    buttons->addWidget(m_remove);
    column->addLayout(buttons);

    // Queued: the edit rebuilds the rows, which must not happen inside the item's own signal.
    connect(m_table, &QTableWidget::cellChanged, this, &BehaviourTable::cellEdited, Qt::QueuedConnection);
    connect(m_add, &QComboBox::activated, this, [this](int index) {
        if (index <= 0)
            return;
        const std::string name = m_add->itemText(index).toStdString();
        change(tr("add %1").arg(m_add->itemText(index)), [&](Behaviours& list) {
            if (named(list, name) == list.end())
                list.push_back({name, 1.0f, {}});
        });
    });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        const int row = m_table->currentRow();
        if (row < 0)
            return;
        const std::string name = m_table->item(row, 0)->text().toStdString();
        change(tr("remove %1").arg(m_table->item(row, 0)->text()),
               [&](Behaviours& list) { std::erase_if(list, [&](const auto& b) { return b.behaviour == name; }); });
    });
}

void BehaviourTable::change(const QString& what, const std::function<void(Behaviours&)>& edit)
{
    m_form.applyEach<Behaviours>("behaviours", tr("behaviours: %1").arg(what), behavioursOf(), [&](const Behaviours& now) {
        Behaviours next = now;
        edit(next);
        return next;
    });
}

void BehaviourTable::refresh()
{
    const std::vector<std::size_t> items = m_form.indices();
    if (items.empty())
        return;
    const Behaviours& list = m_form.scene().agentTypes[items.front()].behaviours;
    const QSignalBlocker block(m_table);
    m_table->setRowCount(int(list.size()));
    for (std::size_t r = 0; r < list.size(); ++r) {
        auto* name = new QTableWidgetItem(QString::fromStdString(list[r].behaviour));
        name->setFlags(name->flags() & ~Qt::ItemIsEditable);
        auto* weight = new QTableWidgetItem;
        weight->setData(Qt::EditRole, double(list[r].weight));
        m_table->setItem(int(r), 0, name);
        m_table->setItem(int(r), 1, weight);
        m_table->setItem(int(r), 2, new QTableWidgetItem(paramsText(list[r].params)));
    }
    m_note->setVisible(list.empty());
    const QSignalBlocker blockAdd(m_add);
    m_add->clear();
    m_add->addItem(tr("Add behaviour..."));
    for (const std::string& name : sim::behaviourNames())
        m_add->addItem(QString::fromStdString(name));
}

void BehaviourTable::cellEdited(int row, int column)
{
    if (row >= m_table->rowCount() || !m_table->item(row, 0) || !m_table->item(row, column))
        return;
    const std::string name = m_table->item(row, 0)->text().toStdString();
    if (column == 1) {
        const double weight = m_table->item(row, 1)->data(Qt::EditRole).toDouble();
        if (!(weight >= 0.0)) {
            emit m_form.problem(tr("A behaviour weight must be 0 or more; %1 keeps its weight.").arg(QString::fromStdString(name)));
            refresh();
            return;
        }
        change(tr("%1 weight").arg(QString::fromStdString(name)), [&](Behaviours& list) {
            if (auto it = named(list, name); it != list.end())
                it->weight = float(weight);
        });
    } else if (column == 2) {
        std::vector<sim::BrainParam> params;
        const QString why = parseParams(name, m_table->item(row, 2)->text(), params);
        if (!why.isEmpty()) {
            emit m_form.problem(tr("%1: %2; the parameters stay as they were.").arg(QString::fromStdString(name), why));
            refresh();
            return;
        }
        change(tr("%1 parameters").arg(QString::fromStdString(name)), [&](Behaviours& list) {
            if (auto it = named(list, name); it != list.end())
                it->params = params;
        });
    }
}

QString BehaviourTable::paramsText(const std::vector<sim::BrainParam>& params)
{
    QStringList parts;
    for (const sim::BrainParam& p : params) {
        QStringList values;
        if (!p.text.empty())
            values << QString::fromStdString(p.text);
        for (float n : p.numbers)
            values << QString::number(double(n));
        parts << QStringLiteral("%1=%2").arg(QString::fromStdString(p.key), values.join(' '));
    }
    return parts.join("; ");
}

QString BehaviourTable::parseParams(const std::string& behaviour, const QString& text, std::vector<sim::BrainParam>& out)
{
    out.clear();
    for (const QString& part : text.split(';', Qt::SkipEmptyParts)) {
        const QStringList keyValue = part.split('=');
        if (keyValue.size() != 2 || keyValue[0].trimmed().isEmpty())
            return tr("\"%1\" is not key=value").arg(part.trimmed());
        sim::BrainParam param;
        param.key = keyValue[0].trimmed().toStdString();
        const QStringList values = keyValue[1].split(' ', Qt::SkipEmptyParts);
        bool numbers = !values.isEmpty();
        for (const QString& v : values) {
            bool ok = false;
            const float n = v.toFloat(&ok);
            numbers = numbers && ok;
            param.numbers.push_back(n);
        }
        if (!numbers) {
            param.numbers.clear();
            param.text = keyValue[1].trimmed().toStdString();
        }
        if (const std::string why = sim::checkBehaviourParam(behaviour, param); !why.empty())
            return QString::fromStdString(why);
        out.push_back(std::move(param));
    }
    return {};
}

}  // namespace throng::editor
