"""Loading, the records, errors, writing and the builder: the library's, through Python."""

from __future__ import annotations

import dataclasses
import errno
import json
import os
import pickle
import pydoc
import re

import numpy as np
import pytest

import box2scene
from box2scene import Body, Builder, Error, Fixture, Joint, Shape

from conftest import ROOT, scene_files, scene_id


def records(scene):
    return (
        scene.version,
        scene.gravity,
        scene.shapes,
        scene.fixtures,
        scene.bodies,
        scene.joints,
        scene.vertices,
        scene.fixture_ids,
        scene.user_data,
        scene.diagnostics,
    )


@pytest.mark.parametrize("path", scene_files(), ids=scene_id)
def test_a_load_from_a_path_equals_a_load_from_bytes(path):
    with open(path, "rb") as f:
        data = f.read()
    from_path = box2scene.load(path)
    assert records(from_path) == records(box2scene.load(data))
    assert records(from_path) == records(box2scene.load(bytearray(data)))
    assert from_path.to_json() == box2scene.load(data).to_json()


def same_float(a, b) -> bool:
    return np.float32(a) == np.float32(b)


def same_value(record_value, dumped) -> bool:
    if isinstance(record_value, tuple) and record_value and isinstance(record_value[0], tuple):
        return len(record_value) == len(dumped) and all(same_value(r, d) for r, d in zip(record_value, dumped))
    if isinstance(record_value, tuple):
        return dumped is not None and len(record_value) == len(dumped) and all(same_value(r, d) for r, d in zip(record_value, dumped))
    if isinstance(record_value, float):
        return same_float(record_value, dumped)
    return record_value == dumped


@pytest.mark.parametrize("path", scene_files(), ids=scene_id)
def test_every_field_is_the_one_the_library_dumps(path):
    """The library's JSON dump, with every field of every record, against the records."""
    scene = box2scene.load(path)
    dump = json.loads(scene.to_json())
    assert scene.version == dump["version"]
    assert same_value(scene.gravity, dump["gravity"]) if scene.gravity else dump["gravity"] is None
    assert len(scene.shapes) == len(dump["shapes"])
    for shape, d in zip(scene.shapes, dump["shapes"]):
        for f in dataclasses.fields(shape):
            assert same_value(getattr(shape, f.name), d[f.name]), (f.name, getattr(shape, f.name), d[f.name])
    for fixture, d in zip(scene.fixtures, dump["fixtures"]):
        flat = dict(d, **d["filter"])
        flat["user_data"] = fixture.user_data if (d["user_data"] is None) == (fixture.user_data is None) else "mismatch"
        for f in dataclasses.fields(fixture):
            assert same_value(getattr(fixture, f.name), flat[f.name]), f.name
    for body, d in zip(scene.bodies, dump["bodies"]):
        for f in dataclasses.fields(body):
            if f.name in d and f.name != "user_data":
                assert same_value(getattr(body, f.name), d[f.name]), f.name
    for joint, d in zip(scene.joints, dump["joints"]):
        for f in dataclasses.fields(joint):
            if f.name in d and f.name != "user_data":
                assert same_value(getattr(joint, f.name), d[f.name]), f.name
    assert [(g.code, g.line, g.column, g.message) for g in scene.diagnostics] == [
        (g["code"], g["line"], g["column"], g["message"]) for g in dump["diagnostics"]
    ]


def test_the_records_are_the_c_views(showcase):
    scene = box2scene.load(showcase)
    ground = scene.bodies[0]
    assert (ground.kind, ground.name, ground.fixtures) == ("static", "Ground", (0, 1, 2))
    assert scene.gravity == (0.0, -10.0)
    bridge = scene.joints[scene.find_joint("BridgeLinkLeft")]
    assert bridge.kind == "revolute" and bridge.local_anchor_b == (np.float32(-0.6), 0.0)
    polygon = next(s for s in scene.shapes if s.kind == "polygon")
    assert polygon.vertices == tuple(scene.vertices[i] for i in range(len(polygon.vertices)))
    assert scene.fixture_ids[: len(ground.fixtures)] == ground.fixtures


