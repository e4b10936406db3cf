#include "simcore/io/detail/YamlFields.h"

#include "simcore/io/SceneLimits.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace throng::sim::detail {

namespace {

const char* typeName(const YAML::Node& node)
{
    switch (node.Type()) {
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Null: return "nothing";
    case YAML::NodeType::Scalar: return "a scalar";
    case YAML::NodeType::Undefined: return "nothing";
    }
    return "something else";
}

std::string shortest(float v)
{
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

}  // namespace

bool parseFiniteFloat(const std::string& text, float& out, std::string& why)
{
    const std::string l = lower(text);
    if (l == ".nan" || l == "nan" || l == "-nan" || l == ".inf" || l == "inf" || l == "+.inf" ||
        l == "-.inf" || l == "-inf" || l == "+inf" || l == "infinity" || l == "-infinity") {
        why = "is not finite ('" + text + "')";
        return false;
    }
    const char* begin = text.data();
    const char* end = text.data() + text.size();
    if (begin != end && *begin == '+')
        ++begin;
    double value = 0.0;
    auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec == std::errc::result_out_of_range) {
        why = "is out of range ('" + text + "')";
        return false;
    }
    if (ec != std::errc() || ptr != end || begin == end) {
        why = "must be a number, got '" + text + "'";
        return false;
    }
    if (!std::isfinite(value)) {
        why = "is not finite ('" + text + "')";
        return false;
    }
    if (std::fabs(value) > double(std::numeric_limits<float>::max())) {
        why = "is out of range for a 32-bit float ('" + text + "')";
        return false;
    }
    out = float(value);
    return true;
}

bool isValidName(const std::string& name)
{
    if (name.empty() || name == "-")
        return false;
    // '#' starts a comment in agent tables, so it cannot be part of a name.
    return std::none_of(name.begin(), name.end(),
                        [](unsigned char c) { return std::isspace(c) || c < 32 || c == '#'; });
}

std::string indexKey(const std::string& key, std::size_t index) { return key + "[" + std::to_string(index) + "]"; }
std::string childKey(const std::string& key, const char* name) { return key.empty() ? name : key + "." + name; }

void YamlFields::error(const YAML::Mark& at, const std::string& key, const std::string& message)
{
    errorAtLine(at.line >= 0 ? at.line + 1 : 0, at.column >= 0 ? at.column + 1 : 0, key, message);
}

void YamlFields::errorAtLine(int line1, int col1, const std::string& key, const std::string& message)
{
    m_out.push_back({Severity::Error, m_file, line1, col1, key, message});
    ++m_errors;
}

void YamlFields::warning(const YAML::Mark& at, const std::string& key, const std::string& message)
{
    m_out.push_back({Severity::Warning, m_file, at.line >= 0 ? at.line + 1 : 0,
                     at.column >= 0 ? at.column + 1 : 0, key, message});
}

bool YamlFields::expectMap(const YAML::Node& node, const std::string& key)
{
    if (node.IsMap())
        return true;
    error(node.Mark(), key, std::string("expected a map, got ") + typeName(node));
    return false;
}

bool YamlFields::expectSequence(const YAML::Node& node, const std::string& key)
{
    if (node.IsSequence())
        return true;
    error(node.Mark(), key, std::string("expected a list, got ") + typeName(node));
    return false;
}

void YamlFields::checkKeys(const YAML::Node& map, const std::string& key, std::initializer_list<const char*> allowed)
{
    checkKeysImpl(map, key, std::span<const char* const>(allowed.begin(), allowed.size()), true);
}

void YamlFields::checkKeys(const YAML::Node& map, const std::string& key, std::span<const char* const> allowed)
{
    checkKeysImpl(map, key, allowed, true);
}

void YamlFields::checkDuplicateKeys(const YAML::Node& map, const std::string& key)
{
    checkKeysImpl(map, key, {}, false);
}

void YamlFields::checkKeysImpl(const YAML::Node& map, const std::string& key,
                               std::span<const char* const> allowed, bool warnUnknown)
{
    std::map<std::string, int> seen;
    for (auto it = map.begin(); it != map.end(); ++it) {
        if (!it->first.IsScalar()) {
            error(it->first.Mark(), key, "a key must be a plain name");
            continue;
        }
        const std::string name = it->first.Scalar();
        const int line = it->first.Mark().line + 1;
        if (auto [pos, inserted] = seen.emplace(name, line); !inserted) {
            error(it->first.Mark(), childKey(key, name.c_str()),
                  "duplicate key (first given on line " + std::to_string(pos->second) + ")");
            continue;
        }
        const bool known = std::any_of(allowed.begin(), allowed.end(), [&](const char* a) { return name == a; });
        if (warnUnknown && !known)
            warning(it->first.Mark(), childKey(key, name.c_str()), "unknown key '" + name + "' is ignored");
    }
}

