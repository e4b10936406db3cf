#include "editor/layout/LayoutPanel.h"

#include "editor/Icons.h"
#include "editor/commands/DeleteItemsCommand.h"
#include "editor/layout/LayoutEdits.h"
#include "editor/layout/LayoutText.h"

#include <QAction>
#include <QCheckBox>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QToolBar>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace throng::editor {

namespace {

constexpr int kSpanFrameRole = Qt::UserRole + 1;
constexpr int kSpanAgentRole = Qt::UserRole + 2;

// What the rows show: the operations and their switches, names and amounts, and the names
// of the groups and types they select.
bool showsChange(const SceneChange& change)
{
    return change.touches(ItemKind::LayoutOp) || change.has(SceneField::Name);
}

}  // namespace

LayoutPanel::LayoutPanel(SceneDocument& document, QWidget* parent) : QWidget(parent), m_document(document)
{
    setObjectName("layoutPanel");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(2);

    auto* bar = new QToolBar(this);
    bar->setObjectName("layoutBar");
    bar->setIconSize(QSize(18, 18));
    auto* addMenu = new QMenu(this);
    addMenu->setObjectName("layoutAddMenu");
    addMenu->setToolTipsVisible(true);
    const char* tips[] = {
        QT_TR_NOOP("Move the selected agents' trajectories by an offset (set it in Properties)"),
        QT_TR_NOOP("Turn the selected agents' trajectories about their centre"),
        QT_TR_NOOP("Start the selected agents one second later (hold their first pose until then)"),
        QT_TR_NOOP("Reflect the selected agents' trajectories across a line"),
        QT_TR_NOOP("Remove the selected agents from the shown frame on (entirely from frame 0)"),
        QT_TR_NOOP("Spread the selected agents apart about their centre, frame by frame"),
        QT_TR_NOOP("Add a copy of each selected agent a metre east, with an id and look of its own"),
        QT_TR_NOOP("Show the selected agents with another look, tint or agent type (set it in Properties)"),
        QT_TR_NOOP("Play another clip (an action such as wave or sit) over the selected agents' frames"),
        QT_TR_NOOP("Nudge apart the bodies the operations above pushed into each other (the selected agents', or "
                   "everyone's with nothing selected); the agents the edits did not move stay where they are"),
    };
    static_assert(std::size(tips) == sim::kLayoutKindCount);
    for (int k = 0; k < sim::kLayoutKindCount; ++k) {
        const auto kind = sim::LayoutKind(k);
        QAction* add = addMenu->addAction(layoutKindTitle(kind));
        add->setObjectName(QStringLiteral("layoutAdd%1").arg(QString(sim::toString(kind))));
        add->setToolTip(tr(tips[k]));
        connect(add, &QAction::triggered, this, [this, kind] { addOperation(kind); });
        m_add[k] = add;
    }
    auto* addButton = new QToolButton(bar);
    addButton->setObjectName("layoutAddButton");
    addButton->setIcon(themeIcon("action-layout-add"));
    addButton->setText(tr("Add"));
    addButton->setToolTip(tr("Add a layout operation for the selected agents, groups or types"));
    addButton->setMenu(addMenu);
    addButton->setPopupMode(QToolButton::InstantPopup);
    bar->addWidget(addButton);
    m_up = bar->addAction(themeIcon("action-move-up"), tr("Earlier"), this, [this] { moveSelected(-1); });
    m_up->setObjectName("layoutUp");
    m_up->setToolTip(tr("Apply the selected operation one step earlier (Ctrl+Up)"));
    m_up->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Up));
    m_up->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_down = bar->addAction(themeIcon("action-move-down"), tr("Later"), this, [this] { moveSelected(+1); });
    m_down->setObjectName("layoutDown");
    m_down->setToolTip(tr("Apply the selected operation one step later (Ctrl+Down)"));
    m_down->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Down));
    m_down->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_remove = bar->addAction(themeIcon("action-delete"), tr("Remove"), this, &LayoutPanel::removeSelected);
    m_remove->setObjectName("layoutRemove");
    // Delete is Edit > Delete's, which removes the selected operations as any selected item.
    m_remove->setToolTip(tr("Remove the selected operation (Delete)"));
    // Their keys work wherever the focus is in the panel (the list, mostly).
    QWidget::addAction(m_up);
    QWidget::addAction(m_down);
    column->addWidget(bar);

    m_clickedOnly = new QCheckBox(tr("Only the clicked agent"), this);
    m_clickedOnly->setObjectName("layoutClickedOnly");
    m_clickedOnly->setToolTip(tr("New operations take only the agent last clicked in the viewport, not the whole "
                                 "selection (a group's member, say)"));
    column->addWidget(m_clickedOnly);

    m_list = new QListWidget(this);
    m_list->setObjectName("layoutList");
    // Narrow as the column is: each row ends in "…", its tooltip says it all.
    m_list->setTextElideMode(Qt::ElideRight);
    m_list->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_list->setToolTip(tr("The layout operations, applied top to bottom to the recorded crowd; untick one to see the "
                          "crowd without it. Select one to edit it in Properties."));
    column->addWidget(m_list, 2);

    auto* checkRow = new QHBoxLayout;
    m_checkLabel = new QLabel(this);
    m_checkLabel->setObjectName("layoutCheckLabel");
    m_checkLabel->setWordWrap(true);
    checkRow->addWidget(m_checkLabel, 1);
    m_checkButton = new QPushButton(tr("Check"), this);
    m_checkButton->setObjectName("layoutCheckButton");
    m_checkButton->setToolTip(tr("Look through the recorded frames for bodies the layout edits pushed into each "
                                 "other and steps they made through walls (on a large shot this takes a few "
                                 "seconds, so it waits to be asked)"));
    connect(m_checkButton, &QPushButton::clicked, this, &LayoutPanel::checkRequested);
    checkRow->addWidget(m_checkButton, 0, Qt::AlignTop);
    column->addLayout(checkRow);
    m_clashes = new QTreeWidget(this);
    m_clashes->setObjectName("layoutClashes");
    m_clashes->setRootIsDecorated(false);
    m_clashes->setHeaderLabels({tr("Frames"), tr("Agent"), tr("With"), tr("Deepest")});
    // Narrow enough for the right column's default width: the columns share what there is.
    m_clashes->header()->setStretchLastSection(true);
    m_clashes->header()->setMinimumSectionSize(36);
    m_clashes->header()->setDefaultSectionSize(64);
    m_clashes->setToolTip(tr("What the layout edits broke: agents that now overlap, or step through a wall. "
                             "Double-click (or Enter) to go to the first frame and click the agent."));
    column->addWidget(m_clashes, 1);
    showCheck({});

    m_list->installEventFilter(this);
    connect(m_list, &QListWidget::itemSelectionChanged, this, &LayoutPanel::takeSelection);
    connect(m_list, &QListWidget::itemChanged, this, &LayoutPanel::rowChanged);
    connect(m_clashes, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* row) {
        emit clashRequested(std::size_t(row->data(0, kSpanFrameRole).toULongLong()),
                            sim::AgentId(row->data(0, kSpanAgentRole).toUInt()));
    });
    connect(&m_document, &SceneDocument::sceneReset, this, &LayoutPanel::rebuild);
    connect(&m_document, &SceneDocument::sceneChanged, this, [this](const SceneChange& change) {
        if (showsChange(change))
            rebuild();
    });
    connect(&m_document, &SceneDocument::selectionChanged, this, &LayoutPanel::showSelection);
    rebuild();
}

