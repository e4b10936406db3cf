// docs/brains.md's reference section is generated from the catalogue, so the two cannot
// drift: tests/brain checks that the file holds exactly this text.
#include "simcore/brain/NodeCatalogue.h"

#include <cstdio>
#include <sstream>

namespace throng::sim {

namespace {

const char* kindName(PortKind k)
{
    switch (k) {
    case PortKind::Scalar: return "scalar";
    case PortKind::PerNeighbour: return "per-neighbour";
    case PortKind::Any: return "scalar or per-neighbour";
    }
    return "";
}

std::string number(float v)
{
    if (v <= -1e29f || v >= 1e29f)
        return "";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(v));
    return buf;
}

std::string paramType(const ParamSpec& p)
{
    switch (p.type) {
    case ParamType::Number: {
        const std::string lo = number(p.min), hi = number(p.max);
        if (lo.empty() && hi.empty())
            return "number";
        return "number in [" + (lo.empty() ? std::string("-inf") : lo) + ", " + (hi.empty() ? std::string("inf") : hi) +
               "]";
    }
    case ParamType::Numbers: return p.count ? "list of " + std::to_string(p.count) + " numbers" : "list of numbers";
    case ParamType::Text: return "text";
    case ParamType::Choice: {
        std::string s = "one of";
        for (const std::string& c : p.choices)
            s += " `" + c + "`";
        return s;
    }
    }
    return "";
}

std::string paramDefault(const ParamSpec& p)
{
    if (p.required)
        return "*required*";
    switch (p.type) {
    case ParamType::Number: return number(p.defaultValue);
    case ParamType::Choice: return "`" + p.choices.front() + "`";
    default: return "none";
    }
}

void writePorts(std::ostringstream& o, const char* title, const NodeSpec& n, const std::vector<PortSpec>& ports,
                bool inputs)
{
    if (ports.empty())
        return;
    o << "- " << title << ":";
    for (std::size_t i = 0; i < ports.size(); ++i) {
        const PortSpec& p = ports[i];
        const bool repeats = inputs ? n.variadic && i + 1 == ports.size() : n.outputPerInput;
        o << (i ? "," : "") << " " << i << (repeats ? "…" : "") << " `" << p.name << "` (" << kindName(p.kind);
        if (inputs && !p.required)
            o << ", optional" << (p.fallbackParam.empty() ? "" : ", else param `" + p.fallbackParam + "`");
        o << ")";
    }
    if (inputs && n.variadic)
        o << "; ports " << ports.size() - 1 << ", " << ports.size() << ", … repeat, at least " << n.minInputs
          << " connected";
    if (!inputs && n.outputPerInput)
        o << "; one output per input";
    o << "\n";
}

}  // namespace

std::string brainCatalogueMarkdown()
{
    std::ostringstream o;
    o << "### Node types\n\n";
    std::string category;
    for (const NodeSpec& n : nodeCatalogue()) {
        if (n.category != category) {
            category = n.category;
            o << "#### " << category << "\n\n";
        }
        o << "**`" << n.type << "`** — " << n.description << "\n\n";
        writePorts(o, "Inputs", n, n.inputs, true);
        writePorts(o, "Outputs", n, n.outputs, false);
        if (n.breaksCycles)
            o << "- Its input is read after the step, so a loop through it is legal.\n";
        if (!n.inputs.empty() || !n.outputs.empty())
            o << "\n";
        if (!n.params.empty()) {
            o << "| Parameter | Type | Default | Meaning |\n|---|---|---|---|\n";
            for (const ParamSpec& p : n.params)
                o << "| `" << p.key << "` | " << paramType(p) << " | " << paramDefault(p) << " | " << p.description
                  << " |\n";
            o << "\n";
        }
    }
    o << "### Sensors\n\nThe `sensor` parameter of an `input` node names one of these.\n\n";
    o << "| Sensor | Kind | Unit | Parameter | Meaning |\n|---|---|---|---|---|\n";
    for (const SensorSpec& s : sensorCatalogue())
        o << "| `" << s.name << "` | "
          << (s.itemSet == "sound" ? "per-source"
              : s.perNeighbour     ? "per-neighbour"
                                   : "scalar")
          << " | " << s.unit << " | " << (s.argument.empty() ? "" : "`" + s.argument + "`") << " | " << s.description
          << " |\n";
    return o.str();
}

}  // namespace throng::sim
