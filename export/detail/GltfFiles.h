#pragma once
// Writes a finished tinygltf model to disk atomically: one .glb, or a .gltf with its .bin
// beside it (the .bin renamed in first). Never leaves a partial or temporary file.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/ExportResult.h"
#include "export/detail/ExportCancel.h"

#include <tiny_gltf.h>

#include <string>

namespace throng::exporting::detail {

ExportResult failedExport(std::string error);
bool endsWithGlb(const std::string& path);
// The .bin's name beside a .gltf; also its URI, so only [A-Za-z0-9._~-] survive.
std::string binFileName(const std::string& gltfPath);
// By extension: .glb, else .gltf + .bin. Reports 0.95 to `progress` before publishing.
ExportResult writeModel(tinygltf::Model& model, const std::string& path, bool prettyJson, const ProgressFn& progress);

}  // namespace throng::exporting::detail
