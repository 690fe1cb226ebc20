"""Loading, the immutable Scene, writing, and building a scene from records."""

from __future__ import annotations

import dataclasses
import os
from typing import Any, Dict, Optional, Sequence, Tuple, Union

from . import _native
from ._native import NativeScene as _NativeScene
from ._error import Error
from ._records import Body, Diagnostic, Fixture, Joint, Shape, UserData, Vec2

Source = Union[str, "os.PathLike[str]", bytes, bytearray, memoryview]


_RECORDS: Dict[str, Any] = {
    "shapes": Shape,
    "fixtures": Fixture,
    "bodies": Body,
    "joints": Joint,
    "user_data": UserData,
    "diagnostics": Diagnostic,
}

_ARRAYS = ("shapes", "fixtures", "bodies", "joints", "vertices", "fixture_ids")


class Scene:
    """A loaded (or built) scene: immutable tuples of frozen records.

    ``shapes``, ``fixtures``, ``bodies``, ``joints``, ``user_data`` and ``diagnostics``
    hold the C view's records (see :mod:`box2scene._records`); ``vertices`` and
    ``fixture_ids`` are its pools, which ``Shape.vertices`` and ``Body.fixtures`` already
    resolve. ``gravity`` is None when the file gave none (the host decides). Each tuple is
    made when first read, so that a load costs what the library's load costs; :meth:`arrays`
    gives the same values as NumPy columns. Two scenes are equal when their records are.
    """

    __slots__ = ("_native", "_made", "version", "gravity")

    _native: _NativeScene
    _made: Dict[str, Any]
    version: int
    gravity: Optional[Vec2]

    def __init__(self, native: _NativeScene):
        set_ = object.__setattr__
        set_(self, "_native", native)
        set_(self, "_made", {})
        set_(self, "version", native.version())
        set_(self, "gravity", native.gravity())

    def _records(self, name: str) -> Any:
        made: Dict[str, Any] = self._made
        if name not in made:
            native = self._native
            if name == "vertices":
                made[name] = native.vertices()
            elif name == "fixture_ids":
                made[name] = tuple(native.fixture_ids())
            else:
                record = _RECORDS[name]
                made[name] = tuple(record(**d) for d in getattr(native, name)())
        return made[name]

    @property
    def shapes(self) -> Tuple[Shape, ...]:
        return self._records("shapes")  # type: ignore[no-any-return]

    @property
    def fixtures(self) -> Tuple[Fixture, ...]:
        return self._records("fixtures")  # type: ignore[no-any-return]

    @property
    def bodies(self) -> Tuple[Body, ...]:
        return self._records("bodies")  # type: ignore[no-any-return]

    @property
    def joints(self) -> Tuple[Joint, ...]:
        return self._records("joints")  # type: ignore[no-any-return]

    @property
    def vertices(self) -> Tuple[Vec2, ...]:
        return self._records("vertices")  # type: ignore[no-any-return]

    @property
    def fixture_ids(self) -> Tuple[int, ...]:
        return self._records("fixture_ids")  # type: ignore[no-any-return]

    @property
    def user_data(self) -> Tuple[UserData, ...]:
        return self._records("user_data")  # type: ignore[no-any-return]

    @property
    def diagnostics(self) -> Tuple[Diagnostic, ...]:
        return self._records("diagnostics")  # type: ignore[no-any-return]

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Scene):
            return NotImplemented
        return bool(self._native.same_records(other._native))

    __hash__ = None  # type: ignore[assignment]

    def arrays(self) -> Dict[str, Dict[str, Any]]:
        """The scene's records as NumPy columns (NumPy must be installed): ``"shapes"``,
        ``"fixtures"``, ``"bodies"``, ``"joints"``, ``"vertices"`` and ``"fixture_ids"``, each a
        dict of one read-only array per field (``position`` of shape (n, 2), ``angle`` of
        shape (n,), kinds as text, absent indices as -1, each optional datum with its
        ``..._given`` flag, a shape's vertices and a body's fixtures as ``..._first`` and
        ``..._count`` into the pools ``arrays()["vertices"]["vertices"]`` and
        ``arrays()["fixture_ids"]["fixture_ids"]``). The library writes each column once
        into memory that the array then reads in place."""
        import numpy as np

        def array(dtype: str, width: int, data: bytes) -> Any:
            values = np.frombuffer(data, dtype=dtype)
            return values.reshape(-1, width) if width > 1 else values

        return {
            name: {column: array(dtype, width, data) for column, dtype, width, data in self._native.columns(name)}
            for name in _ARRAYS
        }

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("a Scene is immutable")

    def __delattr__(self, name: str) -> None:
        raise AttributeError("a Scene is immutable")

    def __repr__(self) -> str:
        return (
            f"<box2scene.Scene version {self.version}: {len(self.shapes)} shapes, "
            f"{len(self.fixtures)} fixtures, {len(self.bodies)} bodies, "
            f"{len(self.joints)} joints, {len(self.diagnostics)} diagnostics>"
        )

    @property
    def dialect(self) -> str:
        """The dialect the scene remembers, which :meth:`to_xml` writes by default: that of
        the file it was loaded from (``"box2scene"``, ``"farseer-3.3"``, ``"farseer-2013"``,
        ``"farseer-3.5"``, ``"aether"``), box2scene's for a built scene."""
        return self._native.dialect()

    def to_xml(self, all_fields: bool = False, dialect: Optional[str] = None) -> str:
        """The scene as Box2Scene XML, which loads back to the same records (every float
        bit for bit). A loaded scene keeps its comments and unknown content. ``all_fields``
        writes fields equal to their defaults too. ``dialect`` names the dialect to write
        (``"box2scene"``, ``"farseer-3.3"``, ``"farseer-2013"``, ``"farseer-3.5"``,
        ``"aether"``); by default the scene's own, never another: a scene read from an
        engine's file that its engine's reader cannot take raises ``dialect-cannot-hold``,
        and ``dialect="box2scene"`` writes it in box2scene's form. Raises :class:`Error`
        for what cannot be written."""
        return self._native.to_xml(all_fields, dialect)

    def write(
        self,
        path: "Union[str, os.PathLike[str]]",
        all_fields: bool = False,
        dialect: Optional[str] = None,
    ) -> None:
        """Writes :meth:`to_xml`'s text to ``path``, replacing the file atomically: a
        failed write leaves the old file as it was."""
        self._native.write(os.fspath(path), all_fields, dialect)

    def to_json(self) -> str:
        """Every field of every record as JSON, floats in shortest round-trip form."""
        return self._native.to_json()

    def draw_svg(
        self,
        title: str = "",
        start: "Optional[Sequence[Tuple[float, float, float]]]" = None,
        end: "Optional[Sequence[Tuple[float, float, float]]]" = None,
        trajectories: "Sequence[Sequence[Tuple[float, float]]]" = (),
        joints_created: "Optional[Sequence[bool]]" = None,
    ) -> str:
        """The scene drawn as an SVG document, the picture ``box2scene render`` and the
        examples make (docs/api.md, "Drawing scenes"): where the file puts every body, or
        where a simulation started (``start``) and ended (``end``), one ``(x, y, angle)`` per
        body, the start then faint; ``trajectories`` holds samples of one ``(x, y)`` per body
        each, drawn as paths; ``joints_created`` one flag per joint, False for a joint the
        host did not create. A pose or point that is not finite is not drawn (a body not
        created). Raises :class:`Error` (``invalid-argument``) for lists of the wrong
        length, a sample of trajectories among them."""
        return self._native.draw_svg(
            title,
            None if start is None else list(start),
            None if end is None else list(end),
            None if joints_created is None else list(joints_created),
            [list(sample) for sample in trajectories],
        )

    def find_body(self, name: str) -> Optional[int]:
        """The index of the first body named ``name``, or None."""
        return next((i for i, b in enumerate(self.bodies) if b.name == name), None)

    def find_fixture(self, name: str) -> Optional[int]:
        """The index of the first fixture named ``name``, or None."""
        return next((i for i, f in enumerate(self.fixtures) if f.name == name), None)

    def find_joint(self, name: str) -> Optional[int]:
        """The index of the first joint named ``name``, or None."""
        return next((i for i, j in enumerate(self.joints) if j.name == name), None)


