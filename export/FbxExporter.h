#pragma once
// Writes a run's recorded frames as one binary FBX file through assimp (Debian's
// libassimp): per agent a node with its root motion, its own skeleton and its skinned
// mesh, a mesh per part it wears with its colours; the set beside them. Reads Scene and
// FrameCache only; never simulates, never leaves a partial file.

#include "export/ExportResult.h"
#include "export/character/Character.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <cstdint>
#include <optional>
#include <string>

namespace throng::exporting {

struct FbxOptions {
    std::string path;                    // ends in .fbx
    Lod lod = Lod::Near;                 // how fine the built-in characters' meshes are
    std::string sceneDirectory;          // where relative character file paths are resolved; empty = cwd
    std::optional<std::uint64_t> seed;   // variation seed; default: the scene's settings.seed
    int jointFrameStep = 1;              // bake joints every N-th frame (and the last), >= 1
    float positionToleranceM = 0.0005f;  // root translation keys this close to their interpolation are dropped
    int threads = 0;                     // agents prepared on this many threads; 0 = one per core
    bool includeSet = true;              // the set too: ground, lanes, crosswalks, walls, obstacles, lights
    std::size_t firstFrame = 0;          // the recording's frame the cache begins with (the lights' phases)
};

// The file (docs/export.md, FBX): Y up, one unit a metre (UnitScaleFactor 100), one
// animation "crowd" whose keys are at each frame's time. Nodes: `Crowd` (translated by the
// cache's origin, in single precision), under it per agent `agent_<id>_<type>` (translation
// and rotation about +Y by the heading, the character's nose on +X, every frame; scale its
// height, a ten-thousandth of it on the frames it is out of the shot), its joints `<agent>__<joint>` keyed at
// the joint frames, and `<agent>_body` with a skinned mesh per part it wears, each with its
// material (the tint on the top, palette colours on skin, hair and clothes); `set` with the
// set's parts and its lamps (scale 1 on the frames the phase lights them, else 10^-4).
// Rotations are keyed on every frame: FBX stores them as Euler angles, which do not
// interpolate between sparse keys. Errors name the file: empty cache, a path that is not
// .fbx, an agent type the scene lacks, a character that cannot be built or loaded, a
// failure inside assimp, any I/O failure.
ExportResult exportFbx(const sim::Scene& scene, const sim::FrameCache& cache, const FbxOptions& options,
                       const ProgressFn& progress = {});

}  // namespace throng::exporting
