#pragma once
// An agent's SkelAnimation in the USD export, baked or compact. Baked: every joint's
// rotations at the joint frames some joint keeps, the hips' translation, per agent.
// Compact: each look's cycles stored once, in a clips layer beside the stage, as banks the
// length the longest agent needs; each agent's animation a value clip into its bank,
// whose `times` map the shot's frames onto the samples its distance walked reaches (the
// plans of CompactPlanner, as the glTF export's compact mode reads them).
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/character/CharacterLibrary.h"
#include "export/detail/AgentBake.h"
#include "export/detail/CompactPlanner.h"
#include "export/detail/UsdCharacter.h"

#include <string>
#include <vector>

namespace throng::exporting::detail {

// `def SkelAnimation "Anim"` at `depth`: the exact bake.
void writeBakedAnimation(std::string& out, int depth, const Character& character, const UsdLook& look,
                         const JointClock& jointClock, const BakedJoints& baked);

class UsdSharedCycles {
public:
    // `clipsAsset`: the clips layer as the stage names it ("./shot.clips.usda").
    UsdSharedCycles(const CharacterLibrary& library, std::string clipsAsset, float fps);

    // `def SkelAnimation "Anim"` at `depth`: a value clip into the agent's bank, or, for one
    // that never walks, its still pose.
    void writeAnimation(std::string& out, int depth, const AgentWork& work, const UsdLook& look);
    // The clips layer: every bank some agent reads (looks: per character, as the stage names them).
    void writeClipsLayer(std::string& out, const std::vector<UsdLook>& looks) const;

    // Clip times kept within this many samples of the planned window.
    static constexpr double kTimeToleranceSamples = 0.02;

private:
    std::string bankName(const UsdLook& look, std::size_t character, int clip) const;

    const CharacterLibrary& m_library;
    std::string m_clipsAsset;
    float m_fps;
    CompactPlanner m_planner;
};

}  // namespace throng::exporting::detail