def _load_options(
    strict: bool,
    max_input_bytes: Optional[int],
    max_elements: Optional[int],
    max_text_bytes: Optional[int],
    max_depth: Optional[int],
    max_chain_vertices: Optional[int],
    threads: int,
) -> Dict[str, Any]:
    given = {
        "max_input_bytes": max_input_bytes,
        "max_elements": max_elements,
        "max_text_bytes": max_text_bytes,
        "max_depth": max_depth,
        "max_chain_vertices": max_chain_vertices,
    }
    options: Dict[str, Any] = {k: v for k, v in given.items() if v is not None}
    options["strict"] = strict
    options["threads"] = threads
    return options


def load(
    source: Source,
    *,
    strict: bool = False,
    max_input_bytes: Optional[int] = None,
    max_elements: Optional[int] = None,
    max_text_bytes: Optional[int] = None,
    max_depth: Optional[int] = None,
    max_chain_vertices: Optional[int] = None,
    threads: int = 0,
) -> Scene:
    """Loads a scene from a path (``str`` or path-like) or from the bytes of a file.

    Both give the same scene, warnings and error. ``strict`` turns every warning into an
    error. The limits default to the library's (1 GiB of input, 10 million elements, 1 MiB
    for one text, depth 64, 100 000 chain vertices); a file past one raises
    ``limit-exceeded``. Raises :class:`Error` (with code, line and column) for a file
    that is not a valid scene, and an :class:`Error` that is also the ``OSError`` of the
    reason (``FileNotFoundError``, ``PermissionError``, ...) for a file that cannot be
    opened. A ``str`` that starts with ``<`` is XML, not a path: :func:`loads` takes it.
    """
    options = _load_options(strict, max_input_bytes, max_elements, max_text_bytes, max_depth, max_chain_vertices, threads)
    if isinstance(source, (bytes, bytearray, memoryview)):
        return Scene(_native.load_bytes(bytes(source), options))
    if isinstance(source, str) and source.lstrip().startswith("<"):
        raise Error("invalid-argument", 0, 0, 0, "load takes a path or bytes; this str is XML text, which box2scene.loads takes")
    return Scene(_native.load_path(os.fspath(source), options))


