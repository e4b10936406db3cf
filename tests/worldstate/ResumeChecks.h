#pragma once
// The determinism check the resume tests share: an edit adopted at step 30 and run on,
// on 1 and 2 threads, and again from the adopted state restored into a fresh World.

#include "StateScenes.h"

#include "simcore/world/WorldState.h"

#include <QTest>

#include <cstddef>
#include <cstdint>

namespace throng::test::state {

// Runs `scene` 30 steps, adopts its state into `edit(world)` (the edited scene, which may
// depend on the running world, as traffic edits do) and records `frames` frames. Checks
// that the adoption succeeds, that restoring the adopted state into a fresh World records
// the same frames, and that 1 and 2 threads record the same frames.
template <class MakeEdited>
void checkResumeIsDeterministic(const sim::Scene& scene, MakeEdited edit, std::size_t frames)
{
    std::uint64_t hashes[2] = {0, 0};
    for (int threads : {1, 2}) {
        sim::WorldOptions options;
        options.threads = threads;
        sim::World a(scene, options);
        for (std::size_t s = 0; s < 30; ++s)
            a.step();
        const sim::Scene after = edit(a);
        sim::World b(after, options);
        QVERIFY(b.adoptState(a.saveState(), scene, after));
        const sim::WorldState atEdit = b.saveState();
        hashes[threads - 1] = record(b, frames).hash();
        sim::World c(after, options);
        c.restoreState(atEdit);
        QCOMPARE(record(c, frames).hash(), hashes[threads - 1]);
    }
    QCOMPARE(hashes[0], hashes[1]);
}

}  // namespace throng::test::state
