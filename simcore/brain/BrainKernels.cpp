// Each kernel is a plain loop over a contiguous range of a float column so the compiler
// vectorises it; per-neighbour instructions run over agentCount × K values. A value
// depends only on its own agent's inputs, so any split of agents gives the same bits.
#include "simcore/brain/detail/BrainKernels.h"

#include "simcore/brain/NodeCatalogue.h"
#include "simcore/base/Rng.h"

#include <algorithm>
#include <cmath>

namespace throng::sim::detail {

namespace {

constexpr std::size_t K = kBrainNeighbours;

struct Col {
    const float* p;
    bool pn;  // per-neighbour column (K values per agent)
};

struct Ctx {
    const BrainProgram& prog;
    const BrainInstr& I;
    const BrainFrame& f;
    std::size_t b, e;

    Col arg(std::uint32_t k) const
    {
        const std::uint32_t s = prog.operands[I.argBegin + k];
        return {f.in[s], prog.valueSlots[s].perNeighbour};
    }
    float param(std::uint32_t k) const { return prog.params[I.paramBegin + k]; }
    float* out(std::uint32_t k = 0) const { return f.out[I.out + k]; }
};

template <class F>
void unary(const Ctx& c, Col a, float* o, F fn)
{
    if (!c.I.perNeighbour) {
        const float* ap = a.p;
        for (std::size_t i = c.b; i < c.e; ++i)
            o[i] = fn(ap[i]);
        return;
    }
    if (a.pn) {
        const float* ap = a.p;
        for (std::size_t j = c.b * K; j < c.e * K; ++j)
            o[j] = fn(ap[j]);
        return;
    }
    for (std::size_t i = c.b; i < c.e; ++i)
        for (std::size_t k = 0; k < K; ++k)
            o[i * K + k] = fn(a.p[i]);
}

template <class F>
void binary(const Ctx& c, Col a, Col b, float* o, F fn)
{
    if (!c.I.perNeighbour) {
        const float* ap = a.p;
        const float* bp = b.p;
        for (std::size_t i = c.b; i < c.e; ++i)
            o[i] = fn(ap[i], bp[i]);
        return;
    }
    if (a.pn && b.pn) {
        const float* ap = a.p;
        const float* bp = b.p;
        for (std::size_t j = c.b * K; j < c.e * K; ++j)
            o[j] = fn(ap[j], bp[j]);
        return;
    }
    for (std::size_t i = c.b; i < c.e; ++i)
        for (std::size_t k = 0; k < K; ++k)
            o[i * K + k] = fn(a.pn ? a.p[i * K + k] : a.p[i], b.pn ? b.p[i * K + k] : b.p[i]);
}

template <class F>
void ternary(const Ctx& c, Col a, Col b, Col t, F fn)
{
    float* o = c.out();
    if (!c.I.perNeighbour) {
        for (std::size_t i = c.b; i < c.e; ++i)
            o[i] = fn(a.p[i], b.p[i], t.p[i]);
        return;
    }
    const auto at = [](Col x, std::size_t i, std::size_t k) { return x.pn ? x.p[i * K + k] : x.p[i]; };
    for (std::size_t i = c.b; i < c.e; ++i)
        for (std::size_t k = 0; k < K; ++k)
            o[i * K + k] = fn(at(a, i, k), at(b, i, k), at(t, i, k));
}

// Folds every operand into the output with fn, left to right.
template <class F>
void fold(const Ctx& c, F fn)
{
    float* o = c.out();
    unary(c, c.arg(0), o, [](float x) { return x; });
    const Col acc{o, c.I.perNeighbour};
    for (std::uint32_t k = 1; k < c.I.argCount; ++k)
        binary(c, acc, c.arg(k), o, fn);
}

float uniform(std::uint64_t key, NodeId node, std::uint64_t counter)
{
    return rngUniform(key, node, counter, 0xb7a1);
}

void noise(const Ctx& c)
{
    const float freq = c.param(0), lo = c.param(1), hi = c.param(2);
    const double t = double(c.f.timeS) * double(freq);
    const double cell = std::floor(t);
    const auto step = std::uint64_t(std::int64_t(cell) + (std::int64_t(1) << 40));
    const float u = float(t - cell);
    const float s = u * u * (3.0f - 2.0f * u);
    float* o = c.out();
    for (std::size_t i = c.b; i < c.e; ++i) {
        const float h0 = uniform(c.f.agentKey[i], c.I.node, step), h1 = uniform(c.f.agentKey[i], c.I.node, step + 1);
        o[i] = lo + (hi - lo) * (h0 + (h1 - h0) * s);
    }
}

// Index of the largest operand (ties: the first) and its value, per agent.
template <class F>
void argmax(const Ctx& c, F emit)
{
    for (std::size_t i = c.b; i < c.e; ++i) {
        std::uint32_t best = 0;
        float bestValue = c.f.in[c.prog.operands[c.I.argBegin]][i];
        for (std::uint32_t k = 1; k < c.I.argCount; ++k) {
            const float v = c.f.in[c.prog.operands[c.I.argBegin + k]][i];
            if (v > bestValue) {
                best = k;
                bestValue = v;
            }
        }
        emit(i, best, bestValue);
    }
}

void defuzzAverage(const Ctx& c)
{
    float* o = c.out();
    const float fallback = c.param(c.I.argCount);
    const std::size_t per = c.I.perNeighbour ? K : 1;
    for (std::size_t i = c.b; i < c.e; ++i)
        for (std::size_t k = 0; k < per; ++k) {
            float num = 0.0f, den = 0.0f;
            for (std::uint32_t a = 0; a < c.I.argCount; ++a) {
                const Col x = c.arg(a);
                const float t = x.pn ? x.p[i * K + k] : x.p[i];
                num += t * c.param(a);
                den += t;
            }
            o[i * per + k] = den > 1e-6f ? num / den : fallback;
        }
}

void priority(const Ctx& c)
{
    for (std::size_t i = c.b; i < c.e; ++i) {
        float left = 1.0f;
        for (std::uint32_t a = 0; a < c.I.argCount; ++a) {
            const float share = std::clamp(c.arg(a).p[i], 0.0f, left);
            c.out(a)[i] = share;
            left -= share;
        }
    }
}

void filter(const Ctx& c)
{
    const int mode = int(c.param(0));
    const float threshold = c.param(1), empty = c.param(2);
    const float* x = c.arg(0).p;
    const std::uint8_t* counts = c.f.itemCounts[c.I.itemSet];
    float* o = c.out();
    for (std::size_t i = c.b; i < c.e; ++i) {
        const std::size_t n = std::min<std::size_t>(counts[i], K);
        const float* v = x + i * K;
        float r = n ? v[0] : empty;
        switch (mode) {
        case 0: break;  // nearest: neighbours come nearest first
        case 1: for (std::size_t k = 1; k < n; ++k) r = std::min(r, v[k]); break;
        case 2: for (std::size_t k = 1; k < n; ++k) r = std::max(r, v[k]); break;
        case 3:
            if (n) {
                r = 0.0f;
                for (std::size_t k = 0; k < n; ++k)
                    r += v[k];
                r /= float(n);
            }
            break;
        default:
            r = 0.0f;
            for (std::size_t k = 0; k < n; ++k)
                r += v[k] > threshold ? 1.0f : 0.0f;
        }
        o[i] = r;
    }
}

void action(const Ctx& c)
{
    float* cur = c.f.state[c.I.state];
    float* left = c.f.state[c.I.state + 1];
    float* o = c.out();
    for (std::size_t i = c.b; i < c.e; ++i) {
        left[i] -= c.f.dtS;
        if (std::isnan(cur[i]) || left[i] <= 0.0f) {
            std::uint32_t best = 0;
            float bestValue = c.arg(0).p[i];
            for (std::uint32_t k = 1; k < c.I.argCount; ++k)
                if (c.arg(k).p[i] > bestValue) {
                    best = k;
                    bestValue = c.arg(k).p[i];
                }
            cur[i] = float(best);
            left[i] = c.param(best);
        }
        o[i] = cur[i];
    }
}

bool compare(int mode, float a, float b)
{
    switch (mode) {
    case 0: return a < b;
    case 1: return a <= b;
    case 2: return a > b;
    case 3: return a >= b;
    case 4: return a == b;
    default: return a != b;
    }
}

}  // namespace

bool isFoldable(BrainOp op)
{
    switch (op) {
    case BrainOp::Time: case BrainOp::Random: case BrainOp::Noise: case BrainOp::Filter: case BrainOp::MemoryRead:
    case BrainOp::MemoryWrite: case BrainOp::Timer: case BrainOp::Latch: case BrainOp::Smooth: case BrainOp::Action:
        return false;
    default:
        return true;
    }
}

void runInstr(const BrainProgram& prog, const BrainInstr& I, const BrainFrame& f, std::size_t b, std::size_t e)
{
    const Ctx c{prog, I, f, b, e};
    switch (I.op) {
    case BrainOp::Time: std::fill(c.out() + b, c.out() + e, f.timeS); break;
    case BrainOp::Random: {
        const float lo = c.param(0), hi = c.param(1);
        float* s = f.state[I.state];  // drawn once per agent, then kept
        for (std::size_t i = b; i < e; ++i) {
            if (std::isnan(s[i]))
                s[i] = lo + (hi - lo) * uniform(f.agentKey[i], I.node, 0);
            c.out()[i] = s[i];
        }
        break;
    }
    case BrainOp::Noise: noise(c); break;
    case BrainOp::Triangle: case BrainOp::Trapezoid: {
        // min(rising edge, falling edge) clamped to [0, 1], branch-free so it vectorises;
        // a vertical edge (a == b or c == d) is a step.
        const float a = c.param(0), b1 = c.param(1);
        const float c1 = I.op == BrainOp::Triangle ? c.param(1) : c.param(2),
                    d = c.param(I.op == BrainOp::Triangle ? 2 : 3);
        const bool stepUp = !(b1 > a), stepDown = !(d > c1);
        const float up = stepUp ? 0.0f : 1.0f / (b1 - a), down = stepDown ? 0.0f : 1.0f / (d - c1);
        unary(c, c.arg(0), c.out(), [=](float x) {
            const float r = stepUp ? (x >= a ? 1.0f : 0.0f) : (x - a) * up;
            const float f = stepDown ? (x <= d ? 1.0f : 0.0f) : (d - x) * down;
            return std::min(std::max(std::min(r, f), 0.0f), 1.0f);
        });
        break;
    }
    case BrainOp::Gaussian: {
        const float centre = c.param(0), k = -0.5f / (c.param(1) * c.param(1));
        unary(c, c.arg(0), c.out(), [=](float x) { return std::exp(k * (x - centre) * (x - centre)); });
        break;
    }
    case BrainOp::Sigmoid: {
        const float centre = c.param(0), slope = c.param(1);
        unary(c, c.arg(0), c.out(), [=](float x) { return 1.0f / (1.0f + std::exp(-slope * (x - centre))); });
        break;
    }
    case BrainOp::AndMin: case BrainOp::Min: fold(c, [](float a, float x) { return std::min(a, x); }); break;
    case BrainOp::OrMax: case BrainOp::Max: fold(c, [](float a, float x) { return std::max(a, x); }); break;
    case BrainOp::AndProduct: case BrainOp::Multiply: fold(c, [](float a, float x) { return a * x; }); break;
    case BrainOp::OrProbSum: fold(c, [](float a, float x) { return a + x - a * x; }); break;
    case BrainOp::Add: fold(c, [](float a, float x) { return a + x; }); break;
    case BrainOp::Not: unary(c, c.arg(0), c.out(), [](float x) { return 1.0f - x; }); break;
    case BrainOp::Weight: {
        const float w = c.param(0);
        unary(c, c.arg(0), c.out(), [=](float x) { return x * w; });
        break;
    }
    case BrainOp::Scale: {
        const float s = c.param(0);
        unary(c, c.arg(0), c.out(), [=](float x) { return x * s; });
        break;
    }
    case BrainOp::HedgeStrong: unary(c, c.arg(0), c.out(), [](float x) { return x * x; }); break;
    case BrainOp::HedgeWeak: unary(c, c.arg(0), c.out(), [](float x) { return std::sqrt(std::max(x, 0.0f)); }); break;
    case BrainOp::Abs: unary(c, c.arg(0), c.out(), [](float x) { return std::fabs(x); }); break;
    case BrainOp::Priority: priority(c); break;
    case BrainOp::DefuzzAverage: defuzzAverage(c); break;
    case BrainOp::Winner: {
        const bool values = I.paramCount > 0;
        argmax(c, [&](std::size_t i, std::uint32_t k, float v) {
            c.out(0)[i] = values ? c.param(k) : float(k);
            c.out(1)[i] = v;
        });
        break;
    }
    case BrainOp::Goal: argmax(c, [&](std::size_t i, std::uint32_t k, float) { c.out()[i] = float(k); }); break;
    case BrainOp::Subtract: binary(c, c.arg(0), c.arg(1), c.out(), [](float a, float x) { return a - x; }); break;
    case BrainOp::Divide: {
        const float fallback = c.param(0);
        binary(c, c.arg(0), c.arg(1), c.out(), [=](float a, float x) { return x != 0.0f ? a / x : fallback; });
        break;
    }
    case BrainOp::Clamp:
        ternary(c, c.arg(0), c.arg(1), c.arg(2),
                [](float x, float lo, float hi) { return std::min(std::max(x, lo), hi); });
        break;
    case BrainOp::Lerp:
        ternary(c, c.arg(0), c.arg(1), c.arg(2), [](float a, float x, float t) { return a + (x - a) * t; });
        break;
    case BrainOp::Remap: {
        const float f0 = c.param(0), inv = 1.0f / (c.param(1) - c.param(0)), t0 = c.param(2), t1 = c.param(3);
        const bool clamp = c.param(4) != 0.0f;
        unary(c, c.arg(0), c.out(), [=](float x) {
            float u = (x - f0) * inv;
            if (clamp)
                u = std::min(std::max(u, 0.0f), 1.0f);
            return t0 + (t1 - t0) * u;
        });
        break;
    }
    case BrainOp::Compare: {
        const int mode = int(c.param(0));
        binary(c, c.arg(0), c.arg(1), c.out(), [=](float a, float x) { return compare(mode, a, x) ? 1.0f : 0.0f; });
        break;
    }
    case BrainOp::Filter: filter(c); break;
    case BrainOp::MemoryRead: std::copy(f.state[I.state] + b, f.state[I.state] + e, c.out() + b); break;
    case BrainOp::MemoryWrite: std::copy(c.arg(0).p + b, c.arg(0).p + e, f.state[I.state] + b); break;
    case BrainOp::Timer: {
        float* s = f.state[I.state];
        const float* run = c.arg(0).p;
        for (std::size_t i = b; i < e; ++i) {
            s[i] = run[i] > 0.5f ? s[i] + f.dtS : 0.0f;
            c.out()[i] = s[i];
        }
        break;
    }
    case BrainOp::Latch: {
        float* s = f.state[I.state];
        const float *set = c.arg(0).p, *reset = c.arg(1).p;
        for (std::size_t i = b; i < e; ++i) {
            s[i] = reset[i] > 0.5f ? 0.0f : set[i] > 0.5f ? 1.0f : s[i];
            c.out()[i] = s[i];
        }
        break;
    }
    case BrainOp::Smooth: {
        float* s = f.state[I.state];
        const float* x = c.arg(0).p;
        const float alpha = 1.0f - std::exp(-f.dtS / c.param(0));
        for (std::size_t i = b; i < e; ++i) {
            s[i] = std::isnan(s[i]) ? x[i] : s[i] + (x[i] - s[i]) * alpha;
            c.out()[i] = s[i];
        }
        break;
    }
    case BrainOp::Action: action(c); break;
    }
}

}  // namespace throng::sim::detail
