// Emits a checked, ordered flat graph as a program: slots for every node output,
// constants folded through the same kernels the evaluator runs, state columns for the
// state nodes, and the sensor and output tables the caller uses.
#include "simcore/brain/detail/BrainFlatGraph.h"
#include "simcore/brain/detail/BrainKernels.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>

namespace throng::sim::detail {

struct EmitPass {
    std::vector<FlatNode>& nodes;
    const std::vector<std::vector<int>>& kinds;  // per node output: -1 per agent, else item set
    BrainProgram& p;
    std::vector<std::vector<std::uint32_t>> slotOf;  // per flat node, per output port
    std::map<std::uint32_t, std::uint32_t> constants;  // value bits -> slot
    std::map<std::string, std::uint32_t> sensors;      // "sensor/argument" -> slot
    std::vector<std::pair<std::uint32_t, int>> memoryWrites;  // state column, flat node

    std::uint32_t constant(float v)
    {
        std::uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        if (auto it = constants.find(bits); it != constants.end())
            return it->second;
        BrainSlot s;
        s.source = SlotSource::Constant;
        s.constant = v;
        p.valueSlots.push_back(s);
        return constants[bits] = std::uint32_t(p.valueSlots.size() - 1);
    }
    std::uint32_t computed(int set)
    {
        BrainSlot s;
        s.perNeighbour = set >= 0;
        s.itemSet = std::uint8_t(std::max(set, 0));
        p.valueSlots.push_back(s);
        return std::uint32_t(p.valueSlots.size() - 1);
    }
    std::uint32_t state(float initial)
    {
        p.stateInitial.push_back(initial);
        return p.stateColumns++;
    }
    // The slot an input reads: its source, or the fallback parameter (or 0) when free.
    std::uint32_t operand(const FlatNode& n, std::size_t port)
    {
        if (port < n.inputs.size() && n.inputs[port].node >= 0)
            return slotOf[std::size_t(n.inputs[port].node)][n.inputs[port].port];
        const PortSpec& spec = n.spec->inputs[std::min(port, n.spec->inputs.size() - 1)];
        return constant(spec.fallbackParam.empty() ? 0.0f : numberParam(n, spec.fallbackParam));
    }

    // Emits op for node i over its inputs; folds it when every operand is a constant.
    void emit(int i, BrainOp op, std::vector<float> params, std::size_t outputs = 1, std::uint32_t stateColumn = 0)
    {
        const FlatNode& n = nodes[std::size_t(i)];
        BrainInstr in;
        in.op = op;
        in.node = n.origin;
        in.argBegin = std::uint32_t(p.operands.size());
        // A memory node reads its input only after the step (MemoryWrite), not here.
        const std::size_t args =
            op == BrainOp::MemoryRead ? 0 : std::max(n.inputs.size(), n.spec->variadic ? 0u : n.spec->inputs.size());
        bool allConstant = true;
        for (std::size_t a = 0; a < args; ++a) {
            const std::uint32_t s = operand(n, a);
            allConstant = allConstant && p.valueSlots[s].source == SlotSource::Constant;
            p.operands.push_back(s);
        }
        in.argCount = std::uint32_t(args);
        in.paramBegin = std::uint32_t(p.params.size());
        in.paramCount = std::uint32_t(params.size());
        p.params.insert(p.params.end(), params.begin(), params.end());
        in.state = stateColumn;
        const int set = op == BrainOp::Filter           ? n.filterSet
                        : kinds[std::size_t(i)].empty() ? -1
                                                        : kinds[std::size_t(i)][0];
        in.perNeighbour = set >= 0 && op != BrainOp::Filter;
        in.itemSet = std::uint8_t(std::max(set, 0));
        in.outCount = std::uint32_t(outputs);
        if (allConstant && isFoldable(op) && !in.perNeighbour) {
            fold(i, in);
            return;
        }
        in.out = std::uint32_t(p.valueSlots.size());
        for (std::size_t o = 0; o < outputs; ++o)
            slotOf[std::size_t(i)].push_back(computed(in.perNeighbour ? set : -1));
        p.code.push_back(in);
    }

