#pragma once
// Mends the framing of a binary FBX file written by Debian 12's assimp (5.2.5): its writer
// leaves out every null record, the 25 zero bytes that end a record's list of children
// and the file's list of records, so that neither assimp's own reader nor Blender's
// reads the file. This parses the records by their end offsets and writes them again with
// the null records in place and every offset moved to match; properties are copied byte
// for byte. A file that already has its null records keeps its framing. It also writes
// the shot's frame rate and length into the file's settings, and connects scale curves to
// "Lcl Scaling" (assimp names a property no model has): what assimp gets wrong.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include <span>
#include <string>
#include <vector>

namespace throng::exporting::detail {

// The shot's time, which assimp writes as 24 fps and one second whatever the animation.
struct FbxShotTime {
    double fps = 24.0;       // > 0
    double durationS = 0.0;  // the last frame's time
};

// `bytes`: a whole binary FBX file (version 7100 to 7500), whose settings are set in place
// (no copy of a file that may be gigabytes). Returns the mended file, its GlobalSettings'
// TimeMode, CustomFrameRate and TimeSpanStop set to `time`; or an empty vector with
// `error` saying what in the file could not be read.
std::vector<unsigned char> mendFbxFraming(std::span<unsigned char> bytes, const FbxShotTime& time,
                                          std::string& error);

}  // namespace throng::exporting::detail
