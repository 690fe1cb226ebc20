#!/usr/bin/env python3
"""simulate.py: load a Box2Scene file, build a pyb2d3 (Box2D v3.1.1) world from it, run it,
and show what happened: examples/simulate_v3.c in Python.

    python simulate.py [SCENE] [--steps N] [--svg OUT.svg]

SCENE defaults to the bundled showcase, N to 300 steps of 1/60 s, OUT.svg to showcase.svg.
Prints the load's warnings and what Box2D v3 could not represent (on standard error), and a
table of every body's start and end position, as simulate_v3 prints it; the SVG shows the
start (faint), the end (solid), the joints and each moving body's trajectory.
"""

from __future__ import annotations

import argparse
import os
import sys
from html import escape

import numpy as np
import pyb2d3

import box2scene
import box2scene.pyb2d3 as b2s3

SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "showcase.xml")
# As simulate_v3: 1/60 s computed in floats, and v3's recommended sub-step count.
TIME_STEP = float(np.float32(1.0) / np.float32(60.0))
SUB_STEPS = 4
TRAJECTORY_SAMPLE_STEPS = 5
STYLE = (
    "g{stroke-width:0.05;stroke-linejoin:round}.start{opacity:0.25}"
    ".static{fill:#c8c8c8;stroke:#606060}.kinematic{fill:#b8e0b0;stroke:#3a7a30}"
    ".dynamic{fill:#a8c8f0;stroke:#2a5a9a}.joints{stroke:#d03030;fill:#d03030}"
    ".joints polyline{fill:none}.trajectories{stroke:#f08a00;stroke-width:0.04;fill:none}"
)


def turn_between(start, end) -> np.float32:
    """How far rotation `end` is turned from `start`, within +-pi, as simulate_v3.c computes
    it: atan2 of the float products (Box2D's own relative angle approximates atan2)."""
    f = np.float32
    s = f(start.c) * f(end.s) - f(start.s) * f(end.c)
    c = f(start.c) * f(end.c) + f(start.s) * f(end.s)
    return np.arctan2(s, c)


def transform(body):
    t = body.transform
    return (t.p.x, t.p.y, t.q.c, t.q.s)


def apply(xf, point):
    x, y, c, s = xf
    return (c * point[0] - s * point[1] + x, s * point[0] + c * point[1] + y)


def world_anchors(joint):
    """A joint's two anchors in world coordinates (revolute and weld anchors coincide)."""
    ends = []
    for body, anchor in ((joint.body_a, joint.local_anchor_a), (joint.body_b, joint.local_anchor_b)):
        ends.append(apply(transform(body), (anchor.x, anchor.y)))
    return ends


class Svg:
    """A drawing in world coordinates (metres, Y up), flipped to SVG's Y down as written."""

    def __init__(self):
        self.parts = []
        self.lower = None
        self.upper = None

    def include(self, p):
        self.lower = p if self.lower is None else (min(self.lower[0], p[0]), min(self.lower[1], p[1]))
        self.upper = p if self.upper is None else (max(self.upper[0], p[0]), max(self.upper[1], p[1]))

    def points(self, element, points):
        for p in points:
            self.include(p)
        text = " ".join(f"{p[0]:g},{0.0 - p[1]:g}" for p in points)
        self.parts.append(f'<{element} points="{text}"/>')

    def circle(self, centre, radius):
        self.include((centre[0] - radius, centre[1] - radius))
        self.include((centre[0] + radius, centre[1] + radius))
        self.parts.append(f'<circle cx="{centre[0]:g}" cy="{0.0 - centre[1]:g}" r="{radius:g}"/>')

    def shape(self, shape, xf):
        kind = shape.type
        if kind == pyb2d3.ShapeType.circle:
            c = shape.circle
            centre = (c.center.x, c.center.y)
            self.circle(apply(xf, centre), c.radius)
            self.points("polyline", [apply(xf, centre), apply(xf, (centre[0] + c.radius, centre[1]))])
        elif kind == pyb2d3.ShapeType.polygon:
            p = shape.polygon
            self.points("polygon", [apply(xf, tuple(v)) for v in p.vertices[: p.count]])
        else:
            s = shape.segment
            self.points("polyline", [apply(xf, (s.point1.x, s.point1.y)), apply(xf, (s.point2.x, s.point2.y))])

    def text(self):
        lower = self.lower or (0.0, 0.0)
        upper = self.upper or (0.0, 0.0)
        margin = 0.5
        x, y = lower[0] - margin, -upper[1] - margin
        w, h = upper[0] - lower[0] + 2 * margin, upper[1] - lower[1] + 2 * margin
        head = f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{x:g} {y:g} {w:g} {h:g}">\n<style>{STYLE}</style>\n'
        return head + "\n".join(self.parts) + "\n</svg>\n"


def draw(svg, scene, built, frames, css):
    for i, body in enumerate(built.bodies):
        if body is None:
            continue
        name = scene.bodies[i].name
        svg.parts.append(f'<g class="{scene.bodies[i].kind} {css}">' + (f"<title>{escape(name)}</title>" if name else ""))
        for shape in body.shapes:
            svg.shape(shape, frames[i])
        svg.parts.append("</g>")


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
    start = {i: transform(b) for i, b in live}
    start_joints = [world_anchors(j) for j in built.joints if j is not None]
    paths = {i: [(b.position.x, b.position.y)] for i, b in live}
    rotations = {i: b.rotation for i, b in live}
    turned = {i: np.float32(0.0) for i, _ in live}
    for step in range(1, args.steps + 1):
        world.step(TIME_STEP, SUB_STEPS)
        for i, b in live:
            rotation = b.rotation
            turned[i] += turn_between(rotations[i], rotation)
            rotations[i] = rotation
        if step % TRAJECTORY_SAMPLE_STEPS == 0 or step == args.steps:
            for i, b in live:
                paths[i].append((b.position.x, b.position.y))
    end = {i: transform(b) for i, b in live}

    print(f"{args.steps} steps of {TIME_STEP:.4f} s")
    names = ["-" if b.name is None else b.name for b in scene.bodies]
    # Padded to a width in bytes of UTF-8, as simulate_v3's printf pads them.
    width = max([4] + [len(n.encode()) for n in names])
    padded = [n + " " * (width - len(n.encode())) for n in names]
    print(f"{'index':>5}  {'name':<{width}}  {'type':<9}  {'start (m)':<18}  {'end (m)':<18}  turned (rad)")
    for i, body in enumerate(scene.bodies):
        row = f"{i:5d}  {padded[i]}  {body.kind:<9}  "
        if i not in start:
            print(row + "not created")
            continue
        (x0, y0, _, _), (x1, y1, _, _) = start[i], end[i]
        print(row + f"({x0:7.2f}, {y0:7.2f})  ({x1:7.2f}, {y1:7.2f})  {float(turned[i]):12.2f}")

    svg = Svg()
    draw(svg, scene, built, start, "start")
    draw(svg, scene, built, end, "end")
    svg.parts.append('<g class="joints">')
    for a, b in start_joints:
        svg.points("polyline", [a, b])
    svg.parts.append("</g>")
    svg.parts.append('<g class="trajectories">')
    for i, points in paths.items():
        if scene.bodies[i].kind != "static" and len(set(points)) > 1:
            svg.points("polyline", points)
    svg.parts.append("</g>")
    with open(args.svg, "w", encoding="utf-8") as out:
        out.write(svg.text())
    print(f"wrote {args.svg}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
