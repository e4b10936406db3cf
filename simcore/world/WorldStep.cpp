// World::step: one fixed time step as a column of phases (DetourCrowd's dtCrowd::update
// reads the same way). Every agent reads the previous state and writes only its own next
// state (RVO2's doStep computes all new velocities before committing any), so the result
// is the same for any thread count.
#include "simcore/world/World.h"

#include "simcore/world/Collide.h"
#include "simcore/world/Commit.h"

#include "simcore/scene/StepRate.h"

namespace throng::sim {

void World::step()
{
    for (int k = 0; k < m_clock.subSteps; ++k)
        stepOnce();
}

void World::stepOnce()
{
    // Anything to constrain walkers against? Not in an open field like `cross`.
    const bool hasStatics = m_set.hasStatics();
    const bool traffic = m_traffic.system.has_value() || !m_traffic.heroes.empty();
    m_phaseTimes.begin();

    // Enter: the sources' agents whose time has come, where their bodies fit (Sources.h);
    // those that choose an exit choose it as they come in (ExitChoice.h).
    std::vector<std::uint32_t> entered;
    if (m_sources.scheduled() != 0 && !m_gridCurrent) {  // arrivals look for room in the grid
        m_grid.rebuild(m_agents.pos, m_hasFliers, m_agents.out, &m_team);
        m_gridCurrent = true;
    }
    if (m_sources.scheduled() != 0 && m_sources.enter(m_clock.timeS(), m_agents, m_grid, m_maxRadius, &entered) != 0) {
        m_gridCurrent = false;
        if (m_exits.active())
            takeExits(m_exits.onEntry(view(), entered));
    }
    // Start: walkers whose reaction time has passed set off (StartPhase.h).
    if (m_starts.pending())
        m_starts.release(m_clock.timeS(), m_agents);
    // Choose: walkers whose turn it is choose their exit again (ExitChoice.h).
    if (m_exits.active() && ExitChoice::roundAt(m_clock.timeS(), double(m_clock.dt)))
        takeExits(m_exits.choose(view(), m_clock.timeS()));
    m_phaseTimes.lap(StepPhase::Enter);
    // Grid: index agents by cell for neighbour queries (the last step's grid phase, at
    // the end of this function, left it current for these positions).
    if (!m_gridCurrent) {
        m_grid.rebuild(m_agents.pos, m_hasFliers, m_agents.out, &m_team);
        m_phaseTimes.lap(StepPhase::Grid);
    }
    m_gridCurrent = false;
    // Decide, or apply the forces decided (StepRate.h).
    m_clock.decide = decisionAt(m_clock.step, double(m_clock.dt));
    m_clock.decideDt = m_clock.decide ? float(decisionIntervalS(m_clock.step, double(m_clock.dt))) : m_clock.decideDt;
    // Navigate: plans and each walker's waypoint or flow direction (WorldNav.cpp).
    m_nav.beforeStep(view());
    m_phaseTimes.lap(StepPhase::Navigate);
    // Brain: sensors from this (previous) state, then each type's program; before the
    // traffic step, which drives brain-driven vehicles by their brains' speeds.
    if (m_brains.active()) {
        m_brains.run(view(), m_agents, m_traffic);
        m_phaseTimes.lap(StepPhase::Brain);
    }
    // Traffic: the lanes' vehicles step on the pedestrians' state before this step.
    m_traffic.beforeStep(m_agents);
    if (traffic)
        m_phaseTimes.lap(StepPhase::Traffic);

    // Keep together: each anchor's pace from how far its members are from their slots.
    m_formations.pace(m_agents, m_set);
    // Move: steer, avoid, integrate and constrain, agent by agent (MovePhase.h).
    m_move.run(view(), m_brains, m_traffic, m_agents, hasStatics);
    m_phaseTimes.lap(StepPhase::Move);
    // Traffic: vehicles and heroes to where the system and their tracks put them.
    m_traffic.drive(m_clock, m_set, m_agents);
    if (traffic)
        m_phaseTimes.lap(StepPhase::Traffic);

    // Collide: bodies still overlapping move apart, and on each decision the contact
    // rounds part those still pressed together (Collide.h).
    collide(view(), m_brains, m_agents, m_move.boids().collideFree(), m_move.boids().slackM(), hasStatics,
            m_contactRounds);
    m_phaseTimes.lap(StepPhase::Collide);
    // Traffic: walkers out of the heroes' way, behind their stop lines, off red crosswalks.
    m_traffic.afterCollide(view(), m_agents);
    if (traffic)
        m_phaseTimes.lap(StepPhase::Traffic);

    // Commit: animate and note arrivals, then swap in the new state (Commit.h).
    const CommitCounts committed = commit(view(), m_agents);
    m_count.addWallCrossings(committed.wallCrossings);
    // Act: walkers that entered an action point stop and play its action; those done go on.
    playActionPoints(view(), m_agents);
    ++m_clock.step;
    m_phaseTimes.lap(StepPhase::Commit);

    // Grid: index the new positions, for the count and the next step's senses.
    m_grid.rebuild(m_agents.pos, m_hasFliers, m_agents.out, &m_team);
    m_gridCurrent = true;
    m_phaseTimes.lap(StepPhase::Grid);
    // Count: the run's figures on the positions the step ended at (CountPhase.h).
    m_count.count(view(), m_agents.onCrosswalk, committed.nonFinite);
    m_phaseTimes.lap(StepPhase::Count);
    m_traffic.afterStep(m_agents);
    if (traffic)
        m_phaseTimes.lap(StepPhase::Traffic);
    m_phaseTimes.endStep();
}

}  // namespace throng::sim
