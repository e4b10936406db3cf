#!/usr/bin/python3
"""Reads a PedPy export of Throng the way PedPy does, and checks it against its set.

Usage: pedpy-check.py TRAJECTORIES.txt SET.wkt

The trajectories are read by PedPy's rules for its text format (pedpy/io/trajectory_loader.py,
load_trajectory_from_txt): the comment lines before the data give the frame rate (the first
number on a line that says "framerate") and the unit ("x/m" or "in m"; "x/cm" or "in cm");
the data are whitespace-separated "id frame x y z" rows. The set is read with Shapely, the
geometry library PedPy builds its WalkableArea with, and the walkable area is made as
docs/export.md says. Prints one JSON line: what was read, and what the walkers did against
the set (points outside the walkable area, steps across a wall or into an obstacle).
Exit 0 when both files read, 1 when one does not (a failure), 2 when Shapely is missing.
"""
import json
import sys

try:
    from shapely import wkt
    from shapely.geometry import LineString, Point
    from shapely.ops import unary_union
    from shapely.prepared import prep
except ImportError as e:  # the test suite installs python3-shapely (scripts/deps.sh test)
    print(f"pedpy-check: needs Shapely (apt-get install python3-shapely): {e}", file=sys.stderr)
    sys.exit(2)


def fail(message):
    print(f"pedpy-check: {message}", file=sys.stderr)
    sys.exit(1)


def read_meta(path):
    frame_rate, unit = None, None
    with open(path, encoding="utf-8-sig") as f:
        for line in f:
            if not line.startswith("#"):
                break
            if "framerate" in line:
                for token in line.split():
                    try:
                        if frame_rate is None:
                            frame_rate = float(token)
                    except ValueError:
                        continue
            if "x/cm" in line.lower() or "in cm" in line.lower():
                unit = "cm"
            if "x/m" in line.lower() or "in m" in line.lower():
                unit = "m"
    return frame_rate, unit


def read_rows(path):
    rows = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            fields = line.split()
            if len(fields) < 5:
                fail(f"{path}:{number}: {len(fields)} columns, PedPy needs id frame x y z")
            try:
                rows.append((int(fields[0]), int(fields[1]), float(fields[2]), float(fields[3]), float(fields[4])))
            except ValueError:
                fail(f"{path}:{number}: not id frame x y z numbers: {line}")
    return rows


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    trajectories, geometry = sys.argv[1], sys.argv[2]
    frame_rate, unit = read_meta(trajectories)
    if frame_rate is None or frame_rate <= 0:
        fail(f"{trajectories}: no frame rate in the comment lines")
    if unit is None:
        fail(f"{trajectories}: no unit in the comment lines")
    rows = read_rows(trajectories)
    with open(geometry, encoding="utf-8") as f:
        try:
            collection = wkt.loads(f.read())
        except Exception as e:  # Shapely's WKT reader raises its own errors
            fail(f"{geometry}: not WKT: {e}")
    if collection.geom_type != "GeometryCollection" or len(collection.geoms) < 1:
        fail(f"{geometry}: not a GEOMETRYCOLLECTION of the bounds and the set")
    parts = list(collection.geoms)
    bounds = parts[0]
    if bounds.geom_type != "Polygon":
        fail(f"{geometry}: the first geometry is a {bounds.geom_type}, not the bounds' POLYGON")
    walls = [g for g in parts[1:] if g.geom_type == "LineString"]
    obstacles = [g for g in parts[1:] if g.geom_type == "Polygon"]
    walkable = bounds.difference(unary_union([w.buffer(0.01) for w in walls] + obstacles))
    inside, solid = prep(walkable), prep(unary_union(obstacles)) if obstacles else None
    wall_lines = prep(unary_union(walls)) if walls else None

    by_agent = {}
    outside = 0
    in_obstacle = 0
    for agent, frame, x, y, _z in rows:
        by_agent.setdefault(agent, []).append((frame, x, y))
        p = Point(x, y)
        if not inside.contains(p):
            outside += 1
        if solid is not None and solid.contains(p):
            in_obstacle += 1
    wall_crossings = 0
    for track in by_agent.values():
        track.sort()
        for (f0, x0, y0), (f1, x1, y1) in zip(track, track[1:]):
            if f1 == f0 + 1 and wall_lines is not None and (x0, y0) != (x1, y1):
                if wall_lines.intersects(LineString([(x0, y0), (x1, y1)])):
                    wall_crossings += 1
    frames = sorted({r[1] for r in rows})
    print(json.dumps({
        "frameRate": frame_rate,
        "unit": unit,
        "rows": len(rows),
        "agents": len(by_agent),
        "firstFrame": frames[0] if frames else -1,
        "lastFrame": frames[-1] if frames else -1,
        "boundsArea": round(bounds.area, 3),
        "walls": len(walls),
        "obstacles": len(obstacles),
        "walkableArea": round(walkable.area, 3),
        "pointsOutsideWalkable": outside,
        "pointsInObstacles": in_obstacle,
        "stepsAcrossWalls": wall_crossings,
    }))


main()
