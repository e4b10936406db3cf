#pragma once
// Writes a run's recorded frames as a USD stage in text (.usda): a UsdSkel crowd. Each
// character look is written once (skeleton, skinned mesh a Mesh per part, materials) as
// an abstract prim every agent wearing it references; each agent is a SkelRoot with its
// own baked SkelAnimation, its root motion, and variant sets for its look and its tint.
// Reads Scene and FrameCache only; never simulates, never leaves a partial file.

#include "export/ExportResult.h"
#include "export/character/Character.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <cstdint>
#include <optional>
#include <string>

namespace throng::exporting {

struct UsdOptions {
    std::string path;                    // ends in .usda
    Lod lod = Lod::Near;                 // how fine the built-in characters' meshes are
    std::string sceneDirectory;          // where relative character file paths are resolved; empty = cwd
    std::optional<std::uint64_t> seed;   // variation seed; default: the scene's settings.seed
    int jointFrameStep = 1;              // exact: bake joints every N-th frame (and the last), >= 1
    bool compact = false;                // the looks' cycles shared in a clips layer beside the stage
    float positionToleranceM = 0.0005f;  // keys this close to their interpolation are dropped, m, >= 0
    float rotationToleranceDeg = 0.2f;   // joint rotations, degrees, >= 0
    float rootRotationToleranceDeg = 0.05f;
    int threads = 0;                     // agents prepared on this many threads; 0 = one per core
    bool includeSet = true;              // the set too: ground, lanes, crosswalks, walls, obstacles, lights
    std::size_t firstFrame = 0;          // the recording's frame the cache begins with (the lights' phases)
};

// The stage (docs/export.md, USD): metersPerUnit 1, upAxis Y, time codes 0 … frames − 1 at
// the cache's fps (timeCodesPerSecond and framesPerSecond). defaultPrim `/Crowd`, an Xform
// translated by the cache's origin (a far scene's coordinates in doubles), holding:
// - `Agents/agent_<id>_<type>` (AgentId; type name made a valid prim name): a SkelRoot
//   whose xformOps are translate (time samples, m, relative to the origin), orient (about
//   +Y by the heading, the character's nose on +X) and scale (its height); visibility
//   time samples when it leaves through an exit or is not present; customData with its
//   id, type, character and variation; skel:animationSource its child `Anim`, a
//   SkelAnimation with every joint's rotations and translations (compact: a value clip
//   into its look's cycle in the clips layer `<stem>.clips.usda` beside the stage, which
//   the export writes too); a child `Character` that
//   the variant set `look` (one variant per look of its type) makes a reference to the
//   look, binding its colours and hiding the accessories it does not wear; and, for a
//   type with tints, a variant set `tint` binding its top's material;
// - `Characters/<look>`: class prims, each a Skeleton `Skel` and a Mesh per part;
// - `Materials`: UsdPreviewSurface materials, one per colour;
// - `Set` (includeSet): as the glTF export's set, the lamps' visibility following the phase.
// Errors name the file: empty cache, a path that is not .usda, an agent type the scene
// lacks, a character that cannot be built or loaded, any I/O failure.
ExportResult exportUsd(const sim::Scene& scene, const sim::FrameCache& cache, const UsdOptions& options,
                       const ProgressFn& progress = {});

}  // namespace throng::exporting
