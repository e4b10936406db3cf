// Throng's own atan2 (base/Atan2.h), which the brains' bearings use: within 2 units in the
// last place of the exact angle over every octant and magnitude, the C library's answers
// at zeros, infinities and NaN, and in four lanes to the bit what one float alone gets.
#include "TestRegistry.h"

#include "simcore/base/Atan2.h"

#include <QTest>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using namespace throng::sim;

namespace {

// How many floats lie between `got` and the exact angle (both finite), in units of the
// spacing of floats at the exact angle.
double ulpsFromExact(float got, double exact)
{
    const float nearest = float(exact);
    const float next = std::nextafter(std::fabs(nearest), INFINITY);
    const double ulp = double(next) - double(std::fabs(nearest));
    return std::fabs(double(got) - exact) / ulp;
}

struct Pair {
    float y, x;
};

// Angles all round at magnitudes from 1e-30 to 1e30, the axes and diagonals, and ratios
// y/x on either side of t = 1e-4 (below it atan(t) is taken as t) and of 1 (the diagonal).
std::vector<Pair> samples(std::size_t count)
{
    std::mt19937 gen(27);
    std::uniform_real_distribution<double> angle(-3.14159265358979, 3.14159265358979), exponent(-30.0, 30.0),
        ratio(0.0, 1.0);
    std::vector<Pair> out;
    for (std::size_t k = 0; k < count; ++k) {
        const double a = angle(gen), r = std::pow(10.0, exponent(gen));
        out.push_back({float(r * std::sin(a)), float(r * std::cos(a))});
        const double t = ratio(gen);  // y/x itself uniform in [0, 1], the polynomial's own range
        out.push_back({float(t), 1.0f});
    }
    for (const float m : {1e-38f, 1e-6f, 1.0f, 3.0f, 1e20f}) {
        for (const float sy : {-1.0f, 1.0f})
            for (const float sx : {-1.0f, 1.0f}) {
                out.push_back({sy * m, sx * m});
                out.push_back({sy * m, 0.0f * sx});
                out.push_back({0.0f * sy, sx * m});
            }
    }
    for (const float at : {1e-4f, 1.0f}) {
        float t = at;
        for (int k = 0; k < 64; ++k, t = std::nextafter(t, 0.0f))
            out.push_back({t, 1.0f});
        t = at;
        for (int k = 0; k < 64; ++k, t = std::nextafter(t, 2.0f))
            out.push_back({-t, -1.0f});
    }
    return out;
}

}  // namespace

class TestAtan2 : public QObject {
    Q_OBJECT
private slots:
    void withinTwoUnitsInTheLastPlace()
    {
        const std::vector<Pair> pairs = samples(400000);
        double worst = 0.0;
        Pair worstAt{0.0f, 0.0f};
        std::size_t beyondOne = 0;
        for (const Pair& p : pairs) {
            const double exact = std::atan2(double(p.y), double(p.x));
            const double ulps = ulpsFromExact(atan2Of(p.y, p.x), exact);
            beyondOne += ulps > 1.0 ? 1 : 0;
            if (ulps > worst) {
                worst = ulps;
                worstAt = p;
            }
        }
        qInfo("worst %.3f units in the last place at atan2(%g, %g); %zu of %zu beyond 1", worst, double(worstAt.y),
              double(worstAt.x), beyondOne, pairs.size());
        QVERIFY2(worst <= 2.0, qPrintable(QString("%1 units at atan2(%2, %3)")
                                              .arg(worst)
                                              .arg(double(worstAt.y))
                                              .arg(double(worstAt.x))));
        QVERIFY(beyondOne * 100 < pairs.size());  // nearly all within one
    }

    void theCLibrarysAnswersAtZerosInfinitiesAndNaN()
    {
        const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
        // Every pair on the axes and the diagonals, zeros and infinities of either sign.
        const float values[] = {0.0f, -0.0f, 1.0f, -1.0f, 2.5f, -2.5f, inf, -inf};
        for (const float y : values)
            for (const float x : values) {
                if (std::fabs(y) != std::fabs(x) && y != 0.0f && x != 0.0f && std::isfinite(x) && std::isfinite(y))
                    continue;  // off the axes and diagonals: withinTwoUnitsInTheLastPlace
                const float want = std::atan2(y, x), got = atan2Of(y, x);
                // The same angle (the library's pi and pi/2 are the nearest floats too) and sign.
                QVERIFY2(got == want && std::signbit(got) == std::signbit(want),
                         qPrintable(QString("atan2(%1, %2): %3, the C library %4")
                                        .arg(y)
                                        .arg(x)
                                        .arg(std::bit_cast<std::uint32_t>(got), 8, 16)
                                        .arg(std::bit_cast<std::uint32_t>(want), 8, 16)));
            }
        QVERIFY(std::isnan(atan2Of(nan, 1.0f)));
        QVERIFY(std::isnan(atan2Of(1.0f, nan)));
        QVERIFY(std::isnan(atan2Of(nan, 0.0f)));
        QVERIFY(std::isnan(atan2Of(0.0f, nan)));
        QVERIFY(std::isnan(atan2Of(nan, inf)));
        // Odd in y, exactly.
        for (const Pair& p : samples(2000))
            QCOMPARE(std::bit_cast<std::uint32_t>(atan2Of(-p.y, p.x)),
                     std::bit_cast<std::uint32_t>(-atan2Of(p.y, p.x)));
    }

    void lanesGiveWhatOneFloatGets()
    {
        const std::vector<Pair> pairs = samples(20000);
        std::size_t compared = 0;
        for (std::size_t k = 0; k + 4 <= pairs.size(); k += 4) {
            simd::F4 y4, x4;
            for (int l = 0; l < 4; ++l) {
                y4[l] = pairs[k + std::size_t(l)].y;
                x4[l] = pairs[k + std::size_t(l)].x;
            }
            const simd::F4 a4 = simd::atan2Of(y4, x4);
            for (int l = 0; l < 4; ++l) {
                QCOMPARE(std::bit_cast<std::uint32_t>(float(a4[l])),
                         std::bit_cast<std::uint32_t>(atan2Of(y4[l], x4[l])));
                ++compared;
            }
        }
        QVERIFY(compared > 30000);
    }
};

THRONG_REGISTER_TEST(TestAtan2)
#include "TestAtan2.moc"
