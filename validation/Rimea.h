#pragma once
// The RiMEA test pack (guideline 4.1.1, www.rimea.de): the tests that apply to a scene on one
// level, each a scene (or two) in resources/validation/ and a criterion measured on its run.
// `throng-cli validate` and the test suite run them. Each test is a row of rimeaTests();
// adding one is its scene file and its row. Never touches Qt; runs Worlds headless.

#include "simcore/scene/Scene.h"

#include <string>
#include <vector>

namespace throng::validation {

struct Outcome {
    std::string measured;  // what was measured, with its unit ("30.1 s")
    bool pass = false;
    std::string error;     // a scene that did not load or run: why (then pass is false)
};

struct RimeaTest {
    int number = 0;                   // the guideline's test number
    std::string title;                // "Corridor: walking speed kept"
    std::string criterion;            // what passing means, with its bounds
    std::vector<std::string> scenes;  // files in the validation folder, in the order run() takes
    // Runs the loaded scenes and judges them. Empty for a test that cannot run yet.
    Outcome (*run)(const std::vector<sim::Scene>& scenes) = nullptr;
    std::string notRunBecause;        // a test with no run(): why, and what it needs
};

// Every test of the guideline's pack (1 to 16), in its order: those that run, and those that
// cannot yet, each saying why (stairs need levels; others are planned).
const std::vector<RimeaTest>& rimeaTests();

// Loads test's scenes from `directory` and runs it; a scene that does not load is the
// outcome's error (file, line and what is wrong).
Outcome runRimeaTest(const RimeaTest& test, const std::string& directory);

}  // namespace throng::validation
