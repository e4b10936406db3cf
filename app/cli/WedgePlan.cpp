#include "WedgePlan.h"

#include <yaml-cpp/yaml.h>

#include <charconv>
#include <cstdio>

namespace throng::cli {

namespace {

bool parseNumber(const std::string& text, std::uint64_t& out)
{
    const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && p == text.data() + text.size() && !text.empty();
}

}  // namespace

std::optional<WedgeAxis> parseAxis(const std::string& text, std::string& error)
{
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0) {
        error = "--set " + text + ": not KEY=V1,V2,...";
        return std::nullopt;
    }
    WedgeAxis axis{text.substr(0, eq), {}};
    if (std::string why; !sim::parseOverride(axis.key + "=x", why)) {
        error = "--set " + text + ": " + why;
        return std::nullopt;
    }
    int depth = 0;
    std::string value;
    for (const char c : text.substr(eq + 1) + ",") {
        if (c == ',' && depth == 0) {
            if (value.empty()) {
                error = "--set " + text + ": an empty value";
                return std::nullopt;
            }
            axis.values.push_back(value);
            value.clear();
            continue;
        }
        depth += (c == '[' || c == '{') ? 1 : (c == ']' || c == '}') ? -1 : 0;
        value += c;
    }
    return axis;
}

std::optional<std::vector<std::uint64_t>> parseSeeds(const std::string& text, std::string& error)
{
    std::vector<std::uint64_t> seeds;
    if (const std::size_t dots = text.find(".."); dots != std::string::npos) {
        std::uint64_t a = 0, b = 0;
        if (!parseNumber(text.substr(0, dots), a) || !parseNumber(text.substr(dots + 2), b) || a > b ||
            b - a >= 100'000) {
            error = "--seeds " + text + ": not A..B with A <= B (at most 100,000 seeds)";
            return std::nullopt;
        }
        for (std::uint64_t s = a; s <= b; ++s)
            seeds.push_back(s);
        return seeds;
    }
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        std::uint64_t s = 0;
        if (!parseNumber(text.substr(start, comma - start), s)) {
            error = "--seeds " + text + ": not A..B or A,B,C (whole numbers)";
            return std::nullopt;
        }
        seeds.push_back(s);
        start = comma + 1;
    }
    return seeds;
}

std::vector<WedgeVariant> expandVariants(const std::vector<WedgeAxis>& axes, const std::vector<std::uint64_t>& seeds)
{
    std::vector<std::vector<sim::SceneOverride>> combos{{}};
    for (const WedgeAxis& axis : axes) {
        std::vector<std::vector<sim::SceneOverride>> next;
        for (const auto& combo : combos)
            for (const std::string& v : axis.values) {
                next.push_back(combo);
                next.back().push_back({axis.key, v});
            }
        combos = std::move(next);
    }
    std::vector<WedgeVariant> variants;
    const std::vector<std::optional<std::uint64_t>> each =
        seeds.empty() ? std::vector<std::optional<std::uint64_t>>{std::nullopt}
                      : std::vector<std::optional<std::uint64_t>>(seeds.begin(), seeds.end());
    for (const auto& combo : combos)
        for (const std::optional<std::uint64_t>& seed : each) {
            WedgeVariant v;
            v.index = variants.size();
            char name[16];
            std::snprintf(name, sizeof name, "v%03zu", v.index);
            v.folder = name;
            v.overrides = combo;
            v.seed = seed;
            variants.push_back(std::move(v));
        }
    return variants;
}

std::string planToYaml(const WedgePlan& plan)
{
    YAML::Emitter y;
    y << YAML::BeginMap;
    y << YAML::Key << "throng_wedge" << YAML::Value << 1;
    y << YAML::Key << "scene" << YAML::Value << plan.scene;
    y << YAML::Key << "axes" << YAML::Value << YAML::BeginSeq;
    for (const WedgeAxis& a : plan.axes) {
        y << YAML::Flow << YAML::BeginMap << YAML::Key << "key" << YAML::Value << a.key;
        y << YAML::Key << "values" << YAML::Value << YAML::Flow << a.values << YAML::EndMap;
    }
    y << YAML::EndSeq;
    y << YAML::Key << "seeds" << YAML::Value << YAML::Flow << plan.seeds;
    y << YAML::Key << "variants" << YAML::Value << YAML::BeginSeq;
    for (const WedgeVariant& v : plan.variants) {
        y << YAML::Flow << YAML::BeginMap << YAML::Key << "folder" << YAML::Value << v.folder;
        if (v.seed)
            y << YAML::Key << "seed" << YAML::Value << *v.seed;
        y << YAML::Key << "set" << YAML::Value << YAML::Flow << YAML::BeginSeq;
        for (const sim::SceneOverride& o : v.overrides)
            y << (o.key + "=" + o.value);
        y << YAML::EndSeq << YAML::EndMap;
    }
    y << YAML::EndSeq << YAML::EndMap;
    return std::string(y.c_str()) + "\n";
}

std::optional<WedgePlan> planFromYaml(const std::string& text, std::string& error)
{
    try {
        const YAML::Node root = YAML::Load(text);
        if (!root.IsMap() || !root["throng_wedge"] || !root["variants"] || !root["variants"].IsSequence()) {
            error = "not a wedge plan (no throng_wedge and variants)";
            return std::nullopt;
        }
        WedgePlan plan;
        plan.scene = root["scene"].as<std::string>("");
        for (const YAML::Node& a : root["axes"])
            plan.axes.push_back({a["key"].as<std::string>(), a["values"].as<std::vector<std::string>>()});
        if (root["seeds"])
            plan.seeds = root["seeds"].as<std::vector<std::uint64_t>>();
        for (const YAML::Node& v : root["variants"]) {
            WedgeVariant variant;
            variant.index = plan.variants.size();
            variant.folder = v["folder"].as<std::string>();
            if (v["seed"])
                variant.seed = v["seed"].as<std::uint64_t>();
            for (const YAML::Node& s : v["set"]) {
                std::string why;
                if (const auto o = sim::parseOverride(s.as<std::string>(), why))
                    variant.overrides.push_back(*o);
            }
            if (variant.folder.empty() || variant.folder.find('/') != std::string::npos ||
                variant.folder.find("..") != std::string::npos) {
                error = "a variant's folder '" + variant.folder + "' is not a plain name";
                return std::nullopt;
            }
            plan.variants.push_back(std::move(variant));
        }
        return plan;
    } catch (const YAML::Exception& e) {
        error = e.what();
        return std::nullopt;
    }
}

}  // namespace throng::cli
