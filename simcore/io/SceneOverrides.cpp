#include "simcore/io/SceneOverrides.h"

#include "simcore/io/detail/SceneReader.h"
#include "simcore/io/detail/YamlDocument.h"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <sstream>
#include <vector>

namespace throng::sim {

namespace {

std::vector<std::string> segmentsOf(const std::string& key)
{
    std::vector<std::string> out;
    std::stringstream s(key);
    std::string part;
    while (std::getline(s, part, '.'))
        out.push_back(part);
    if (!key.empty() && key.back() == '.')
        out.emplace_back();
    return out;
}

// The list item named `name` (its `name` key), else the one at that index; null when none.
YAML::Node itemOf(const YAML::Node& list, const std::string& name)
{
    for (const YAML::Node& item : list)
        if (item.IsMap() && item["name"] && item["name"].IsScalar() && item["name"].Scalar() == name)
            return item;
    if (!name.empty() && name.find_first_not_of("0123456789") == std::string::npos && name.size() < 9) {
        const std::size_t index = std::stoul(name);
        if (index < list.size())
            return list[index];
    }
    return YAML::Node(YAML::NodeType::Undefined);
}

// Sets `o` in `root`; an empty string, or why not.
std::string apply(YAML::Node& root, const SceneOverride& o)
{
    YAML::Node value;
    try {
        value = YAML::Load(o.value);
    } catch (const YAML::Exception& e) {
        return "'" + o.value + "' is not a YAML value: " + e.msg;
    }
    const std::vector<std::string> path = segmentsOf(o.key);
    YAML::Node at;
    at.reset(root);
    std::string walked;
    for (std::size_t k = 0; k + 1 < path.size(); ++k) {
        walked += (walked.empty() ? "" : ".") + path[k];
        YAML::Node next(YAML::NodeType::Undefined);
        if (at.IsMap()) {
            next.reset(at[path[k]]);
        } else if (at.IsSequence()) {
            next.reset(itemOf(at, path[k]));
            if (!next.IsDefined())
                return "the list at '" + walked.substr(0, walked.size() - path[k].size() - (k > 0 ? 1 : 0)) +
                       "' has no item named '" + path[k] + "'";
        }
        if (!next.IsDefined() || next.IsNull() || !(next.IsMap() || next.IsSequence()))
            return "the scene has no map or list at '" + walked + "'";
        at.reset(next);
    }
    const std::string& last = path.back();
    if (at.IsMap()) {
        at[last] = value;
        return {};
    }
    if (at.IsSequence()) {
        YAML::Node item = itemOf(at, last);
        if (!item.IsDefined())
            return "the list at '" + walked + "' has no item named '" + last + "'";
        item = value;
        return {};
    }
    return "the scene has no map or list at '" + walked + "'";
}

}  // namespace

std::optional<SceneOverride> parseOverride(const std::string& text, std::string& error)
{
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) {
        error = "'" + text + "' is not KEY=VALUE";
        return std::nullopt;
    }
    SceneOverride o{text.substr(0, eq), text.substr(eq + 1)};
    for (const std::string& segment : segmentsOf(o.key))
        if (segment.empty()) {
            error = "'" + o.key + "' is not a key: an empty part between dots";
            return std::nullopt;
        }
    if (o.key.empty()) {
        error = "'" + text + "' has no key before '='";
        return std::nullopt;
    }
    return o;
}

LoadResult loadScene(const std::string& path, std::span<const SceneOverride> overrides)
{
    if (overrides.empty())
        return loadScene(path);
    // The file, read once; as it is first: its own problems with its own lines.
    LoadResult result;
    detail::YamlFields fields(path, result.diagnostics);
    std::string text;
    YAML::Node root;
    if (!detail::readYamlFile(fields, text, root))
        return result;
    const std::string baseDir = std::filesystem::path(path).parent_path().string();
    LoadResult plain = parseScene(text, path, baseDir);
    if (!plain.ok())
        return plain;
    result.diagnostics = plain.diagnostics;
    bool applied = root.IsMap();
    for (const SceneOverride& o : overrides) {
        if (!root.IsMap())
            break;
        if (const std::string why = apply(root, o); !why.empty()) {
            detail::YamlFields named("--set " + o.key, result.diagnostics);
            named.errorAtLine(0, 0, "", why);
            applied = false;
        }
    }
    if (!applied) {
        result.scene = Scene{};
        return result;
    }
    // Read as the edited document (its text re-emitted, so the reader's marks are its own):
    // the file's warnings were said above; what the overrides bring are its errors, and a
    // key the format does not know (otherwise only a warning, and the value ignored).
    YAML::Emitter emitter;
    emitter << root;
    const LoadResult read = parseScene(emitter.c_str(), path + " (with --set)", baseDir);
    for (const Diagnostic& d : read.diagnostics)
        if (d.severity == Severity::Error)
            result.diagnostics.push_back(d);
    for (const SceneOverride& o : overrides) {
        const std::string last = segmentsOf(o.key).back();
        bool unknown = false;
        for (const Diagnostic& d : read.diagnostics)
            unknown = unknown || (d.severity == Severity::Warning &&
                                  d.format().find("unknown key '" + last + "'") != std::string::npos);
        if (unknown) {
            detail::YamlFields named("--set " + o.key, result.diagnostics);
            named.errorAtLine(0, 0, "", "the scene format has no key '" + last + "' there");
        }
    }
    result.scene = result.ok() ? read.scene : Scene{};
    return result;
}

}  // namespace throng::sim