def test_user_data_and_names_come_through():
    path = os.path.join(ROOT, "tests", "fixtures", "scenes", "every-v1-field.xml")
    scene = box2scene.load(path)
    rubber = scene.fixtures[0]
    assert rubber.name == "rubber"
    data = scene.user_data[rubber.user_data]
    assert (data.type_name, data.value) == ("System.String", "tyre & rim")
    assert "<Type>System.String</Type>" in data.raw


def test_warnings_carry_their_code_and_position():
    text = b'<World Version="1">\n  <Shapes/>\n  <Fixtures/>\n  <Bodies/>\n  <Joints/>\n  <Bogus/>\n</World>\n'
    scene = box2scene.load(text)
    [warning] = scene.diagnostics
    assert (warning.code, warning.severity, warning.line, warning.column) == ("unknown-element", "warning", 6, 3)
    with pytest.raises(Error) as raised:
        box2scene.load(text, strict=True)
    assert (raised.value.code, raised.value.line, raised.value.column) == ("unknown-element", 6, 3)


BAD = [
    (b'<World Version="1">\n  <Bodies>\n    <Body Type="Dynamic">\n      <Angle>0,5</Angle>\n', "float-decimal-comma", 4, 15),
    (b'<World Version="7"/>', "unsupported-version", 1, 17),
    (b'<!DOCTYPE x>\n<World/>', "doctype-forbidden", 1, 1),
    (b'<World Version="1">\n<Shapes>\n <Shape Type="Circle"><Radius>-1</Radius><Position>0 0</Position></Shape>\n</Shapes>\n</World>', "bad-radius", 3, 31),
]


@pytest.mark.parametrize("text,code,line,column", BAD, ids=[b[1] for b in BAD])
def test_bad_input_raises_the_error_with_its_position(tmp_path, text, code, line, column):
    path = tmp_path / "bad.xml"
    path.write_bytes(text)
    for source in (text, path, str(path)):
        with pytest.raises(Error) as raised:
            box2scene.load(source)
        e = raised.value
        assert (e.code, e.line, e.column) == (code, line, column), e
        assert e.byte_offset > 0 or (line, column) == (1, 1)
        assert str(e).startswith(f"{line}:{column}: error[{code}]: ")


def test_a_missing_file_is_an_io_error(tmp_path):
    with pytest.raises(Error) as raised:
        box2scene.load(tmp_path / "none.xml")
    assert raised.value.code == "io-error"


def test_a_file_that_cannot_be_opened_raises_the_oserror_of_its_kind(tmp_path):
    missing = tmp_path / "none.xml"
    with pytest.raises(FileNotFoundError) as raised:
        box2scene.load(missing)
    e = raised.value
    assert isinstance(e, Error) and isinstance(e, OSError)
    assert (e.errno, e.strerror, e.filename) == (errno.ENOENT, os.strerror(errno.ENOENT), str(missing))
    assert (e.code, e.line, e.column, e.byte_offset) == ("io-error", 0, 0, 0)
    assert str(e) == f"error[io-error]: cannot read {missing}: No such file or directory (os error 2)"
    (tmp_path / "file").write_bytes(b"")
    with pytest.raises(NotADirectoryError) as raised:
        box2scene.load(str(tmp_path / "file" / "scene.xml"))
    assert isinstance(raised.value, Error) and raised.value.errno == errno.ENOTDIR
    assert str(tmp_path / "file" / "scene.xml") in str(raised.value)
    with pytest.raises(IsADirectoryError) as raised:
        box2scene.load(tmp_path)
    assert isinstance(raised.value, Error) and (raised.value.errno, raised.value.filename) == (errno.EISDIR, str(tmp_path))


def test_an_unreadable_file_raises_permission_error(tmp_path, showcase):
    if os.geteuid() == 0:
        pytest.skip("root reads every file: no permission is refused")
    path = tmp_path / "locked.xml"
    path.write_bytes(open(showcase, "rb").read())
    path.chmod(0)
    with pytest.raises(PermissionError) as raised:
        box2scene.load(path)
    assert isinstance(raised.value, Error) and raised.value.filename == str(path)


