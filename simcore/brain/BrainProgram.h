#pragma once
// A compiled brain: a flat, topologically ordered list of instructions over numbered
// value slots (one float column per slot), the sensors it reads and the outputs it
// drives. Produced by compileBrain, run by BrainEvaluator; holds no agent data.

#include "simcore/scene/BrainGraph.h"

#include <cstdint>
#include <string>
#include <vector>

namespace throng::sim {

enum class BrainOp : std::uint8_t {
    Time, Random, Noise,
    Triangle, Trapezoid, Gaussian, Sigmoid,
    AndMin, AndProduct, OrMax, OrProbSum, Not, Weight, HedgeStrong, HedgeWeak, Priority,
    DefuzzAverage, Winner,
    Add, Subtract, Multiply, Divide, Min, Max, Clamp, Abs, Lerp, Remap, Compare,
    Filter,
    MemoryRead, MemoryWrite, Timer, Latch, Smooth,
    Scale, Action, Goal,
};

enum class SlotSource : std::uint8_t { Computed, Constant, Sensor };

struct BrainSlot {
    bool perNeighbour = false;  // the column holds agentCount × kBrainNeighbours values
    std::uint8_t itemSet = 0;   // perNeighbour: index into BrainProgram::itemSets
    SlotSource source = SlotSource::Computed;
    float constant = 0.0f;      // Constant: the value of every agent
    std::uint32_t sensor = 0;   // Sensor: index into BrainProgram::sensors
};

struct BrainInstr {
    BrainOp op = BrainOp::Add;
    bool perNeighbour = false;     // runs over every neighbour value of every agent
    std::uint8_t itemSet = 0;      // per-neighbour (and filter) instructions: whose items
    std::uint32_t out = 0;         // first output slot; outputs are out, out+1, ...
    std::uint32_t outCount = 1;
    std::uint32_t argBegin = 0;    // operand slots: operands[argBegin, argBegin + argCount)
    std::uint32_t argCount = 0;
    std::uint32_t paramBegin = 0;  // numbers: params[paramBegin, paramBegin + paramCount)
    std::uint32_t paramCount = 0;
    std::uint32_t state = 0;       // first per-agent state column (stateful ops)
    NodeId node = 0;               // the graph node it comes from (a macro's node for expanded ones)
};

// A sensor the caller must supply, one column per entry, in this order.
struct BrainSensorUse {
    std::string sensor;    // a name from sensorCatalogue()
    std::string argument;  // channel / attribute / tag name, empty when the sensor takes none
    bool perNeighbour = false;
    std::string itemSet;   // per-item sensors: "neighbours" or "sound:<channel>"
};

// Where a graph node's output lives, for the live view.
struct BrainNodeSlot {
    NodeId node = 0;
    std::uint32_t port = 0;
    std::uint32_t slot = 0;
};

struct BrainOutputSlot {
    std::string channel;  // speed, turn, weight, tag
    std::string name;     // weight: the behaviour; tag: the tag; else empty
    std::uint32_t slot = 0;
};

struct BrainChoiceSlot {
    std::vector<std::string> names;  // action or goal names, by index
    std::uint32_t slot = 0;          // the chosen index per agent, as a float
    bool used = false;
};

struct BrainProbe {
    NodeId node = 0;
    std::string name;
    std::uint32_t slot = 0;
};

struct BrainProgram {
    std::string name;
    std::vector<BrainSlot> valueSlots;  // not "slots": Qt defines that as a macro
    std::vector<BrainInstr> code;
    std::vector<std::uint32_t> operands;
    std::vector<float> params;
    std::uint32_t stateColumns = 0;  // per-agent state floats
    std::vector<float> stateInitial; // initial value of each state column
    std::vector<BrainSensorUse> sensors;
    std::vector<BrainNodeSlot> nodeSlots;
    std::vector<BrainOutputSlot> outputs;
    BrainChoiceSlot action;
    std::vector<float> actionDurations;  // seconds per action (0 = may change every step)
    BrainChoiceSlot goal;
    std::vector<BrainProbe> probes;
    std::uint32_t graphNodes = 0;    // nodes of the graph that compute (notes excluded, macros expanded)
    // Item sets the per-item values come from ("neighbours", "sound:<channel>"); the
    // caller gives one count column per entry.
    std::vector<std::string> itemSets;
    bool usesRandomKeys = false;     // input.random / input.noise: needs per-agent keys
};

}  // namespace throng::sim
