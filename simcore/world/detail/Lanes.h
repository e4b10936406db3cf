#pragma once
// Four floats side by side, for the boids kernel's search and steering of four boids at
// once (WorldFlockSense.cpp, WorldFlockLanes.cpp). GCC's vector extension: SSE on x86-64,
// plain code elsewhere; a mask picks lanes with the vector form of ?:, which GCC has in
// C++. Each helper does per lane exactly what its glm or SteeringMath.h counterpart does
// for one float, operation for operation (no reciprocal estimates; simcore builds with
// -ffp-contract=off, so no fused multiply-add either), so the results are the same to the
// bit.

#include <cstdint>
#include <limits>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace throng::sim::detail {

using F4 = float __attribute__((vector_size(16)));
using M4 = std::int32_t __attribute__((vector_size(16)));  // lane masks: all ones or zero

inline F4 f4(float x) { return F4{x, x, x, x}; }
inline F4 select(M4 m, F4 a, F4 b) { return m ? a : b; }
// std::min, lane by lane: b < a ? b : a.
inline F4 minOf(F4 a, F4 b) { return select(b < a, b, a); }
// std::max, lane by lane: a < b ? b : a.
inline F4 maxOf(F4 a, F4 b) { return select(a < b, b, a); }
inline F4 sqrtOf(F4 x)
{
#if defined(__SSE__)
    return _mm_sqrt_ps(x);
#else
    return F4{__builtin_sqrtf(x[0]), __builtin_sqrtf(x[1]), __builtin_sqrtf(x[2]), __builtin_sqrtf(x[3])};
#endif
}
inline bool any(M4 m) { return (m[0] | m[1] | m[2] | m[3]) != 0; }
// The lanes a mask holds, as bits 0 to 3.
inline unsigned bitsOf(M4 m)
{
#if defined(__SSE__)
    return unsigned(_mm_movemask_ps(__m128(m)));
#else
    return unsigned(m[0] & 1) | unsigned(m[1] & 2) | unsigned(m[2] & 4) | unsigned(m[3] & 8);
#endif
}

// A glm::vec3 per lane.
struct V4 {
    F4 x, y, z;
};
inline V4 operator+(V4 a, V4 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V4 operator-(V4 a, V4 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V4 operator*(V4 a, F4 s) { return {a.x * s, a.y * s, a.z * s}; }
inline V4 operator/(V4 a, F4 s) { return {a.x / s, a.y / s, a.z / s}; }
inline V4 select(M4 m, V4 a, V4 b) { return {m ? a.x : b.x, m ? a.y : b.y, m ? a.z : b.z}; }
// glm::dot: (x + y) + z of the products.
inline F4 dot(V4 a, V4 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline F4 length(V4 v) { return sqrtOf(dot(v, v)); }
// glm::cross, term for term.
inline V4 cross(V4 a, V4 b) { return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y}; }

inline constexpr float kLaneInfinity = std::numeric_limits<float>::infinity();

// SteeringMath.h's nonNegative, normalizeOr and truncate, and isFinite of a vector.
inline F4 nonNegativeOf(F4 x) { return select((x > 0.0f) & (x < kLaneInfinity), x, f4(0.0f)); }
inline V4 normalizeOr(V4 v, V4 fallback, float tiny)
{
    const F4 l = length(v);
    return select((l > tiny) & (l < kLaneInfinity), v * (1.0f / l), fallback);
}
inline V4 truncate(V4 v, F4 maxLength)
{
    maxLength = nonNegativeOf(maxLength);
    const F4 l2 = dot(v, v);
    const V4 cut = select(l2 > maxLength * maxLength, v * (maxLength / sqrtOf(l2)), v);
    return select(l2 < kLaneInfinity, cut, V4{f4(0.0f), f4(0.0f), f4(0.0f)});
}
inline M4 finite(V4 v) { return v.x * 0.0f + v.y * 0.0f + v.z * 0.0f == 0.0f; }

}  // namespace throng::sim::detail