def test_xml_text_is_refused_as_a_path_and_loads_takes_it(showcase):
    text = open(showcase, encoding="utf-8").read()
    for source in (text, "\n  " + text):
        with pytest.raises(Error) as raised:
            box2scene.load(source)
        assert raised.value.code == "invalid-argument"
        assert "box2scene.loads" in str(raised.value) and len(str(raised.value)) < 200
    assert records(box2scene.loads(text)) == records(box2scene.load(showcase))
    assert records(box2scene.loads(text.encode())) == records(box2scene.load(showcase))
    with pytest.raises(Error) as raised:
        box2scene.loads('<World Version="7"/>')
    assert (raised.value.code, raised.value.line, raised.value.column) == ("unsupported-version", 1, 17)
    assert str(raised.value).startswith("1:17: error[unsupported-version]: ")


def test_limits_are_load_options(showcase):
    with pytest.raises(Error) as raised:
        box2scene.load(showcase, max_depth=2)
    assert raised.value.code == "limit-exceeded"
    with pytest.raises(Error) as raised:
        box2scene.load(open(showcase, "rb").read(), max_input_bytes=100)
    assert raised.value.code == "limit-exceeded"
    assert len(box2scene.load(showcase, max_depth=64, threads=1).bodies) == 34


def test_a_scene_is_immutable(showcase):
    scene = box2scene.load(showcase)
    with pytest.raises(AttributeError):
        scene.bodies = ()
    with pytest.raises(dataclasses.FrozenInstanceError):
        scene.bodies[0].position = (1.0, 1.0)
    assert isinstance(scene.bodies, tuple) and isinstance(scene.shapes[0].vertices, tuple)


# The scene files whose own engine dialect cannot hold them (comments, a chain for
# Farseer 3.3.1's reader): written, they keep their dialect or are refused.
NOT_IN_THEIR_OWN_DIALECT = {
    "tests/fixtures/scenes/farseer-v2-2013-ids.xml",
    "tests/fixtures/scenes/farseer-v2.xml",
    "tests/fixtures/scenes/farseer-v3-counter-ids.xml",
}


@pytest.mark.parametrize("path", scene_files(), ids=scene_id)
def test_what_is_written_loads_back_to_the_same_scene(tmp_path, path):
    scene = box2scene.load(path)
    dialect = None
    if scene_id(path) in NOT_IN_THEIR_OWN_DIALECT:
        with pytest.raises(Error) as raised:
            scene.to_xml()
        assert raised.value.code == "dialect-cannot-hold"
        dialect = "box2scene"
    again = box2scene.load(scene.to_xml(dialect=dialect).encode())
    assert records(again)[1:9] == records(scene)[1:9]
    out = tmp_path / "out.xml"
    scene.write(out, dialect=dialect)
    assert out.read_bytes() == scene.to_xml(dialect=dialect).encode()
    assert records(box2scene.load(out))[1:9] == records(scene)[1:9]
    everything = scene.to_xml(all_fields=True, dialect=dialect)
    assert records(box2scene.load(everything.encode()))[1:9] == records(scene)[1:9]


def test_a_scene_is_written_in_the_dialect_asked_for():
    """The dialect a scene is written in: its own by default, any other by its name."""
    scene = box2scene.load(os.path.join(ROOT, "tests/fixtures/dialects/aether.xml"))
    assert scene.dialect == "aether"
    assert box2scene.loads(scene.to_xml()).dialect == "aether"
    own = box2scene.loads(scene.to_xml(dialect="box2scene"))
    assert own.dialect == "box2scene"
    every_record = lambda s: (s.gravity, s.shapes, s.fixtures, s.bodies, s.joints, s.user_data)
    assert every_record(own) == every_record(scene)
    with pytest.raises(ValueError, match='unknown dialect "farseer" \\(one of box2scene, '):
        scene.to_xml(dialect="farseer")


