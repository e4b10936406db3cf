#include "editor/brain/NodePalette.h"

#include "simcore/brain/NodeCatalogue.h"

#include <QKeyEvent>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QVBoxLayout>

#include <algorithm>
#include <map>

namespace throng::editor {

NodePalette::NodePalette(QWidget* parent) : QFrame(parent)
{
    setObjectName("nodePalette");
    setFrameShape(QFrame::StyledPanel);
    setAutoFillBackground(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    m_search = new QLineEdit(this);
    m_search->setObjectName("paletteSearch");
    m_search->setPlaceholderText(tr("Type to find a node..."));
    m_list = new QListWidget(this);
    m_list->setObjectName("paletteList");
    layout->addWidget(m_search);
    layout->addWidget(m_list);
    resize(340, 300);
    hide();
    m_search->installEventFilter(this);
    connect(m_search, &QLineEdit::textChanged, this, &NodePalette::refilter);
    connect(m_search, &QLineEdit::returnPressed, this, &NodePalette::choose);
    connect(m_list, &QListWidget::itemActivated, this, &NodePalette::choose);
}

void NodePalette::open(QPoint pos, std::vector<std::string> allowed)
{
    m_allowed = std::move(allowed);
    m_search->clear();
    refilter();
    const QSize room = parentWidget() ? parentWidget()->size() : size();
    move(std::clamp(pos.x(), 0, std::max(0, room.width() - width())),
         std::clamp(pos.y(), 0, std::max(0, room.height() - height())));
    show();
    raise();
    m_search->setFocus();
}

QStringList NodePalette::shownTypes() const
{
    QStringList out;
    for (int i = 0; i < m_list->count(); ++i)
        out << m_list->item(i)->data(Qt::UserRole).toString();
    return out;
}

void NodePalette::refilter()
{
    const QStringList words = m_search->text().toLower().split(' ', Qt::SkipEmptyParts);
    m_list->clear();
    // The exact name first, then names that start with what was typed, then the rest.
    std::vector<const sim::NodeSpec*> ranked[3];
    for (const sim::NodeSpec& spec : sim::nodeCatalogue()) {
        if (!m_allowed.empty() && std::find(m_allowed.begin(), m_allowed.end(), spec.type) == m_allowed.end())
            continue;
        const QString type = QString::fromStdString(spec.type);
        const QString haystack =
            (type + ' ' + QString::fromStdString(spec.category) + ' ' + QString::fromStdString(spec.description)).toLower();
        if (!std::all_of(words.begin(), words.end(), [&](const QString& w) { return haystack.contains(w); }))
            continue;
        const int rank = words.isEmpty() ? 2 : type == words.front() ? 0 : type.startsWith(words.front()) ? 1 : 2;
        ranked[rank].push_back(&spec);
    }
    for (const auto& group : ranked)
        for (const sim::NodeSpec* spec : group) {
            const QString type = QString::fromStdString(spec->type);
            auto* item = new QListWidgetItem(QStringLiteral("%1 — %2").arg(type, QString::fromStdString(spec->description)));
            item->setData(Qt::UserRole, type);
            item->setToolTip(QString::fromStdString(spec->description));
            m_list->addItem(item);
        }
    if (m_list->count() > 0)
        m_list->setCurrentRow(0);
}

void NodePalette::choose()
{
    QListWidgetItem* item = m_list->currentItem();
    if (!item)
        return;
    const QString type = item->data(Qt::UserRole).toString();
    hide();
    emit chosen(type);
}

bool NodePalette::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_search && event->type() == QEvent::KeyPress) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Escape) {
            hide();
            return true;
        }
        if (key->key() == Qt::Key_Down || key->key() == Qt::Key_Up) {
            const int step = key->key() == Qt::Key_Down ? 1 : -1;
            m_list->setCurrentRow(std::clamp(m_list->currentRow() + step, 0, std::max(0, m_list->count() - 1)));
            return true;
        }
    }
    return QFrame::eventFilter(watched, event);
}

QMenu* NodePalette::categoryMenu(QWidget* parent)
{
    auto* menu = new QMenu(tr("Add Node"), parent);
    menu->setObjectName("addNodeMenu");
    std::map<std::string, QMenu*> sub;
    for (const sim::NodeSpec& spec : sim::nodeCatalogue()) {
        QMenu*& m = sub[spec.category];
        if (!m)
            m = menu->addMenu(QString::fromStdString(spec.category));
        QAction* a = m->addAction(QString::fromStdString(spec.type));
        a->setToolTip(QString::fromStdString(spec.description));
        const QString type = QString::fromStdString(spec.type);
        connect(a, &QAction::triggered, this, [this, type] { emit chosen(type); });
    }
    return menu;
}

}  // namespace throng::editor