YAML::Node YamlFields::find(const YAML::Node& map, const char* name, const std::string& key, bool required)
{
    if (map.IsMap()) {
        // Iterate rather than index so the first of duplicate keys wins, as checkKeys
        // reports. A default-constructed YAML::Node counts as defined, so return early.
        for (auto it = map.begin(); it != map.end(); ++it)
            if (it->first.IsScalar() && it->first.Scalar() == name)
                return it->second;
    }
    if (required)
        error(map.Mark(), childKey(key, name), std::string("missing required key '") + name + "'");
    // A const lookup of a missing key yields an undefined node and inserts nothing.
    const YAML::Node& constMap = map;
    return constMap[name];
}

bool YamlFields::inRange(float v, Range range, const YAML::Mark& at, const std::string& key)
{
    switch (range) {
    case Range::Any: return true;
    case Range::NonNegative:
        if (v >= 0.0f) return true;
        error(at, key, "must not be negative, got " + shortest(v));
        return false;
    case Range::Positive:
        if (v > 0.0f) return true;
        error(at, key, "must be greater than 0, got " + shortest(v));
        return false;
    case Range::Unit:
        if (v >= 0.0f && v <= 1.0f) return true;
        error(at, key, "must be between 0 and 1, got " + shortest(v));
        return false;
    }
    return true;
}

bool YamlFields::toFloat(const YAML::Node& node, const std::string& key, float& out, Range range)
{
    if (!node.IsScalar()) {
        error(node.Mark(), key, std::string("must be a number, got ") + typeName(node));
        return false;
    }
    float v = 0.0f;
    std::string why;
    if (!parseFiniteFloat(node.Scalar(), v, why)) {
        error(node.Mark(), key, why);
        return false;
    }
    if (!inRange(v, range, node.Mark(), key))
        return false;
    out = v;
    return true;
}

bool YamlFields::toVec2(const YAML::Node& node, const std::string& key, glm::vec2& out, Range range)
{
    if (!node.IsSequence() || node.size() != 2) {
        error(node.Mark(), key, std::string("must be a list of 2 numbers, got ") +
                                    (node.IsSequence() ? std::to_string(node.size()) + " items" : typeName(node)));
        return false;
    }
    glm::vec2 v;
    if (!toFloat(node[0], indexKey(key, 0), v.x, range) || !toFloat(node[1], indexKey(key, 1), v.y, range))
        return false;
    for (int i = 0; i < 2; ++i)
        if (!withinWorld(v[i], node[std::size_t(i)].Mark(), indexKey(key, std::size_t(i))))
            return false;
    out = v;
    return true;
}

bool YamlFields::withinWorld(float v, const YAML::Mark& at, const std::string& key)
{
    if (std::abs(v) <= kMaxCoordinateM)
        return true;
    char m[128];
    std::snprintf(m, sizeof m, "%g is beyond %g m from the origin (a typo? lengths this far overflow)", double(v),
                  double(kMaxCoordinateM));
    error(at, key, m);
    return false;
}

bool YamlFields::readFloat(const YAML::Node& map, const char* name, const std::string& key, float& out,
                           bool required, Range range)
{
    YAML::Node node = find(map, name, key, required);
    if (!node.IsDefined())
        return !required;
    return toFloat(node, childKey(key, name), out, range);
}

bool YamlFields::readUInt(const YAML::Node& map, const char* name, const std::string& key, std::uint64_t& out,
                          bool required, std::uint64_t maxValue)
{
    YAML::Node node = find(map, name, key, required);
    if (!node.IsDefined())
        return !required;
    const std::string k = childKey(key, name);
    if (!node.IsScalar()) {
        error(node.Mark(), k, std::string("must be a whole number, got ") + typeName(node));
        return false;
    }
    const std::string& s = node.Scalar();
    std::uint64_t v = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec == std::errc::result_out_of_range || (ec == std::errc() && v > maxValue)) {
        error(node.Mark(), k, "is out of range ('" + s + "', at most " + std::to_string(maxValue) + ")");
        return false;
    }
    if (ec != std::errc() || ptr != s.data() + s.size() || s.empty()) {
        error(node.Mark(), k, "must be a whole number >= 0, got '" + s + "'");
        return false;
    }
    out = v;
    return true;
}

bool YamlFields::readU32(const YAML::Node& map, const char* name, const std::string& key, std::uint32_t& out,
                         bool required)
{
    std::uint64_t v = out;
    if (!readUInt(map, name, key, v, required, std::numeric_limits<std::uint32_t>::max()))
        return false;
    out = std::uint32_t(v);
    return true;
}

bool YamlFields::readIndexOfType(const YAML::Node& map, const char* name, const std::string& key, int& out,
                                 std::size_t count, const std::string& typeName)
{
    std::uint32_t v = 0;
    if (!map[name].IsDefined() || !readU32(map, name, key, v, false))
        return false;
    if (!typeName.empty() && v >= count) {
        error(map[name].Mark(), key + "." + name,
              std::string(name) + " " + std::to_string(v) + " is out of range: type '" + typeName + "' has " +
                  std::to_string(count));
        return false;
    }
    out = int(v);
    return true;
}

