#pragma once
// Writes a run's recorded frames as one animated glTF 2.0 scene of skinned characters:
// per agent a root node with root motion, its own joints with baked (or, in compact mode,
// shared) walk cycles, and its own mesh entry over the shared geometry. Reads Scene and
// FrameCache only; never simulates, never leaves partial files.

#include "export/ExportResult.h"
#include "export/character/Character.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <cstdint>
#include <optional>
#include <string>

namespace throng::exporting {

enum class GltfMode {
    Exact,    // every joint of every agent baked from its own gait, frame by frame
    Compact,  // one stored cycle per look and clip; each agent a window into it (docs/export.md)
};

struct GltfOptions {
    std::string path;                    // ends in .glb: one binary file; else .gltf + .bin beside it
    GltfMode mode = GltfMode::Exact;
    Lod lod = Lod::Near;                 // how fine the built-in characters' meshes are
    std::string sceneDirectory;          // where relative character file paths are resolved; empty = cwd
    std::optional<std::uint64_t> seed;   // variation seed; default: the scene's settings.seed
    int jointFrameStep = 1;              // exact: bake joints every N-th frame (and the last), >= 1
    float positionToleranceM = 0.0005f;  // keys this close to their interpolation are dropped, m, >= 0
    float rotationToleranceDeg = 0.2f;   // joint rotations, degrees, >= 0
    float rootRotationToleranceDeg = 0.05f;
    bool prettyJson = false;             // .gltf only: indented JSON
    int threads = 0;                     // agents prepared on this many threads; 0 = one per core
    bool includeSet = true;              // the set too: ground, lanes, crosswalks, walls, obstacles, lights
    std::size_t firstFrame = 0;          // the recording's frame the cache begins with: the lights' phases
                                         // on the cache's frame f are those of frame firstFrame + f
};

// Where an export's bytes went (binary buffer only; the JSON is the file's remainder).
struct GltfExportStats {
    std::size_t fileBytes = 0;          // .glb, or .gltf + .bin
    std::size_t geometryBytes = 0;      // meshes, skins' inverse bind matrices
    std::size_t clockBytes = 0;         // the shared time accessors
    std::size_t rootMotionBytes = 0;    // agents' root translation and rotation keys
    std::size_t jointBytes = 0;         // joint animation: baked keys, or cycle banks and agents' time maps
    std::size_t animationKeys = 0;      // output elements of all samplers, shared windows counted once per agent
};

// Nodes `agent_<id>_<type>` (AgentId, type name) in the cache's dense order: translation
// (m) and rotation (about +Y by headingRad, the character's nose on +X) keyed from frame
// f at f / fps, static scale = the agent's height scale (an agent that leaves through an
// exit, AgentFrame::out, gets a STEP scale channel: that scale, then 0 from the frame it
// left); children `<agent>__<joint>`; a
// scene-root node `<agent>_body` with the agent's own mesh entry (a primitive per mesh part
// it wears, each with its slot's material: the tint on the top, palette colours on skin,
// hair, clothes and accessories) and skin. One animation,
// "crowd". Rotations are normalised int16. Asset and scene extras carry generator
// "Throng", fps, frameCount, agentCount, mode, seed, set; each root's extras its variation.
// With includeSet, a scene-root node `set` holds the set as the editor's 3D view stands it
// up, a child per part: `set_ground` (the bounds, on the terrain), `set_lanes`,
// `set_crosswalks`, `set_walls` (extruded to their height, 0.2 m thick), `set_obstacles`
// (1 m high) and `set_lights` (poles and heads, every lamp dark), and per light and lamp a
// node `set_lamp_<light>_<red|yellow|green>` whose STEP scale is 1 on the frames the light's
// phase lights it and 0 otherwise (docs/export.md, The set).
// writtenPaths: {path} for .glb, {path, <stem>.bin} for .gltf (the .bin name keeps only
// [A-Za-z0-9._~-], others become '_'). Errors name the file: empty cache, an agent type
// index the scene lacks, a character that cannot be built or loaded, a .glb over 4 GiB,
// any I/O failure. Files go to temporaries beside the target and are renamed in.
ExportResult exportGltf(const sim::Scene& scene, const sim::FrameCache& cache, const GltfOptions& options,
                        const ProgressFn& progress = {}, GltfExportStats* stats = nullptr);

}  // namespace throng::exporting