def loads(
    text: Union[str, bytes, bytearray, memoryview],
    *,
    strict: bool = False,
    max_input_bytes: Optional[int] = None,
    max_elements: Optional[int] = None,
    max_text_bytes: Optional[int] = None,
    max_depth: Optional[int] = None,
    max_chain_vertices: Optional[int] = None,
    threads: int = 0,
) -> Scene:
    """Loads a scene from its XML text (a ``str``, or the bytes of a file), with
    :func:`load`'s options, warnings and errors."""
    options = _load_options(strict, max_input_bytes, max_elements, max_text_bytes, max_depth, max_chain_vertices, threads)
    data = text.encode("utf-8") if isinstance(text, str) else bytes(text)
    return Scene(_native.load_bytes(data, options))


def _fields(record: Any) -> Dict[str, Any]:
    return {f.name: getattr(record, f.name) for f in dataclasses.fields(record)}


class Builder:
    """Builds a scene from records, as a host saves its level: each record is checked with
    the loader's rules when it is added (an :class:`Error` names the object), and
    :meth:`finish` gives an ordinary immutable :class:`Scene`, which writes and loads back
    to the same records. Objects refer to objects added before them."""

    def __init__(self) -> None:
        self._native = _native.NativeBuilder()

    @classmethod
    def from_scene(cls, scene: Scene) -> "Builder":
        """A builder holding everything ``scene`` holds but its diagnostics, the text its
        file held beyond the records too: comments, unknown elements and attributes,
        Farseer-only joints. What is added, replaced or removed changes only itself, so
        the finished scene writes every such text of the records left as they were, as
        ``box2scene fmt`` writes them. A replaced record keeps the comments around it but
        not the unknown content inside it."""
        builder = cls.__new__(cls)
        builder._native = _native.NativeBuilder.from_scene(scene._native)
        return builder

    def set_gravity(self, gravity: Optional[Sequence[float]]) -> None:
        """The world's gravity (any sequence of two numbers: a tuple, a list, a NumPy
        array), or None (the host decides)."""
        self._native.set_gravity(gravity)

    def add_user_data(
        self,
        raw: Optional[str] = None,
        type_name: Optional[str] = None,
        value: Optional[str] = None,
    ) -> int:
        """User data from raw XML content, or a type name and value in the editor's form;
        returns its index."""
        return self._native.add_user_data(raw, type_name, value)

    def add_shape(self, shape: Shape) -> int:
        """Adds a shape and returns its index."""
        return self._native.add_shape(_fields(shape))

    def add_fixture(self, fixture: Fixture) -> int:
        """Adds a fixture on an added shape and returns its index."""
        return self._native.add_fixture(_fields(fixture))

    def add_body(self, body: Body) -> int:
        """Adds a body whose fixtures were added and returns its index."""
        return self._native.add_body(_fields(body))

    def add_joint(self, joint: Joint) -> int:
        """Adds a joint between added bodies (a gear after its two joints); returns its
        index."""
        return self._native.add_joint(_fields(joint))

    def replace_shape(self, index: int, shape: Shape) -> None:
        """Replaces shape ``index``, checked as :meth:`add_shape` checks a new one."""
        self._native.replace_shape(index, _fields(shape))

    def replace_fixture(self, index: int, fixture: Fixture) -> None:
        """Replaces fixture ``index``, checked as :meth:`add_fixture` checks a new one."""
        self._native.replace_fixture(index, _fields(fixture))

    def replace_body(self, index: int, body: Body) -> None:
        """Replaces body ``index``, checked as :meth:`add_body` checks a new one."""
        self._native.replace_body(index, _fields(body))

    def replace_joint(self, index: int, joint: Joint) -> None:
        """Replaces joint ``index``, checked as :meth:`add_joint` checks a new one; a joint
        a gear couples stays revolute or prismatic."""
        self._native.replace_joint(index, _fields(joint))

    def remove_shape(self, index: int) -> None:
        """Removes shape ``index``, which no fixture may use; later shapes move down one,
        and the fixtures' indices with them."""
        self._native.remove_shape(index)

    def remove_fixture(self, index: int) -> None:
        """Removes fixture ``index``, which no body may hold; later fixtures move down."""
        self._native.remove_fixture(index)

    def remove_body(self, index: int) -> None:
        """Removes body ``index``, which no joint may join; later bodies move down."""
        self._native.remove_body(index)

    def remove_joint(self, index: int) -> None:
        """Removes joint ``index``, which no gear may couple; later joints move down."""
        self._native.remove_joint(index)

    def finish(self) -> Scene:
        """The finished scene; the builder cannot be used afterwards."""
        return Scene(self._native.finish())
