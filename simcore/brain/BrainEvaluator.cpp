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
    m_agents = agentCount;
    layOut();
    for (std::size_t c = 0; c < m_state.size(); ++c)
        m_state[c].resize(agentCount, m_program->stateInitial[c]);
}

void BrainEvaluator::keepOnlyOutputs()
{
    m_keepEvery = false;
    layOut();
    m_blocks.clear();  // made again, with the new scratch, as the threads need them
}

// Which slots are kept for every agent, and where each slot's values go; the kept
// constants are written here, the others once into each thread's scratch (evaluate). The
// scratch's layout does not depend on the agent count, so resizing keeps the blocks.
void BrainEvaluator::layOut()
{
    const BrainProgram& p = *m_program;
    m_kept.assign(p.valueSlots.size(), m_keepEvery ? 1 : 0);
    for (const BrainOutputSlot& o : p.outputs)
        m_kept[o.slot] = 1;
    if (p.action.used)
        m_kept[p.action.slot] = 1;
    if (p.goal.used)
        m_kept[p.goal.slot] = 1;
    for (const BrainProbe& probe : p.probes)
        m_kept[probe.slot] = 1;
    m_offset.assign(p.valueSlots.size(), 0);
    std::size_t kept = 0;
    m_scratchFloats = 0;
    for (std::size_t s = 0; s < p.valueSlots.size(); ++s) {
        if (p.valueSlots[s].source == SlotSource::Sensor)
            continue;
        const std::size_t width = p.valueSlots[s].perNeighbour ? kBrainNeighbours : 1;
        std::size_t& total = m_kept[s] ? kept : m_scratchFloats;
        m_offset[s] = total;
        total += width * (m_kept[s] ? m_agents : kBlock);
    }
    m_values.assign(kept, 0.0f);
    for (std::size_t s = 0; s < p.valueSlots.size(); ++s)
        if (p.valueSlots[s].source == SlotSource::Constant && m_kept[s])
            std::fill_n(m_values.begin() + std::ptrdiff_t(m_offset[s]),
                        m_agents * (p.valueSlots[s].perNeighbour ? kBrainNeighbours : 1), p.valueSlots[s].constant);
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

    // Every instruction over one block of agents, blocks in parallel; the picked agent's
    // values are taken in its block, while the sensor columns and the scratch hold them.
    const std::size_t threads = team ? std::size_t(std::max(1, team->size())) : 1;
    while (m_blocks.size() < threads) {
        Block& block = m_blocks.emplace_back();
        block.scratch.assign(m_scratchFloats, 0.0f);
        for (std::size_t s = 0; s < p.valueSlots.size(); ++s)
            if (p.valueSlots[s].source == SlotSource::Constant && !m_kept[s])
                std::fill_n(block.scratch.begin() + std::ptrdiff_t(m_offset[s]),
                            kBlock * (p.valueSlots[s].perNeighbour ? kBrainNeighbours : 1),
                            p.valueSlots[s].constant);
        block.in.resize(p.valueSlots.size());
        block.out.resize(p.valueSlots.size());
        block.state.resize(m_state.size());
        block.itemCounts.resize(p.itemSets.size());
    }
    m_pickedValues.clear();
    auto run = [&](std::size_t b, std::size_t e, int slot) {
        evaluateBlock(inputs, b, e, m_blocks[std::size_t(slot)]);
    };
    if (team) {
        team->forChunks(m_agents, kBlock, run);
    } else {
        for (std::size_t b = 0; b < m_agents; b += kBlock)
            run(b, std::min(m_agents, b + kBlock), 0);
    }
    return true;
}

// Agents [begin, end), at most kBlock: every column the block reads or writes starts at
// agent `begin` (the kept ones and the caller's where that agent's values begin, the
// scratch as it is), so the instructions run over [0, end - begin).
void BrainEvaluator::evaluateBlock(const BrainInputs& inputs, std::size_t begin, std::size_t end, Block& block)
{
    const BrainProgram& p = *m_program;
    for (std::size_t s = 0; s < p.valueSlots.size(); ++s) {
        const BrainSlot& slot = p.valueSlots[s];
        const std::size_t first = begin * (slot.perNeighbour ? kBrainNeighbours : 1);
        if (slot.source == SlotSource::Sensor) {
            block.in[s] = inputs.sensors[slot.sensor] + first;
            block.out[s] = nullptr;
        } else {
            block.out[s] = m_kept[s] ? m_values.data() + m_offset[s] + first : block.scratch.data() + m_offset[s];
            block.in[s] = block.out[s];
        }
    }
    for (std::size_t c = 0; c < m_state.size(); ++c)
        block.state[c] = m_state[c].data() + begin;
    for (std::size_t s = 0; s < p.itemSets.size(); ++s)
        block.itemCounts[s] = inputs.itemCounts[s] + begin;
    detail::BrainFrame frame;
    frame.in = block.in.data();
    frame.out = block.out.data();
    frame.state = block.state.data();
    frame.itemCounts = block.itemCounts.data();
    frame.agentKey = inputs.agentKey ? inputs.agentKey + begin : nullptr;
    frame.timeS = inputs.timeS;
    frame.dtS = inputs.dtS;
    for (const BrainInstr& in : p.code)
        detail::runInstr(p, in, frame, 0, end - begin);
    if (m_picked >= 0 && std::size_t(m_picked) >= begin && std::size_t(m_picked) < end)
        keepPicked(block, std::size_t(m_picked) - begin);
}

// The live view: the picked agent's value of every node, from its block's columns.
void BrainEvaluator::keepPicked(const Block& block, std::size_t inBlock)
{
    const BrainProgram& p = *m_program;
    for (const BrainNodeSlot& ns : p.nodeSlots) {
        BrainNodeValue v{ns.node, ns.port, {}};
        const float* col = block.in[ns.slot];
        const BrainSlot& slot = p.valueSlots[ns.slot];
        if (slot.perNeighbour) {
            const std::size_t count =
                std::min<std::size_t>(block.itemCounts[slot.itemSet][inBlock], kBrainNeighbours);
            v.values.assign(col + inBlock * kBrainNeighbours, col + inBlock * kBrainNeighbours + count);
        } else {
            v.values.push_back(col[inBlock]);
        }
        m_pickedValues.push_back(std::move(v));
    }
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
            return m_program->valueSlots[ns.slot].source == SlotSource::Sensor || !m_kept[ns.slot] ? nullptr
                                                                                                : column(ns.slot);
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
