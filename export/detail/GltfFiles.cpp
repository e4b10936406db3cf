#include "export/detail/GltfFiles.h"

#include "simcore/base/AtomicFile.h"
#include "export/detail/StagingDirectory.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace throng::exporting::detail {

namespace {

// A GLB stores its total length in 32 bits; keep room for the JSON chunk.
constexpr std::uint64_t kMaxGlbBinBytes = 0xFFFFFFFFull - (256ull << 20);

ExportResult writeGlb(const tinygltf::Model& model, const std::string& path, const ProgressFn& progress)
{
    if (model.buffers[0].data.size() > kMaxGlbBinBytes)
        return failedExport("cannot export '" + path + "': " + std::to_string(model.buffers[0].data.size() >> 20) +
                            " MiB of binary data do not fit a .glb (4 GiB at most); write .gltf instead");
    sim::AtomicFile file(path);
    if (!file.open())
        return failedExport(file.error());
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, file.stream(), false, true))
        return failedExport("cannot write '" + path + "': the glTF serialiser failed");
    if (cancelledAt(progress, 0.95f))
        return cancelledExport(path);
    if (!file.commit())
        return failedExport(file.error());
    return ExportResult{{path}, {}, false};
}

// tinygltf's file writer does not report short writes; a complete staged file is
// exactly as long as the data (.bin) or ends with the JSON's closing brace (.gltf).
bool stagedFileComplete(const std::string& path, std::uintmax_t expectedSize, bool json)
{
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || (!json && size != expectedSize) || (json && size < 2))
        return false;
    if (!json)
        return true;
    std::ifstream in(path, std::ios::binary);
    char tail[2] = {};
    in.seekg(-2, std::ios::end);
    in.read(tail, 2);
    return in && (tail[1] == '}' || (tail[0] == '}' && tail[1] == '\n'));
}

ExportResult writeGltfAndBin(tinygltf::Model& model, const std::string& path, bool prettyJson,
                             const ProgressFn& progress)
{
    namespace fs = std::filesystem;
    const std::string binName = binFileName(path);
    const std::string gltfName = fs::path(path).filename().string();
    const std::string binPath = (fs::path(path).parent_path() / binName).string();
    model.buffers[0].uri = binName;

    StagingDirectory staging(path);
    if (!staging.create())
        return failedExport(staging.error());
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&model, staging.filePath(gltfName), false, false, prettyJson, false))
        return failedExport("cannot write '" + path + "' or '" + binPath + "'");
    if (!stagedFileComplete(staging.filePath(binName), model.buffers[0].data.size(), false))
        return failedExport("could not write all of '" + binPath + "' (disk full?)");
    if (!stagedFileComplete(staging.filePath(gltfName), 0, true))
        return failedExport("could not write all of '" + path + "' (disk full?)");
    if (cancelledAt(progress, 0.95f))
        return cancelledExport(path);
    // The .bin first: the .gltf that names it must never appear before it.
    if (!staging.syncToDisk() || !staging.publish(binName, binPath) || !staging.publish(gltfName, path))
        return failedExport(staging.error());
    return ExportResult{{path, binPath}, {}, false};
}

}  // namespace

ExportResult failedExport(std::string error)
{
    ExportResult result;
    result.error = std::move(error);
    return result;
}

bool endsWithGlb(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".glb";
}

std::string binFileName(const std::string& gltfPath)
{
    std::string stem = std::filesystem::path(gltfPath).stem().string();
    for (char& c : stem) {
        const bool safe = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_' || c == '~';
        if (!safe)
            c = '_';
    }
    return (stem.empty() ? std::string("crowd") : stem) + ".bin";
}

ExportResult writeModel(tinygltf::Model& model, const std::string& path, bool prettyJson, const ProgressFn& progress)
{
    return endsWithGlb(path) ? writeGlb(model, path, progress) : writeGltfAndBin(model, path, prettyJson, progress);
}

}  // namespace throng::exporting::detail
