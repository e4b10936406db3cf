#pragma once
// The RiMEA tests that set speed against density (Rimea.h's rows 4 and 16), and the
// formatting the pack's measured texts share. Private to the validation library.

#include "validation/Rimea.h"

#include <string>
#include <vector>

namespace throng::validation {

// printf into a string, up to three numbers: "30.1 s".
std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0);

// Test 4: walkers filling a corridor at six densities walk, in its middle, at Weidmann's
// speed for the density measured there.
Outcome fundamentalDiagram(const std::vector<sim::Scene>& scenes);
// Test 16: walkers in single file round a ring walk at Seyfried's speed for their spacing.
Outcome singleFile(const std::vector<sim::Scene>& scenes);

}  // namespace throng::validation
