#pragma once
// Resolves each agent type of a scene to the characters its agents wear: the type's
// built-in or user character, and the looks its variation lists. Owns the characters;
// never writes files.

#include "export/character/Character.h"
#include "simcore/scene/Scene.h"

#include <span>
#include <string>
#include <vector>

namespace throng::exporting {

class CharacterLibrary {
public:
    // The level of detail built-in characters are made at (before resolve).
    void setLod(Lod lod) { m_lod = lod; }

    // typeUsed[t]: whether some agent has type t (unused types are not loaded). Returns an
    // error naming the type and the file when a character cannot be built or loaded.
    std::string resolve(const sim::Scene& scene, const std::string& sceneDirectory, const std::vector<bool>& typeUsed);

    std::size_t characterCount() const { return m_characters.size(); }
    const Character& character(std::size_t i) const { return m_characters[i]; }
    // Indices of the characters agents of type `typeIndex` may wear, at least one.
    std::span<const std::size_t> looksOf(std::size_t typeIndex) const { return m_looks[typeIndex]; }

private:
    std::size_t add(Character character, const std::string& key);
    std::vector<Character> m_characters;
    std::vector<std::string> m_keys;
    std::vector<std::vector<std::size_t>> m_looks;
    Lod m_lod = Lod::Near;
};

// The character a type wears when it names none: man, car or bird by its kind.
const char* defaultCharacterFor(sim::AgentKind kind);

}  // namespace throng::exporting
