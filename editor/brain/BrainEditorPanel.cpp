#include "editor/brain/BrainEditorPanel.h"

#include "editor/brain/AutoLayout.h"
#include "editor/brain/BrainGraphModel.h"
#include "editor/brain/BrainLibrary.h"
#include "editor/brain/BrainLinkRules.h"
#include "editor/brain/BrainMacro.h"
#include "editor/brain/BrainScene.h"
#include "editor/brain/BrainView.h"
#include "editor/brain/NodePalette.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QComboBox>
#include <QFileInfo>
#include <QMenu>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QMouseEvent>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

namespace throng::editor {

BrainEditorPanel::BrainEditorPanel(SceneDocument& document, SimulationController& simulation, Viewport* viewport,
                                   QWidget* parent)
    : QWidget(parent), m_document(document), m_simulation(simulation), m_viewport(viewport)
{
    setObjectName("brainEditor");
    m_model = new BrainGraphModel(document, this);
    m_scene = new BrainScene(*m_model, this);
    m_view = new BrainView(m_scene, this);
    m_palette = new NodePalette(m_view);
    m_status = new QLabel(this);
    m_status->setObjectName("brainStatus");
    m_status->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    // The two rows of controls scroll sideways in a narrow dock instead of widening the
    // whole window.
    QWidget* bar = createBar();
    auto* barScroll = new QScrollArea(this);
    barScroll->setWidget(bar);
    barScroll->setWidgetResizable(true);
    barScroll->setFrameShape(QFrame::NoFrame);
    barScroll->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    barScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    barScroll->setFixedHeight(bar->sizeHint().height() + barScroll->horizontalScrollBar()->sizeHint().height());
    layout->addWidget(barScroll);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_status);

    connect(m_model, &BrainGraphModel::graphChanged, this, [this] {
        refreshList();
        recompile();
    });
    auto rescene = [this] {
        refreshList();  // agent types and brain names may change without the shown graph
    };
    connect(&m_document, &SceneDocument::sceneChanged, this, [rescene](const SceneChange& change) {
        if (change.touches(ItemKind::Brain) || change.touches(ItemKind::AgentType))
            rescene();
    });
    connect(&m_document, &SceneDocument::sceneReset, this, rescene);
    connect(&m_document, &SceneDocument::sceneReset, this, [this] {
        pickAgent(-1);
        m_view->frameAll();
    });
    connect(m_palette, &NodePalette::chosen, this, &BrainEditorPanel::addFromPalette);
    connect(m_view, &BrainView::paletteRequested, this, [this](QPoint at) {
        m_pending.reset();
        m_paletteScenePos = m_view->mapToScene(at);
        m_palette->open(at);
    });
    connect(m_view, &BrainView::copyRequested, this, &BrainEditorPanel::copySelection);
    connect(m_view, &BrainView::pasteRequested, this, &BrainEditorPanel::paste);
    connect(m_view, &BrainView::duplicateRequested, this, &BrainEditorPanel::duplicateSelection);
    connect(m_view, &BrainView::collapseRequested, this, &BrainEditorPanel::collapseSelection);
    connect(m_view, &BrainView::expandRequested, this, &BrainEditorPanel::expandSelection);
    connect(m_scene, &BrainScene::linkRefused, this, [this](const QString& why) { setStatus(tr("Link refused: %1").arg(why), true); });
    connect(m_scene, &BrainScene::linkAdded, this, [this] { setStatus(tr("Linked."), false); });
    connect(m_scene, &BrainScene::paramRefused, this, [this](const QString& why) { setStatus(why, true); });
    connect(m_scene, &BrainScene::linkDroppedOnEmpty, this,
            [this](sim::NodeId node, int port, bool fromInput, sim::PortKind kind, QPointF pos) {
                m_pending = PendingLink{node, port, fromInput};
                m_paletteScenePos = pos;
                m_palette->open(m_view->mapFromScene(pos), compatibleNodeTypes(kind, fromInput));
            });
    connect(&m_simulation, &SimulationController::frameChanged, this, &BrainEditorPanel::updateLive);
    connect(&m_simulation, &SimulationController::brainValuesChanged, this, &BrainEditorPanel::updateLive);
    if (m_viewport) {
        m_viewport->installEventFilter(this);
        // An agent clicked in the viewport while the brain editor is open is inspected.
        connect(m_viewport, &Viewport::agentPicked, this, [this](sim::AgentId id) {
            if (!isVisible())
                return;
            const auto agents = m_simulation.cache().agents();
            for (std::size_t i = 0; i < agents.size(); ++i)
                if (agents[i].id == id)
                    pickAgent(std::ptrdiff_t(i));
        });
    }
    refreshList();
    recompile();
}

// The viewport may go first (the main window deletes its central widget before its
// docks); Qt drops an event filter whose object is deleted, so there is nothing to undo.
BrainEditorPanel::~BrainEditorPanel() = default;

