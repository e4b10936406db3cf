#include "simcore/scenarios/BenchBrains.h"

#include <string>
#include <utility>
#include <vector>

namespace throng::sim {

namespace {

struct Builder {
    BrainGraph g;
    NodeId add(std::string type, std::vector<BrainParam> params = {}, std::vector<NodeId> inputs = {})
    {
        const NodeId id = NodeId(g.nodes.size() + 1);
        g.nodes.push_back({id, std::move(type), {}, {}, std::move(params)});
        for (std::size_t p = 0; p < inputs.size(); ++p)
            g.links.push_back({inputs[p], 0, id, std::uint32_t(p)});
        return id;
    }
    NodeId sensor(const std::string& s, std::vector<BrainParam> extra = {})
    {
        extra.insert(extra.begin(), {"sensor", s, {}});
        return add("input", std::move(extra));
    }
};

BrainParam n(std::string k, float v) { return {std::move(k), {}, {v}}; }
BrainParam pts(std::vector<float> v) { return {"points", {}, std::move(v)}; }
BrainParam t(std::string k, std::string v) { return {std::move(k), std::move(v), {}}; }

}  // namespace

BrainGraph benchPedestrianBrain()
{
    Builder b;
    const NodeId gd = b.sensor("goal_distance"), gb = b.sensor("goal_bearing"), light = b.sensor("light_state");
    const NodeId line = b.sensor("stop_line_distance"), nearest = b.sensor("nearest_distance"),
                 speed = b.sensor("speed");
    const NodeId nd = b.sensor("neighbour_distance"), nb = b.sensor("neighbour_bearing");
    const NodeId maxSpeed = b.sensor("attribute", {t("name", "max_speed")});
    const NodeId far = b.add("fuzz.trapezoid", {pts({0.2f, 1.5f, 1e6f, 1e6f})}, {gd});
    const NodeId red = b.add("fuzz.trapezoid", {pts({0.25f, 0.5f, 2, 2})}, {light});
    const NodeId atLine = b.add("fuzz.trapezoid", {pts({-0.05f, 0, 1.5f, 3.5f})}, {line});
    const NodeId crowded = b.add("fuzz.trapezoid", {pts({-1, 0, 0.5f, 1.2f})}, {nearest});
    const NodeId left = b.add("fuzz.sigmoid", {n("centre", 10), n("slope", 0.1f)}, {gb});
    const NodeId right = b.add("fuzz.sigmoid", {n("centre", -10), n("slope", -0.1f)}, {gb});
    const NodeId straight = b.add("fuzz.gaussian", {n("centre", 0), n("width", 15)}, {gb});
    const NodeId close = b.add("fuzz.trapezoid", {pts({-1, 0, 1, 3})}, {nd});
    const NodeId ahead = b.add("fuzz.triangle", {pts({-45, 0, 45})}, {nb});
    const NodeId threatEach = b.add("rule.and", {}, {close, ahead});
    const NodeId threat = b.add("filter", {t("mode", "most")}, {threatEach});
    const NodeId mustStop = b.add("rule.and", {}, {red, atLine});
    const NodeId stop = b.add("rule.or", {}, {mustStop, threat});
    const NodeId go = b.add("rule.not", {}, {stop});
    const NodeId walk = b.add("rule.and", {t("mode", "product")}, {go, far});
    const NodeId polite = b.add("rule.hedge", {t("mode", "weak")}, {crowded});
    const NodeId ease = b.add("math.remap", {{"from", {}, {0, 1}}, {"to", {}, {1, 0.6f}}}, {polite});
    const NodeId noise = b.add("input.noise", {n("frequency", 0.3f), n("min", 0.9f), n("max", 1.0f)});
    const NodeId want = b.add("math.multiply", {}, {walk, maxSpeed, ease, noise});
    const NodeId smooth = b.add("state.smooth", {n("tau", 0.3f)}, {want});
    b.add("output", {t("channel", "speed")}, {smooth});
    const NodeId turn = b.add("defuzz.average", {{"values", {}, {90, -90, 0}}}, {left, right, straight});
    b.add("output", {t("channel", "turn")}, {turn});
    const NodeId sep = b.add("math.remap", {{"from", {}, {0, 1}}, {"to", {}, {1, 4}}}, {crowded});
    b.add("output", {t("channel", "weight"), t("behaviour", "separation")}, {sep});
    b.add("output", {t("channel", "weight"), t("behaviour", "arrival")}, {go});
    const NodeId arrived = b.add("rule.not", {}, {far});
    b.add("output.action", {t("actions", "idle walk wait"), {"durations", {}, {1, 0, 0.5f}}}, {arrived, walk, stop});
    const NodeId before = b.add("state.memory", {}, {speed});
    const NodeId change = b.add("math.subtract", {}, {speed, before});
    b.add("math.abs", {}, {change});
    b.g.name = "bench40";
    return b.g;
}

// Turns toward the loudest agent heard on "chat" and slows when many are heard.
BrainGraph benchListenerBrain()
{
    Builder b;
    const NodeId bearing =
        b.add("filter", {t("mode", "nearest")}, {b.sensor("sound_source_bearing", {t("channel", "chat")})});
    b.add("output", {t("channel", "turn")}, {bearing});
    const NodeId heard = b.add("filter", {t("mode", "count"), n("threshold", 0.2f)},
                               {b.sensor("sound_source_strength", {t("channel", "chat")})});
    b.add("output", {t("channel", "speed")},
          {b.add("math.remap", {{"from", {}, {0, 8}}, {"to", {}, {1.4f, 0.4f}}}, {heard})});
    b.g.name = "listen";
    return b.g;
}

}  // namespace throng::sim
