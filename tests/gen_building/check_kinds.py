#!/usr/bin/env python3
"""Tests scripts/gen-building's `lab` and `lcorridor` kinds.

    check_kinds.py GEN_BUILDING COGMAP WORK_DIR

1. `lab` (no rotation): one rectangular room 8-14 x 5-8 m; every desk (an unrotated box) stands
   against a long wall (its back 0.08 m from the wall line: half the wall and 2 cm); no item
   reaches into the 1.8 m aisle down the middle, which the route follows there and back;
   duration_s is 90 s for every 25 m^2 of floor; `cogmap world check` accepts the world.
2. `lcorridor` (no rotation): N offices, ceil(N/2) south of the first leg and the rest east of
   the second; both legs as wide as asked; one door 0.9-1.2 m wide per office, in the
   corridor's wall; the route enters every office's centre and stays inside the L's outline;
   duration_s is 90 s for every 25 m^2 of each office (at least one office's worth) plus one for
   the corridor; `cogmap world check` accepts it. Sizes drawn with --room-sizes-m stay within.
3. `lcorridor --offices 1` is refused with exit 2 naming the option, nothing written; the same
   command twice makes the same files (every draw from --seed).
Prints what failed and exits 1, or exits 0.
"""
import math
import os
import re
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree from a test run
from generated_files import duration_of, read_world, waypoints_of  # noqa: E402

GEN, COGMAP, WORK = sys.argv[1:4]
WALL_M = 0.12
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def gen(args, out):
    r = subprocess.run([sys.executable, GEN] + args.split() + ["--out", out], capture_output=True,
                       text=True)
    check(r.returncode == 0, f"{args}: exit {r.returncode}: {r.stderr}")
    return r.stdout.strip() if r.returncode == 0 else None


def read(path):
    with open(path) as f:
        return f.read()


def items(text):
    """(kind, centre, size or radius) of each obstacle line the generator writes."""
    out = []
    for line in text.splitlines():
        m = re.search(r"circle: \{center: \[([-\d.]+), ([-\d.]+)\], radius_m: ([\d.]+)", line)
        if m:
            out.append(("circle", (float(m[1]), float(m[2])), float(m[3])))
        m = re.search(r"box: \{center: \[([-\d.]+), ([-\d.]+)\], size: \[([\d.]+), ([\d.]+)\],"
                      r" angle_deg: ([-\d.]+)", line)
        if m:
            out.append(("box", (float(m[1]), float(m[2])), (float(m[3]), float(m[4]),
                                                            float(m[5]))))
    return out


def world_check(path, what):
    r = subprocess.run([COGMAP, "world", "check", path], capture_output=True, text=True)
    check(r.returncode == 0, f"{what}: cogmap world check: {r.stdout}{r.stderr}")


def inside_polygon(p, poly):
    x, y = p
    inside = False
    for (x1, y1), (x2, y2) in zip(poly, poly[1:]):
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            inside = not inside
    return inside


# 1. Labs (the last one as narrow as --room-sizes-m allows a lab, where the chairs meet the
#    aisle's edge).
for args, (w_lo, w_hi), (d_lo, d_hi) in (("lab --seed 1", (8, 14), (5, 8)),
                                         ("lab --seed 2", (8, 14), (5, 8)),
                                         ("lab --seed 3", (8, 14), (5, 8)),
                                         ("lab --seed 6 --room-sizes-m 5-5.2", (5, 5.2), (5, 5.2))):
    out = os.path.join(WORK, "lab")
    name = gen(args, out)
    if name is None:
        continue
    path = os.path.join(out, f"{name}.world.yaml")
    text = read(path)
    walls = read_world(path)["polylines"]
    check(len(walls) == 1 and len(walls[0]) == 5, f"{name}: walls {walls}")
    W, D = walls[0][2]
    check(w_lo <= W <= w_hi and d_lo <= D <= d_hi and W >= D, f"{name}: {W} x {D} m")
    lo, hi = D / 2 - 0.9, D / 2 + 0.9
    desks = 0
    for kind, (cx, cy), size in items(text):
        if kind == "box":
            sx, sy, angle = size
            check(angle == 0.0, f"{name}: a desk turned {angle} deg")
            back = min(cy - sy / 2, D - (cy + sy / 2))
            check(abs(back - (WALL_M / 2 + 0.02)) < 1e-2, f"{name}: desk at {cy} is not against"
                  f" a long wall ({back:.3f} m off it)")
            reach_lo, reach_hi = cy - sy / 2, cy + sy / 2
            desks += 1
        else:
            reach_lo, reach_hi = cy - size, cy + size
        check(reach_hi <= lo or reach_lo >= hi, f"{name}: an item {reach_lo:.2f}-{reach_hi:.2f}"
              f" reaches into the aisle {lo:.2f}-{hi:.2f}")
    check(desks >= 2 * int(W / 3.5), f"{name}: {desks} desks along {W} m walls")
    route = waypoints_of(os.path.join(out, f"{name}.route.yaml"))
    check(len(route) == 2 and all(abs(y - D / 2) < 1e-3 and 0 < x < W for x, y in route),
          f"{name}: route {route}")
    for kind in ("route", "explore"):
        got = duration_of(os.path.join(out, f"{name}.{kind}.yaml"))
        check(got == math.ceil(90 * W * D / 25), f"{name}: {kind} duration_s {got}")
    world_check(path, name)

