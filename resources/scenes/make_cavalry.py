# Writes cavalry.yaml: the cone field (seeded jitter), the leader's route (waypoints; Throng
# plans the way between them round the cones with A* at load) and the riders.
# python3 resources/scenes/make_cavalry.py 5000 resources/scenes/cavalry.yaml
import math, random, sys
n_riders = int(sys.argv[1]) if len(sys.argv) > 1 else 5000
out = sys.argv[2] if len(sys.argv) > 2 else "cavalry.yaml"
rnd = random.Random(4)
route = [(0,0),(40,0),(80,25),(130,40),(180,25),(220,-15),(270,-40),(320,-25),(360,0),(400,0)]
cones=[]
for gx in range(0, 41):
    for gz in range(-11, 12):
        x = 10*gx + rnd.uniform(-2,2); z = 10*gz + rnd.uniform(-2,2)
        if not (5 <= x <= 395): continue
        # Only the waypoints are kept clear; the way between them is Throng's to find.
        if min(math.hypot(x-wx,z-wz) for (wx,wz) in route) < 5.0: continue
        cones.append((round(x,2),round(z,2)))
L=[]
L.append("# cavalry.yaml: %d riders chase a fleeing leader along a route planned across a field" % n_riders)
L.append("# of cones (circles 0.4 m in radius on a jittered 10 m grid): the route's points are")
L.append("# waypoints, and Throng plans the shortest way between them round the cones with A* at")
L.append("# load (plan: astar), keeping 3 m clear of every cone and smoothed to its corners.")
L.append("# The leader (priority 10) is as fast as the fastest rider; riders part for it,")
L.append("# never push it off its line and follow behind it (Reynolds' leader following). The")
L.append("# stats count leader_overtaken and obstacle_penetrations (both must stay 0).")
L.append("# Run: throng-cli run resources/scenes/cavalry.yaml --stats cavalry.json")
L.append("# Written by resources/scenes/make_cavalry.py (the cone field is seeded, so it is reproducible).")
L.append("throng: 1")
L.append("settings: {fps: 24, duration: 60, seed: 7, bounds: {min: [-130, -140], max: [430, 140]}}")
L.append("agent_types:")
L.append("  - name: fugitive")
L.append("    radius: 0.6")
L.append("    max_speed: 8.4")
L.append("    max_force: 40")
L.append("    mass: 1")
L.append("    perception: 3")
L.append("    character: tall_man")
L.append("    priority: 10")
L.append("    variation: {speed: [1, 1]}")
L.append("    behaviours:")
L.append("      path_following: {weight: 2, ahead: 4}")
L.append("      containment: 1")
L.append("      reciprocal_avoidance: 1")
L.append("  - name: rider")
L.append("    radius: 0.6")
L.append("    max_speed: 8.4")
L.append("    max_force: 30")
L.append("    mass: 1")
L.append("    perception: 3")
L.append("    character: man")
L.append("    variation: {speed: [0.9, 1]}")
L.append("    behaviours:")
L.append("      leader_following: {weight: 1, behind: 5, corridor_length: 6, corridor_half_width: 3}")
L.append("      obstacle_avoidance: {weight: 3, margin: 0.3}")
L.append("      wall_following: 2")
L.append("      separation: {weight: 2, range: 0.8}")
L.append("      containment: 2")
L.append("      reciprocal_avoidance: 1")
L.append("agents:")
L.append("  - {id: 1, type: fugitive, position: [0, 0], heading: 0, path: route}")
L.append("groups:")
L.append("  - {name: riders, type: rider, count: %d, rect: {min: [-110, -110], max: [-15, 110]}, leader: 1}" % n_riders)
L.append("paths:")
L.append("  - name: route")
L.append("    radius: 2")
L.append("    plan: astar")
L.append("    clearance: 3")
L.append("    points: [" + ", ".join("[%g, %g]" % p for p in route) + "]")
L.append("walls:")
L.append("  - {name: fence, points: [[-125, -135], [425, -135], [425, 135], [-125, 135], [-125, -135]]}")
L.append("obstacles:")
for k,(x,z) in enumerate(cones):
    L.append("  - {name: cone%d, shape: circle, center: [%g, %g], radius: 0.4}" % (k+1, x, z))
open(out,"w").write("\n".join(L)+"\n")
print(len(cones), "cones")
