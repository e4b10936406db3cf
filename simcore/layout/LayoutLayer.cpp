#include "simcore/layout/LayoutLayer.h"

namespace throng::sim {

namespace {

constexpr const char* kNames[kLayoutKindCount] = {"translate", "rotate", "time_offset", "mirror",   "delete",
                                                      "expand",    "duplicate", "swap",     "replace_clip", "resolve"};

}  // namespace

const char* toString(LayoutKind kind) { return kNames[static_cast<int>(kind)]; }

bool layoutKindFromName(std::string_view name, LayoutKind& kind)
{
    for (int k = 0; k < kLayoutKindCount; ++k)
        if (name == kNames[k]) {
            kind = static_cast<LayoutKind>(k);
            return true;
        }
    return false;
}

}  // namespace throng::sim
