#include "simcore/brain/NodeCatalogue.h"

#include <algorithm>

namespace throng::sim {

namespace {

PortSpec in(std::string name, PortKind kind = PortKind::Any) { return {std::move(name), kind, true, {}}; }
PortSpec opt(std::string name, std::string fallback, PortKind kind = PortKind::Any)
{
    return {std::move(name), kind, false, std::move(fallback)};
}
PortSpec out(std::string name, PortKind kind = PortKind::Any) { return {std::move(name), kind, true, {}}; }

ParamSpec num(std::string key, float def, std::string what, float lo = -1e30f, float hi = 1e30f)
{
    ParamSpec p;
    p.key = std::move(key);
    p.defaultValue = def;
    p.min = lo;
    p.max = hi;
    p.description = std::move(what);
    return p;
}
ParamSpec nums(std::string key, std::size_t count, bool required, std::string what)
{
    ParamSpec p;
    p.key = std::move(key);
    p.type = ParamType::Numbers;
    p.count = count;
    p.required = required;
    p.description = std::move(what);
    return p;
}
ParamSpec text(std::string key, bool required, std::string what)
{
    ParamSpec p;
    p.key = std::move(key);
    p.type = ParamType::Text;
    p.required = required;
    p.description = std::move(what);
    return p;
}
ParamSpec choice(std::string key, std::vector<std::string> choices, std::string what)
{
    ParamSpec p;
    p.key = std::move(key);
    p.type = ParamType::Choice;
    p.choices = std::move(choices);
    p.description = std::move(what);
    return p;
}

NodeSpec node(std::string type, std::string category, std::string description, std::vector<PortSpec> inputs,
              std::vector<PortSpec> outputs, std::vector<ParamSpec> params = {})
{
    NodeSpec n;
    n.type = std::move(type);
    n.category = std::move(category);
    n.description = std::move(description);
    n.inputs = std::move(inputs);
    n.outputs = std::move(outputs);
    n.params = std::move(params);
    return n;
}
NodeSpec variadic(NodeSpec n, int minInputs)
{
    n.variadic = true;
    n.minInputs = minInputs;
    return n;
}

std::vector<NodeSpec> makeCatalogue()
{
    const PortKind S = PortKind::Scalar, PN = PortKind::PerNeighbour;
    std::vector<NodeSpec> c;
    // input
    c.push_back(
        node("input", "input",
             "A sensor channel of the agent (see Sensors); per-neighbour sensors give one value per neighbour.", {},
             {out("value")},
             {text("sensor", true, "the sensor's name"), text("channel", false, "sound channel (sound_* sensors)"),
              text("name", false, "attribute name (attribute sensor)"),
              text("tag", false, "tag name (neighbour_tag sensor)")}));
    c.push_back(node("input.constant", "input", "A constant value.", {}, {out("value", S)},
                     {num("value", 0.0f, "the value")}));
    c.push_back(node("input.random", "input", "A random value per agent, fixed for the agent's life.", {},
                     {out("value", S)}, {num("min", 0.0f, "smallest value"), num("max", 1.0f, "largest value")}));
    c.push_back(node("input.noise", "input", "Smooth noise over time, different for each agent.", {}, {out("value", S)},
                     {num("frequency", 0.5f, "changes per second (Hz)", 1e-4f, 1e4f),
                      num("min", -1.0f, "smallest value"), num("max", 1.0f, "largest value")}));
    // fuzz
    c.push_back(node("fuzz.triangle", "fuzz", "Triangle membership: 0 at a and c, 1 at b.", {in("x")}, {out("truth")},
                     {nums("points", 3, true, "[a, b, c], a <= b <= c")}));
    c.push_back(node("fuzz.trapezoid", "fuzz", "Trapezoid membership: rises a..b, 1 on b..c, falls c..d.", {in("x")},
                     {out("truth")}, {nums("points", 4, true, "[a, b, c, d], a <= b <= c <= d")}));
    c.push_back(node("fuzz.gaussian", "fuzz", "Gaussian membership exp(-(x-centre)^2 / (2 width^2)).", {in("x")},
                     {out("truth")},
                     {num("centre", 0.0f, "where the truth is 1"), num("width", 1.0f, "standard deviation", 1e-6f)}));
    c.push_back(node("fuzz.sigmoid", "fuzz", "Sigmoid membership 1 / (1 + exp(-slope (x - centre))).", {in("x")},
                     {out("truth")},
                     {num("centre", 0.0f, "where the truth is 0.5"), num("slope", 1.0f, "steepness; negative falls")}));
    // rule
    c.push_back(variadic(node("rule.and", "rule", "Fuzzy AND of its inputs.", {in("a")}, {out("truth")},
                              {choice("mode", {"min", "product"}, "min (Zadeh) or product")}), 2));
    c.push_back(variadic(node("rule.or", "rule", "Fuzzy OR of its inputs.", {in("a")}, {out("truth")},
                              {choice("mode", {"max", "probsum"}, "max (Zadeh) or probabilistic sum a+b-ab")}), 2));
    c.push_back(node("rule.not", "rule", "Fuzzy NOT: 1 - x.", {in("x")}, {out("truth")}));
    c.push_back(node("rule.weight", "rule", "Scales a truth by a weight.", {in("x")}, {out("truth")},
                     {num("weight", 1.0f, "factor, >= 0", 0.0f)}));
    c.push_back(node("rule.hedge", "rule", "Hedge: strong (very) squares x, weak (somewhat) takes its square root.",
                     {in("x")}, {out("truth")}, {choice("mode", {"strong", "weak"}, "strong = x^2, weak = sqrt(x)")}));
    NodeSpec priority =
        variadic(node("rule.priority", "rule",
                      "Earlier inputs claim their share of a total truth of 1 first; output i is what input i got.",
                      {in("a", S)}, {out("share", S)}),
                 1);
    priority.outputPerInput = true;
    c.push_back(priority);
    // defuzz
    c.push_back(
        variadic(node("defuzz.average", "defuzz", "Weighted average of candidate values, weighted by their truths.",
                      {in("truth")}, {out("value")},
                      {nums("values", 0, true, "one candidate value per input"),
                       num("default", 0.0f, "the result when every truth is 0")}),
                 1));
    c.push_back(variadic(node("defuzz.winner", "defuzz",
                              "Winner takes all: the index (or value) of the truest input; ties go to the first.",
                              {in("truth", S)}, {out("choice", S), out("strength", S)},
                              {nums("values", 0, false, "optional: one value per input, given instead of the index")}),
                         1));
    // math
    c.push_back(variadic(node("math.add", "math", "Sum of the inputs.", {in("a")}, {out("value")}), 2));
    c.push_back(node("math.subtract", "math", "a - b.", {in("a"), in("b")}, {out("value")}));
    c.push_back(variadic(node("math.multiply", "math", "Product of the inputs.", {in("a")}, {out("value")}), 2));
    c.push_back(node("math.divide", "math", "a / b, or the fallback when b is 0.", {in("a"), in("b")}, {out("value")},
                     {num("fallback", 0.0f, "result of a division by 0")}));
    c.push_back(variadic(node("math.min", "math", "Smallest input.", {in("a")}, {out("value")}), 2));
    c.push_back(variadic(node("math.max", "math", "Largest input.", {in("a")}, {out("value")}), 2));
    c.push_back(node("math.clamp", "math", "x limited to [min, max].", {in("x"), opt("min", "min"), opt("max", "max")},
                     {out("value")},
                     {num("min", 0.0f, "lower limit when the min input is free"),
                      num("max", 1.0f, "upper limit when the max input is free")}));
    c.push_back(node("math.abs", "math", "|x|.", {in("x")}, {out("value")}));
    c.push_back(node("math.lerp", "math", "a + (b - a) t.", {in("a"), in("b"), in("t")}, {out("value")}));
    c.push_back(node("math.remap", "math", "Maps [from0, from1] linearly onto [to0, to1], optionally clamped.",
                     {in("x")}, {out("value")},
                     {nums("from", 2, true, "[from0, from1], from0 != from1"), nums("to", 2, true, "[to0, to1]"),
                      choice("clamp", {"yes", "no"}, "clamp the result to [to0, to1]")}));
    c.push_back(node(
        "math.compare", "math", "1 when the comparison holds, else 0.", {in("a"), opt("b", "value")}, {out("truth")},
        {choice("mode", {"lt", "le", "gt", "ge", "eq", "ne"}, "a < b, a <= b, a > b, a >= b, a == b, a != b"),
         num("value", 0.0f, "b when the b input is free")}));
    // filter
    c.push_back(node("filter", "filter", "Collapses a per-neighbour (or per-source) value to one value per agent.",
                     {in("x", PN)}, {out("value", S)},
                     {choice("mode", {"nearest", "least", "most", "average", "count"},
                             "the first item's value (the nearest neighbour, the loudest source), the least, the most, "
                             "the average, or how many exceed the threshold"),
                      num("threshold", 0.5f, "count: values above this count"),
                      num("empty", 0.0f, "the result with no neighbours")}));
    // state
    NodeSpec memory =
        node("state.memory", "state", "The input's value at the previous step: the only way to close a loop.",
             {in("x", S)}, {out("value", S)}, {num("initial", 0.0f, "the value at the first step")});
    memory.breaksCycles = true;
    c.push_back(memory);
    c.push_back(node("state.timer", "state", "Seconds the input has been continuously above 0.5; 0 when it is not.",
                     {in("run", S)}, {out("seconds", S)}));
    c.push_back(node("state.latch", "state", "Becomes 1 when set > 0.5 and stays 1 until reset > 0.5 (reset wins).",
                     {in("set", S), opt("reset", "", S)}, {out("value", S)},
                     {num("initial", 0.0f, "the value at the first step", 0.0f, 1.0f)}));
    c.push_back(node("state.smooth", "state", "Exponential smoothing of the input with a time constant.",
                     {in("x", S)}, {out("value", S)}, {num("tau", 0.5f, "time constant in seconds", 1e-4f)}));
    // output
    c.push_back(node(
        "output", "output",
        "Drives the agent: desired speed, turn, a steering behaviour's weight or a tag others sense.", {in("x", S)}, {},
        {choice("channel", {"speed", "turn", "weight", "tag"}, "speed (m/s), turn (degrees/s, + = left), weight, tag"),
         text("behaviour", false, "weight: the steering behaviour"), text("tag", false, "tag: the tag's name"),
         num("scale", 1.0f, "factor applied to the input")}));
    c.push_back(
        variadic(node("output.action", "output",
                      "Action layer: the most desirable action becomes current whenever the current clip ends.",
                      {in("desire", S)}, {out("action", S)},
                      {text("actions", true,
                            "action names, space-separated: idle walk run, a clip (wait look_around wave talk "
                            "phone cheer sit shift_weight point fall get_up) or your own"),
                       nums("durations", 0, false, "clip length per action in seconds; 0 = may change every step")}),
                 1));
    c.push_back(
        variadic(node("output.goal", "output", "Goal choice: the goal with the most desirable input (ties: the first).",
                      {in("desire", S)}, {out("goal", S)}, {text("goals", true, "goal names, space-separated")}),
                 1));
    // macro
    c.push_back(
        variadic(node("macro", "macro",
                      "A brain used as a node: its macro.in nodes are the inputs, its macro.out nodes the outputs.",
                      {in("in")}, {out("out")}, {text("brain", true, "the name of the brain to use")}),
                 0));
    c.push_back(node(
        "macro.in", "macro", "Inside a macro brain: the value of the macro node's input number `port`.", {},
        {out("value")},
        {num("port", 0.0f, "input index", 0.0f, 255.0f), num("value", 0.0f, "value when used as a brain of its own")}));
    c.push_back(node("macro.out", "macro", "Inside a macro brain: makes x the macro node's output number `port`.",
                     {in("x")}, {}, {num("port", 0.0f, "output index", 0.0f, 255.0f)}));
    // probe / note
    c.push_back(node("probe", "probe", "Shows and logs its input for the picked agent.", {in("x")}, {},
                     {text("name", false, "the label in the log")}));
    c.push_back(
        node("note", "probe", "A text note on the graph; does nothing.", {}, {}, {text("text", false, "the note")}));
    return c;
}

SensorSpec sensor(std::string name, std::string unit, std::string what, std::string argument = {}, bool pn = false)
{
    std::string set = pn ? (name.rfind("sound", 0) == 0 ? "sound" : "neighbours") : "";
    return {std::move(name), pn, std::move(set), std::move(argument), std::move(unit), std::move(what)};
}

}  // namespace

const std::vector<NodeSpec>& nodeCatalogue()
{
    static const std::vector<NodeSpec> catalogue = makeCatalogue();
    return catalogue;
}

const NodeSpec* findNodeSpec(std::string_view type)
{
    for (const NodeSpec& n : nodeCatalogue())
        if (n.type == type)
            return &n;
    return nullptr;
}

const std::vector<SensorSpec>& sensorCatalogue()
{
    static const std::vector<SensorSpec> sensors{
        sensor("speed", "m/s", "the agent's speed"),
        sensor("goal_bearing", "degrees", "direction of the goal, + = left of the heading"),
        sensor("goal_distance", "m", "distance to the goal"),
        sensor("path_offset", "m", "signed distance from the path's centre line, + = left"),
        sensor("flow_bearing", "degrees", "direction of the flow field, + = left of the heading"),
        sensor("neighbour_count", "", "neighbours perceived (radius and view cone)"),
        sensor("neighbour_density", "1/m^2", "neighbours perceived per square metre of the perception area"),
        sensor("nearest_distance", "m",
               "distance to the nearest perceived neighbour (the perception radius when none)"),
        sensor("nearest_bearing", "degrees", "direction of the nearest neighbour, + = left (0 when none)"),
        sensor("vision_left", "", "neighbours in the left third of the view cone"),
        sensor("vision_centre", "", "neighbours in the centre third of the view cone"),
        sensor("vision_right", "", "neighbours in the right third of the view cone"),
        sensor("sound_bearing", "degrees", "direction of the loudest source heard on the channel", "channel"),
        sensor("sound_distance", "m", "distance to the loudest source heard on the channel", "channel"),
        sensor("sound_strength", "0..1", "loudness of the loudest source heard on the channel (0 = silence)",
               "channel"),
        sensor("feeler_left", "m", "free distance along the left feeler (its length when clear)"),
        sensor("feeler_centre", "m", "free distance straight ahead (the feeler length when clear)"),
        sensor("feeler_right", "m", "free distance along the right feeler (its length when clear)"),
        sensor("wall_distance", "m", "distance to the nearest wall"),
        sensor("light_state", "0..1", "the traffic light ahead: 0 green or none, 0.5 amber, 1 red"),
        sensor("stop_line_distance", "m", "distance to the stop line ahead (large when none)"),
        sensor("hero_distance", "m", "distance to the nearest hero (large when none)"),
        sensor("hero_bearing", "degrees", "direction of the nearest hero, + = left"),
        sensor("action_point_distance", "m",
               "distance to the nearest action point's edge this agent stops at (0 inside; large when none)"),
        sensor("action_point_bearing", "degrees", "direction of that action point's centre, + = left (0 when none)"),
        sensor("action_point_time", "s", "seconds left of the action the agent plays at an action point (0 when none)"),
        sensor("terrain_slope", "degrees", "slope of the ground along the heading, + = uphill"),
        sensor("time", "s", "simulation time"),
        sensor("attribute", "", "an agent attribute (max_speed, radius, speed_factor, ...)", "name"),
        sensor("neighbour_distance", "m", "distance to each perceived neighbour", {}, true),
        sensor("neighbour_bearing", "degrees", "direction of each neighbour, + = left", {}, true),
        sensor("neighbour_speed", "m/s", "speed of each neighbour", {}, true),
        sensor("neighbour_heading", "degrees", "each neighbour's heading relative to the agent's, + = left", {}, true),
        sensor("neighbour_tag", "", "each neighbour's value of a tag (set by its output node)", "tag", true),
        sensor("sound_source_bearing", "degrees",
               "direction of each source heard on the channel, loudest first, + = left", "channel", true),
        sensor("sound_source_distance", "m", "distance to each source heard on the channel, loudest first", "channel",
               true),
        sensor("sound_source_strength", "0..1", "loudness of each source heard on the channel, loudest first",
               "channel", true),
    };
    return sensors;
}

const SensorSpec* findSensorSpec(std::string_view name)
{
    for (const SensorSpec& s : sensorCatalogue())
        if (s.name == name)
            return &s;
    return nullptr;
}

const std::vector<std::string>& outputChannels()
{
    static const std::vector<std::string> channels{"speed", "turn", "weight", "tag"};
    return channels;
}

const std::vector<std::string>& builtinActions()
{
    static const std::vector<std::string> actions{"idle", "walk", "run", "wait"};
    return actions;
}

}  // namespace throng::sim
