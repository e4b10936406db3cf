// The step's split of the grid order between threads: the ranges always cover the run
// once, and they move until threads whose items cost unequally take equally long.
#include "TestRegistry.h"

#include "simcore/world/RunSplit.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

using namespace throng::sim;

namespace {

// The ranges of all threads, checked to cover [0, n) in order without gaps or overlaps.
bool coversOnce(const RunSplit& split, std::size_t n, int threads)
{
    std::size_t next = 0;
    for (int t = 0; t < threads; ++t) {
        const auto [first, last] = split.range(n, t);
        if (first != next || last < first)
            return false;
        next = last;
    }
    return next == n;
}

// Seconds for items [first, last) when item i costs cost(i / n).
double secondsFor(std::size_t first, std::size_t last, std::size_t n, const std::function<double(double)>& cost)
{
    double s = 0.0;
    for (std::size_t i = first; i < last; ++i)
        s += cost(double(i) / double(n)) * 1e-6;
    return s;
}

}  // namespace

class TestRunSplit : public QObject {
    Q_OBJECT
private slots:
    void startsEqualAndCoversTheRun()
    {
        for (int threads : {1, 2, 3, 8}) {
            RunSplit split;
            split.prepare(threads);
            for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(7), std::size_t(100000)}) {
                QVERIFY(coversOnce(split, n, threads));
                for (int t = 0; t < threads; ++t) {
                    const auto [first, last] = split.range(n, t);
                    QVERIFY(last - first <= n / std::size_t(threads) + 1);
                }
            }
        }
    }

    // The first half of the run costs three times as much per item (a gathered flock):
    // after a few steps both threads take the same time, within 3 %.
    void unevenCostsEvenOut()
    {
        for (int threads : {2, 3}) {
            const std::size_t n = 30000;
            auto cost = [](double x) { return x < 0.5 ? 3.0 : 1.0; };
            RunSplit split;
            split.prepare(threads);
            std::vector<double> seconds(std::size_t(threads), 0.0);
            for (int step = 0; step < 12; ++step) {
                for (int t = 0; t < threads; ++t) {
                    const auto [first, last] = split.range(n, t);
                    seconds[std::size_t(t)] = secondsFor(first, last, n, cost);
                    split.record(t, seconds[std::size_t(t)]);
                }
                split.rebalance();
                QVERIFY(coversOnce(split, n, threads));
            }
            const auto [lo, hi] = std::minmax_element(seconds.begin(), seconds.end());
            QVERIFY2(*hi < *lo * 1.03, qPrintable(QString("%1 threads: %2 s against %3 s").arg(threads).arg(*hi).arg(*lo)));
            const auto [first, last] = split.range(n, 0);
            QCOMPARE(first, std::size_t(0));
            QVERIFY(last < n / std::size_t(threads));  // the costly first range is the shorter
        }
    }

    // A clock reading of zero or NaN leaves the split as it was; a thread far slower than
    // the other still keeps a quarter of an equal share.
    void badTimesAreIgnoredAndRangesKeepAFloor()
    {
        const std::size_t n = 1000;
        RunSplit split;
        split.prepare(2);
        split.record(0, 0.0);
        split.record(1, 1.0);
        split.rebalance();
        QCOMPARE(split.range(n, 0).second, std::size_t(500));
        split.record(0, std::nan(""));
        split.rebalance();
        QCOMPARE(split.range(n, 0).second, std::size_t(500));
        for (int step = 0; step < 20; ++step) {
            split.record(0, 1000.0);
            split.record(1, 1.0);
            split.rebalance();
        }
        QCOMPARE(split.range(n, 0).second, std::size_t(125));
        QVERIFY(coversOnce(split, n, 2));
        split.prepare(3);  // a new thread count starts from equal ranges
        QCOMPARE(split.range(n, 0).second, std::size_t(333));
        QVERIFY(coversOnce(split, n, 3));
    }
};

THRONG_REGISTER_TEST(TestRunSplit)
#include "TestRunSplit.moc"
