"""Scenes made for one mapping row each, and stepping helpers."""

from __future__ import annotations

import math
import os
import re

import numpy as np

from box2scene import Body, Builder, Fixture, Joint, Shape

DT = float(np.float32(1.0) / np.float32(60.0))
BOX = ((-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5))


def f32(x: float) -> float:
    return float(np.float32(x))


class SceneMaker:
    """A builder with shortcuts: a box fixture of density 1 shared by the bodies."""

    def __init__(self, gravity=(0.0, -10.0)):
        self.b = Builder()
        self.b.set_gravity(gravity)
        self.box = self.b.add_fixture(Fixture.new(self.b.add_shape(Shape.new("polygon", vertices=BOX)), density=1.0))

    def body(self, kind="dynamic", fixtures=None, **changes) -> int:
        return self.b.add_body(Body.new(kind, fixtures=(self.box,) if fixtures is None else fixtures, **changes))

    def shape(self, kind, **changes) -> int:
        return self.b.add_shape(Shape.new(kind, **changes))

    def fixture(self, shape, **changes) -> int:
        return self.b.add_fixture(Fixture.new(shape, **changes))

    def joint(self, kind, a, b, **changes) -> int:
        return self.b.add_joint(Joint.new(kind, a, b, **changes))

    def finish(self):
        return self.b.finish()


def codes(reports):
    return [(r.code, r.object, r.index) for r in reports]


def finite(*values) -> bool:
    return all(math.isfinite(v) for v in values)


def resident_bytes() -> int:
    """This process's resident memory now (Linux's /proc/self/statm), after a collection."""
    import gc
    import os

    gc.collect()
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def growth_over(worlds: int, make_and_drop) -> int:
    """How much the resident memory grows over ``worlds`` calls of ``make_and_drop``, after
    a warm-up that lets the allocators and caches of the engines settle."""
    for _ in range(50):
        make_and_drop()
    before = resident_bytes()
    for _ in range(worlds):
        make_and_drop()
    return resident_bytes() - before


def fidelity_scene(root: str, name: str) -> str:
    """The XML of reference scene ``name`` of c_tests/fidelity_scenes.h, the scenes the C and
    C++ adapters are checked against worlds built by hand: its C string literals and the
    header's FIDELITY_ macros joined."""
    with open(os.path.join(root, "c_tests", "fidelity_scenes.h")) as f:
        header = f.read()
    literal = r'"((?:[^"\\]|\\.)*)"'
    macros = {m.group(1): m.group(2) for m in re.finditer(r"#define (FIDELITY_\w+)((?:[^\n]*\\\n)*[^\n]*)", header)}

    def text(source: str) -> str:
        parts = re.finditer(literal + r"|(FIDELITY_\w+)", source)
        return "".join(p.group(1).replace('\\"', '"') if p.group(1) is not None else text(macros[p.group(2)]) for p in parts)

    start = header.index('{"%s",' % name) + len(name) + 4
    return text(header[start : header.index('</World>"}', start) + len('</World>"')])


def labels(scene, records):
    """Each record's Name and the raw XML of its UserData (None where it has none)."""
    return [(r.name, None if r.user_data is None else scene.user_data[r.user_data].raw) for r in records]
