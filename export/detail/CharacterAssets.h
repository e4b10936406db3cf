#pragma once
// Writes one character's geometry once (interleaved vertices with byteStride, joints,
// indices, inverse bind matrices) and hands back the accessors every agent wearing it
// shares. Never writes per-agent data.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/character/Character.h"
#include "export/detail/GltfBuilder.h"

#include <map>
#include <string>
#include <vector>

namespace throng::exporting::detail {

struct CharacterAccessors {
    std::map<std::string, int> attributes;  // POSITION, NORMAL, WEIGHTS_0, JOINTS_0
    std::vector<int> partIndices;  // per part of partsOf(mesh): its run of the indices
    int inverseBindMatrices = -1;
};

CharacterAccessors writeCharacterAssets(GltfBuilder& builder, const Character& character);

}  // namespace throng::exporting::detail
