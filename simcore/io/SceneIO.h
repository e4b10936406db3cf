#pragma once
// Reading and writing scene files (YAML, format v1; docs/scene-format.md). Loading
// validates everything and reports every problem with file:line:col; saving is atomic.

#include "simcore/base/Diagnostic.h"
#include "simcore/scene/Scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace throng::sim {

struct LoadResult {
    Scene scene;                          // complete only when ok()
    std::vector<Diagnostic> diagnostics;  // errors and warnings, in file order of discovery
    bool ok() const { return !hasErrors(diagnostics); }
};

// Files larger than this are refused before parsing.
constexpr std::uint64_t kMaxSceneFileBytes = 512ull * 1024 * 1024;

// Loads and validates a scene file. Relative file references (brains, characters,
// keyframes) are resolved against the scene file's directory.
LoadResult loadScene(const std::string& path);
// Same, from text already in memory; `fileName` names it in diagnostics.
LoadResult parseScene(const std::string& text, const std::string& fileName, const std::string& baseDir);

// Text of the scene in format v1. Brains with a file are written as references only.
std::string sceneToYaml(const Scene& scene);

// Text of a .brain.yaml file holding one brain graph.
std::string brainToYaml(const BrainGraph& brain);

struct SaveResult {
    bool ok = false;
    std::string error;  // what went wrong, naming the file
};
// Writes to a temporary file beside `path`, then renames it over `path`, so a crash
// never leaves half a file. Brains and hero keyframes with a file reference are written
// to that file (relative to the scene's directory) the same way, so a Save As into
// another folder is complete. Character files (.glb) are not copied.
SaveResult saveScene(const Scene& scene, const std::string& path);

// Atomic text write used by every saver (temporary file + fsync + rename).
SaveResult writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace throng::sim
