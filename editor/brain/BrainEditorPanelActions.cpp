// BrainEditorPanel's graph actions (palette, clipboard, macros) and its live view of a
// picked agent; the construction and the brain list are in BrainEditorPanel.cpp.
#include "editor/brain/BrainEditorPanel.h"

#include "editor/brain/BrainCommands.h"
#include "editor/brain/BrainGraphModel.h"
#include "editor/brain/BrainLibrary.h"
#include "editor/brain/BrainMacro.h"
#include "editor/brain/BrainScene.h"
#include "editor/brain/BrainView.h"
#include "editor/brain/NodeItem.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QLabel>
#include <QMouseEvent>
#include <QSpinBox>
#include <QToolButton>

namespace throng::editor {

void BrainEditorPanel::addFromPalette(const QString& type)
{
    if (!m_model->hasBrain())
        newBrain();
    const std::optional<PendingLink> pending = std::exchange(m_pending, std::nullopt);
    QUndoStack* stack = m_document.undoStack();
    stack->beginMacro(tr("Add %1 node").arg(type));
    const sim::NodeId id = m_model->addNode(type.toStdString(), m_paletteScenePos);
    if (pending && id != 0) {
        // The new node's first port that takes (or gives) the dropped link's value.
        const NodeItem* item = m_scene->nodeItem(id);
        std::string problem = "no compatible port";
        const int ports = item ? (pending->fromInput ? item->outputCount() : item->inputCount()) : 0;
        for (int p = 0; p < ports; ++p) {
            const sim::BrainLink link = pending->fromInput
                                            ? sim::BrainLink{id, std::uint32_t(p), pending->node, std::uint32_t(pending->port)}
                                            : sim::BrainLink{pending->node, std::uint32_t(pending->port), id, std::uint32_t(p)};
            if (m_model->addLink(link, &problem))
                break;
        }
    }
    stack->endMacro();
    if (NodeItem* item = m_scene->nodeItem(id)) {
        m_scene->clearSelection();
        item->setSelected(true);
    }
    m_view->setFocus();
}

void BrainEditorPanel::copySelection()
{
    m_clipboard = m_model->copy(m_scene->selectedNodes());
    setStatus(tr("Copied %n node(s).", nullptr, int(m_clipboard.nodes.size())), false);
}

void BrainEditorPanel::paste()
{
    const std::vector<sim::NodeId> added = m_model->paste(m_clipboard, QPointF(40, 40));
    m_scene->clearSelection();
    for (sim::NodeId id : added)
        if (NodeItem* item = m_scene->nodeItem(id))
            item->setSelected(true);
    // Pasting again lands beside this copy, not on it.
    for (sim::BrainNode& n : m_clipboard.nodes)
        n.position += glm::vec2(40.0f);
}

void BrainEditorPanel::duplicateSelection()
{
    const sim::BrainGraph keep = m_clipboard;
    copySelection();
    paste();
    m_clipboard = keep;
}

bool BrainEditorPanel::collapseSelection()
{
    if (!m_model->hasBrain())
        return false;
    const sim::Scene& s = m_document.scene();
    std::string problem;
    const std::string name = brainlib::uniqueName(s, m_model->graph().name + " macro");
    const auto collapse = collapseToMacro(m_model->graph(), m_scene->selectedNodes(), name, &problem);
    if (!collapse) {
        setStatus(QString::fromStdString(problem), true);
        return false;
    }
    EditBrainsCommand::State after = brainlib::current(s);
    after.brains[std::size_t(m_model->brainIndex())] = collapse->outer;
    after.brains.push_back(collapse->inner);
    pushLibrary(after, tr("Collapse %n node(s) into a macro", nullptr, int(m_scene->selectedNodes().size())));
    setStatus(tr("Collapsed into macro brain '%1'.").arg(QString::fromStdString(name)), false);
    return true;
}

bool BrainEditorPanel::expandSelection()
{
    const std::vector<sim::NodeId> sel = m_scene->selectedNodes();
    std::string problem = "select one macro node";
    const auto expanded = sel.size() == 1 ? expandMacro(m_model->graph(), sel[0], m_document.scene().brains, &problem)
                                          : std::nullopt;
    if (!expanded) {
        setStatus(QString::fromStdString(problem), true);
        return false;
    }
    return m_model->replace(*expanded, tr("Expand macro node %1").arg(sel[0]));
}

void BrainEditorPanel::pickAgent(std::ptrdiff_t agent)
{
    if (agent >= 0 && std::size_t(agent) >= m_simulation.cache().agentCount())
        agent = -1;
    m_picked = agent;
    m_simulation.pickBrainAgent(agent);
    if (m_viewport)
        m_viewport->setInspectedAgent(agent >= 0 ? m_simulation.cache().agents()[std::size_t(agent)].id : 0);
    {
        const QSignalBlocker block(m_agent);
        m_agent->setValue(int(agent));
    }
    if (agent >= 0) {
        // Show the brain the picked agent runs.
        const std::size_t type = m_simulation.cache().agents()[std::size_t(agent)].typeIndex;
        const sim::Scene& s = m_document.scene();
        const std::string brain = brainOf(agent);
        for (std::size_t b = 0; b < s.brains.size(); ++b)
            if (s.brains[b].name == brain && int(b) != m_model->brainIndex())
                showBrain(int(b));
        setStatus(tr("Showing agent %1's values (%2).")
                      .arg(m_simulation.cache().agents()[std::size_t(agent)].id)
                      .arg(type < s.agentTypes.size() ? QString::fromStdString(s.agentTypes[type].name) : QString()),
                  false);
    }
    updateLive();
}

std::string BrainEditorPanel::brainOf(std::ptrdiff_t agent) const
{
    const sim::FrameCache& cache = m_simulation.cache();
    if (agent < 0 || std::size_t(agent) >= cache.agentCount())
        return {};
    const sim::AgentInfo& info = cache.agents()[std::size_t(agent)];
    const sim::Scene& s = m_document.scene();
    for (const sim::Agent& a : s.agents)
        if (a.id == info.id && !a.brain.empty())
            return a.brain;
    return info.typeIndex < s.agentTypes.size() ? s.agentTypes[info.typeIndex].brain : std::string();
}

void BrainEditorPanel::updateLive()
{
    const std::vector<sim::BrainNodeValue>* values =
        m_picked < 0 || !m_model->hasBrain() ? nullptr : m_simulation.brainValues(m_simulation.currentFrame(), m_picked);
    const bool shown = values && brainOf(m_picked) == m_model->graph().name;
    m_scene->setLiveValues(shown ? *values : std::vector<sim::BrainNodeValue>{});
}

void BrainEditorPanel::armViewportPick()
{
    m_pick->setChecked(m_viewport != nullptr);
    if (m_viewport)
        setStatus(tr("Click an agent in the viewport."), false);
}

bool BrainEditorPanel::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != m_viewport || !m_pick->isChecked() || event->type() != QEvent::MouseButtonPress)
        return QWidget::eventFilter(watched, event);
    auto* mouse = static_cast<QMouseEvent*>(event);
    if (mouse->button() != Qt::LeftButton)
        return QWidget::eventFilter(watched, event);
    m_pick->setChecked(false);
    const std::optional<glm::vec3> ground = m_viewport->pixelToGround(mouse->position());
    const sim::FrameCache& cache = m_simulation.cache();
    std::ptrdiff_t best = -1;
    float bestD = 1.5f;  // m: a click this close to an agent picks it
    if (ground && m_simulation.currentFrame() < cache.frameCount())
        for (std::size_t i = 0; i < cache.agentCount(); ++i) {
            if (!cache.at(m_simulation.currentFrame(), i).present)
                continue;  // not there on this frame (an edit added or removed it)
            const glm::vec3 p = cache.at(m_simulation.currentFrame(), i).position;
            const float d = glm::length(glm::vec2(p.x - ground->x, p.z - ground->z));
            if (d < bestD) {
                bestD = d;
                best = std::ptrdiff_t(i);
            }
        }
    pickAgent(best);
    if (best < 0)
        setStatus(tr("No agent there."), true);
    return true;  // The pick click is not a tool's click.
}

}  // namespace throng::editor
