#include "export/ExportFormats.h"

#include "export/AgentTextCache.h"
#include "export/FbxExporter.h"
#include "export/GltfExporter.h"
#include "export/PedPyExport.h"
#include "export/TrajectoryCsv.h"
#include "export/UsdExporter.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace throng::exporting {

namespace {

// The choices every skinned-crowd writer (glTF, USD, FBX) reads, as its options.
template <typename Options>
Options crowdOptions(const ExportRequest& request)
{
    Options options;
    options.path = request.path;
    options.sceneDirectory = request.sceneDirectory;
    options.seed = request.seed;
    options.jointFrameStep = request.jointFrameStep;
    options.lod = request.lod;
    options.threads = request.threads;
    options.includeSet = request.includeSet;
    options.firstFrame = request.firstFrame;
    return options;
}

ExportResult writeGltf(const sim::Scene& scene, const sim::FrameCache& cache, const ExportRequest& request,
                       const ProgressFn& progress)
{
    GltfOptions options = crowdOptions<GltfOptions>(request);
    options.mode = request.jointBake == JointBake::Compact ? GltfMode::Compact : GltfMode::Exact;
    options.prettyJson = request.indentedText;
    return exportGltf(scene, cache, options, progress);
}

ExportResult writeUsd(const sim::Scene& scene, const sim::FrameCache& cache, const ExportRequest& request,
                      const ProgressFn& progress)
{
    UsdOptions options = crowdOptions<UsdOptions>(request);
    options.compact = request.jointBake == JointBake::Compact;
    return exportUsd(scene, cache, options, progress);
}

ExportResult writeFbx(const sim::Scene& scene, const sim::FrameCache& cache, const ExportRequest& request,
                      const ProgressFn& progress)
{
    return exportFbx(scene, cache, crowdOptions<FbxOptions>(request), progress);
}

ExportResult writeCsv(const sim::Scene&, const sim::FrameCache& cache, const ExportRequest& request,
                      const ProgressFn& progress)
{
    return writeTrajectoryCsv(cache, request.path, progress);
}

ExportResult writePedPy(const sim::Scene& scene, const sim::FrameCache& cache, const ExportRequest& request,
                        const ProgressFn& progress)
{
    return writePedPyTrajectories(scene, cache, request.path, progress);
}

ExportResult writeTextCache(const sim::Scene&, const sim::FrameCache& cache, const ExportRequest& request,
                            const ProgressFn& progress)
{
    // "shot/" names the directory "shot": its staging sibling must not land inside it.
    std::string directory = request.path;
    while (directory.size() > 1 && directory.back() == '/')
        directory.pop_back();
    return writeAgentTextCache(cache, directory, progress);
}

// The text cache for Maya (docs/export.md, Maya): +Z forward unless asked otherwise, and the
// manifest resources/maya/throngCrowd.mel reads.
ExportResult writeMayaCache(const sim::Scene& scene, const sim::FrameCache& cache, const ExportRequest& request,
                            const ProgressFn& progress)
{
    (void)scene;
    std::string directory = request.path;
    while (directory.size() > 1 && directory.back() == '/')
        directory.pop_back();
    return writeAgentTextCache(cache, directory, progress, {.forward = request.mayaForward, .manifest = true});
}

std::string lowerCase(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

}  // namespace

const std::vector<ExportFormat>& exportFormats()
{
    static const std::vector<ExportFormat> formats{
        {.key = "gltf",
         .label = "glTF 2.0 animated crowd (.glb, or .gltf + .bin)",
         .suffixes = {".glb", ".gltf"},
         .indentedSuffixes = {".gltf"},
         .writesSet = true,
         .writesCharacters = true,
         .sharesCycles = true,
         .write = writeGltf},
        {.key = "usd",
         .label = "USD crowd, UsdSkel (.usda)",
         .suffixes = {".usda"},
         .writesSet = true,
         .writesCharacters = true,
         .sharesCycles = true,
         .write = writeUsd},
        {.key = "fbx",
         .label = "FBX skinned crowd (.fbx)",
         .suffixes = {".fbx"},
         .writesSet = true,
         .writesCharacters = true,
         .write = writeFbx},
        {.key = "csv", .label = "Trajectories CSV (.csv)", .suffixes = {".csv"}, .write = writeCsv},
        {.key = "pedpy",
         .label = "PedPy trajectories of the walkers (.txt, the set beside it as .wkt)",
         .suffixes = {".txt"},
         .write = writePedPy},
        {.key = "text-cache",
         .label = "Per-agent text cache (a directory)",
         .suffixes = {},
         .writesDirectory = true,
         .write = writeTextCache},
        {.key = "maya-cache",
         .label = "Maya per-agent cache and manifest (a directory; +Z forward)",
         .suffixes = {},
         .writesDirectory = true,
         .write = writeMayaCache},
    };
    return formats;
}

const ExportFormat* formatForPath(const std::string& path)
{
    const std::vector<ExportFormat>& formats = exportFormats();
    if (!path.empty() && path.back() == '/') {
        const auto found = std::find_if(formats.begin(), formats.end(),
                                        [](const ExportFormat& f) { return f.writesDirectory; });
        return found == formats.end() ? nullptr : &*found;
    }
    const std::string suffix = lowerCase(std::filesystem::path(path).extension().string());
    if (suffix.empty())
        return nullptr;
    for (const ExportFormat& f : formats)
        if (std::find(f.suffixes.begin(), f.suffixes.end(), suffix) != f.suffixes.end())
            return &f;
    return nullptr;
}

const ExportFormat* formatByKey(const std::string& key)
{
    for (const ExportFormat& f : exportFormats())
        if (f.key == key)
            return &f;
    return nullptr;
}

bool indentsText(const ExportFormat& format, const std::string& path)
{
    const std::string suffix = lowerCase(std::filesystem::path(path).extension().string());
    return std::find(format.indentedSuffixes.begin(), format.indentedSuffixes.end(), suffix) !=
           format.indentedSuffixes.end();
}

std::string pathForms(const ExportFormat& format)
{
    if (format.writesDirectory)
        return "DIR/";
    std::string text;
    for (const std::string& s : format.suffixes)
        text += (text.empty() ? "" : ", ") + s;
    return text;
}

std::string knownPathForms()
{
    std::string text;
    for (const ExportFormat& f : exportFormats())
        if (formatForPath(f.writesDirectory ? "d/" : "d" + f.suffixes.front()) == &f)  // one DIR/
            text += (text.empty() ? "" : ", ") + pathForms(f);
    return text;
}

}  // namespace throng::exporting
