#!/usr/bin/env python3
"""Tests scripts/gen-building's room sizes (`--room-sizes-m A-B`).

    check_sizes.py GEN_BUILDING COGMAP GENERATED_DIR WORK_DIR

1. The buildings made before sizes could vary come out the same: each world and experiment in
   GENERATED_DIR (tests/integration/generated) is made again from the command on its first line
   and must match it byte for byte below that line.
2. With sizes: every column's width and row's depth of a block, and every office's width and
   each office row's depth of a corridor, lies within A-B and they are not all equal; every
   route point lies inside the building; `cogmap world check` accepts the world; both
   experiments' duration_s is 90 s for every 25 m^2 of each room's floor (at least 90 s a room;
   a corridor counts once), from the wall lines.
3. A range a door cannot fit in (A < 3 m) is refused with exit 2, naming the option.
4. An --out whose name is not UTF-8 works, and the same command twice leaves the same files.
Prints what failed and exits 1, or exits 0.
"""
import glob
import math
import os
import re
import shlex
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree from a test run
from generated_files import duration_of, read_world, waypoints_of  # noqa: E402

GEN, COGMAP, GENERATED, WORK = sys.argv[1:5]
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def gen(args, out):
    return subprocess.run([sys.executable, GEN] + args + ["--out", out], capture_output=True,
                          text=True)


# 1. Unchanged buildings.
for world in sorted(glob.glob(os.path.join(GENERATED, "*.world.yaml"))):
    with open(world) as f:
        first = f.readline()
    args = shlex.split(first.split("scripts/gen-building", 1)[1])
    if "--out" in args:
        i = args.index("--out")
        del args[i:i + 2]
    out = os.path.join(WORK, "again")
    r = gen(args, out)
    check(r.returncode == 0, f"{world}: gen-building failed: {r.stderr}")
    name = os.path.basename(world)[: -len(".world.yaml")]
    for kind in ("world", "route", "explore"):
        old = os.path.join(GENERATED, f"{name}.{kind}.yaml")
        if not os.path.exists(old):
            continue
        with open(old) as a, open(os.path.join(out, f"{name}.{kind}.yaml")) as b:
            check(a.readlines()[1:] == b.readlines()[1:], f"{old} is not made the same any more")


def lines_of(world):
    """x of the vertical and y of the horizontal wall lines, outline included."""
    xs, ys = set(), set()
    for pl in world["polylines"]:
        for (x1, y1), (x2, y2) in zip(pl, pl[1:]):
            if abs(x1 - x2) < 1e-9:
                xs.add(round(x1, 3))
            if abs(y1 - y2) < 1e-9:
                ys.add(round(y1, 3))
    return sorted(xs), sorted(ys)


def within(values, lo, hi, what):
    gaps = [round(b - a, 3) for a, b in zip(values, values[1:])]
    check(all(lo - 1e-6 <= g <= hi + 1e-6 for g in gaps), f"{what}: {gaps} not within {lo}-{hi}")
    return gaps


# 2. Sized buildings (no rotation: the wall lines stay axis-parallel).
cases = [("block --rows 3 --cols 4 --seed 7 --room-sizes-m 3.2-8.5 --clutter 1", 3.2, 8.5),
         ("corridor --offices 5 --seed 8 --corridor-width-m 2.2 --room-sizes-m 3-7", 3.0, 7.0)]
for args, lo, hi in cases:
    out = os.path.join(WORK, "sized")
    r = gen(args.split(), out)
    check(r.returncode == 0, f"{args}: exit {r.returncode}: {r.stderr}")
    if r.returncode != 0:
        continue
    name = r.stdout.strip()
    path = os.path.join(out, f"{name}.world.yaml")
    world = read_world(path)
    xs, ys = lines_of(world)
    widths = within(xs, lo, hi, f"{args}: widths")
    if args.startswith("block"):
        depths = within(ys, lo, hi, f"{args}: depths")
    else:
        # Office rows: outline to corridor wall on each side; the corridor between is 2.2 m.
        check(abs(ys[2] - ys[1] - 2.2) < 1e-6, f"{args}: corridor {ys}")
        depths = within([ys[0], ys[1]], lo, hi, f"{args}: south row") + \
            within([ys[2], ys[3]], lo, hi, f"{args}: north row")
    if args.startswith("block"):
        areas = [w * d for w in widths for d in depths]
        hall = 0
    else:
        # Offices alternate south (even) and north (odd), two to a column of the same width.
        offices = int(args.split("--offices ")[1].split()[0])
        areas = [widths[i // 2] * depths[i % 2] for i in range(offices)]
        hall = 1
    want = math.ceil(90 * (sum(max(1.0, a / 25.0) for a in areas) + hall))
    for kind in ("route", "explore"):
        got = duration_of(os.path.join(out, f"{name}.{kind}.yaml"))
        check(got == want, f"{args}: {kind} duration_s {got}, want {want} (areas {areas})")
    check(len(set(widths + depths)) > 2, f"{args}: the sizes do not vary: {widths} {depths}")
    check(f"{lo:g}-{hi:g} m" in world["description"], f"{args}: {world['description']!r}")
    route = waypoints_of(os.path.join(out, f"{name}.route.yaml"))
    check(len(route) > 4, f"{args}: no route")
    inside = all(xs[0] < x < xs[-1] and ys[0] < y < ys[-1] for x, y in route)
    check(inside, f"{args}: a route point outside the building")
    r = subprocess.run([COGMAP, "world", "check", path], capture_output=True, text=True)
    check(r.returncode == 0, f"{args}: cogmap world check: {r.stdout}{r.stderr}")

# 3. A range too small for a door.
r = gen("block --rows 2 --cols 2 --room-sizes-m 2-4".split(), os.path.join(WORK, "never"))
check(r.returncode == 2 and re.search(r"--room-sizes-m.*'2-4'", r.stderr) is not None,
      f"--room-sizes-m 2-4: exit {r.returncode}, {r.stderr!r}")
check(not os.path.exists(os.path.join(WORK, "never")), "--room-sizes-m 2-4 wrote a building")

# 4. An --out whose name is not UTF-8 (the command line written into each file's first line
#    raised UnicodeEncodeError, a traceback and a half-written world), made twice: the same
#    command again leaves the identical files as they are.
odd = os.path.join(os.fsencode(WORK), b"odd_\xff")
for attempt in (1, 2):
    r = subprocess.run([sys.executable, GEN, "block", "--rows", "2", "--cols", "2", "--out", odd],
                       capture_output=True, text=True, errors="replace")
    check(r.returncode == 0, f"--out odd_\\xff (call {attempt}): exit {r.returncode}: {r.stderr}")
world = os.path.join(odd, b"block_2x2_s1.world.yaml")
if os.path.exists(world):
    with open(world, "rb") as f:
        first = f.readline()
    check(first.decode("utf-8", "replace") == first.decode("utf-8", "ignore") and
          b"odd_\\xff" in first, f"--out odd_\\xff: first line {first!r}")
else:
    check(False, "--out odd_\\xff: no world written")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
