#pragma once
// The catalogue of brain node types and sensors: each type's typed ports, parameters
// (defaults, ranges) and a one-line description. The compiler, the editor's palette and
// docs/brains.md all read it; it never evaluates anything.

#include <string>
#include <string_view>
#include <vector>

namespace throng::sim {

// How many items a per-neighbour value holds per agent: the nearest neighbours, or the
// loudest sound sources of a channel, in order.
constexpr int kBrainNeighbours = 8;

enum class PortKind {
    Scalar,        // one value per agent
    PerNeighbour,  // one value per perceived neighbour or heard source (up to kBrainNeighbours)
    Any,           // input: either; output: per-neighbour when any input is
};

struct PortSpec {
    std::string name;
    PortKind kind = PortKind::Scalar;
    bool required = true;  // an optional input left unconnected reads `fallbackParam` (or 0)
    std::string fallbackParam;
};

enum class ParamType {
    Number,   // one number in [min, max]
    Numbers,  // a list of numbers (count numbers, or any count when count == 0)
    Text,     // free text (a name)
    Choice,   // one of `choices`
};

struct ParamSpec {
    std::string key;
    ParamType type = ParamType::Number;
    bool required = false;
    float defaultValue = 0.0f;  // Number
    float min = -1e30f;         // Number / Numbers
    float max = 1e30f;
    std::size_t count = 0;      // Numbers: exact count, 0 = any (checked by the node)
    std::vector<std::string> choices;  // Choice; choices[0] is the default
    std::string description;
};

struct NodeSpec {
    std::string type;      // e.g. "fuzz.triangle"
    std::string category;  // input, fuzz, rule, defuzz, math, filter, state, output, macro, probe
    std::string description;
    std::vector<PortSpec> inputs;
    std::vector<PortSpec> outputs;
    std::vector<ParamSpec> params;
    bool variadic = false;          // the last input repeats: ports last, last+1, ...
    int minInputs = 0;              // with variadic: at least this many connected inputs
    bool outputPerInput = false;    // one output per connected input (rule.priority)
    bool breaksCycles = false;      // its input is last step's value (state.memory)
};

struct SensorSpec {
    std::string name;
    bool perNeighbour = false;  // one value per item of `itemSet`
    std::string itemSet;        // per-item sensors: "neighbours", or "sound" (sources heard on the channel)
    std::string argument;  // the parameter naming a channel/attribute/tag, empty = none
    std::string unit;
    std::string description;
};

const std::vector<NodeSpec>& nodeCatalogue();
const NodeSpec* findNodeSpec(std::string_view type);
const std::vector<SensorSpec>& sensorCatalogue();
const SensorSpec* findSensorSpec(std::string_view name);
// Output channels of the `output` node.
const std::vector<std::string>& outputChannels();
// The built-in actions a brain may choose between (user actions are any other name).
const std::vector<std::string>& builtinActions();

// docs/brains.md's generated reference section (Markdown), from this catalogue.
std::string brainCatalogueMarkdown();

}  // namespace throng::sim
