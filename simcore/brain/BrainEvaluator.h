#pragma once
// Runs a compiled brain for all agents of a type: instruction by instruction over
// contiguous float columns, in blocks of agents spread over a ThreadTeam's threads, with the
// state nodes' per-agent state kept between steps. Knows nothing of the World: the caller
// fills BrainInputs and reads BrainOutputs. Identical results for any thread count.

#include "simcore/base/ThreadTeam.h"
#include "simcore/brain/BrainProgram.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace throng::sim {

struct BrainInputs {
    // One column per entry of program().sensors, in that order: agentCount values for a
    // scalar sensor, agentCount × kBrainNeighbours for a per-item one (agent i's items at
    // [i*K, i*K + count[i]): its nearest neighbours, or the loudest sources). Not owned.
    std::vector<const float*> sensors;
    // One column per entry of program().itemSets ("neighbours", "sound:<channel>"): how
    // many items (<= kBrainNeighbours) each agent has in that set. Not owned.
    std::vector<const std::uint8_t*> itemCounts;
    const std::uint64_t* agentKey = nullptr;       // per agent, stable (e.g. rng(seed, AgentId, 0, s));
                                                   // needed when program().usesRandomKeys
    float timeS = 0.0f;  // simulation time, s
    float dtS = 0.0f;    // step length, s, > 0
};

// Views into the evaluator's columns, valid until the next evaluate or resize.
struct BrainOutputs {
    const float* speed = nullptr;  // desired speed, m/s; null when the brain has no speed output
    const float* turn = nullptr;   // desired turn rate, degrees/s, + = left; null when none
    std::vector<std::pair<std::string, const float*>> weights;  // steering behaviour -> weight
    std::vector<std::pair<std::string, const float*>> tags;     // tag name -> value others sense
    const float* action = nullptr;  // index into actionNames, as a float; null when none
    std::vector<std::string> actionNames;
    const float* goal = nullptr;    // index into goalNames, as a float; null when none
    std::vector<std::string> goalNames;
};

// One node output of the picked agent, for the brain editor's live view.
struct BrainNodeValue {
    NodeId node = 0;
    std::uint32_t port = 0;
    std::vector<float> values;  // one value, or one per item the agent has
};

class BrainEvaluator {
public:
    explicit BrainEvaluator(std::shared_ptr<const BrainProgram> program);

    const BrainProgram& program() const { return *m_program; }
    std::size_t agentCount() const { return m_agents; }

    // Sets the agent count. Existing agents keep their state; new ones start fresh.
    void resize(std::size_t agentCount);
    // Gives agent `to` the state of agent `from` (for a swap-and-pop removal).
    void moveAgentState(std::size_t from, std::size_t to);
    void resetAgentState(std::size_t agent);
    // Every agent's state, per state column (checkpoints); setStateColumns takes columns
    // of the same shape (state column count x agentCount), else changes nothing.
    const std::vector<std::vector<float>>& stateColumns() const { return m_state; }
    void setStateColumns(const std::vector<std::vector<float>>& columns);

    // Runs one step for every agent. Returns false and says why in `error` when the
    // inputs do not match the program (a missing column); nothing is evaluated then.
    // Blocks of agents run on `team` where given, else on the calling thread.
    bool evaluate(const BrainInputs& inputs, std::string* error = nullptr, const ThreadTeam* team = nullptr);
    BrainOutputs outputs() const;
    // Every agent's value of a node's output after the last evaluate (agentCount values,
    // or × kBrainNeighbours when per-neighbour); null for a sensor node or an unknown port,
    // and after keepOnlyOutputs for a node whose values are not kept.
    const float* nodeValues(NodeId node, std::uint32_t port) const;
    // Keeps every agent's values only where they are read after evaluate: outputs() and
    // the probes. Every other value lives in a scratch of one block (1,024 agents) per thread
    // while its block is worked out: a few hundred kilobytes in all instead of a float per
    // agent and value (about 300 bytes an agent for a brain of 40 nodes), and it stays in
    // cache. The results are the same to the bit; pickedValues is taken from the scratch.
    // By default every value is kept.
    void keepOnlyOutputs();

    // The agent whose node values are kept after each evaluate (-1 = none).
    void setPickedAgent(std::ptrdiff_t agent) { m_picked = agent; }
    const std::vector<BrainNodeValue>& pickedValues() const { return m_pickedValues; }
    // The picked agent's probe values: probe name (or "node <id>") and value.
    std::vector<std::pair<std::string, float>> pickedProbes() const;

private:
    // A thread's block: its scratch values (the slots not kept) and the columns one block
    // reads and writes, each from the block's first agent on.
    struct Block {
        std::vector<float> scratch;
        std::vector<const float*> in;
        std::vector<float*> out;
        std::vector<float*> state;
        std::vector<const std::uint8_t*> itemCounts;
    };
    const float* column(std::uint32_t slot) const;
    void layOut();
    void evaluateBlock(const BrainInputs& inputs, std::size_t begin, std::size_t end, Block& block);
    void keepPicked(const Block& block, std::size_t inBlock);

    std::shared_ptr<const BrainProgram> m_program;
    std::size_t m_agents = 0;
    bool m_keepEvery = true;
    // Per slot (computed and constant): kept for every agent in m_values, else in the
    // blocks' scratch; its offset into the one or the other.
    std::vector<char> m_kept;
    std::vector<std::size_t> m_offset;
    std::size_t m_scratchFloats = 0;
    std::vector<float> m_values;
    std::vector<std::vector<float>> m_state;
    std::vector<Block> m_blocks;  // per thread
    std::ptrdiff_t m_picked = -1;
    std::vector<BrainNodeValue> m_pickedValues;
};

}  // namespace throng::sim
