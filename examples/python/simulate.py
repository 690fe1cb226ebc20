#!/usr/bin/env python3
"""simulate.py: load a Box2Scene file, build a pyb2d3 (Box2D v3.1.1) world from it, run it,
and show what happened: examples/simulate_v3.c in Python.

    python simulate.py [SCENE] [--steps N] [--svg OUT.svg]

SCENE defaults to the bundled showcase, N to 300 steps of 1/60 s, OUT.svg to showcase.svg.
Prints the load's warnings and what Box2D v3 could not represent (on standard error), and a
table of every body's start and end position, as simulate_v3 prints it; the SVG is the
picture simulate_v3 draws, drawn by the library (Scene.draw_svg).
"""

from __future__ import annotations

import argparse
import math
import os
import sys

import numpy as np
import pyb2d3

import box2scene
import box2scene.pyb2d3 as b2s3

SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "showcase.xml")
# As simulate_v3: 1/60 s computed in floats, and v3's recommended sub-step count.
TIME_STEP = float(np.float32(1.0) / np.float32(60.0))
SUB_STEPS = 4
TRAJECTORY_SAMPLE_STEPS = 5
def turn_between(start, end) -> np.float32:
    """How far rotation `end` is turned from `start`, within +-pi, as simulate_v3.c computes
    it: atan2 of the float products (Box2D's own relative angle approximates atan2)."""
    f = np.float32
    s = f(start.c) * f(end.s) - f(start.s) * f(end.c)
    c = f(start.c) * f(end.c) + f(start.s) * f(end.s)
    return np.arctan2(s, c)


NOT_CREATED = (math.nan, math.nan, math.nan)


def pose(body):
    """A body's place as the library draws it: (x, y, angle), the angle as Box2D v3's
    b2Rot_GetAngle gives it, the one simulate_v3 draws with."""
    return (body.position.x, body.position.y, pyb2d3.get_angle(body.rotation))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", nargs="?", default=SCENE)
    parser.add_argument("--steps", type=int, default=300)
    parser.add_argument("--svg", default="showcase.svg")
    args = parser.parse_args(argv)
    try:
        scene = box2scene.load(args.scene)
    except box2scene.Error as e:
        print(f"{args.scene}:{e.line}:{e.column}: error[{e.code}]: {e.message}", file=sys.stderr)
        return 1
    for d in scene.diagnostics:
        print(f"{args.scene}:{d.line}:{d.column}: warning[{d.code}]: {d.message}", file=sys.stderr)
    # The scene decides gravity; a file without <Gravity> gets Earth's, Y up.
    gravity = b2s3.scene_gravity(scene, (0.0, -10.0))
    given = "from the scene" if scene.gravity is not None else "the default: the scene gives none"
    print(f"gravity ({gravity[0]:g}, {gravity[1]:g}) m/s^2, {given}")
    world = b2s3.create_world(scene, (0.0, -10.0))
    built = b2s3.build_world(scene, world)
    for r in built.reports:
        name = f' "{r.name}"' if r.name is not None else ""
        print(f"box2d v3: not represented[{r.code}]: {r.object} {r.index}{name}: {r.message}", file=sys.stderr)

    live = [(i, b) for i, b in enumerate(built.bodies) if b is not None]
    poses = lambda: [NOT_CREATED if b is None else pose(b) for b in built.bodies]
    sample = lambda: [NOT_CREATED[:2] if b is None else (b.position.x, b.position.y) for b in built.bodies]
    start = poses()
    samples = [sample()]
    rotations = {i: b.rotation for i, b in live}
    turned = {i: np.float32(0.0) for i, _ in live}
    for step in range(1, args.steps + 1):
        world.step(TIME_STEP, SUB_STEPS)
        for i, b in live:
            rotation = b.rotation
            turned[i] += turn_between(rotations[i], rotation)
            rotations[i] = rotation
        if step % TRAJECTORY_SAMPLE_STEPS == 0 or step == args.steps:
            samples.append(sample())
    end = poses()

    print(f"{args.steps} steps of {TIME_STEP:.4f} s")
    names = ["-" if b.name is None else b.name for b in scene.bodies]
    # Padded to a width in bytes of UTF-8, as simulate_v3's printf pads them.
    width = max([4] + [len(n.encode()) for n in names])
    padded = [n + " " * (width - len(n.encode())) for n in names]
    print(f"{'index':>5}  {'name':<{width}}  {'type':<9}  {'start (m)':<18}  {'end (m)':<18}  turned (rad)")
    for i, body in enumerate(scene.bodies):
        row = f"{i:5d}  {padded[i]}  {body.kind:<9}  "
        if built.bodies[i] is None:
            print(row + "not created")
            continue
        (x0, y0, _), (x1, y1, _) = start[i], end[i]
        print(row + f"({x0:7.2f}, {y0:7.2f})  ({x1:7.2f}, {y1:7.2f})  {float(turned[i]):12.2f}")

    # The library's picture, as simulate_v3 draws it: the start faint, the end solid, the
    # paths between, the joints the adapter created.
    title = f"{os.path.basename(args.scene)}: {args.steps} steps of 1/60 s in Box2D v3.1"
    created = [j is not None for j in built.joints]
    svg = scene.draw_svg(title, start, end, samples, created)
    with open(args.svg, "w", encoding="utf-8") as out:
        out.write(svg)
    print(f"wrote {args.svg}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
