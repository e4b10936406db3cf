#include "export/character/CharacterLibrary.h"

#include "export/character/BuiltinCharacters.h"
#include "export/character/UserCharacter.h"

#include <algorithm>
#include <filesystem>
#include <optional>

namespace throng::exporting {

const char* defaultCharacterFor(sim::AgentKind kind)
{
    switch (kind) {
    case sim::AgentKind::Vehicle: return "car";
    case sim::AgentKind::Flier: return "bird";
    case sim::AgentKind::Pedestrian: break;
    }
    return "man";
}

std::size_t CharacterLibrary::add(Character character, const std::string& key)
{
    m_characters.push_back(std::move(character));
    m_keys.push_back(key);
    return m_characters.size() - 1;
}

std::string CharacterLibrary::resolve(const sim::Scene& scene, const std::string& sceneDirectory,
                                      const std::vector<bool>& typeUsed)
{
    m_looks.assign(scene.agentTypes.size(), {});
    for (std::size_t t = 0; t < scene.agentTypes.size(); ++t)
        if (t < typeUsed.size() && typeUsed[t])
            if (std::string error = resolveType(scene, sceneDirectory, t); !error.empty())
                return error;
    return {};
}

std::vector<std::string> CharacterLibrary::resolveEach(const sim::Scene& scene, const std::string& sceneDirectory,
                                                       const std::vector<bool>& typeUsed)
{
    m_looks.assign(scene.agentTypes.size(), {});
    std::vector<std::string> errors(scene.agentTypes.size());
    for (std::size_t t = 0; t < scene.agentTypes.size(); ++t)
        if (t < typeUsed.size() && typeUsed[t])
            errors[t] = resolveType(scene, sceneDirectory, t);
    return errors;
}

CharacterLibrary CharacterLibrary::atLod(Lod lod) const
{
    CharacterLibrary other;
    other.m_lod = lod;
    other.m_keys = m_keys;
    other.m_looks = m_looks;
    other.m_characters.reserve(m_characters.size());
    for (std::size_t i = 0; i < m_characters.size(); ++i) {
        std::optional<Character> built = fromFile(i) ? std::nullopt : makeBuiltinCharacter(m_keys[i], lod);
        other.m_characters.push_back(built ? std::move(*built) : m_characters[i]);
    }
    return other;
}

std::string CharacterLibrary::resolveType(const sim::Scene& scene, const std::string& sceneDirectory, std::size_t t)
{
    auto find = [&](const std::string& key) -> std::ptrdiff_t {
        const auto it = std::find(m_keys.begin(), m_keys.end(), key);
        return it == m_keys.end() ? -1 : it - m_keys.begin();
    };
    auto builtin = [&](const std::string& name) -> std::ptrdiff_t {
        if (const std::ptrdiff_t i = find(name); i >= 0)
            return i;
        std::optional<Character> c = makeBuiltinCharacter(name, m_lod);
        return c ? static_cast<std::ptrdiff_t>(add(std::move(*c), name)) : -1;
    };
    const sim::AgentType& type = scene.agentTypes[t];
    const std::string base = type.character.empty() ? defaultCharacterFor(type.kind) : type.character;
    std::ptrdiff_t baseIndex = builtin(base);
    if (baseIndex < 0) {
        const std::filesystem::path file = std::filesystem::path(sceneDirectory.empty() ? "." : sceneDirectory) / base;
        std::string key = "file:" + file.lexically_normal().string() + "#" + type.clips.idle + "," +
                          type.clips.walk + "," + type.clips.run;
        for (const auto& [action, clip] : type.clips.actions)
            key += "," + action + "=" + clip;
        baseIndex = find(key);
        if (baseIndex < 0) {
            std::string error;
            const ClipNames clips{type.clips.idle, type.clips.walk, type.clips.run, type.clips.actions};
            std::optional<Character> loaded = loadCharacterFile(file.string(), clips, error);
            if (!loaded)
                return "agent type '" + type.name + "': " + error;
            baseIndex = static_cast<std::ptrdiff_t>(add(std::move(*loaded), key));
        }
    }
    // Looks that name a built-in character of the same family become mesh variants;
    // other names (a costume the character file does not have) wear the base.
    const bool humanoidBase = m_characters[baseIndex].joints.size() == kHumanoidJointCount &&
                              m_keys[baseIndex].rfind("file:", 0) != 0;
    for (const std::string& look : type.variation.looks) {
        const bool humanoidLook = humanoidBuild(look).has_value();
        const std::ptrdiff_t i = humanoidBase && humanoidLook ? builtin(look) : -1;
        if (i >= 0 && std::find(m_looks[t].begin(), m_looks[t].end(), std::size_t(i)) == m_looks[t].end())
            m_looks[t].push_back(static_cast<std::size_t>(i));
    }
    if (m_looks[t].empty())
        m_looks[t].push_back(static_cast<std::size_t>(baseIndex));
    return {};
}

}  // namespace throng::exporting