def test_a_failed_write_leaves_the_old_file(tmp_path, showcase):
    scene = box2scene.load(showcase)
    target = tmp_path / "level.xml"
    target.write_text("old")
    with pytest.raises(Error) as raised:
        scene.write(tmp_path / "missing-folder" / "level.xml")
    assert raised.value.code == "io-error"
    scene.write(target)
    assert box2scene.load(target).bodies == scene.bodies
    assert sorted(os.listdir(tmp_path)) == ["level.xml"]


def built_scene():
    b = Builder()
    b.set_gravity((0.0, -9.81))
    data = b.add_user_data(type_name="System.String", value="crate & co")
    box = b.add_shape(Shape.new("polygon", name="box", vertices=((-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5))))
    ground = b.add_shape(Shape.new("edge", vertices=((-20.0, 0.0), (20.0, 0.0))))
    wheel = b.add_shape(Shape.new("circle", radius=0.1, position=(0.3, 0.0)))
    chain = b.add_shape(Shape.new("chain", vertices=((-5.0, 1.0), (0.0, 0.5), (5.0, 1.0)), prev_vertex=(-6.0, 2.0)))
    f_box = b.add_fixture(Fixture.new(box, density=1.0, friction=0.1, user_data=data, category_bits=2, mask_bits=0xFFFD))
    f_ground = b.add_fixture(Fixture.new(ground))
    f_wheel = b.add_fixture(Fixture.new(wheel, density=3.0, restitution=0.7))
    f_chain = b.add_fixture(Fixture.new(chain))
    b.add_body(Body.new("static", name="Ground", fixtures=(f_ground, f_chain)))
    b.add_body(Body.new("dynamic", name="Crate", position=(0.1, 2.0), angle=0.3, fixtures=(f_box, f_wheel), mass=2.5))
    b.add_body(Body.new("dynamic", name="Ball", position=(1.0, 4.0), linear_velocity=(0.5, 0.0), fixtures=(f_wheel,)))
    b.add_joint(Joint.new("distance", 1, 2, name="Rod", length=2.0, frequency_hz=4.0, damping_ratio=0.5))
    b.add_joint(Joint.new("revolute", 0, 1, local_anchor_a=(0.1, 2.0), enable_limit=True, lower_limit=-0.5, upper_limit=0.5))
    return b.finish()


def test_the_builder_makes_a_scene_that_writes_and_loads_back_exactly():
    scene = built_scene()
    assert scene.version == 2  # an edge and a chain are Version 2 constructs
    assert scene.bodies[1].mass == np.float32(2.5) and scene.bodies[1].inertia is None
    assert scene.bodies[1].angle == float(np.float32(0.3))
    text = scene.to_xml()
    assert "<Angle>0.3</Angle>" in text  # the shortest text that reads back to the float
    assert "crate &amp; co" in text
    again = box2scene.load(text.encode(), strict=True)
    assert records(again)[1:9] == records(scene)[1:9]


def test_the_builder_refuses_what_would_not_read_back():
    b = Builder()
    shape = b.add_shape(Shape.new("circle", radius=1.0))
    with pytest.raises(Error) as raised:
        b.add_fixture(Fixture.new(shape, density=-1.0))
    assert (raised.value.code, raised.value.line, raised.value.column) == ("negative-value", 0, 0)
    assert raised.value.message.startswith("fixture 0: ")
    with pytest.raises(Error) as raised:
        b.add_body(Body.new("dynamic", fixtures=(7,)))
    assert raised.value.code == "id-out-of-range"
    with pytest.raises(Error) as raised:
        b.add_shape(Shape.new("circle", radius=1.0, name="bell\x07"))
    assert raised.value.code == "malformed-xml" and "U+0007" in raised.value.message
    with pytest.raises(ValueError):
        Shape.new("hexagon")
    with pytest.raises(Error):
        b.add_joint(Joint.new("revolute", 0, 0))
    b.finish()
    with pytest.raises(RuntimeError):
        b.finish()


