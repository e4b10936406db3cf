// Must not compile: export's detail/ headers are private to throng::export
// (tests/build/CMakeLists.txt expects the guard's message).
#include "export/detail/TextFields.h"
