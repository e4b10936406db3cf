#pragma once
// The colour each shown agent is drawn in, by what the user colours by: its tint (from
// the type's palette, set by hand with the variation brush, else drawn per agent id as
// export draws it, or the type's colour when the type has no tints), its type, the group,
// goal, path or brain it was given, its speed (of its type's top speed) or the crowd
// density where it stands. Says what the colours mean (legend). Cached while the same
// agents are shown in a colouring that does not change per frame. No GL.

#include "editor/viewport/AgentCategories.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace throng::editor {

enum class ColourBy { Tint, Type, Group, Goal, Path, Brain, Speed, Density };
inline constexpr int kColourByCount = 8;
// The menu's name of a colouring ("Speed").
const char* colourByName(ColourBy by);

// What the colours of one colouring mean: named swatches, or a gradient's stops from
// low to high.
struct ColourLegend {
    std::string title;
    struct Entry {
        std::string label;
        glm::vec3 colour;
    };
    std::vector<Entry> entries;
    bool gradient = false;
    std::size_t more = 0;  // categories left out of `entries` (too many to list)
};

class AgentColours {
public:
    // Most categories the legend lists; the colours repeat after kCategoryColours.
    static constexpr std::size_t kLegendEntries = 8;
    static constexpr std::size_t kCategoryColours = 10;
    // Agents given no group, goal, path or brain.
    static constexpr glm::vec3 kNoCategory{0.42f, 0.43f, 0.45f};

    void setScene(const sim::Scene& scene);
    void setColourBy(ColourBy by);
    ColourBy colourBy() const { return m_by; }
    // Whether the colours change from frame to frame (speed, density).
    bool perFrame() const { return m_by == ColourBy::Speed || m_by == ColourBy::Density; }

    // One colour per agent of `agents`, in order. `frames` (the same agents) gives speeds;
    // `density`, agents per m² where each stands, is read when colouring by density.
    const std::vector<glm::vec3>& coloursFor(std::span<const sim::AgentFrame> frames,
                                             std::span<const sim::AgentInfo> agents,
                                             std::span<const float> density = {});
    ColourLegend legend() const;

    // The colour of category `index` (-1 = none) and of a fraction in [0, 1] on the
    // speed gradient (blue, cyan, green, yellow, red). Densities take the density map's
    // colours (DensityHeatmap::colourFor), opaque.
    static glm::vec3 categoryColour(int index);
    static glm::vec3 gradientColour(float t);

private:
    glm::vec3 tint(const sim::AgentInfo& agent) const;
    void colourCategories(std::span<const sim::AgentInfo> agents);

    ColourBy m_by = ColourBy::Tint;
    std::vector<sim::Variation> m_variations;         // by type index
    std::vector<std::string> m_typeNames;             // by type index
    std::vector<float> m_typeTopSpeed;                // m/s, by type index
    std::unordered_map<std::uint32_t, int> m_handTint; // agent id -> tint index
    std::uint64_t m_seed = 1;
    AgentCategories m_categories;
    std::vector<sim::AgentInfo> m_cachedFor;
    ColourBy m_cachedBy = ColourBy::Tint;
    std::vector<glm::vec3> m_colours;
};

}  // namespace throng::editor