QWidget* BrainEditorPanel::createBar()
{
    auto* bar = new QWidget(this);
    auto* rows = new QVBoxLayout(bar);
    rows->setContentsMargins(0, 0, 0, 0);
    auto* top = new QHBoxLayout;
    auto* bottom = new QHBoxLayout;
    rows->addLayout(top);
    rows->addLayout(bottom);
    auto button = [&](QHBoxLayout* row, const QString& text, const QString& name, const QString& tip, auto slot) {
        auto* b = new QToolButton(bar);
        b->setText(text);
        b->setObjectName(name);
        b->setToolTip(tip);
        row->addWidget(b);
        connect(b, &QToolButton::clicked, this, slot);
        return b;
    };
    m_brains = new QComboBox(bar);
    m_brains->setObjectName("brainList");
    m_brains->setToolTip(tr("The brain shown in the graph"));
    top->addWidget(m_brains, 1);
    connect(m_brains, &QComboBox::activated, this, &BrainEditorPanel::showBrain);
    button(top, tr("New"), "newBrainButton", tr("Add an empty brain to the scene"), &BrainEditorPanel::newBrain);
    button(top, tr("Rename"), "renameBrainButton", tr("Rename the brain (agent types follow)"), [this] {
        bool ok = false;
        const QString name = QInputDialog::getText(this, tr("Rename Brain"), tr("Name:"), QLineEdit::Normal,
                                                   m_brains->currentText(), &ok);
        if (ok)
            renameBrain(name);
    });
    button(top, tr("Duplicate"), "duplicateBrainButton", tr("Copy the brain under a new name"), &BrainEditorPanel::duplicateBrain);
    button(top, tr("Delete"), "deleteBrainButton", tr("Remove the brain from the scene"), &BrainEditorPanel::deleteBrain);
    button(top, tr("Import..."), "importBrainButton", tr("Add a brain from a .brain.yaml file"), [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Import Brain"), {}, tr("Brains (*.brain.yaml *.yaml)"));
        if (!path.isEmpty())
            importBrain(path);
    });
    button(top, tr("Export..."), "exportBrainButton", tr("Write the brain to a .brain.yaml file"), [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export Brain"), m_brains->currentText() + ".brain.yaml",
                                                          tr("Brains (*.brain.yaml)"));
        if (!path.isEmpty())
            exportBrain(path);
    });
    auto* add = new QToolButton(bar);
    add->setText(tr("Add Node"));
    add->setObjectName("addNodeButton");
    add->setToolTip(tr("Add a node by category (or press Tab over the graph and type)"));
    add->setPopupMode(QToolButton::InstantPopup);
    add->setMenu(m_palette->categoryMenu(add));
    connect(add->menu(), &QMenu::aboutToShow, this, [this] {
        m_pending.reset();
        m_paletteScenePos = m_view->mapToScene(m_view->viewport()->rect().center());
    });
    bottom->addWidget(add);
    button(bottom, tr("Layout"), "layoutBrainButton", tr("Arrange the nodes in columns by their inputs"), [this] {
        sim::BrainGraph g = m_model->graph();
        autoLayout(g);
        m_model->replace(g, tr("Lay out brain"));
        m_view->frameAll();
    });
    m_types = new QComboBox(bar);
    m_types->setObjectName("agentTypeList");
    m_types->setToolTip(tr("Agent type to run the shown brain"));
    bottom->addWidget(m_types, 1);
    button(bottom, tr("Assign"), "assignBrainButton", tr("The chosen agent type runs the shown brain"),
           [this] { assignToType(m_types->currentIndex()); });
    m_pick = button(bottom, tr("Pick Agent"), "pickAgentButton",
                    tr("Click an agent in the viewport to see its brain's values live"), &BrainEditorPanel::armViewportPick);
    m_pick->setCheckable(true);
    m_agent = new QSpinBox(bar);
    m_agent->setObjectName("liveAgent");
    m_agent->setRange(-1, 1 << 30);
    m_agent->setValue(-1);
    m_agent->setSpecialValueText(tr("nobody"));
    m_agent->setToolTip(tr("The agent whose node values the graph shows"));
    bottom->addWidget(m_agent);
    connect(m_agent, &QSpinBox::valueChanged, this, [this](int v) { pickAgent(v); });
    return bar;
}

QString BrainEditorPanel::statusText() const
{
    return m_status->text();
}

void BrainEditorPanel::setStatus(const QString& text, bool problem)
{
    m_status->setText(text);
    m_status->setStyleSheet(problem ? "color: #e05050;" : QString());
}

void BrainEditorPanel::refreshList()
{
    const sim::Scene& s = m_document.scene();
    const QSignalBlocker block(m_brains), blockTypes(m_types);
    m_brains->clear();
    for (const sim::BrainGraph& g : s.brains)
        m_brains->addItem(QString::fromStdString(g.name));
    m_brains->setCurrentIndex(m_model->brainIndex());
    const int type = m_types->currentIndex();
    m_types->clear();
    for (const sim::AgentType& t : s.agentTypes)
        m_types->addItem(QStringLiteral("%1 (%2)").arg(QString::fromStdString(t.name),
                                                      t.brain.empty() ? tr("no brain") : QString::fromStdString(t.brain)));
    m_types->setCurrentIndex(std::clamp(type, 0, m_types->count() - 1));
    updateHint();
}

