#include "simcore/brain/BrainEvaluator.h"

#include "simcore/brain/NodeCatalogue.h"
#include "simcore/brain/detail/BrainKernels.h"

#include <algorithm>

namespace throng::sim {

namespace {
// Agents per block: a block's columns (a few dozen × 1024 floats) stay in L2 while
// every instruction runs over it. Blocks are fixed, so results never depend on threads.
constexpr std::size_t kBlock = 1024;
}  // namespace

BrainEvaluator::BrainEvaluator(std::shared_ptr<const BrainProgram> program) : m_program(std::move(program))
{
    m_state.resize(m_program->stateColumns);
    resize(0);
}

void BrainEvaluator::resize(std::size_t agentCount)
{
    const BrainProgram& p = *m_program;
    m_agents = agentCount;
    m_offset.assign(p.valueSlots.size(), 0);
    std::size_t total = 0;
    for (std::size_t s = 0; s < p.valueSlots.size(); ++s) {
        if (p.valueSlots[s].source == SlotSource::Sensor)
            continue;
        m_offset[s] = total;
        total += p.valueSlots[s].perNeighbour ? agentCount * kBrainNeighbours : agentCount;
    }
    m_values.assign(total, 0.0f);
    for (std::size_t s = 0; s < p.valueSlots.size(); ++s)
        if (p.valueSlots[s].source == SlotSource::Constant)
            std::fill_n(m_values.begin() + std::ptrdiff_t(m_offset[s]), agentCount, p.valueSlots[s].constant);
    for (std::size_t c = 0; c < m_state.size(); ++c)
        m_state[c].resize(agentCount, p.stateInitial[c]);
}

void BrainEvaluator::moveAgentState(std::size_t from, std::size_t to)
{
    for (std::vector<float>& column : m_state)
        column[to] = column[from];
}

void BrainEvaluator::resetAgentState(std::size_t agent)
{
    for (std::size_t c = 0; c < m_state.size(); ++c)
        m_state[c][agent] = m_program->stateInitial[c];
}

void BrainEvaluator::setStateColumns(const std::vector<std::vector<float>>& columns)
{
    if (columns.size() != m_state.size())
        return;
    for (const std::vector<float>& c : columns)
        if (c.size() != m_agents)
            return;
    m_state = columns;
}

const float* BrainEvaluator::column(std::uint32_t slot) const
{
    return m_values.data() + m_offset[slot];
}

bool BrainEvaluator::evaluate(const BrainInputs& inputs, std::string* error, const ThreadTeam* team)
{
    const BrainProgram& p = *m_program;
    const auto fail = [&](std::string why) {
        if (error)
            *error = "brain '" + p.name + "': " + std::move(why);
        return false;
    };
    if (inputs.sensors.size() != p.sensors.size())
        return fail("expected " + std::to_string(p.sensors.size()) + " sensor columns, got " +
                    std::to_string(inputs.sensors.size()));
    for (std::size_t s = 0; s < p.sensors.size(); ++s)
        if (!inputs.sensors[s] && m_agents > 0)
            return fail("no column for sensor '" + p.sensors[s].sensor + "'");
    if (inputs.itemCounts.size() != p.itemSets.size())
        return fail("expected " + std::to_string(p.itemSets.size()) + " item count columns, got " +
                    std::to_string(inputs.itemCounts.size()));
    for (std::size_t s = 0; s < p.itemSets.size(); ++s)
        if (!inputs.itemCounts[s] && m_agents > 0)
            return fail("no item counts for '" + p.itemSets[s] + "'");
    if (p.usesRandomKeys && !inputs.agentKey && m_agents > 0)
        return fail("random and noise nodes need agent keys");

    m_reads.assign(p.valueSlots.size(), nullptr);
    m_writes.assign(p.valueSlots.size(), nullptr);
    for (std::size_t s = 0; s < p.valueSlots.size(); ++s) {
        if (p.valueSlots[s].source == SlotSource::Sensor) {
            m_reads[s] = inputs.sensors[p.valueSlots[s].sensor];
        } else {
            m_writes[s] = m_values.data() + m_offset[s];
            m_reads[s] = m_writes[s];
        }
    }
    std::vector<float*> state(m_state.size());
    for (std::size_t c = 0; c < m_state.size(); ++c)
        state[c] = m_state[c].data();
    detail::BrainFrame frame;
    frame.in = m_reads.data();
    frame.out = m_writes.data();
    frame.state = state.data();
    frame.itemCounts = inputs.itemCounts.data();
    frame.agentKey = inputs.agentKey;
    frame.timeS = inputs.timeS;
    frame.dtS = inputs.dtS;

    // Evaluate: every instruction over one block of agents, blocks in parallel.
    auto evaluateBlock = [&](std::size_t b, std::size_t e, int) {
        for (const BrainInstr& in : p.code)
            detail::runInstr(p, in, frame, b, e);
    };
    if (team) {
        team->forChunks(m_agents, kBlock, evaluateBlock);
    } else {
        for (std::size_t b = 0; b < m_agents; b += kBlock)
            evaluateBlock(b, std::min(m_agents, b + kBlock), 0);
    }

    // Live view: copy the picked agent's values while the sensor columns are valid.
    m_pickedValues.clear();
    if (m_picked >= 0 && std::size_t(m_picked) < m_agents) {
        const auto i = std::size_t(m_picked);
        for (const BrainNodeSlot& ns : p.nodeSlots) {
            BrainNodeValue v{ns.node, ns.port, {}};
            const float* col = m_reads[ns.slot];
            const BrainSlot& slot = p.valueSlots[ns.slot];
            const std::size_t count =
                slot.perNeighbour ? std::min<std::size_t>(inputs.itemCounts[slot.itemSet][i], kBrainNeighbours) : 0;
            if (slot.perNeighbour)
                v.values.assign(col + i * kBrainNeighbours, col + i * kBrainNeighbours + count);
            else
                v.values.push_back(col[i]);
            m_pickedValues.push_back(std::move(v));
        }
    }
    return true;
}

BrainOutputs BrainEvaluator::outputs() const
{
    const BrainProgram& p = *m_program;
    BrainOutputs o;
    for (const BrainOutputSlot& s : p.outputs) {
        const float* col = column(s.slot);
        if (s.channel == "speed")
            o.speed = col;
        else if (s.channel == "turn")
            o.turn = col;
        else if (s.channel == "weight")
            o.weights.emplace_back(s.name, col);
        else
            o.tags.emplace_back(s.name, col);
    }
    if (p.action.used) {
        o.action = column(p.action.slot);
        o.actionNames = p.action.names;
    }
    if (p.goal.used) {
        o.goal = column(p.goal.slot);
        o.goalNames = p.goal.names;
    }
    return o;
}

const float* BrainEvaluator::nodeValues(NodeId node, std::uint32_t port) const
{
    for (const BrainNodeSlot& ns : m_program->nodeSlots)
        if (ns.node == node && ns.port == port)
            return m_program->valueSlots[ns.slot].source == SlotSource::Sensor ? nullptr : column(ns.slot);
    return nullptr;
}

std::vector<std::pair<std::string, float>> BrainEvaluator::pickedProbes() const
{
    std::vector<std::pair<std::string, float>> out;
    if (m_picked < 0 || std::size_t(m_picked) >= m_agents)
        return out;
    for (const BrainProbe& probe : m_program->probes) {
        const bool sensor = m_program->valueSlots[probe.slot].source == SlotSource::Sensor;
        // Sensor columns belong to the caller; a probe on a sensor reads the kept copy.
        float v = 0.0f;
        if (!sensor)
            v = column(probe.slot)[std::size_t(m_picked) *
                                   (m_program->valueSlots[probe.slot].perNeighbour ? kBrainNeighbours : 1)];
        else
            for (const BrainNodeSlot& ns : m_program->nodeSlots)
                if (ns.slot == probe.slot)
                    for (const BrainNodeValue& nv : m_pickedValues)
                        if (nv.node == ns.node && nv.port == ns.port && !nv.values.empty())
                            v = nv.values[0];
        out.emplace_back(probe.name.empty() ? "node " + std::to_string(probe.node) : probe.name, v);
    }
    return out;
}

}  // namespace throng::sim
