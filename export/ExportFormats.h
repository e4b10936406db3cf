#pragma once
// The table of export formats that the CLI and the editor both offer: per format a key,
// a label, the path forms it accepts and one writer with a signature shared by all.
// Adding a format is one row here; the table never simulates and holds no state.

#include "export/AgentTextCache.h"
#include "export/ExportResult.h"
#include "export/character/Character.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace throng::exporting {

enum class JointBake {
    Exact,    // every joint of every agent baked from its own gait, frame by frame
    Compact,  // one stored cycle per look and clip; each agent a window into it (docs/export.md)
};

// What a user asks of any export. A format reads the choices it has and ignores the rest.
struct ExportRequest {
    std::string path;                   // the file; for a format that writes a directory, the directory
    std::string sceneDirectory;         // where relative file paths of the scene (characters) resolve; empty = cwd
    std::optional<std::uint64_t> seed;  // variation seed; default: the scene's settings.seed
    int threads = 0;                    // worker threads; 0 = one per core
    JointBake jointBake = JointBake::Exact;  // skinned characters: how joints are baked
    int jointFrameStep = 1;             // skinned characters, exact bake: joints every N-th frame, >= 1
    Lod lod = Lod::Near;                // built-in characters: how fine their meshes are
    bool indentedText = false;          // structured text (glTF JSON): indented for reading
    ForwardAxis mayaForward = ForwardAxis::PlusZ;  // the Maya cache: the axis its rigs face at rotY 0
    bool includeSet = true;             // glTF: the set (ground, lanes, walls, obstacles, lights) too
    std::size_t firstFrame = 0;         // the recording's frame the cache begins with (an export of a
                                        // range): the set's traffic lights keep the recording's time
};

// Every format's writer. Writes `request.path` from the recorded frames, atomically:
// a failure or a cancel by `progress` leaves nothing of this export at the target.
using FormatWriter = ExportResult (*)(const sim::Scene& scene, const sim::FrameCache& cache,
                                      const ExportRequest& request, const ProgressFn& progress);

struct ExportFormat {
    std::string key;                    // stable name: "gltf", "csv", "text-cache"
    std::string label;                  // what the editor's format list shows
    std::vector<std::string> suffixes;  // lower case, with the dot; the first is the default; empty for a directory
    bool writesDirectory = false;       // the path is a directory the format fills
    // The suffixes whose files honour ExportRequest::indentedText (a .gltf's JSON; a .glb is
    // binary); empty for a format that does not.
    std::vector<std::string> indentedSuffixes{};
    bool writesSet = false;             // honours ExportRequest::includeSet
    bool writesCharacters = false;      // skinned characters: honours lod and jointFrameStep
    bool sharesCycles = false;          // honours jointBake (Compact: each look's cycles shared)
    FormatWriter write = nullptr;
};

// Every format, in the order the editor lists them.
const std::vector<ExportFormat>& exportFormats();

// The format whose suffix `path` ends with (case-insensitive), or, for a path ending in
// '/', the first format that writes a directory (the text cache; the others are chosen by
// key: the CLI's --maya-cache, the editor's format list). nullptr when none.
const ExportFormat* formatForPath(const std::string& path);
const ExportFormat* formatByKey(const std::string& key);
// Whether a file of `format` at `path` honours ExportRequest::indentedText (by its suffix).
bool indentsText(const ExportFormat& format, const std::string& path);

// How a path names `format`: ".glb, .gltf" or "DIR/".
std::string pathForms(const ExportFormat& format);
// The path forms formatForPath knows, in table order: ".glb, .gltf, .csv, .txt, DIR/".
std::string knownPathForms();

}  // namespace throng::exporting
