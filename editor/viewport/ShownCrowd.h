#pragma once
// The agents of the shown frame as the viewport draws them, kept on the CPU until the next
// paint uploads them: one glyph per drawn agent, by kind (walkers, vehicles as cars,
// fliers as birds), coloured as the user chose and posed in the character its type wears;
// the counts the HUD shows; their extent for framing; and ShownAgents for picking and the
// rings. Keeps the frame it was given, to colour it again. Plain data; never touches GL.

#include "editor/viewport/AgentCharacters.h"
#include "editor/viewport/AgentColours.h"
#include "editor/viewport/AgentGlyph.h"
#include "editor/viewport/GroundBox.h"
#include "editor/viewport/ShownAgents.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace throng::editor {

class ShownCrowd {
public:
    // The agents' kinds, each drawn as its own batch.
    enum Kind : std::size_t { Walkers, Vehicles, Fliers, kKinds };

    // The agent types of `scene`: their radius, kind, name, colours and the characters they
    // wear (character files relative to the scene are found in `sceneDirectory`). The shown
    // frame keeps its glyphs until the next build.
    void setScene(const sim::Scene& scene, const std::string& sceneDirectory);
    void setColourBy(ColourBy by) { m_colours.setColourBy(by); }
    ColourBy colourBy() const { return m_colours.colourBy(); }
    // What the colours mean, for the HUD.
    ColourLegend legend() const { return m_colours.legend(); }

    // Keeps `frames` and `agents` (as many as the shorter holds) as the shown frame; the
    // kept frame itself may be given again.
    void keep(std::span<const sim::AgentFrame> frames, std::span<const sim::AgentInfo> agents);
    // Makes the kept frame ready to draw. density: agents per m² where each stands (read
    // when colouring by density); timeS: the frame's time, which actions run by; cache and
    // frameIndex: the recording the frame is from, which one-shot clips and gaits run by
    // (null for a World's state).
    void build(std::span<const float> density, double timeS, const sim::FrameCache* cache, std::size_t frameIndex);

    std::span<const sim::AgentFrame> frames() const { return m_frames; }
    std::span<const sim::AgentInfo> agents() const { return m_agents; }
    // The kept frame's agents by World index, drawn or not.
    const ShownAgents& shown() const { return m_shown; }
    // The glyphs of one kind, with the poses of the characters they wear.
    AgentBatch batch(Kind kind) const { return {m_glyphs[kind], m_poses[kind]}; }
    std::size_t glyphCount() const;
    // The drawn agents' bodies on the ground; empty when none is drawn.
    const GroundBox& extent() const { return m_extent; }
    const std::vector<PoseTable>& poseTables() const { return m_characters.poseTables(); }

    // The counts the HUD shows: agents drawn (in all and per type, as type name and count,
    // types without any left out), arrived, and gone through an exit.
    struct Counts {
        std::size_t shown = 0, arrived = 0, out = 0;
        std::vector<std::pair<std::string, std::size_t>> perType;
    };
    const Counts& counts() const { return m_counts; }

    // What changed since the last call: the glyphs, the characters' pose tables.
    struct Changed {
        bool glyphs = false, characters = false;
    };
    Changed takeChanged();
    // The next takeChanged reports everything (a new GL context has nothing uploaded).
    void markAllChanged() { m_changed = {true, true}; }

private:
    // Agent i's type's body radius, and its kind (a type the scene lacks: a walker).
    float radiusOf(std::size_t type) const;
    Kind kindOf(std::size_t type) const;

    // By Scene::agentTypes index.
    std::vector<float> m_typeRadiusM;
    std::vector<Kind> m_typeKind;
    std::vector<std::string> m_typeNames;
    AgentColours m_colours;
    AgentCharacters m_characters;

    std::vector<sim::AgentFrame> m_frames;
    std::vector<sim::AgentInfo> m_agents;
    std::array<std::vector<AgentGlyph>, kKinds> m_glyphs;
    std::array<std::vector<AgentPose>, kKinds> m_poses;  // one per glyph
    std::vector<AgentPose> m_framePoses;                // scratch: one per agent of the frame
    std::vector<float> m_clipSinceS;                    // scratch: per agent, s since its clip began
    std::vector<exporting::GaitFrame> m_gait;           // scratch: per agent, its gait as exported
    ShownAgents m_shown;
    GroundBox m_extent;
    Counts m_counts;
    Changed m_changed{true, true};
};

}  // namespace throng::editor