    // Runs the instruction once for one agent, through the evaluator's own kernel.
    void fold(int i, BrainInstr in)
    {
        std::vector<float> values(p.valueSlots.size() + in.outCount, 0.0f);
        std::vector<const float*> reads(values.size());
        std::vector<float*> writes(values.size());
        for (std::size_t s = 0; s < values.size(); ++s) {
            if (s < p.valueSlots.size())
                values[s] = p.valueSlots[s].constant;
            reads[s] = &values[s];
            writes[s] = &values[s];
        }
        in.out = std::uint32_t(p.valueSlots.size());
        BrainFrame f;
        f.in = reads.data();
        f.out = writes.data();
        runInstr(p, in, f, 0, 1);
        for (std::uint32_t o = 0; o < in.outCount; ++o)
            slotOf[std::size_t(i)].push_back(constant(values[in.out + o]));
    }
};

void emitNode(EmitPass& e, int i)
{
    FlatNode& n = e.nodes[std::size_t(i)];
    const std::string& t = n.node->type;
    const auto num = [&](const char* key) { return numberParam(n, key); };
    const auto nums = [&](const char* key) {
        const std::vector<float>* v = numbersParam(n, key);
        return v ? *v : std::vector<float>{};
    };
    std::vector<std::uint32_t>& slots = e.slotOf[std::size_t(i)];
    if (n.pass) {
        if (n.inputs.empty() || n.inputs[0].node < 0)
            slots.push_back(e.constant(t == "macro.in" ? num("value") : 0.0f));
        else
            slots.push_back(e.slotOf[std::size_t(n.inputs[0].node)][n.inputs[0].port]);
        return;
    }
    if (t == "input") {
        const std::string sensor = textParam(n, "sensor");
        if (sensor == "time")
            return e.emit(i, BrainOp::Time, {});
        const SensorSpec* spec = findSensorSpec(sensor);
        BrainSensorUse use{
            sensor, spec->argument.empty() ? std::string() : textParam(n, spec->argument), spec->perNeighbour, {}};
        const int set = e.kinds[std::size_t(i)][0];
        if (set >= 0)
            use.itemSet = e.p.itemSets[std::size_t(set)];
        const std::string key = use.sensor + "/" + use.argument;
        if (!e.sensors.count(key)) {
            BrainSlot s;
            s.source = SlotSource::Sensor;
            s.perNeighbour = use.perNeighbour;
            s.itemSet = std::uint8_t(std::max(set, 0));
            s.sensor = std::uint32_t(e.p.sensors.size());
            e.p.valueSlots.push_back(s);
            e.p.sensors.push_back(use);
            e.sensors[key] = std::uint32_t(e.p.valueSlots.size() - 1);
        }
        slots.push_back(e.sensors[key]);
        return;
    }
    if (t == "input.constant")
        return slots.push_back(e.constant(num("value")));
    if (t == "input.random" || t == "input.noise")
        e.p.usesRandomKeys = true;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    if (t == "input.random")
        return e.emit(i, BrainOp::Random, {num("min"), num("max")}, 1, e.state(nan));
    if (t == "input.noise")
        return e.emit(i, BrainOp::Noise, {num("frequency"), num("min"), num("max")});
    if (t == "fuzz.triangle")
        return e.emit(i, BrainOp::Triangle, nums("points"));
    if (t == "fuzz.trapezoid")
        return e.emit(i, BrainOp::Trapezoid, nums("points"));
    if (t == "fuzz.gaussian")
        return e.emit(i, BrainOp::Gaussian, {num("centre"), num("width")});
    if (t == "fuzz.sigmoid")
        return e.emit(i, BrainOp::Sigmoid, {num("centre"), num("slope")});
    if (t == "rule.and")
        return e.emit(i, textParam(n, "mode") == "min" ? BrainOp::AndMin : BrainOp::AndProduct, {});
    if (t == "rule.or")
        return e.emit(i, textParam(n, "mode") == "max" ? BrainOp::OrMax : BrainOp::OrProbSum, {});
    if (t == "rule.not")
        return e.emit(i, BrainOp::Not, {});
    if (t == "rule.weight")
        return e.emit(i, BrainOp::Weight, {num("weight")});
    if (t == "rule.hedge")
        return e.emit(i, textParam(n, "mode") == "strong" ? BrainOp::HedgeStrong : BrainOp::HedgeWeak, {});
    if (t == "rule.priority")
        return e.emit(i, BrainOp::Priority, {}, n.inputs.size());
    if (t == "defuzz.average") {
        std::vector<float> params = nums("values");
        params.push_back(num("default"));
        return e.emit(i, BrainOp::DefuzzAverage, params);
    }
    if (t == "defuzz.winner")
        return e.emit(i, BrainOp::Winner, nums("values"), 2);
    static const std::map<std::string, BrainOp> math{
        {"math.add", BrainOp::Add},       {"math.subtract", BrainOp::Subtract}, {"math.multiply", BrainOp::Multiply},
        {"math.min", BrainOp::Min},       {"math.max", BrainOp::Max},           {"math.clamp", BrainOp::Clamp},
        {"math.abs", BrainOp::Abs},       {"math.lerp", BrainOp::Lerp}};
    if (auto m = math.find(t); m != math.end())
        return e.emit(i, m->second, {});
    if (t == "math.divide")
        return e.emit(i, BrainOp::Divide, {num("fallback")});
    if (t == "math.remap") {
        const std::vector<float> from = nums("from"), to = nums("to");
        return e.emit(i, BrainOp::Remap,
                      {from[0], from[1], to[0], to[1], textParam(n, "clamp") == "yes" ? 1.0f : 0.0f});
    }
    const auto choiceIndex = [&](const char* key) {
        const std::string v = textParam(n, key);
        const auto& choices = std::find_if(n.spec->params.begin(), n.spec->params.end(),
                                           [&](const ParamSpec& s) { return s.key == key; })->choices;
        return float(std::find(choices.begin(), choices.end(), v) - choices.begin());
    };
    if (t == "math.compare")
        return e.emit(i, BrainOp::Compare, {choiceIndex("mode")});
    if (t == "filter")
        return e.emit(i, BrainOp::Filter, {choiceIndex("mode"), num("threshold"), num("empty")});
    if (t == "state.memory") {
        const std::uint32_t column = e.state(num("initial"));
        e.memoryWrites.emplace_back(column, i);
        return e.emit(i, BrainOp::MemoryRead, {}, 1, column);
    }
    if (t == "state.timer")
        return e.emit(i, BrainOp::Timer, {}, 1, e.state(0.0f));
    if (t == "state.latch")
        return e.emit(i, BrainOp::Latch, {}, 1, e.state(num("initial")));
    if (t == "state.smooth")
        return e.emit(i, BrainOp::Smooth, {num("tau")}, 1, e.state(nan));
    if (t == "output") {
        e.emit(i, BrainOp::Scale, {num("scale")});
        const std::string channel = textParam(n, "channel");
        const std::string name = channel == "weight" ? textParam(n, "behaviour")
                                 : channel == "tag"  ? textParam(n, "tag")
                                                     : "";
        e.p.outputs.push_back({channel, name, slots[0]});
        return;
    }
    if (t == "output.action") {
        const std::vector<std::string> names = words(textParam(n, "actions"));
        std::vector<float> durations = nums("durations");
        durations.resize(names.size(), 0.0f);
        const std::uint32_t column = e.state(nan);
        e.state(0.0f);
        e.emit(i, BrainOp::Action, durations, 1, column);
        e.p.action = {names, slots[0], true};
        e.p.actionDurations = durations;
        return;
    }
    if (t == "output.goal") {
        e.emit(i, BrainOp::Goal, {});
        e.p.goal = {words(textParam(n, "goals")), slots[0], true};
        return;
    }
    if (t == "probe") {
        e.p.probes.push_back({n.origin, textParam(n, "name"), e.operand(n, 0)});
        return;
    }
}

std::shared_ptr<BrainProgram> emitAll(std::vector<FlatNode>& nodes, const std::vector<int>& sorted,
                                      const std::vector<std::vector<int>>& kinds, const std::vector<std::string>& sets,
                                      const std::string& name)
{
    auto program = std::make_shared<BrainProgram>();
    program->name = name;
    program->itemSets = sets;
    EmitPass e{nodes, kinds, *program, std::vector<std::vector<std::uint32_t>>(nodes.size()), {}, {}, {}};
    for (int i : sorted) {
        emitNode(e, i);
        const FlatNode& n = nodes[std::size_t(i)];
        if (!n.pass && n.node->type != "probe")
            ++program->graphNodes;
        if (n.where.empty())
            for (std::size_t o = 0; o < e.slotOf[std::size_t(i)].size(); ++o)
                program->nodeSlots.push_back({n.node->id, std::uint32_t(o), e.slotOf[std::size_t(i)][o]});
    }
    // A macro node shows the values of its macro.out nodes.
    for (const FlatNode& n : nodes)
        if (n.where.empty() && n.node->type == "macro")
            for (const auto& [port, out] : n.macroOutputs)
                if (!e.slotOf[std::size_t(out)].empty())
                    program->nodeSlots.push_back({n.node->id, port, e.slotOf[std::size_t(out)][0]});
    // Memory nodes store their input after everything else has read last step's value.
    for (auto [column, i] : e.memoryWrites) {
        BrainInstr in;
        in.op = BrainOp::MemoryWrite;
        in.node = nodes[std::size_t(i)].origin;
        in.argBegin = std::uint32_t(program->operands.size());
        in.argCount = 1;
        in.state = column;
        in.outCount = 0;
        program->operands.push_back(e.operand(nodes[std::size_t(i)], 0));
        program->code.push_back(in);
    }
    return program;
}

}  // namespace throng::sim::detail
