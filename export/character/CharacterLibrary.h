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
    // As resolve, but every used type is tried: one error per type (empty: resolved), and a
    // type that failed has no looks. Each file is loaded once.
    std::vector<std::string> resolveEach(const sim::Scene& scene, const std::string& sceneDirectory,
                                         const std::vector<bool>& typeUsed);
    // The same characters, in the same order and with the same looks, at another level of
    // detail: built-ins are built again at it, characters from files (one level) copied.
    CharacterLibrary atLod(Lod lod) const;

    std::size_t characterCount() const { return m_characters.size(); }
    const Character& character(std::size_t i) const { return m_characters[i]; }
    // Whether character i came from a file (one level of detail) rather than built in.
    bool fromFile(std::size_t i) const { return m_keys[i].rfind("file:", 0) == 0; }
    // Indices of the characters agents of type `typeIndex` may wear, at least one.
    std::span<const std::size_t> looksOf(std::size_t typeIndex) const { return m_looks[typeIndex]; }

private:
    std::size_t add(Character character, const std::string& key);
    std::string resolveType(const sim::Scene& scene, const std::string& sceneDirectory, std::size_t t);
    std::vector<Character> m_characters;
    std::vector<std::string> m_keys;
    std::vector<std::vector<std::size_t>> m_looks;
    Lod m_lod = Lod::Near;
};

// The character a type wears when it names none: man, car or bird by its kind.
const char* defaultCharacterFor(sim::AgentKind kind);

}  // namespace throng::exporting
