#pragma once
// How many Worlds the calling thread has built (World's constructor counts them). An
// editor keeps every World off its GUI thread; its tests check that here, without timing
// anything.

#include <cstdint>

namespace throng::sim {

std::uint64_t worldsBuiltOnThisThread();

}  // namespace throng::sim
