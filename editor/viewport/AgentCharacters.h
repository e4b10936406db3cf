#pragma once
// The characters the viewport dresses agents in, as export resolves them: each agent
// type's character and looks (CharacterLibrary), skinned into pose tables, and per agent
// the look and height scale export would give it. Types whose character cannot be
// resolved keep the glyph. CPU data only, no GL; rebuilt only when the types change.

#include "editor/viewport/AgentPose.h"
#include "editor/viewport/GaitPhases.h"
#include "editor/viewport/PoseTable.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace throng::editor {

class AgentCharacters {
public:
    // `sceneDirectory` resolves character files named relative to the scene. Returns
    // true when the pose tables changed (the renderer must upload them again).
    bool setScene(const sim::Scene& scene, const std::string& sceneDirectory);

    // Pose tables by character and level: character c's near table (Lod::Mid) at
    // kLevels * c, its far one (Lod::Far) after it.
    static constexpr int kLevels = 2;
    const std::vector<PoseTable>& poseTables() const { return m_tables; }
    // Why some types keep the glyph; empty when every type has its character.
    const std::string& problems() const { return m_problems; }

    // One pose per agent of `frames`/`agents` (same length), in order; timeS: the frame's
    // time (frame / fps), which an action's phase runs by; clipSinceS: per agent, seconds
    // since it switched to its clip, which a one-shot (fall, get_up) runs by (empty or
    // shorter: played to its end).
    // gait: per agent, its gait as the export computes it (gaitAt), which sets the phase of
    // its walk and the walk, run or ladder rung it shows; empty or shorter: the recorded
    // phase and clip.
    void posesFor(std::span<const sim::AgentFrame> frames, std::span<const sim::AgentInfo> agents, double timeS,
                  std::vector<AgentPose>& poses, std::span<const float> clipSinceS = {},
                  std::span<const exporting::GaitFrame> gait = {});
    // Per agent of the cache, its gait on `frame` as the export computes it from the
    // recording (GaitPhases).
    void gaitAt(const sim::FrameCache& cache, std::size_t frame, std::vector<exporting::GaitFrame>& gait);

private:
    struct Look {
        int character = -1;
        float heightScale = 1.0f;
        std::uint32_t lookBits = 0;
        exporting::AgentVariation variation;
    };
    Look lookOf(const sim::AgentInfo& agent) const;
    const std::vector<Look>& looksFor(std::span<const sim::AgentInfo> agents);

    std::string m_signature;                        // what the tables were built from
    std::vector<PoseTable> m_tables;                // by character of the library and level
    std::vector<std::vector<exporting::MeshPart>> m_parts;  // by character: its mesh's parts
    std::vector<std::vector<int>> m_looksOfType;    // type -> characters; empty = unresolved
    std::vector<sim::Variation> m_variations;       // by type index
    std::unordered_map<std::uint32_t, sim::Agent> m_handSet;  // placed agents with a hand-set look or height
    std::uint64_t m_seed = 1;
    std::string m_problems;
    std::vector<sim::AgentInfo> m_cachedFor;
    std::vector<Look> m_looks;
    // By character of the library: what its gait needs (its clips; no mesh).
    std::vector<exporting::Character> m_gaitCharacters;
    std::vector<sim::AgentInfo> m_walkersFor;   // the cache's agents m_walkers were made for
    std::vector<GaitPhases::Walker> m_walkers;  // per agent of m_walkersFor
    GaitPhases m_gait;
};

// Per agent of the cache, seconds since it switched to the clip it plays on `frame`, counted
// back through the recorded frames for the agents playing a one-shot (fall, get_up) and only
// as far as the clip lasts (AgentCharacters::posesFor's clipSinceS); 0 for the others.
void clipSinceS(const sim::FrameCache& cache, std::size_t frame, std::vector<float>& sinceS);

}  // namespace throng::editor
