#pragma once
// A seeded generator of valid scenes that use every section and every key, for
// round-trip and robustness tests. Test-only.

#include "simcore/scene/Scene.h"

#include <cstdint>

namespace throng::test {

// `agents` placed agents; 64 or more makes the writer use the table form.
sim::Scene makeRandomScene(std::uint32_t seed, std::uint32_t agents);

}  // namespace throng::test