bool YamlFields::readBool(const YAML::Node& map, const char* name, const std::string& key, bool& out, bool required)
{
    YAML::Node node = find(map, name, key, required);
    if (!node.IsDefined())
        return !required;
    const std::string s = node.IsScalar() ? lower(node.Scalar()) : std::string();
    if (s == "true" || s == "yes" || s == "on") {
        out = true;
        return true;
    }
    if (s == "false" || s == "no" || s == "off") {
        out = false;
        return true;
    }
    error(node.Mark(), childKey(key, name),
          "must be true or false, got " + (node.IsScalar() ? "'" + node.Scalar() + "'" : std::string(typeName(node))));
    return false;
}

bool YamlFields::readString(const YAML::Node& map, const char* name, const std::string& key, std::string& out,
                            bool required)
{
    YAML::Node node = find(map, name, key, required);
    if (!node.IsDefined())
        return !required;
    if (!node.IsScalar()) {
        error(node.Mark(), childKey(key, name), std::string("must be text, got ") + typeName(node));
        return false;
    }
    out = node.Scalar();
    return true;
}

bool YamlFields::readName(const YAML::Node& map, const char* name, const std::string& key, std::string& out,
                          bool required)
{
    std::string s;
    YAML::Node node = find(map, name, key, false);
    if (!node.IsDefined()) {
        if (required)
            find(map, name, key, true);
        return !required;
    }
    if (!readString(map, name, key, s, required))
        return false;
    if (!isValidName(s)) {
        error(node.Mark(), childKey(key, name),
              "'" + s + "' is not a valid name (non-empty, no spaces or '#', not '-')");
        return false;
    }
    out = s;
    return true;
}

bool YamlFields::readVec2(const YAML::Node& map, const char* name, const std::string& key, glm::vec2& out,
                          bool required, Range range)
{
    YAML::Node node = find(map, name, key, required);
    if (!node.IsDefined())
        return !required;
    return toVec2(node, childKey(key, name), out, range);
}

bool YamlFields::readPoint3(const YAML::Node& map, const char* name, const std::string& key, glm::vec3& out,
                            bool required)
{
    YAML::Node node = find(map, name, key, required);
    if (!node.IsDefined())
        return !required;
    const std::string k = childKey(key, name);
    if (!node.IsSequence() || (node.size() != 2 && node.size() != 3)) {
        error(node.Mark(), k, "must be [x, z] or [x, y, z]");
        return false;
    }
    float v[3] = {0, 0, 0};
    for (std::size_t i = 0; i < node.size(); ++i)
        if (!toFloat(node[i], indexKey(k, i), v[i], Range::Any) || !withinWorld(v[i], node[i].Mark(), indexKey(k, i)))
            return false;
    out = node.size() == 2 ? glm::vec3(v[0], 0.0f, v[1]) : glm::vec3(v[0], v[1], v[2]);
    return true;
}

bool YamlFields::readPolyline(const YAML::Node& map, const char* name, const std::string& key,
                              std::vector<glm::vec2>& out, bool required, std::size_t minPoints)
{
    YAML::Node node = find(map, name, key, required);
    if (!node.IsDefined())
        return !required;
    const std::string k = childKey(key, name);
    if (!expectSequence(node, k))
        return false;
    if (node.size() < minPoints) {
        error(node.Mark(), k, "needs at least " + std::to_string(minPoints) + " points, got " +
                                  std::to_string(node.size()));
        return false;
    }
    std::vector<glm::vec2> points;
    points.reserve(node.size());
    for (std::size_t i = 0; i < node.size(); ++i) {
        glm::vec2 p;
        if (!toVec2(node[i], indexKey(k, i), p, Range::Any))
            return false;
        points.push_back(p);
    }
    out = std::move(points);
    return true;
}

bool YamlFields::readFloatList(const YAML::Node& map, const char* name, const std::string& key,
                               std::vector<float>& out, bool required)
{
    YAML::Node node = find(map, name, key, required);
    if (!node.IsDefined())
        return !required;
    const std::string k = childKey(key, name);
    if (!expectSequence(node, k))
        return false;
    std::vector<float> values(node.size());
    for (std::size_t i = 0; i < node.size(); ++i)
        if (!toFloat(node[i], indexKey(k, i), values[i], Range::Any))
            return false;
    out = std::move(values);
    return true;
}

bool YamlFields::readStringList(const YAML::Node& map, const char* name, const std::string& key,
                                std::vector<std::string>& out, bool required)
{
    YAML::Node node = find(map, name, key, required);
    if (!node.IsDefined())
        return !required;
    const std::string k = childKey(key, name);
    if (!expectSequence(node, k))
        return false;
    std::vector<std::string> values;
    for (std::size_t i = 0; i < node.size(); ++i) {
        if (!node[i].IsScalar()) {
            error(node[i].Mark(), indexKey(k, i), "must be text");
            return false;
        }
        values.push_back(node[i].Scalar());
    }
    out = std::move(values);
    return true;
}

}  // namespace throng::sim::detail
