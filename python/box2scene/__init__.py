"""box2scene: load, check and write Box2Scene physics scenes, and build Box2D worlds.

A Box2Scene file is XML describing a whole Box2D world (shapes, fixtures, bodies, joints),
as the level editor that defined the format, Farseer, Velcro and Aether wrote it. This
package is the box2scene library (Rust) for Python:

    import box2scene
    scene = box2scene.load("level.xml")          # or load(data) with the file's bytes
    scene = box2scene.loads(xml_text)            # or from the XML as a str
    for d in scene.diagnostics:
        print(f"{d.line}:{d.column}: {d.code}: {d.message}")
    scene.bodies[0].position, scene.shapes[0].vertices
    scene.write("copy.xml")                      # atomic; reads back to the same scene

Everything wrong with a file raises :class:`Error` with its code, line and column; a file
that cannot be opened raises one that is also the ``OSError`` of the reason
(``FileNotFoundError``, ``PermissionError``, ...). :class:`Builder` makes a scene from
records, or edits a loaded one (``Builder.from_scene``: records replaced, added or removed,
the file's comments kept); ``scene.arrays()`` gives every record field as NumPy columns.
Two modules build worlds of the Python Box2D engines from a scene and capture worlds back
into scenes:

- :mod:`box2scene.pyb2d3`: pyb2d3 (Box2D v3.1.1), as the library's C v3 adapter does;
- :mod:`box2scene.pybox2d`: pybox2d (the ``box2d`` package 2.3.x, Box2D 2.3).

Neither engine is needed to load or write scenes.
"""

from ._error import Error
from ._records import Body, Diagnostic, Fixture, Joint, Shape, UserData, Vec2
from ._scene import Builder, Scene, load, loads

__all__ = [
    "Body",
    "Builder",
    "Diagnostic",
    "Error",
    "Fixture",
    "Joint",
    "Scene",
    "Shape",
    "UserData",
    "Vec2",
    "load",
    "loads",
]