void BrainEditorPanel::updateHint()
{
    if (m_document.scene().brains.empty())
        m_view->setHint(tr("This scene has no brains yet.\n\nPress Tab here and type a node's name, or use Add Node, "
                           "to start one; New makes an empty brain, and Import... adds a .brain.yaml (Throng's own "
                           "are in resources/brains). Assign then gives the shown brain to an agent type."));
    else if (m_model->hasBrain() && m_model->graph().nodes.empty())
        m_view->setHint(tr("'%1' has no nodes yet.\n\nPress Tab here and type a node's name, or use Add Node. "
                           "Drag from one node's port to another's to link them.")
                            .arg(QString::fromStdString(m_model->graph().name)));
    else
        m_view->setHint({});
}

void BrainEditorPanel::recompile()
{
    std::vector<sim::BrainError> errors;
    if (m_model->hasBrain() && !m_model->graph().nodes.empty())
        errors = sim::compileBrain(m_model->graph(), m_document.scene().brains).errors;
    m_scene->setErrors(errors);
    const bool changed = errors.size() != m_errors.size() ||
                         !std::equal(errors.begin(), errors.end(), m_errors.begin(),
                                     [](const sim::BrainError& a, const sim::BrainError& b) { return a.message == b.message; });
    m_errors = std::move(errors);
    // After the caller is done: opening a scene lists what the load said first, and the
    // brain's verdict must not be overwritten by that.
    if (changed)
        QTimer::singleShot(0, this, &BrainEditorPanel::reportErrors);
}

void BrainEditorPanel::reportErrors()
{
    std::vector<sim::Diagnostic> diagnostics;
    for (const sim::BrainError& e : m_errors)
        diagnostics.push_back({sim::Severity::Error, e.file, e.line, e.column,
                               "brains[" + std::to_string(m_model->brainIndex()) + "]", e.message});
    const QString name = QString::fromStdString(m_model->graph().name);
    emit brainMessages(m_errors.empty() ? tr("Brain '%1' compiles.").arg(name)
                                        : tr("Brain '%1' has %n error(s):", nullptr, int(m_errors.size())).arg(name),
                       diagnostics);
}

void BrainEditorPanel::showBrain(int index)
{
    m_model->setBrainIndex(index);
    m_view->frameAll();
    updateLive();
}

void BrainEditorPanel::pushLibrary(const EditBrainsCommand::State& after, const QString& text)
{
    m_document.undoStack()->push(new EditBrainsCommand(m_document, brainlib::current(m_document.scene()), after, text));
}

void BrainEditorPanel::newBrain()
{
    pushLibrary(brainlib::added(m_document.scene(), "brain"), tr("New brain"));
    showBrain(int(m_document.scene().brains.size()) - 1);
}

bool BrainEditorPanel::renameBrain(const QString& name)
{
    QString problem;
    const auto after = brainlib::renamed(m_document.scene(), std::size_t(std::max(0, m_model->brainIndex())),
                                         name.trimmed().toStdString(), &problem);
    if (!after || !m_model->hasBrain()) {
        setStatus(problem, true);
        return false;
    }
    pushLibrary(*after, tr("Rename brain to %1").arg(name));
    return true;
}

void BrainEditorPanel::duplicateBrain()
{
    if (!m_model->hasBrain())
        return;
    pushLibrary(brainlib::duplicated(m_document.scene(), std::size_t(m_model->brainIndex())), tr("Duplicate brain"));
    showBrain(int(m_document.scene().brains.size()) - 1);
}

void BrainEditorPanel::deleteBrain()
{
    if (m_model->hasBrain())
        pushLibrary(brainlib::removed(m_document.scene(), std::size_t(m_model->brainIndex())), tr("Delete brain"));
}

bool BrainEditorPanel::importBrain(const QString& path)
{
    QString problem;
    const auto after = brainlib::imported(m_document.scene(), path, &problem);
    if (!after) {
        setStatus(tr("Cannot import %1:\n%2").arg(path, problem), true);
        return false;
    }
    pushLibrary(*after, tr("Import brain %1").arg(QFileInfo(path).fileName()));
    showBrain(int(m_document.scene().brains.size()) - 1);
    setStatus(tr("Imported %1.").arg(path), false);
    return true;
}

bool BrainEditorPanel::exportBrain(const QString& path)
{
    QString problem;
    if (!m_model->hasBrain() ||
        !brainlib::exportBrain(m_document.scene(), std::size_t(m_model->brainIndex()), path, &problem)) {
        setStatus(tr("Cannot export: %1").arg(problem), true);
        return false;
    }
    setStatus(tr("Exported to %1.").arg(path), false);
    return true;
}

void BrainEditorPanel::assignToType(int type)
{
    if (type < 0 || !m_model->hasBrain())
        return;
    pushLibrary(brainlib::assigned(m_document.scene(), std::size_t(type), m_model->graph().name),
                tr("Assign brain %1").arg(QString::fromStdString(m_model->graph().name)));
}

}  // namespace throng::editor
