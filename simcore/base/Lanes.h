#pragma once
// Floats side by side, four (F4) or eight (F8), for the boids kernel's search and steering
// of several boids at once (BoidKernelSense.cpp, BoidKernelLanes.cpp). GCC's vector
// extension: SSE on x86-64, plain code elsewhere; eight lanes are one AVX register inside
// a function built for AVX2 (World::steerEightBoids) and two SSE ones anywhere else. A
// mask picks lanes with the vector form of ?:, which GCC has in C++. Each helper does per
// lane exactly what its glm or SteeringMath.h counterpart does for one float, operation
// for operation (no reciprocal estimates; simcore builds with -ffp-contract=off, so no
// fused multiply-add either), so the results are the same to the bit at either width.
//
// The helpers are templates on the lane type, written for any width, so one kernel serves
// both, and none uses an instruction beyond baseline x86-64. They are always inlined: an
// eight-float value passed to a function not built for AVX would be passed another way
// than AVX code passes it, so no call may take one (at any optimisation level).

#include <cstdint>
#include <limits>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace throng::sim::simd {

using F1 = float __attribute__((vector_size(4)));  // one agent, in code written for lanes
using F4 = float __attribute__((vector_size(16)));
using F8 = float __attribute__((vector_size(32)));
using M4 = std::int32_t __attribute__((vector_size(16)));  // lane masks: all ones or zero

// The lanes of a lane type, and the mask type its comparisons give.
template <class F>
inline constexpr int kWidth = int(sizeof(F) / sizeof(float));
template <class F>
using MaskOf = decltype(F{} < F{});

template <class F>
[[gnu::always_inline]] inline F splat(float x)
{
    F r;
    for (int l = 0; l < kWidth<F>; ++l)
        r[l] = x;
    return r;
}
[[gnu::always_inline]] inline F4 f4(float x) { return splat<F4>(x); }
template <class M, class F>
[[gnu::always_inline]] inline F select(M m, F a, F b)
{
    return m ? a : b;
}
// std::min, lane by lane: b < a ? b : a.
template <class F>
[[gnu::always_inline]] inline F minOf(F a, F b)
{
    return select(b < a, b, a);
}
// std::max, lane by lane: a < b ? b : a.
template <class F>
[[gnu::always_inline]] inline F maxOf(F a, F b)
{
    return select(a < b, b, a);
}
template <class F>
[[gnu::always_inline]] inline F sqrtOf(F x)
{
#if defined(__SSE__)
    if constexpr (sizeof(F) == sizeof(F4))
        return _mm_sqrt_ps(x);
#endif
    // Lane by lane; with -fno-math-errno GCC makes one vector square root of it where the
    // width has one.
    F r;
    for (int l = 0; l < kWidth<F>; ++l)
        r[l] = __builtin_sqrtf(x[l]);
    return r;
}
// The lanes a mask holds, as bits 0 to width - 1.
template <class M>
[[gnu::always_inline]] inline unsigned bitsOf(M m)
{
#if defined(__SSE__)
    if constexpr (sizeof(M) == sizeof(M4))
        return unsigned(_mm_movemask_ps(__m128(m)));
    // Eight: each half's four (lane by lane, GCC made eight extracts of it).
    if constexpr (sizeof(M) == 2 * sizeof(M4))
        return bitsOf(M4(__builtin_shufflevector(m, m, 0, 1, 2, 3))) |
               bitsOf(M4(__builtin_shufflevector(m, m, 4, 5, 6, 7))) << 4;
#endif
    unsigned bits = 0;
    for (int l = 0; l < int(sizeof(M) / sizeof(std::int32_t)); ++l)
        bits |= unsigned(m[l] & 1) << l;
    return bits;
}
template <class M>
[[gnu::always_inline]] inline bool any(M m)
{
    return bitsOf(m) != 0;
}

// A glm::vec3 per lane.
template <class F>
struct Lanes3 {
    F x, y, z;
};
using V4 = Lanes3<F4>;
template <class F>
[[gnu::always_inline]] inline Lanes3<F> operator+(Lanes3<F> a, Lanes3<F> b)
{
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class F>
[[gnu::always_inline]] inline Lanes3<F> operator-(Lanes3<F> a, Lanes3<F> b)
{
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class F>
[[gnu::always_inline]] inline Lanes3<F> operator*(Lanes3<F> a, F s)
{
    return {a.x * s, a.y * s, a.z * s};
}
template <class F>
[[gnu::always_inline]] inline Lanes3<F> operator/(Lanes3<F> a, F s)
{
    return {a.x / s, a.y / s, a.z / s};
}
template <class M, class F>
[[gnu::always_inline]] inline Lanes3<F> select(M m, Lanes3<F> a, Lanes3<F> b)
{
    return {m ? a.x : b.x, m ? a.y : b.y, m ? a.z : b.z};
}
// glm::dot: (x + y) + z of the products.
template <class F>
[[gnu::always_inline]] inline F dot(Lanes3<F> a, Lanes3<F> b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class F>
[[gnu::always_inline]] inline F length(Lanes3<F> v)
{
    return sqrtOf(dot(v, v));
}
// glm::cross, term for term.
template <class F>
[[gnu::always_inline]] inline Lanes3<F> cross(Lanes3<F> a, Lanes3<F> b)
{
    return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}

inline constexpr float kLaneInfinity = std::numeric_limits<float>::infinity();

// SteeringMath.h's nonNegative, normalizeOr and truncate, and isFinite of a vector.
template <class F>
[[gnu::always_inline]] inline F nonNegativeOf(F x)
{
    return select((x > 0.0f) & (x < kLaneInfinity), x, F{});
}
template <class F>
[[gnu::always_inline]] inline Lanes3<F> normalizeOr(Lanes3<F> v, Lanes3<F> fallback, float tiny)
{
    const F l = length(v);
    return select((l > tiny) & (l < kLaneInfinity), v * (1.0f / l), fallback);
}
template <class F>
[[gnu::always_inline]] inline Lanes3<F> truncate(Lanes3<F> v, F maxLength)
{
    maxLength = nonNegativeOf(maxLength);
    const F l2 = dot(v, v);
    const Lanes3<F> cut = select(l2 > maxLength * maxLength, v * (maxLength / sqrtOf(l2)), v);
    return select(l2 < kLaneInfinity, cut, Lanes3<F>{});
}
template <class F>
[[gnu::always_inline]] inline MaskOf<F> finite(Lanes3<F> v)
{
    return v.x * 0.0f + v.y * 0.0f + v.z * 0.0f == 0.0f;
}

}  // namespace throng::sim::simd
