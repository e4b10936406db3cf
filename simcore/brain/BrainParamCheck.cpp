// Parameter checks: each parameter against the catalogue (type, count, range, choice),
// then the rules a node type adds (sensor names, ordered points, known behaviours).
#include "simcore/brain/detail/BrainFlatGraph.h"

#include "simcore/scene/Scene.h"

#include <algorithm>
#include <cstdio>

namespace throng::sim::detail {

namespace {

std::string show(float v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(v));
    return buf;
}

bool checkOne(const BrainParam& p, const ParamSpec& s, std::string& why)
{
    switch (s.type) {
    case ParamType::Number:
        if (!p.text.empty() || p.numbers.size() != 1) {
            why = "must be a number";
            return false;
        }
        if (p.numbers[0] < s.min || p.numbers[0] > s.max) {
            why = "must be in [" + show(s.min) + ", " + show(s.max) + "], not " + show(p.numbers[0]);
            return false;
        }
        return true;
    case ParamType::Numbers:
        if (!p.text.empty()) {
            why = "must be a list of numbers";
            return false;
        }
        if (s.count && p.numbers.size() != s.count) {
            why = "needs " + std::to_string(s.count) + " numbers, not " + std::to_string(p.numbers.size());
            return false;
        }
        return true;
    case ParamType::Text:
        if (p.text.empty()) {
            why = "must be text";
            return false;
        }
        return true;
    case ParamType::Choice:
        if (std::find(s.choices.begin(), s.choices.end(), p.text) == s.choices.end()) {
            why = "must be one of";
            for (const std::string& c : s.choices)
                why += " " + c;
            why += ", not '" + (p.text.empty() && !p.numbers.empty() ? show(p.numbers[0]) : p.text) + "'";
            return false;
        }
        return true;
    }
    return true;
}

bool ascending(const std::vector<float>& v)
{
    return std::is_sorted(v.begin(), v.end());
}

}  // namespace

void checkNodeParams(FlatNode& n, BrainErrorList& errors)
{
    const auto bad = [&](const std::string& message) {
        errors.at(n, message);
        n.badParams = true;
    };
    for (const BrainParam& p : n.node->params) {
        const auto s = std::find_if(n.spec->params.begin(), n.spec->params.end(),
                                    [&](const ParamSpec& ps) { return ps.key == p.key; });
        std::string why;
        if (s == n.spec->params.end())
            bad("unknown parameter '" + p.key + "'");
        else if (!checkOne(p, *s, why))
            bad("parameter '" + p.key + "' " + why);
    }
    for (const ParamSpec& s : n.spec->params) {
        const bool given = std::any_of(n.node->params.begin(), n.node->params.end(),
                                       [&](const BrainParam& p) { return p.key == s.key; });
        if (s.required && !given)
            bad("missing parameter '" + s.key + "'");
    }
    if (n.badParams)
        return;
    const std::string& type = n.node->type;
    if (type == "input") {
        const std::string name = textParam(n, "sensor");
        const SensorSpec* sensor = findSensorSpec(name);
        if (!sensor)
            bad("unknown sensor '" + name + "'");
        else if (!sensor->argument.empty() && textParam(n, sensor->argument).empty())
            bad("sensor '" + name + "' needs parameter '" + sensor->argument + "'");
    } else if (type == "fuzz.triangle" || type == "fuzz.trapezoid") {
        if (!ascending(*numbersParam(n, "points")))
            bad("parameter 'points' must be in ascending order");
    } else if (type == "math.remap") {
        const std::vector<float>& from = *numbersParam(n, "from");
        if (from[0] == from[1])
            bad("parameter 'from' needs two different numbers");
    } else if (type == "output") {
        const std::string channel = textParam(n, "channel");
        if (channel == "weight") {
            const std::string b = textParam(n, "behaviour");
            const auto& names = behaviourNames();
            if (b.empty())
                bad("channel 'weight' needs parameter 'behaviour'");
            else if (std::find(names.begin(), names.end(), b) == names.end())
                bad("unknown steering behaviour '" + b + "'");
        } else if (channel == "tag" && textParam(n, "tag").empty()) {
            bad("channel 'tag' needs parameter 'tag'");
        }
    } else if (type == "output.action" || type == "output.goal") {
        const auto names = words(textParam(n, type == "output.action" ? "actions" : "goals"));
        for (std::size_t i = 0; i < names.size(); ++i)
            for (std::size_t j = 0; j < i; ++j)
                if (names[i] == names[j])
                    bad("'" + names[i] + "' is listed twice");
        if (const std::vector<float>* d = numbersParam(n, "durations"); d && type == "output.action") {
            if (d->size() != names.size())
                bad("parameter 'durations' needs one number per action (" + std::to_string(names.size()) + ")");
            else if (std::any_of(d->begin(), d->end(), [](float v) { return v < 0.0f; }))
                bad("parameter 'durations' must not be negative");
        }
    }
}

}  // namespace throng::sim::detail
