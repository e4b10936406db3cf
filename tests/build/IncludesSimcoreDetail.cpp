// Must not compile: simcore's detail/ headers are private to throng::simcore
// (tests/build/CMakeLists.txt expects the guard's message).
#include "simcore/world/detail/StepGeometry.h"