def test_a_builder_error_prints_no_position():
    b = Builder()
    shape = b.add_shape(Shape.new("circle", radius=1.0))
    with pytest.raises(Error) as raised:
        b.add_fixture(Fixture.new(shape, density=-1.0))
    assert raised.value.line == 0
    assert str(raised.value) == f"error[negative-value]: {raised.value.message}"
    assert "0:0" not in str(raised.value)


def test_defaults_are_the_formats():
    assert Joint.new("wheel", 0, 1).frequency_hz == np.float32(2.0)
    assert Joint.new("pulley", 0, 1).ground_anchor_a == (-1.0, 1.0)
    assert Fixture.new(0).friction == np.float32(0.2) and Fixture.new(0).mask_bits == 0xFFFF
    assert Body.new("dynamic").allow_sleep and Body.new("dynamic").mass is None


def test_the_package_version_is_the_librarys():
    def version(path):
        text = open(path, encoding="utf-8").read()
        return re.search(r'^version = "([^"]+)"', text, re.M).group(1)

    assert version(os.path.join(ROOT, "python", "Cargo.toml")) == version(os.path.join(ROOT, "Cargo.toml"))
    from importlib.metadata import version as installed

    assert installed("box2scene") == version(os.path.join(ROOT, "Cargo.toml"))


def test_help_reads_well():
    text = pydoc.render_doc(box2scene, renderer=pydoc.plaintext)
    for words in ("load(source", "class Scene", "class Error", "class Builder", "pyb2d3", "pybox2d"):
        assert words in text, words
    assert box2scene.load.__doc__ and box2scene.Scene.write.__doc__


def test_a_scene_is_drawn_as_the_library_draws_it(showcase):
    """Scene.draw_svg is b2s_draw_svg: the scene where its file puts it, or a run's start,
    end and paths; lists of the wrong length are the library's invalid-argument."""
    scene = box2scene.load(showcase)
    alone = scene.draw_svg("showcase")
    assert alone.startswith('<?xml version="1.0" encoding="UTF-8"?>\n<svg ')
    assert "<title>showcase</title>" in alone and '<g class="key">' in alone
    assert '<g class="start">' in alone and 'class="end"' not in alone
    lower = [(b.position[0], b.position[1] - 1.0, b.angle) for b in scene.bodies]
    samples = [[b.position for b in scene.bodies], [(x, y) for x, y, _ in lower]]
    run = scene.draw_svg(end=lower, trajectories=samples, joints_created=[False] * len(scene.joints))
    assert '<g class="start" opacity="0.3">' in run and '<g class="end">' in run
    assert '<g class="paths"' in run and 'class="joints"' not in run
    with pytest.raises(Error) as raised:
        scene.draw_svg(end=lower[1:])
    assert raised.value.code == "invalid-argument"
    assert raised.value.message == f"end holds {len(lower) - 1} poses for {len(lower)} bodies"


def test_ragged_trajectories_are_refused_sample_by_sample(showcase):
    """A sample of one point too many and another of one too few hold, together, a whole
    number of samples: flattened, every point between them would land on the next body.
    Each sample holds one point per body, or the picture is refused naming the first that
    does not."""
    scene = box2scene.load(showcase)
    bodies = [b.position for b in scene.bodies]
    n = len(bodies)
    for ragged, index, count in (
        ([bodies, bodies + [(0.0, 0.0)], bodies[1:]], 1, n + 1),
        ([bodies[1:], bodies + [(0.0, 0.0)]], 0, n - 1),
        ([bodies, []], 1, 0),
    ):
        with pytest.raises(Error) as raised:
            scene.draw_svg(trajectories=ragged)
        assert raised.value.code == "invalid-argument"
        assert raised.value.message == f"trajectories sample {index} holds {count} points for {n} bodies"
    drawn = scene.draw_svg(trajectories=[bodies, [(x, y - 1.0) for x, y in bodies]])
    assert '<g class="paths"' in drawn


