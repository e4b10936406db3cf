#pragma once
// atan2 of Throng's own, for the bearings the brains' senses report (a neighbour's, the
// goal's, a sound's): in lanes, so an agent's eight neighbours take two 4-wide
// computations instead of eight calls into the C library, and the same to the bit in
// every lane width and for one float alone, since each lane does the same operations
// (Lanes.h; simcore builds with -ffp-contract=off). The bearings are also the same on
// every C library, where std::atan2 is each library's own (the brains' other functions,
// such as exp, are still the library's).
//
// Within 2 units in the last place of the exact angle (TestAtan2 measures it against
// double precision), with the C library's conventions for signed zeros, infinities and
// NaN. The method: the smaller of |y| and |x| over the larger gives t in [0, 1], whose
// atan one polynomial gives; then the octant's reflection.

#include "simcore/base/Lanes.h"

#include <bit>
#include <cstdint>
#include <type_traits>

namespace throng::sim::simd {

namespace atan2detail {
// One float, or lanes: the integer type of its bits, a value in every lane, and bit casts.
template <class F>
using Bits = std::conditional_t<std::is_same_v<F, float>, std::int32_t, MaskOf<F>>;
template <class F>
[[gnu::always_inline]] inline F all(float x)
{
    if constexpr (std::is_same_v<F, float>)
        return x;
    else
        return splat<F>(x);
}
template <class F>
[[gnu::always_inline]] inline Bits<F> rawBits(F x)
{
    if constexpr (std::is_same_v<F, float>)
        return std::bit_cast<std::int32_t>(x);
    else
        return Bits<F>(x);
}
template <class F>
[[gnu::always_inline]] inline F rawFloats(Bits<F> b)
{
    if constexpr (std::is_same_v<F, float>)
        return std::bit_cast<float>(b);
    else
        return F(b);
}
}  // namespace atan2detail

// atan2 for one float (F = float) or in lanes (F4, F8): the same operations either way.
template <class F>
[[gnu::always_inline]] inline F atan2Of(F y, F x)
{
    using namespace atan2detail;
    constexpr std::int32_t kMagnitude = 0x7fffffff;
    const Bits<F> yBits = rawBits(y), xBits = rawBits(x);
    const F ax = rawFloats<F>(xBits & kMagnitude), ay = rawFloats<F>(yBits & kMagnitude);
    const auto steep = ay > ax, behind = xBits < 0;  // nearer the y axis; x negative (or -0)
    const F num = select(steep, ax, ay), den = select(steep, ay, ax);
    F t = num / den;
    t = select(den == 0.0f, all<F>(0.0f), t);           // both zero
    t = select(num == kLaneInfinity, all<F>(1.0f), t);  // both infinite
    // atan(t), t in [0, 1]: the polynomial in z = t^2 is (atan(t)/t - 1)/z fitted over
    // [0, 1] (Chebyshev, absolute error 1.6e-8), its terms summed in pairs and the pairs by
    // powers of z^2 (Estrin's scheme), so the sums do not wait on each other in turn. Below
    // t = 1e-4, atan(t) is t to within 4e-9 of it, and z is taken as 0: its powers would
    // otherwise fall to subnormal floats, which x86 works out a hundred times as slowly
    // (a neighbour straight ahead has t near 0).
    const F z = select(t < 1e-4f, all<F>(0.0f), t * t), z2 = z * z, z4 = z2 * z2;
    const F p01 = -0.33333332f + 0.19999739f * z, p23 = -0.14278569f + 0.11033764f * z;
    const F p45 = -0.086568804f + 0.062501694f * z, p67 = -0.035871539f + 0.013507771f * z;
    const F poly = (p01 + p23 * z2) + ((p45 + p67 * z2) + -0.0023869973f * z4) * z4;
    const F a = select(t == 1.0f, all<F>(0.78539819f), t + t * (z * poly));  // the diagonals: pi/4 exactly rounded
    // The octant: a, pi/2 - a, pi/2 + a or pi - a, with pi/2 and pi each a float and the
    // remainder below it; then y's sign.
    const F base = select(steep, all<F>(1.5707964f), select(behind, all<F>(3.1415927f), all<F>(0.0f)));
    const F below = select(steep, all<F>(-4.3711388e-08f), select(behind, all<F>(-8.7422777e-08f), all<F>(0.0f)));
    const F angle = base + (select(steep != behind, -a, a) + below);
    const F signed_ = rawFloats<F>(rawBits(angle) | (yBits & ~kMagnitude));
    return select((x != x) | (y != y), x + y, signed_);
}

}  // namespace throng::sim::simd

namespace throng::sim {

// atan2(y, x) in radians, as simd::atan2Of gives each lane.
[[gnu::always_inline]] inline float atan2Of(float y, float x)
{
    return simd::atan2Of(y, x);
}

}  // namespace throng::sim
