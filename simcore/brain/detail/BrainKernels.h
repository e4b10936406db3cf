#pragma once
// The per-instruction loops of the brain evaluator: each runs one instruction for a
// contiguous range of agents over float columns. Private to simcore/brain.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/brain/BrainProgram.h"

#include <cstddef>
#include <cstdint>

namespace throng::sim::detail {

struct BrainFrame {
    const float* const* in = nullptr;  // per slot: the column to read
    float* const* out = nullptr;       // per slot: the column to write (computed slots)
    float* const* state = nullptr;     // per state column
    const std::uint8_t* const* itemCounts = nullptr;  // per item set: per agent, <= kBrainNeighbours
    const std::uint64_t* agentKey = nullptr;       // per agent, for random and noise
    float timeS = 0.0f;
    float dtS = 0.0f;
};

// Runs `instr` for agents [begin, end). Writes only those agents' values.
void runInstr(const BrainProgram& program, const BrainInstr& instr, const BrainFrame& frame, std::size_t begin,
              std::size_t end);

// Whether an instruction with constant operands may be computed once at compile time.
bool isFoldable(BrainOp op);

}  // namespace throng::sim::detail
