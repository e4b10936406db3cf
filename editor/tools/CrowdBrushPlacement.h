#pragma once
// Where one crowd-brush dab puts new agents: Poisson-disc style dart throwing inside the
// brush disk up to the wanted density, never closer than the minimum spacing to any
// agent, never inside a wall, obstacle or outside the bounds. Plain data in and out; it
// neither edits the scene nor knows Qt.

#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace throng::editor {

enum class HeadingMode { Random, AlongStroke, TowardPoint };

struct TypeShare {
    std::string type;    // agent type name
    float weight = 1.0f; // relative share, >= 0
};

struct CrowdBrushSettings {
    float radiusM = 3.0f;          // brush radius, m, > 0
    float densityPerM2 = 0.5f;     // wanted agents per square metre inside the brush, > 0
    float minSpacingM = 0.8f;      // least distance between agent centres, m, >= 0
    std::vector<TypeShare> mix;    // empty: the scene's first pedestrian type
    HeadingMode heading = HeadingMode::Random;
    glm::vec2 towardPoint{0.0f};   // TowardPoint: where new agents face (x, z)
};

// New agents (without ids) for one dab centred at `centre` (x, z). `strokeDir` is the
// stroke's direction on the ground (any length; zero = unknown). `seed` makes the dab
// reproducible. `extra` lists agents placed earlier in the same stroke but not yet in
// `scene`.
std::vector<sim::Agent> placeDab(const sim::Scene& scene, const std::vector<sim::Agent>& extra, glm::vec2 centre,
                                 glm::vec2 strokeDir, const CrowdBrushSettings& settings, std::uint64_t seed);

// The type an empty mix paints: the scene's first pedestrian type, else its first type,
// else "" (no type).
std::string defaultBrushType(const sim::Scene& scene);

// True when a body of `radiusM` at `p` overlaps a wall, an obstacle or leaves the bounds.
bool isBlocked(const sim::Scene& scene, glm::vec2 p, float radiusM);

}  // namespace throng::editor
