#pragma once
// Reads a YAML document with the checks every Throng file gets before parsing: a size
// limit, no binary data, no tab indentation, an optional UTF-8 BOM, and parser errors
// turned into located diagnostics. Never throws.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/io/detail/YamlFields.h"

#include <string>

namespace throng::sim::detail {

// Parses `text`; false (with a diagnostic through `f`) when it is empty or not YAML.
bool parseYamlText(const std::string& text, YamlFields& f, YAML::Node& root);
// Reads the file at f.file() into `text` and parses it.
bool readYamlFile(YamlFields& f, std::string& text, YAML::Node& root);

}  // namespace throng::sim::detail