# 2. L-shaped corridors.
cases = [("lcorridor --offices 5 --seed 3", 5, 2.4, (5.0, 5.0)),
         ("lcorridor --offices 4 --corridor-width-m 1.8 --seed 4 --clutter 1", 4, 1.8, (5.0, 5.0)),
         ("lcorridor --offices 7 --corridor-width-m 2.6 --seed 5 --room-sizes-m 3.5-7", 7, 2.6,
          (3.5, 7.0))]
for args, offices, width, (size_lo, size_hi) in cases:
    out = os.path.join(WORK, "lcorridor")
    name = gen(args, out)
    if name is None:
        continue
    path = os.path.join(out, f"{name}.world.yaml")
    walls = read_world(path)["polylines"]
    outline = walls[0]
    check(len(outline) == 11, f"{args}: outline {outline}")
    # (0, -d1), (A, -d1), ...: the first leg's offices end at x = A; (E, Wc): the second leg's
    # east wall and the corridor's width.
    (_, south), (offices_end, _) = outline[0], outline[1]
    east, wc = outline[4]
    check(abs(wc - width) < 1e-6 and abs(east - offices_end - width) < 1e-6,
          f"{args}: legs {wc} and {east - offices_end} m wide, want {width}")
    n1, n2 = math.ceil(offices / 2), offices - math.ceil(offices / 2)
    doors = []
    for vertical in (False, True):
        pieces = sorted(tuple(sorted(p)) for p in walls[1:]
                        if (vertical and p[0][0] == p[1][0] == east) or
                        (not vertical and p[0][1] == p[1][1] == 0.0))
        along = [(p[0][1], p[1][1]) if vertical else (p[0][0], p[1][0]) for p in pieces]
        doors += [(b0, a1) for (_, b0), (a1, _) in zip(along, along[1:])]
    widths = [b - a for a, b in doors]
    check(len(doors) == offices, f"{args}: {len(doors)} gaps in the corridor walls for {offices}"
          " offices")
    check(all(0.9 - 1e-6 <= w <= 1.2 + 1e-6 for w in widths), f"{args}: door widths {widths}")
    route = waypoints_of(os.path.join(out, f"{name}.route.yaml"))
    check(all(inside_polygon(p, outline) for p in route), f"{args}: a route point outside the L")
    # In the corridor the route keeps to the legs' midlines (or a door in their walls).
    for x, y in route:
        if 0 < y < wc and x < offices_end:
            check(abs(y - wc / 2) < 1e-3, f"{args}: ({x}, {y}) off the first leg's midline")
        elif y > wc and offices_end < x < east:
            check(abs(x - (offices_end + wc / 2)) < 1e-3, f"{args}: ({x}, {y}) off the second leg's midline")
    # Office centres: the route's points south of the first leg and east of the second.
    south_rooms = [p for p in route if p[1] < -0.5]
    east_rooms = [p for p in route if p[0] > east + 0.5]
    check(len(south_rooms) == n1 and len(east_rooms) == n2,
          f"{args}: {len(south_rooms)} south and {len(east_rooms)} east offices entered")
    depth_s = -south
    depth_e = outline[5][0] - east
    for d in (depth_s, depth_e):
        check(size_lo - 1e-6 <= d <= size_hi + 1e-6, f"{args}: office depth {d}")
    # Duration: offices' widths from the partitions and the outline.
    xs = sorted({round(p[0][0], 3) for p in walls[1:] if p[0][0] == p[1][0] and p[0][1] < 0})
    ys = sorted({round(p[0][1], 3) for p in walls[1:] if p[0][1] == p[1][1] and p[0][0] >= east})
    south_w = [b - a for a, b in zip([0.0] + xs, xs + [offices_end])]
    east_h = [b - a for a, b in zip([wc] + ys, ys + [outline[6][1]])]
    areas = [w * depth_s for w in south_w] + [h * depth_e for h in east_h]
    check(len(areas) == offices, f"{args}: {len(areas)} offices from the partitions")
    check(all(size_lo - 1e-6 <= v <= size_hi + 1e-6 for v in south_w + east_h),
          f"{args}: office sizes {south_w} {east_h}")
    want = math.ceil(90 * (sum(max(1.0, v / 25) for v in areas) + 1))
    for kind in ("route", "explore"):
        got = duration_of(os.path.join(out, f"{name}.{kind}.yaml"))
        check(got == want, f"{args}: {kind} duration_s {got}, want {want}")
    world_check(path, args)

# 3. Refused, and made the same twice.
never = os.path.join(WORK, "never")
r = subprocess.run([sys.executable, GEN, "lcorridor", "--offices", "1", "--out", never],
                   capture_output=True, text=True)
check(r.returncode == 2 and "--offices 1: want 2-100" in r.stderr,
      f"lcorridor --offices 1: exit {r.returncode}, {r.stderr!r}")
check(not os.path.exists(never), "lcorridor --offices 1 wrote a building")
texts = []
for attempt in ("a", "b"):
    out = os.path.join(WORK, f"twice_{attempt}")
    name = gen("lab --seed 9 --clutter 2 --rotation-deg 40", out)
    if name:
        texts.append(read(os.path.join(out, f"{name}.world.yaml")).split("\n", 1)[1])
check(len(texts) == 2 and texts[0] == texts[1], "lab --seed 9 made two different worlds")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