LayoutPanel::~LayoutPanel()
{
    m_list->removeEventFilter(this);
    m_list->blockSignals(true);
    m_clashes->blockSignals(true);
}

bool LayoutPanel::eventFilter(QObject* watched, QEvent* event)
{
    // Space in the list switches the current operation, as in any list of check boxes,
    // rather than playing (the window's shortcut) while the list has the focus.
    if (watched == m_list && event->type() == QEvent::ShortcutOverride &&
        static_cast<QKeyEvent*>(event)->key() == Qt::Key_Space && m_list->currentItem()) {
        event->accept();
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

void LayoutPanel::rebuild()
{
    const QSignalBlocker block(m_list);
    m_updating = true;
    m_list->clear();
    const sim::Scene& scene = m_document.scene();
    for (std::size_t i = 0; i < scene.layout.ops.size(); ++i) {
        const sim::LayoutOp& op = scene.layout.ops[i];
        auto* row = new QListWidgetItem(QStringLiteral("%1 — %2").arg(itemLabel(scene, {ItemKind::LayoutOp, i}),
                                                                       layoutSummary(op)),
                                        m_list);
        row->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable);
        row->setCheckState(op.enabled ? Qt::Checked : Qt::Unchecked);
        row->setToolTip(layoutSummary(op));
    }
    m_updating = false;
    showSelection();
}

void LayoutPanel::showSelection()
{
    const QSignalBlocker block(m_list);
    m_list->clearSelection();
    for (const SceneItem& item : m_document.selection())
        if (item.kind == ItemKind::LayoutOp && int(item.index) < m_list->count()) {
            m_list->item(int(item.index))->setSelected(true);
            m_list->setCurrentRow(int(item.index), QItemSelectionModel::NoUpdate);
        }
    updateActions();
}

void LayoutPanel::takeSelection()
{
    Selection selection;
    for (int r = 0; r < m_list->count(); ++r)
        if (m_list->item(r)->isSelected())
            selection.push_back({ItemKind::LayoutOp, std::size_t(r)});
    if (!selection.empty())
        m_document.setSelection(selection);
    updateActions();
}

void LayoutPanel::rowChanged(QListWidgetItem* row)
{
    if (m_updating)
        return;
    const int r = m_list->row(row);
    const sim::Scene& scene = m_document.scene();
    if (r < 0 || std::size_t(r) >= scene.layout.ops.size())
        return;
    const bool on = row->checkState() == Qt::Checked;
    if (scene.layout.ops[std::size_t(r)].enabled == on)
        return;
    sim::LayoutLayer after = scene.layout;
    after.ops[std::size_t(r)].enabled = on;
    const QString label = itemLabel(scene, {ItemKind::LayoutOp, std::size_t(r)});
    m_document.undoStack()->push(changeLayoutCommand(
        m_document, std::move(after), on ? tr("Turn on %1").arg(label) : tr("Turn off %1").arg(label)));
}

int LayoutPanel::selectedRow() const
{
    const QList<QListWidgetItem*> rows = m_list->selectedItems();
    return rows.size() == 1 ? m_list->row(rows.front()) : -1;
}

void LayoutPanel::updateActions()
{
    const int r = selectedRow();
    m_up->setEnabled(r > 0);
    m_down->setEnabled(r >= 0 && r + 1 < m_list->count());
    m_remove->setEnabled(!m_list->selectedItems().isEmpty());
}

bool LayoutPanel::addOperation(sim::LayoutKind kind)
{
    const LayoutContext context = m_context ? m_context() : LayoutContext{};
    const sim::Scene& scene = m_document.scene();
    std::optional<std::uint32_t> clicked;
    if (m_clickedOnly->isChecked())
        clicked = context.clicked;
    sim::AgentSelector agents = selectorFor(scene, m_document.selection(), clicked);
    // A resolve without agents resolves everyone the operations before it moved.
    if (agents == sim::AgentSelector{} && kind != sim::LayoutKind::Resolve) {
        emit problem(m_clickedOnly->isChecked()
                         ? tr("No layout operation added: click an agent in the viewport first.")
                         : tr("No layout operation added: select agents, groups or agent types first (in the "
                              "viewport or the Outliner)."));
        return false;
    }
    const glm::vec2 centre = context.centreOf ? context.centreOf(agents) : glm::vec2(0.0f);
    sim::LayoutLayer after = scene.layout;
    after.ops.push_back(newLayoutOp(kind, std::move(agents), scene.layout, context.frame, context.fps, centre));
    const QString name = QString::fromStdString(after.ops.back().name);
    m_document.undoStack()->push(changeLayoutCommand(m_document, std::move(after), tr("Add %1").arg(name)));
    m_document.setSelection({{ItemKind::LayoutOp, m_document.scene().layout.ops.size() - 1}});
    return true;
}

void LayoutPanel::moveSelected(int by)
{
    const int r = selectedRow();
    const sim::Scene& scene = m_document.scene();
    const int to = r + by;
    if (r < 0 || to < 0 || std::size_t(to) >= scene.layout.ops.size())
        return;
    sim::LayoutLayer after = scene.layout;
    std::swap(after.ops[std::size_t(r)], after.ops[std::size_t(to)]);
    const QString label = itemLabel(scene, {ItemKind::LayoutOp, std::size_t(r)});
    m_document.undoStack()->push(changeLayoutCommand(
        m_document, std::move(after), by < 0 ? tr("Apply %1 earlier").arg(label) : tr("Apply %1 later").arg(label)));
    m_document.setSelection({{ItemKind::LayoutOp, std::size_t(to)}});
}

void LayoutPanel::removeSelected()
{
    Selection ops;
    for (const SceneItem& item : m_document.selection())
        if (item.kind == ItemKind::LayoutOp)
            ops.push_back(item);
    if (ops.empty())
        return;
    auto* command = new DeleteItemsCommand(m_document, ops);
    m_document.setSelection({});
    m_document.undoStack()->push(command);
}

void LayoutPanel::showCheckSkipped(std::size_t agentFrames)
{
    m_clashes->clear();
    m_clashes->hide();
    m_checkLabel->setText(tr("The shot is large (%L1 agent-frames): press Check to look for what the layout edits "
                             "broke.").arg(qulonglong(agentFrames)));
}

void LayoutPanel::showCheck(const sim::LayoutCheck& check)
{
    m_clashes->clear();
    const std::string text = sim::describe(check);
    if (text.empty()) {
        m_checkLabel->setText(m_document.scene().layout.ops.empty()
                                  ? tr("No layout edits.")
                                  : tr("The layout edits make no overlaps or wall crossings."));
        m_clashes->hide();
        return;
    }
    m_checkLabel->setText(tr("The layout edits make %1.").arg(QString::fromStdString(text)));
    for (const sim::LayoutClashSpan& span : sim::clashSpans(check)) {
        const QString frames = span.first == span.last ? QString::number(span.first)
                                                       : QStringLiteral("%1–%2").arg(span.first).arg(span.last);
        const QString with = span.other ? tr("agent %1").arg(span.other)
                                        : tr("through %1").arg(QString::fromStdString(span.wall));
        const QString deepest = span.other ? tr("%1 m").arg(double(span.deepestM), 0, 'f', 2) : QString();
        auto* row = new QTreeWidgetItem(m_clashes, {frames, QString::number(span.agent), with, deepest});
        row->setData(0, kSpanFrameRole, qulonglong(span.first));
        row->setData(0, kSpanAgentRole, uint(span.agent));
    }
    m_clashes->show();
}

}  // namespace throng::editor
