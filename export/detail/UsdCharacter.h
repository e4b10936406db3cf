#pragma once
// A character in the USD export: its skeleton and its skinned mesh, a Mesh prim per part,
// written once as an abstract (class) prim that every agent wearing it references. Names
// its joints as UsdSkel paths and its parts as prims; binds each part a material.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/character/Character.h"

#include <string>
#include <vector>

namespace throng::exporting::detail {

struct UsdLook {
    std::string prim;                     // its name under the characters' scope
    std::vector<std::string> jointPaths;  // per joint: "hips/spine/chest", valid prim names, unique
    std::vector<std::string> partNames;   // per part of partsOf(mesh): its Mesh prim, "skin", "skin_1", …
};

UsdLook usdLookOf(const Character& character, const std::string& prim);

// `class Xform "<look.prim>"` at `depth`, with `def Skeleton "Skel"` (joints, bind and rest
// transforms) and a `def Mesh` per part: its own vertices, normals, four joint influences a
// vertex, bound to the skeleton and to partMaterials[p] (a prim path; empty: none).
// `path`: the look's own prim path, which the meshes' skeleton relationships name.
void writeUsdCharacter(std::string& out, int depth, const Character& character, const UsdLook& look,
                       const std::string& path, const std::vector<std::string>& partMaterials);

// The joint paths as a USD token array: ["hips", "hips/spine", …].
void appendUsdJointTokens(std::string& out, const UsdLook& look);

}  // namespace throng::exporting::detail
