#pragma once
// Typed, located reads of YAML fields for the scene reader: every problem becomes a
// Diagnostic with file:line:col and the dotted key. Never throws; never touches a Scene.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/base/Diagnostic.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace throng::sim::detail {

enum class Range { Any, NonNegative, Positive, Unit };  // Unit = [0, 1]

class YamlFields {
public:
    YamlFields(std::string file, std::vector<Diagnostic>& out) : m_file(std::move(file)), m_out(out) {}

    const std::string& file() const { return m_file; }
    void error(const YAML::Mark& at, const std::string& key, const std::string& message);
    void warning(const YAML::Mark& at, const std::string& key, const std::string& message);
    void errorAtLine(int line1, int col1, const std::string& key, const std::string& message);
    int errorCount() const { return m_errors; }

    // True when node is a map; otherwise reports "expected a map".
    bool expectMap(const YAML::Node& node, const std::string& key);
    bool expectSequence(const YAML::Node& node, const std::string& key);
    // Warns about keys not in `allowed`; reports duplicate keys as errors.
    void checkKeys(const YAML::Node& map, const std::string& key, std::initializer_list<const char*> allowed);
    void checkKeys(const YAML::Node& map, const std::string& key, std::span<const char* const> allowed);
    // Reports duplicate keys only, for maps whose keys are data (behaviours, params).
    void checkDuplicateKeys(const YAML::Node& map, const std::string& key);

    // Each reads map[name] into out. A missing optional key leaves out unchanged and
    // returns true; a missing required key or a bad value reports and returns false.
    bool readFloat(const YAML::Node& map, const char* name, const std::string& key, float& out,
                   bool required, Range range = Range::Any);
    bool readUInt(const YAML::Node& map, const char* name, const std::string& key, std::uint64_t& out,
                  bool required, std::uint64_t maxValue);
    bool readU32(const YAML::Node& map, const char* name, const std::string& key, std::uint32_t& out,
                 bool required);
    // An optional index into the `count` items (looks, tints) the agent type `typeName`
    // has, set into `out` when given and in range; out of range is an error naming the
    // type. An empty typeName (the type is unknown) takes any index.
    bool readIndexOfType(const YAML::Node& map, const char* name, const std::string& key, int& out,
                         std::size_t count, const std::string& typeName);
    bool readBool(const YAML::Node& map, const char* name, const std::string& key, bool& out, bool required);
    bool readString(const YAML::Node& map, const char* name, const std::string& key, std::string& out,
                    bool required);
    // A name: non-empty, no whitespace, not "-" (names appear in agent tables).
    bool readName(const YAML::Node& map, const char* name, const std::string& key, std::string& out,
                  bool required);
    bool readVec2(const YAML::Node& map, const char* name, const std::string& key, glm::vec2& out,
                  bool required, Range range = Range::Any);
    // Accepts [x, z] (y = 0) or [x, y, z].
    bool readPoint3(const YAML::Node& map, const char* name, const std::string& key, glm::vec3& out,
                    bool required);
    bool readPolyline(const YAML::Node& map, const char* name, const std::string& key,
                      std::vector<glm::vec2>& out, bool required, std::size_t minPoints);
    bool readFloatList(const YAML::Node& map, const char* name, const std::string& key,
                       std::vector<float>& out, bool required);
    bool readStringList(const YAML::Node& map, const char* name, const std::string& key,
                        std::vector<std::string>& out, bool required);

    // Scalar conversions on a node already found.
    bool toFloat(const YAML::Node& node, const std::string& key, float& out, Range range);
    bool toVec2(const YAML::Node& node, const std::string& key, glm::vec2& out, Range range);

private:
    YAML::Node find(const YAML::Node& map, const char* name, const std::string& key, bool required);
    void checkKeysImpl(const YAML::Node& map, const std::string& key, std::span<const char* const> allowed,
                       bool warnUnknown);
    bool inRange(float v, Range range, const YAML::Mark& at, const std::string& key);
    // Coordinates past SceneLimits' kMaxCoordinateM are errors (their squares overflow).
    bool withinWorld(float v, const YAML::Mark& at, const std::string& key);

    std::string m_file;
    std::vector<Diagnostic>& m_out;
    int m_errors = 0;
};

// Parses a YAML scalar as a finite float; returns a reason on failure ("not a number",
// "not finite", "out of range for a 32-bit float").
bool parseFiniteFloat(const std::string& text, float& out, std::string& why);
bool isValidName(const std::string& name);
std::string indexKey(const std::string& key, std::size_t index);  // key + "[i]"
std::string childKey(const std::string& key, const char* name);   // key + "." + name

}  // namespace throng::sim::detail