def test_a_load_makes_no_record_until_one_is_read(showcase):
    scene = box2scene.load(showcase)
    assert scene._made == {}
    bodies = scene.bodies
    assert list(scene._made) == ["bodies"] and scene.bodies is bodies
    assert len(bodies) == 34 and scene.find_body(bodies[3].name) == 3


@pytest.mark.parametrize("path", scene_files(), ids=scene_id)
def test_scenes_compare_by_value(path):
    with open(path, "rb") as f:
        data = f.read()
    a, b = box2scene.load(path), box2scene.load(data)
    assert a == b and not (a != b)
    assert a == a and a != data and a != None  # noqa: E711
    with pytest.raises(TypeError):
        hash(a)


def test_scenes_with_one_field_apart_are_unequal(showcase):
    scene = box2scene.load(showcase)
    b = Builder()
    b.set_gravity((0.0, -10.0))
    built = b.finish()
    b = Builder()
    b.set_gravity((0.0, -9.5))
    assert built != b.finish() and built != scene
    b = Builder()
    b.set_gravity((0.0, -10.0))
    assert built == b.finish()


def test_records_pickle_to_equal_records(showcase):
    scene = box2scene.load(showcase)
    for records_of_a_kind in (scene.shapes, scene.fixtures, scene.bodies, scene.joints, scene.user_data, scene.diagnostics):
        assert pickle.loads(pickle.dumps(records_of_a_kind)) == records_of_a_kind


def owner(array):
    """The object whose memory an array reads."""
    while isinstance(array.base, np.ndarray):
        array = array.base
    return array.base


def as_column(value):
    if value is None:
        return -1
    return value


@pytest.mark.parametrize("path", scene_files(), ids=scene_id)
def test_arrays_hold_the_records_values(path):
    scene = box2scene.load(path)
    arrays = scene.arrays()
    assert set(arrays) == {"shapes", "fixtures", "bodies", "joints", "vertices", "fixture_ids"}
    for name, records_of_a_kind in (("shapes", scene.shapes), ("fixtures", scene.fixtures), ("bodies", scene.bodies), ("joints", scene.joints)):
        columns = arrays[name]
        for column in columns.values():
            assert len(column) == len(records_of_a_kind)
            assert not column.flags.writeable and isinstance(owner(column), bytes)
        for i, record in enumerate(records_of_a_kind):
            for f in dataclasses.fields(record):
                value = getattr(record, f.name)
                if f.name in ("vertices", "fixtures", "name"):
                    continue
                if f.name in columns:
                    given = columns.get(f"{f.name}_given", columns.get(f"has_{f.name}"))
                    if given is not None:
                        assert bool(given[i]) == (value is not None), (name, f.name)
                        if value is None:
                            continue
                    got = columns[f.name][i]
                    expected = as_column(value) if f.name in ("shape", "user_data", "body_a", "body_b", "joint_a", "joint_b") else value
                    assert np.array_equal(np.asarray(got), np.asarray(expected, dtype=np.asarray(got).dtype)), (name, f.name, i)
                else:
                    raise AssertionError(f"{name} has no column {f.name}")
    pool = arrays["vertices"]["vertices"]
    assert pool.shape == (len(scene.vertices), 2) and pool.dtype == np.float32
    for i, shape in enumerate(scene.shapes):
        first, count = arrays["shapes"]["vertices_first"][i], arrays["shapes"]["vertices_count"][i]
        assert [tuple(float(x) for x in v) for v in pool[first : first + count]] == list(shape.vertices)
    ids = arrays["fixture_ids"]["fixture_ids"]
    for i, body in enumerate(scene.bodies):
        first, count = arrays["bodies"]["fixtures_first"][i], arrays["bodies"]["fixtures_count"][i]
        assert tuple(int(x) for x in ids[first : first + count]) == body.fixtures


