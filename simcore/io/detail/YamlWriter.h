#pragma once
// Small helpers over YAML::Emitter for the scene writer: lossless shortest floats and
// flow-style points. Holds no scene knowledge.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <yaml-cpp/yaml.h>

#include <charconv>
#include <string>
#include <vector>

namespace throng::sim::detail {

// Shortest text that reads back to the same float, so save/load is lossless and small.
inline std::string num(float v)
{
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : std::string("0");
}

class YamlWriter {
public:
    YAML::Emitter out;

    void vec2(const glm::vec2& v) { out << YAML::Flow << YAML::BeginSeq << num(v.x) << num(v.y) << YAML::EndSeq; }
    void vec3(const glm::vec3& v)
    {
        out << YAML::Flow << YAML::BeginSeq << num(v.x) << num(v.y) << num(v.z) << YAML::EndSeq;
    }
    void polyline(const std::vector<glm::vec2>& points)
    {
        out << YAML::Flow << YAML::BeginSeq;
        for (const glm::vec2& p : points)
            vec2(p);
        out << YAML::EndSeq;
    }
    void key(const char* k) { out << YAML::Key << k << YAML::Value; }
    void kv(const char* k, const std::string& v) { out << YAML::Key << k << YAML::Value << v; }
    void kvf(const char* k, float v) { out << YAML::Key << k << YAML::Value << num(v); }
    void kvOpt(const char* k, const std::string& v)
    {
        if (!v.empty())
            kv(k, v);
    }
};

}  // namespace throng::sim::detail