def test_every_vec2_argument_takes_a_sequence_or_a_numpy_array():
    def build(vec):
        b = Builder()
        b.set_gravity(vec((0.0, -10.0)))
        polygon = b.add_shape(Shape.new("polygon", vertices=[vec(v) for v in ((-1.0, 0.0), (1.0, 0.0), (0.0, 1.0))]))
        circle = b.add_shape(Shape.new("circle", radius=0.5, position=vec((0.25, 0.5))))
        fixtures = (b.add_fixture(Fixture.new(polygon)), b.add_fixture(Fixture.new(circle)))
        b.add_body(Body.new("dynamic", fixtures=fixtures, position=vec((1.0, 2.0)), linear_velocity=vec((3.0, -4.0)), center=vec((0.5, 0.5))))
        return b.finish()

    tuples = build(tuple)
    assert tuples.bodies[0].position == (1.0, 2.0)
    for vec in (list, np.array, lambda v: np.array(v, dtype=np.float32)):
        assert build(vec) == tuples
    b = Builder()
    b.add_shape(Shape.new("polygon", vertices=np.array([(-1.0, 0.0), (1.0, 0.0), (0.0, 1.0)])))
    assert b.finish().shapes[0].vertices == ((-1.0, 0.0), (1.0, 0.0), (0.0, 1.0))
    with pytest.raises(ValueError, match="a vector is two numbers, not 3"):
        Builder().set_gravity([0.0, 1.0, 2.0])
    with pytest.raises(TypeError):
        Builder().set_gravity(5.0)
    svg = tuples.draw_svg(trajectories=[[np.array((1.0, 2.0))], [[1.5, 2.5]]])
    assert svg == tuples.draw_svg(trajectories=[[(1.0, 2.0)], [(1.5, 2.5)]])


def comments(text):
    return re.findall(r"<!--(.*?)-->", text, re.S)


def test_a_loaded_scene_edited_keeps_every_comment_of_the_records_left_unchanged(showcase):
    scene = box2scene.load(showcase)
    assert len(comments(scene.to_xml())) == 20
    assert Builder.from_scene(scene).finish().to_xml() == scene.to_xml()
    b = Builder.from_scene(scene)
    driver = scene.find_body("GearDriver")
    b.replace_body(driver, dataclasses.replace(scene.bodies[driver], position=(-3.5, 7.25)))
    extra = b.add_body(Body.new("dynamic", name="Newcomer", fixtures=scene.bodies[driver].fixtures, position=[1.0, 2.0]))
    weld = next(i for i, j in enumerate(scene.joints) if j.kind == "weld")
    b.remove_joint(weld)
    edited = b.finish()
    text = edited.to_xml()
    assert comments(text) == [c for c in comments(scene.to_xml()) if c != " Weld "]
    again = box2scene.loads(text)
    assert again.bodies[driver].position == (-3.5, 7.25)
    assert again.find_body("Newcomer") == extra == len(scene.bodies)
    assert len(again.joints) == len(scene.joints) - 1
    gear = again.joints[again.find_joint("GearMesh")]
    assert (gear.joint_a, gear.joint_b) == (again.find_joint("GearDriverAxle"), again.find_joint("GearFollowerAxle"))
    untouched = [i for i in range(len(scene.bodies)) if i != driver]
    assert [again.bodies[i] for i in untouched] == [scene.bodies[i] for i in untouched]
    every_record = lambda s: (s.version, s.gravity, s.shapes, s.fixtures, s.bodies, s.joints, s.user_data)
    assert every_record(again) == every_record(edited)
    assert [d.code for d in again.diagnostics] == ["joint-starts-violated"]


def test_what_a_record_refers_to_is_not_removed(showcase):
    scene = box2scene.load(showcase)
    b = Builder.from_scene(scene)
    axle, gear = scene.find_joint("GearDriverAxle"), scene.find_joint("GearMesh")
    with pytest.raises(Error) as raised:
        b.remove_joint(axle)
    assert (raised.value.code, raised.value.message) == ("invalid-argument", f"joint {axle}: gear joint {gear} refers to it; replace or take that out first")
    with pytest.raises(Error) as raised:
        b.replace_body(1000, scene.bodies[0])
    assert (raised.value.code, str(raised.value)) == ("id-out-of-range", "error[id-out-of-range]: body 1000: there is no body 1000: the scene has 34")
    assert b.finish() == scene
