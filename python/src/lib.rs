//! `box2scene._native`: the library's load, write and builder for Python. Records cross as
//! dicts of plain values (the Python package wraps them in frozen dataclasses); every rule,
//! default and guarantee is the library's own.

use std::path::PathBuf;
use std::sync::Mutex;

use box2scene::draw::{Picture, Pose};
use box2scene::{
    Body, BodyKind, Builder, Code, Diagnostic, Dialect, Fixture, Joint, JointKind, LoadOptions,
    NONE, Position, Scene, Shape, ShapeKind, UserData, Vec2, WriteOptions,
};
use pyo3::exceptions::{PyKeyError, PyOverflowError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};

mod held;
mod plan;

const SHAPE_KINDS: [(&str, ShapeKind); 4] = [
    ("circle", ShapeKind::Circle),
    ("polygon", ShapeKind::Polygon),
    ("edge", ShapeKind::Edge),
    ("chain", ShapeKind::Chain),
];

const BODY_KINDS: [(&str, BodyKind); 3] = [
    ("static", BodyKind::Static),
    ("kinematic", BodyKind::Kinematic),
    ("dynamic", BodyKind::Dynamic),
];

const JOINT_KINDS: [(&str, JointKind); 12] = [
    ("revolute", JointKind::Revolute),
    ("prismatic", JointKind::Prismatic),
    ("distance", JointKind::Distance),
    ("pulley", JointKind::Pulley),
    ("line", JointKind::Line),
    ("weld", JointKind::Weld),
    ("friction", JointKind::Friction),
    ("gear", JointKind::Gear),
    ("wheel", JointKind::Wheel),
    ("rope", JointKind::Rope),
    ("motor", JointKind::Motor),
    ("unsupported", JointKind::Unsupported),
];

/// The Python name of a kind number (the number itself as text for one no table has).
fn kind_name<K: Copy>(
    table: &[(&'static str, K)],
    value: u32,
    number: impl Fn(K) -> u32,
) -> String {
    table
        .iter()
        .find(|(_, k)| number(*k) == value)
        .map_or_else(|| value.to_string(), |(name, _)| (*name).to_owned())
}

/// The kind a Python name means.
fn kind_of<K: Copy>(table: &[(&'static str, K)], name: &str, what: &str) -> PyResult<K> {
    let names: Vec<&str> = table.iter().map(|(n, _)| *n).collect();
    table.iter().find(|(n, _)| n.eq_ignore_ascii_case(name)).map(|(_, k)| *k).ok_or_else(|| {
        PyValueError::new_err(format!("unknown {what} kind {name:?} (one of {})", names.join(", ")))
    })
}

/// The package's `box2scene.Error` for a library error.
fn error(py: Python<'_>, e: box2scene::Error) -> PyErr {
    let raised = py.import("box2scene._error").and_then(|m| m.getattr("Error")).and_then(|class| {
        class.call1((
            e.code.name(),
            e.position.line,
            e.position.column,
            e.position.byte_offset,
            e.message.clone(),
        ))
    });
    match raised {
        Ok(value) => PyErr::from_value(value),
        Err(e) => e,
    }
}

/// A value of a record field, as Python holds it.
trait Field: Sized {
    fn to_py<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>>;
    fn from_py(value: &Bound<'_, PyAny>) -> PyResult<Self>;
}

impl Field for f32 {
    fn to_py<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(self.into_pyobject(py)?.into_any())
    }
    fn from_py(value: &Bound<'_, PyAny>) -> PyResult<Self> {
        value.extract()
    }
}

impl Field for bool {
    fn to_py<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(self.into_pyobject(py)?.to_owned().into_any())
    }
    fn from_py(value: &Bound<'_, PyAny>) -> PyResult<Self> {
        value.extract()
    }
}

impl Field for Vec2 {
    fn to_py<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok((self.x, self.y).into_pyobject(py)?.into_any())
    }
    fn from_py(value: &Bound<'_, PyAny>) -> PyResult<Self> {
        vec2_from_py(value)
    }
}

/// A vector from any sequence of two numbers: a tuple, a list, a NumPy array.
fn vec2_from_py(value: &Bound<'_, PyAny>) -> PyResult<Vec2> {
    let numbers: Vec<f32> = value.extract()?;
    match numbers[..] {
        [x, y] => Ok(Vec2::new(x, y)),
        _ => Err(PyValueError::new_err(format!("a vector is two numbers, not {}", numbers.len()))),
    }
}

/// An index that may be absent: None in Python, `NONE` in the record.
fn index_to_py(py: Python<'_>, index: u32) -> PyResult<Bound<'_, PyAny>> {
    match index {
        NONE => Ok(py.None().into_bound(py)),
        i => Ok(i.into_pyobject(py)?.into_any()),
    }
}

fn index_from_py(value: &Bound<'_, PyAny>) -> PyResult<u32> {
    if value.is_none() {
        return Ok(NONE);
    }
    let index: u32 = value.extract()?;
    if index == NONE {
        return Err(PyOverflowError::new_err(format!("index {index} is out of range")));
    }
    Ok(index)
}

/// An optional value: None where the record says it was not given.
fn optional_to_py<'py, T: Field>(
    py: Python<'py>,
    given: bool,
    value: &T,
) -> PyResult<Bound<'py, PyAny>> {
    match given {
        true => value.to_py(py),
        false => Ok(py.None().into_bound(py)),
    }
}

fn optional_from_py<T: Field + Default>(value: &Bound<'_, PyAny>) -> PyResult<(bool, T)> {
    match value.is_none() {
        true => Ok((false, T::default())),
        false => Ok((true, T::from_py(value)?)),
    }
}

/// Bits of a filter field, whatever width the scene keeps them in.
fn bits<T: TryFrom<i64>>(value: &Bound<'_, PyAny>, field: &str) -> PyResult<T> {
    let wide: i64 = value.extract()?;
    T::try_from(wide).map_err(|_| {
        PyOverflowError::new_err(format!("{field} {wide} does not fit the scene's filter"))
    })
}

/// The fields each record shares with its dict under the same name, both ways.
macro_rules! plain_fields {
    ($to:ident, $from:ident, $columns:ident, $record:ty { $($field:ident),* $(,)? }) => {
        fn $to(py: Python<'_>, r: &$record, d: &Bound<'_, PyDict>) -> PyResult<()> {
            $(d.set_item(stringify!($field), Field::to_py(&r.$field, py)?)?;)*
            Ok(())
        }

        /// Takes the field named `key` from `value`; false when no plain field has that name.
        fn $from(r: &mut $record, key: &str, value: &Bound<'_, PyAny>) -> PyResult<bool> {
            match key {
                $(stringify!($field) => r.$field = Field::from_py(value)?,)*
                _ => return Ok(false),
            }
            Ok(true)
        }

        /// The fields' columns of `items`, for `Scene.arrays()`.
        fn $columns<'py>(
            py: Python<'py>,
            items: &[$record],
            columns: &mut Vec<Column<'py>>,
        ) -> PyResult<()> {
            $(columns.push(column(py, stringify!($field), items, |r| r.$field)?);)*
            Ok(())
        }
    };
}

plain_fields!(shape_to, shape_from, shape_columns, Shape { radius, position, is_loop });
plain_fields!(
    fixture_to,
    fixture_from,
    fixture_columns,
    Fixture { density, friction, restitution, is_sensor }
);
plain_fields!(
    body_to,
    body_from,
    body_columns,
    Body {
        position,
        angle,
        linear_velocity,
        angular_velocity,
        linear_damping,
        angular_damping,
        gravity_scale,
        inertia_scale,
        active,
        allow_sleep,
        awake,
        bullet,
        fixed_rotation,
    }
);
plain_fields!(
    joint_to,
    joint_from,
    joint_columns,
    Joint {
        local_anchor_a,
        local_anchor_b,
        local_axis_a,
        ground_anchor_a,
        ground_anchor_b,
        linear_offset,
        reference_angle,
        lower_limit,
        upper_limit,
        motor_speed,
        max_motor_torque,
        max_motor_force,
        length,
        frequency_hz,
        damping_ratio,
        length_a,
        length_b,
        max_length_a,
        max_length_b,
        ratio,
        max_force,
        max_torque,
        max_length,
        angular_offset,
        correction_factor,
        collide_connected,
        enable_limit,
        enable_motor,
    }
);

fn text(scene: &Scene, s: box2scene::Str) -> Option<String> {
    scene.text(s).map(str::to_owned)
}

fn vertices_to_py<'py>(py: Python<'py>, vertices: &[Vec2]) -> PyResult<Bound<'py, PyAny>> {
    let items = vertices.iter().map(|v| (v.x, v.y));
    Ok(pyo3::types::PyTuple::new(py, items)?.into_any())
}

fn shape_dict<'py>(py: Python<'py>, scene: &Scene, s: &Shape) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("kind", kind_name(&SHAPE_KINDS, s.kind, |k| k as u32))?;
    d.set_item("name", text(scene, s.name))?;
    shape_to(py, s, &d)?;
    d.set_item("vertices", vertices_to_py(py, scene.vertices(s))?)?;
    d.set_item("centroid", optional_to_py(py, s.centroid_given, &s.centroid)?)?;
    d.set_item("prev_vertex", optional_to_py(py, s.has_prev_vertex, &s.prev_vertex)?)?;
    d.set_item("next_vertex", optional_to_py(py, s.has_next_vertex, &s.next_vertex)?)?;
    Ok(d)
}

fn fixture_dict<'py>(py: Python<'py>, scene: &Scene, f: &Fixture) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("shape", index_to_py(py, f.shape)?)?;
    d.set_item("name", text(scene, f.name))?;
    fixture_to(py, f, &d)?;
    d.set_item("category_bits", u64::from(f.filter.category_bits))?;
    d.set_item("mask_bits", u64::from(f.filter.mask_bits))?;
    d.set_item("group_index", i64::from(f.filter.group_index))?;
    d.set_item("user_data", index_to_py(py, f.user_data)?)?;
    Ok(d)
}

fn body_dict<'py>(py: Python<'py>, scene: &Scene, b: &Body) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("kind", kind_name(&BODY_KINDS, b.kind, |k| k as u32))?;
    d.set_item("name", text(scene, b.name))?;
    body_to(py, b, &d)?;
    let m = &b.mass_data;
    d.set_item("mass", optional_to_py(py, m.mass_given, &m.mass)?)?;
    d.set_item("center", optional_to_py(py, m.center_given, &m.center)?)?;
    d.set_item("inertia", optional_to_py(py, m.inertia_given, &m.inertia)?)?;
    d.set_item("fixtures", pyo3::types::PyTuple::new(py, scene.body_fixtures(b))?)?;
    d.set_item("user_data", index_to_py(py, b.user_data)?)?;
    Ok(d)
}

fn joint_dict<'py>(py: Python<'py>, scene: &Scene, j: &Joint) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("kind", kind_name(&JOINT_KINDS, j.kind, |k| k as u32))?;
    d.set_item("name", text(scene, j.name))?;
    d.set_item("body_a", index_to_py(py, j.body_a)?)?;
    d.set_item("body_b", index_to_py(py, j.body_b)?)?;
    d.set_item("joint_a", index_to_py(py, j.joint_a)?)?;
    d.set_item("joint_b", index_to_py(py, j.joint_b)?)?;
    d.set_item("user_data", index_to_py(py, j.user_data)?)?;
    joint_to(py, j, &d)?;
    Ok(d)
}

fn user_data_dict<'py>(
    py: Python<'py>,
    scene: &Scene,
    u: &UserData,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("raw", text(scene, u.raw))?;
    d.set_item("type_name", text(scene, u.type_name))?;
    d.set_item("value", text(scene, u.value))?;
    Ok(d)
}

fn diagnostic_dict<'py>(
    py: Python<'py>,
    scene: &Scene,
    g: &Diagnostic,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("code", g.code().map_or_else(|| g.code.to_string(), |c| c.name().to_owned()))?;
    d.set_item(
        "severity",
        g.severity().map_or_else(|| g.severity.to_string(), |s| s.name().to_owned()),
    )?;
    d.set_item("line", g.line)?;
    d.set_item("column", g.column)?;
    d.set_item("byte_offset", g.byte_offset)?;
    d.set_item("message", text(scene, g.message))?;
    Ok(d)
}

/// A loaded or built scene, immutable.
#[pyclass(frozen, module = "box2scene._native")]
struct NativeScene {
    scene: Scene,
}

fn dicts<'py, T>(
    py: Python<'py>,
    scene: &Scene,
    items: &[T],
    dict: impl Fn(Python<'py>, &Scene, &T) -> PyResult<Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyList>> {
    let list = PyList::empty(py);
    for item in items {
        list.append(dict(py, scene, item)?)?;
    }
    Ok(list)
}

/// How `to_xml` and `write` write: `dialect` is a dialect's own name (`"box2scene"`,
/// `"aether"`, ...), or None for the one the scene remembers.
fn write_options(all_fields: bool, dialect: Option<&str>) -> PyResult<WriteOptions> {
    let dialect = match dialect {
        None => 0,
        Some(name) => Dialect::named(name).ok_or_else(|| {
            let names: Vec<&str> = Dialect::ALL.iter().map(|d| d.name()).collect();
            PyValueError::new_err(format!("unknown dialect {name:?} (one of {})", names.join(", ")))
        })? as u32,
    };
    Ok(WriteOptions { all_fields, dialect, ..WriteOptions::default() })
}

/// One column of `Scene.arrays()`: its name, NumPy's type of its items, how many items each
/// record has (2 for a vector), and the items, written once into bytes that NumPy reads
/// in place.
type Column<'py> = (&'static str, &'static str, usize, Bound<'py, PyBytes>);

/// A value of a column, as NumPy holds it: little-endian bytes, which its type code names,
/// so that the array reads the same on any machine.
trait ColumnValue {
    const DTYPE: &'static str;
    const WIDTH: usize;
    const SIZE: usize;
    fn put(&self, out: &mut [u8]);
}

impl ColumnValue for f32 {
    const DTYPE: &'static str = "<f4";
    const WIDTH: usize = 1;
    const SIZE: usize = 4;
    fn put(&self, out: &mut [u8]) {
        out.copy_from_slice(&self.to_le_bytes());
    }
}

impl ColumnValue for Vec2 {
    const DTYPE: &'static str = "<f4";
    const WIDTH: usize = 2;
    const SIZE: usize = 8;
    fn put(&self, out: &mut [u8]) {
        self.x.put(&mut out[..4]);
        self.y.put(&mut out[4..]);
    }
}

impl ColumnValue for bool {
    const DTYPE: &'static str = "|b1";
    const WIDTH: usize = 1;
    const SIZE: usize = 1;
    fn put(&self, out: &mut [u8]) {
        out[0] = u8::from(*self);
    }
}

impl ColumnValue for u32 {
    const DTYPE: &'static str = "<u4";
    const WIDTH: usize = 1;
    const SIZE: usize = 4;
    fn put(&self, out: &mut [u8]) {
        out.copy_from_slice(&self.to_le_bytes());
    }
}

impl ColumnValue for i16 {
    const DTYPE: &'static str = "<i2";
    const WIDTH: usize = 1;
    const SIZE: usize = 2;
    fn put(&self, out: &mut [u8]) {
        out.copy_from_slice(&self.to_le_bytes());
    }
}

/// An index into a sibling array, -1 where absent (`NONE`).
struct Index(u32);

impl ColumnValue for Index {
    const DTYPE: &'static str = "<i8";
    const WIDTH: usize = 1;
    const SIZE: usize = 8;
    fn put(&self, out: &mut [u8]) {
        let index = if self.0 == NONE { -1 } else { i64::from(self.0) };
        out.copy_from_slice(&index.to_le_bytes());
    }
}

/// A kind's Python name, as NumPy's fixed-width text (UTF-32, 11 characters: "unsupported").
struct KindName(String);

impl ColumnValue for KindName {
    const DTYPE: &'static str = "<U11";
    const WIDTH: usize = 1;
    const SIZE: usize = 44;
    fn put(&self, out: &mut [u8]) {
        for (c, slot) in self.0.chars().zip(out.chunks_exact_mut(4)) {
            slot.copy_from_slice(&u32::from(c).to_le_bytes());
        }
    }
}

fn column<'py, R, V: ColumnValue>(
    py: Python<'py>,
    name: &'static str,
    items: &[R],
    value: impl Fn(&R) -> V,
) -> PyResult<Column<'py>> {
    let bytes = PyBytes::new_with(py, items.len() * V::SIZE, |out| {
        for (slot, item) in out.chunks_exact_mut(V::SIZE).zip(items) {
            value(item).put(slot);
        }
        Ok(())
    })?;
    Ok((name, V::DTYPE, V::WIDTH, bytes))
}

fn shape_table<'py>(py: Python<'py>, shapes: &[Shape]) -> PyResult<Vec<Column<'py>>> {
    let kind = |s: &Shape| KindName(kind_name(&SHAPE_KINDS, s.kind, |k| k as u32));
    let mut columns = vec![column(py, "kind", shapes, kind)?];
    shape_columns(py, shapes, &mut columns)?;
    columns.extend([
        column(py, "vertices_first", shapes, |s| s.vertices.first)?,
        column(py, "vertices_count", shapes, |s| s.vertices.count)?,
        column(py, "centroid", shapes, |s| s.centroid)?,
        column(py, "centroid_given", shapes, |s| s.centroid_given)?,
        column(py, "prev_vertex", shapes, |s| s.prev_vertex)?,
        column(py, "has_prev_vertex", shapes, |s| s.has_prev_vertex)?,
        column(py, "next_vertex", shapes, |s| s.next_vertex)?,
        column(py, "has_next_vertex", shapes, |s| s.has_next_vertex)?,
    ]);
    Ok(columns)
}

fn fixture_table<'py>(py: Python<'py>, fixtures: &[Fixture]) -> PyResult<Vec<Column<'py>>> {
    let mut columns = vec![column(py, "shape", fixtures, |f| Index(f.shape))?];
    fixture_columns(py, fixtures, &mut columns)?;
    columns.extend([
        column(py, "category_bits", fixtures, |f| f.filter.category_bits)?,
        column(py, "mask_bits", fixtures, |f| f.filter.mask_bits)?,
        column(py, "group_index", fixtures, |f| f.filter.group_index)?,
        column(py, "user_data", fixtures, |f| Index(f.user_data))?,
    ]);
    Ok(columns)
}

fn body_table<'py>(py: Python<'py>, bodies: &[Body]) -> PyResult<Vec<Column<'py>>> {
    let kind = |b: &Body| KindName(kind_name(&BODY_KINDS, b.kind, |k| k as u32));
    let mut columns = vec![column(py, "kind", bodies, kind)?];
    body_columns(py, bodies, &mut columns)?;
    columns.extend([
        column(py, "mass", bodies, |b| b.mass_data.mass)?,
        column(py, "mass_given", bodies, |b| b.mass_data.mass_given)?,
        column(py, "center", bodies, |b| b.mass_data.center)?,
        column(py, "center_given", bodies, |b| b.mass_data.center_given)?,
        column(py, "inertia", bodies, |b| b.mass_data.inertia)?,
        column(py, "inertia_given", bodies, |b| b.mass_data.inertia_given)?,
        column(py, "fixtures_first", bodies, |b| b.fixtures.first)?,
        column(py, "fixtures_count", bodies, |b| b.fixtures.count)?,
        column(py, "user_data", bodies, |b| Index(b.user_data))?,
    ]);
    Ok(columns)
}

fn joint_table<'py>(py: Python<'py>, joints: &[Joint]) -> PyResult<Vec<Column<'py>>> {
    let kind = |j: &Joint| KindName(kind_name(&JOINT_KINDS, j.kind, |k| k as u32));
    let mut columns = vec![
        column(py, "kind", joints, kind)?,
        column(py, "body_a", joints, |j| Index(j.body_a))?,
        column(py, "body_b", joints, |j| Index(j.body_b))?,
        column(py, "joint_a", joints, |j| Index(j.joint_a))?,
        column(py, "joint_b", joints, |j| Index(j.joint_b))?,
        column(py, "user_data", joints, |j| Index(j.user_data))?,
    ];
    joint_columns(py, joints, &mut columns)?;
    Ok(columns)
}

/// The columns of one array of a scene (`"shapes"`, `"fixtures"`, `"bodies"`, `"joints"`,
/// or the pools `"vertices"` and `"fixture_ids"`, of one column named as the pool).
fn table<'py>(py: Python<'py>, scene: &Scene, array: &str) -> PyResult<Vec<Column<'py>>> {
    match array {
        "shapes" => shape_table(py, scene.shapes()),
        "fixtures" => fixture_table(py, scene.fixtures()),
        "bodies" => body_table(py, scene.bodies()),
        "joints" => joint_table(py, scene.joints()),
        "vertices" => Ok(vec![column(py, "vertices", scene.vertex_pool(), |v| *v)?]),
        "fixture_ids" => Ok(vec![column(py, "fixture_ids", scene.fixture_id_pool(), |i| *i)?]),
        _ => Err(PyValueError::new_err(format!("a scene has no array {array:?}"))),
    }
}

#[pymethods]
impl NativeScene {
    fn version(&self) -> u32 {
        self.scene.version()
    }
    fn gravity(&self) -> Option<(f32, f32)> {
        self.scene.gravity().map(|g| (g.x, g.y))
    }
    fn shapes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        dicts(py, &self.scene, self.scene.shapes(), shape_dict)
    }
    fn fixtures<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        dicts(py, &self.scene, self.scene.fixtures(), fixture_dict)
    }
    fn bodies<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        dicts(py, &self.scene, self.scene.bodies(), body_dict)
    }
    fn joints<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        dicts(py, &self.scene, self.scene.joints(), joint_dict)
    }
    fn user_data<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        dicts(py, &self.scene, self.scene.user_data(), user_data_dict)
    }
    fn diagnostics<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        dicts(py, &self.scene, self.scene.diagnostics(), diagnostic_dict)
    }
    fn vertices<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        vertices_to_py(py, self.scene.vertex_pool())
    }
    fn fixture_ids(&self) -> Vec<u32> {
        self.scene.fixture_id_pool().to_vec()
    }
    /// The dialect the scene remembers (that of its file; box2scene's for a built one).
    fn dialect(&self) -> &'static str {
        self.scene.dialect().name()
    }
    #[pyo3(signature = (all_fields, dialect=None))]
    fn to_xml(&self, py: Python<'_>, all_fields: bool, dialect: Option<&str>) -> PyResult<String> {
        let options = write_options(all_fields, dialect)?;
        self.scene.to_xml(&options).map_err(|e| error(py, e))
    }
    #[pyo3(signature = (path, all_fields, dialect=None))]
    fn write(
        &self,
        py: Python<'_>,
        path: PathBuf,
        all_fields: bool,
        dialect: Option<&str>,
    ) -> PyResult<()> {
        let options = write_options(all_fields, dialect)?;
        py.detach(|| box2scene::write_path(&self.scene, &path, &options)).map_err(|e| error(py, e))
    }
    fn to_json(&self) -> String {
        self.scene.to_json()
    }
    fn columns<'py>(&self, py: Python<'py>, array: &str) -> PyResult<Vec<Column<'py>>> {
        table(py, &self.scene, array)
    }
    /// Whether both scenes hold the same values: every field of every record, as the
    /// library's JSON dump gives them.
    fn same_records(&self, py: Python<'_>, other: &NativeScene) -> bool {
        std::ptr::eq(self, other) || py.detach(|| self.scene.to_json() == other.scene.to_json())
    }
    /// The library's picture (`box2scene::draw`): poses as (x, y, angle), one per body;
    /// samples of one point per body each. The library takes the samples end to end, where
    /// only their total shows: each sample's length is checked here, where they are apart,
    /// since a sample one point short and another one long would put every point between
    /// them on the wrong body.
    #[pyo3(signature = (title, start, end, joints_created, trajectories))]
    fn draw_svg(
        &self,
        py: Python<'_>,
        title: &str,
        start: Option<Vec<(f32, f32, f32)>>,
        end: Option<Vec<(f32, f32, f32)>>,
        joints_created: Option<Vec<bool>>,
        trajectories: Vec<Vec<Bound<'_, PyAny>>>,
    ) -> PyResult<String> {
        let poses = |poses: Option<Vec<(f32, f32, f32)>>| {
            let pose = |(x, y, angle)| Pose { position: Vec2 { x, y }, angle };
            poses.map(|poses| poses.into_iter().map(pose).collect::<Vec<Pose>>())
        };
        let (start, end) = (poses(start), poses(end));
        let bodies = self.scene.bodies().len();
        let ragged = trajectories.iter().enumerate().find(|(_, sample)| sample.len() != bodies);
        if let Some((index, sample)) = ragged {
            let message = format!(
                "trajectories sample {index} holds {} points for {bodies} bodies",
                sample.len()
            );
            let invalid = box2scene::Error {
                code: Code::InvalidArgument,
                position: Position::default(),
                message,
            };
            return Err(error(py, invalid));
        }
        let trajectories =
            trajectories.iter().flatten().map(vec2_from_py).collect::<PyResult<Vec<Vec2>>>()?;
        let picture = Picture {
            title,
            start: start.as_deref(),
            end: end.as_deref(),
            joints: joints_created.as_deref(),
            trajectories: &trajectories,
        };
        box2scene::draw::svg(&self.scene, &picture).map_err(|e| error(py, e))
    }
}

fn load_options(options: &Bound<'_, PyDict>) -> PyResult<LoadOptions> {
    let mut o = LoadOptions::default();
    for (key, value) in options.iter() {
        let key: String = key.extract()?;
        match key.as_str() {
            "strict" => o.strict = value.extract()?,
            "max_input_bytes" => o.max_input_bytes = value.extract()?,
            "max_elements" => o.max_elements = value.extract()?,
            "max_text_bytes" => o.max_text_bytes = value.extract()?,
            "max_depth" => o.max_depth = value.extract()?,
            "max_chain_vertices" => o.max_chain_vertices = value.extract()?,
            "threads" => o.threads = value.extract()?,
            _ => return Err(PyKeyError::new_err(format!("unknown load option {key:?}"))),
        }
    }
    Ok(o)
}

/// Loads a scene from the bytes of a file.
#[pyfunction]
fn load_bytes(py: Python<'_>, data: &[u8], options: &Bound<'_, PyDict>) -> PyResult<NativeScene> {
    let options = load_options(options)?;
    let loaded = py.detach(|| box2scene::load(data, &options));
    loaded.map(|scene| NativeScene { scene }).map_err(|e| error(py, e))
}

/// Loads a scene from a file.
#[pyfunction]
fn load_path(py: Python<'_>, path: PathBuf, options: &Bound<'_, PyDict>) -> PyResult<NativeScene> {
    let options = load_options(options)?;
    let file = std::fs::File::open(&path).map_err(|e| cannot_open(py, &path, &e))?;
    // A directory opens, and only reading it fails: an empty read of it gets the system's
    // reason (EISDIR), as a load's first read would.
    if file.metadata().is_ok_and(|m| m.is_dir()) {
        std::io::Read::read(&mut &file, &mut []).map_err(|e| cannot_open(py, &path, &e))?;
    }
    let loaded = py.detach(|| box2scene::load_file(file, &path, &options));
    loaded.map(|scene| NativeScene { scene }).map_err(|e| error(py, e))
}

/// The package's error for a file that cannot be opened: a `box2scene.Error` that is also
/// the `OSError` Python raises for the system's reason, with the library's message.
fn cannot_open(py: Python<'_>, path: &std::path::Path, e: &std::io::Error) -> PyErr {
    let message = box2scene::Error::cannot_read(path, e).message;
    let errno = e.raw_os_error().unwrap_or_default();
    let raised = py
        .import("box2scene._error")
        .and_then(|m| m.getattr("cannot_open"))
        .and_then(|cannot_open| cannot_open.call1((errno, path.as_os_str(), message)));
    match raised {
        Ok(value) => PyErr::from_value(value),
        Err(e) => e,
    }
}

/// The defaults of a record of `record` ("shape", "fixture", "body", "joint") and `kind`, as
/// the dict a loaded record of that kind has.
#[pyfunction]
#[pyo3(signature = (record, kind=None))]
fn defaults<'py>(
    py: Python<'py>,
    record: &str,
    kind: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    let empty = Builder::new().finish();
    let kind = kind.unwrap_or_default();
    let d = match record {
        "shape" => shape_dict(py, &empty, &Shape::new(kind_of(&SHAPE_KINDS, kind, "shape")?))?,
        "fixture" => fixture_dict(py, &empty, &Fixture::default())?,
        "body" => body_dict(py, &empty, &Body::new(kind_of(&BODY_KINDS, kind, "body")?))?,
        "joint" => joint_dict(py, &empty, &Joint::new(kind_of(&JOINT_KINDS, kind, "joint")?))?,
        _ => return Err(PyValueError::new_err(format!("no record is called {record:?}"))),
    };
    Ok(d)
}

/// Reads the fields of `record` into `r`: those `plain` takes and those `special` takes;
/// any other key is an error.
fn fields_into<R>(
    record: &Bound<'_, PyDict>,
    r: &mut R,
    what: &str,
    plain: impl Fn(&mut R, &str, &Bound<'_, PyAny>) -> PyResult<bool>,
    mut special: impl FnMut(&mut R, &str, &Bound<'_, PyAny>) -> PyResult<bool>,
) -> PyResult<()> {
    for (key, value) in record.iter() {
        let key: String = key.extract()?;
        let taken = plain(r, &key, &value)? || special(r, &key, &value)?;
        if !taken {
            return Err(PyKeyError::new_err(format!("a {what} has no field {key:?}")));
        }
    }
    Ok(())
}

fn kind_field(record: &Bound<'_, PyDict>) -> PyResult<String> {
    match record.get_item("kind")? {
        Some(kind) => kind.extract(),
        None => Err(PyKeyError::new_err("the record has no kind")),
    }
}

/// A shape record's dict as the library's shape, name and vertices.
fn shape_record(record: &Bound<'_, PyDict>) -> PyResult<(Shape, Option<String>, Vec<Vec2>)> {
    let mut shape = Shape::new(kind_of(&SHAPE_KINDS, &kind_field(record)?, "shape")?);
    let (mut name, mut vertices) = (None::<String>, Vec::new());
    fields_into(record, &mut shape, "shape", shape_from, |s, key, value| {
        match key {
            "kind" => {}
            "name" => name = value.extract()?,
            "vertices" => {
                for v in value.try_iter()? {
                    vertices.push(Vec2::from_py(&v?)?);
                }
            }
            "centroid" => (s.centroid_given, s.centroid) = optional_from_py(value)?,
            "prev_vertex" => (s.has_prev_vertex, s.prev_vertex) = optional_from_py(value)?,
            "next_vertex" => (s.has_next_vertex, s.next_vertex) = optional_from_py(value)?,
            _ => return Ok(false),
        }
        Ok(true)
    })?;
    Ok((shape, name, vertices))
}

/// A fixture record's dict as the library's fixture and name.
fn fixture_record(record: &Bound<'_, PyDict>) -> PyResult<(Fixture, Option<String>)> {
    let mut fixture = Fixture::default();
    let mut name = None::<String>;
    fields_into(record, &mut fixture, "fixture", fixture_from, |f, key, value| {
        match key {
            "name" => name = value.extract()?,
            "shape" => f.shape = index_from_py(value)?,
            "user_data" => f.user_data = index_from_py(value)?,
            "category_bits" => f.filter.category_bits = bits(value, "category_bits")?,
            "mask_bits" => f.filter.mask_bits = bits(value, "mask_bits")?,
            "group_index" => f.filter.group_index = bits(value, "group_index")?,
            _ => return Ok(false),
        }
        Ok(true)
    })?;
    Ok((fixture, name))
}

/// A body record's dict as the library's body, name and fixtures.
fn body_record(record: &Bound<'_, PyDict>) -> PyResult<(Body, Option<String>, Vec<u32>)> {
    let mut body = Body::new(kind_of(&BODY_KINDS, &kind_field(record)?, "body")?);
    let (mut name, mut fixtures) = (None::<String>, Vec::new());
    fields_into(record, &mut body, "body", body_from, |b, key, value| {
        let m = &mut b.mass_data;
        match key {
            "kind" => {}
            "name" => name = value.extract()?,
            "fixtures" => fixtures = value.extract()?,
            "user_data" => b.user_data = index_from_py(value)?,
            "mass" => (m.mass_given, m.mass) = optional_from_py(value)?,
            "center" => (m.center_given, m.center) = optional_from_py(value)?,
            "inertia" => (m.inertia_given, m.inertia) = optional_from_py(value)?,
            _ => return Ok(false),
        }
        Ok(true)
    })?;
    Ok((body, name, fixtures))
}

/// A joint record's dict as the library's joint and name.
fn joint_record(record: &Bound<'_, PyDict>) -> PyResult<(Joint, Option<String>)> {
    let mut joint = Joint::new(kind_of(&JOINT_KINDS, &kind_field(record)?, "joint")?);
    let mut name = None::<String>;
    fields_into(record, &mut joint, "joint", joint_from, |j, key, value| {
        match key {
            "kind" => {}
            "name" => name = value.extract()?,
            "body_a" => j.body_a = index_from_py(value)?,
            "body_b" => j.body_b = index_from_py(value)?,
            "joint_a" => j.joint_a = index_from_py(value)?,
            "joint_b" => j.joint_b = index_from_py(value)?,
            "user_data" => j.user_data = index_from_py(value)?,
            _ => return Ok(false),
        }
        Ok(true)
    })?;
    Ok((joint, name))
}

/// A scene under construction, in the library's builder.
#[pyclass(frozen, module = "box2scene._native")]
struct NativeBuilder {
    builder: Mutex<Option<Builder>>,
}

impl NativeBuilder {
    fn with<T>(
        &self,
        py: Python<'_>,
        f: impl FnOnce(&mut Builder) -> Result<T, box2scene::Error>,
    ) -> PyResult<T> {
        let mut guard =
            self.builder.lock().map_err(|_| PyRuntimeError::new_err("the builder is poisoned"))?;
        let builder =
            guard.as_mut().ok_or_else(|| PyRuntimeError::new_err("the builder is finished"))?;
        f(builder).map_err(|e| error(py, e))
    }
}

#[pymethods]
impl NativeBuilder {
    #[new]
    fn new() -> NativeBuilder {
        NativeBuilder { builder: Mutex::new(Some(Builder::new())) }
    }

    fn set_gravity(&self, py: Python<'_>, gravity: Option<Bound<'_, PyAny>>) -> PyResult<()> {
        let gravity = gravity.as_ref().map(vec2_from_py).transpose()?;
        self.with(py, |b| b.set_gravity(gravity))
    }

    #[pyo3(signature = (raw=None, type_name=None, value=None))]
    fn add_user_data(
        &self,
        py: Python<'_>,
        raw: Option<&str>,
        type_name: Option<&str>,
        value: Option<&str>,
    ) -> PyResult<u32> {
        self.with(py, |b| b.add_user_data(raw, type_name, value))
    }

    fn add_shape(&self, py: Python<'_>, record: &Bound<'_, PyDict>) -> PyResult<u32> {
        let (shape, name, vertices) = shape_record(record)?;
        self.with(py, |b| b.add_shape(&shape, name.as_deref(), &vertices))
    }

    fn add_fixture(&self, py: Python<'_>, record: &Bound<'_, PyDict>) -> PyResult<u32> {
        let (fixture, name) = fixture_record(record)?;
        self.with(py, |b| b.add_fixture(&fixture, name.as_deref()))
    }

    fn add_body(&self, py: Python<'_>, record: &Bound<'_, PyDict>) -> PyResult<u32> {
        let (body, name, fixtures) = body_record(record)?;
        self.with(py, |b| b.add_body(&body, name.as_deref(), &fixtures))
    }

    fn add_joint(&self, py: Python<'_>, record: &Bound<'_, PyDict>) -> PyResult<u32> {
        let (joint, name) = joint_record(record)?;
        self.with(py, |b| b.add_joint(&joint, name.as_deref()))
    }

    /// A builder holding everything `scene` holds, the text its file held beyond the
    /// records too (`Builder::from_scene`).
    #[staticmethod]
    fn from_scene(scene: &NativeScene) -> NativeBuilder {
        NativeBuilder { builder: Mutex::new(Some(Builder::from_scene(&scene.scene))) }
    }

    fn replace_shape(
        &self,
        py: Python<'_>,
        index: u32,
        record: &Bound<'_, PyDict>,
    ) -> PyResult<()> {
        let (shape, name, vertices) = shape_record(record)?;
        self.with(py, |b| b.replace_shape(index, &shape, name.as_deref(), &vertices))
    }

    fn replace_fixture(
        &self,
        py: Python<'_>,
        index: u32,
        record: &Bound<'_, PyDict>,
    ) -> PyResult<()> {
        let (fixture, name) = fixture_record(record)?;
        self.with(py, |b| b.replace_fixture(index, &fixture, name.as_deref()))
    }

    fn replace_body(&self, py: Python<'_>, index: u32, record: &Bound<'_, PyDict>) -> PyResult<()> {
        let (body, name, fixtures) = body_record(record)?;
        self.with(py, |b| b.replace_body(index, &body, name.as_deref(), &fixtures))
    }

    fn replace_joint(
        &self,
        py: Python<'_>,
        index: u32,
        record: &Bound<'_, PyDict>,
    ) -> PyResult<()> {
        let (joint, name) = joint_record(record)?;
        self.with(py, |b| b.replace_joint(index, &joint, name.as_deref()))
    }

    fn remove_shape(&self, py: Python<'_>, index: u32) -> PyResult<()> {
        self.with(py, |b| b.remove_shape(index))
    }

    fn remove_fixture(&self, py: Python<'_>, index: u32) -> PyResult<()> {
        self.with(py, |b| b.remove_fixture(index))
    }

    fn remove_body(&self, py: Python<'_>, index: u32) -> PyResult<()> {
        self.with(py, |b| b.remove_body(index))
    }

    fn remove_joint(&self, py: Python<'_>, index: u32) -> PyResult<()> {
        self.with(py, |b| b.remove_joint(index))
    }

    fn finish(&self) -> PyResult<NativeScene> {
        let mut guard =
            self.builder.lock().map_err(|_| PyRuntimeError::new_err("the builder is poisoned"))?;
        let builder =
            guard.take().ok_or_else(|| PyRuntimeError::new_err("the builder is finished"))?;
        Ok(NativeScene { scene: builder.finish() })
    }
}

/// The widths, in bits, of the scene's filter categories and masks and of its groups.
#[pyfunction]
fn filter_widths() -> (usize, usize) {
    let f = box2scene::Filter::default();
    (8 * size_of_val(&f.category_bits), 8 * size_of_val(&f.group_index))
}

/// Single-precision math as the engines' C code does it (the C library's `cosf`, `sinf` and
/// `atan2f`, which Rust's `f32` methods call), for the builders' values that must match the
/// C adapters bit for bit.
#[pyfunction]
fn cosf(x: f32) -> f32 {
    x.cos()
}

#[pyfunction]
fn sinf(x: f32) -> f32 {
    x.sin()
}

#[pyfunction]
fn atan2f(y: f32, x: f32) -> f32 {
    y.atan2(x)
}

/// The float next to `x` in the direction of `toward` (C's `nextafterf`).
#[pyfunction]
fn nextafterf(x: f32, toward: f32) -> f32 {
    match x.partial_cmp(&toward) {
        Some(std::cmp::Ordering::Less) => x.next_up(),
        Some(std::cmp::Ordering::Greater) => x.next_down(),
        Some(std::cmp::Ordering::Equal) => toward,
        None => f32::NAN,
    }
}

/// The engine version a Python name means.
fn engine_named(engine: &str) -> PyResult<box2scene::Engine> {
    let Some((_, engine)) = ENGINES.iter().find(|(name, _)| *name == engine) else {
        let names: Vec<&str> = ENGINES.iter().map(|(n, _)| *n).collect();
        return Err(PyValueError::new_err(format!(
            "unknown engine {engine:?} (one of {})",
            names.join(", ")
        )));
    };
    Ok(*engine)
}

const ENGINES: [(&str, box2scene::Engine); 4] = [
    ("box2d-2.3", box2scene::Engine::Box2d23),
    ("box2d-2.4", box2scene::Engine::Box2d24),
    ("box2d-3.1", box2scene::Engine::Box2d31),
    ("box2d-3.2", box2scene::Engine::Box2d32),
];

/// The library's working range of an engine version (`"box2d-2.3"` as pybox2d holds it,
/// `"box2d-3.1"` as pyb2d3 does): every bound by its C field's name, the floats as the
/// library holds them (f32, widened exactly).
#[pyfunction]
fn working_range<'py>(py: Python<'py>, engine: &str) -> PyResult<Bound<'py, PyDict>> {
    let r = engine_named(engine)?.working_range();
    let d = PyDict::new(py);
    for (name, value) in r.bounds() {
        d.set_item(name, f64::from(value))?;
    }
    d.set_item("name_bytes", r.name_bytes)?;
    d.set_item("friction_at_anchors", r.friction_at_anchors)?;
    d.set_item("prismatic_lever_to_b", r.prismatic_lever_to_b)?;
    Ok(d)
}

/// The library's plan of `scene` for `engine` (a name of `working_range`), placed at
/// `placement` ((x, y), (cos, sin)), in a world of `gravity` whose maximum linear speed is
/// `max_linear_speed` (FLT_MAX where the engine has none).
#[pyfunction]
#[pyo3(signature = (scene, engine, gravity, max_linear_speed=f32::MAX, placement=((0.0, 0.0), (1.0, 0.0))))]
fn make_plan(
    py: Python<'_>,
    scene: &NativeScene,
    engine: &str,
    gravity: (f32, f32),
    max_linear_speed: f32,
    placement: ((f32, f32), (f32, f32)),
) -> PyResult<plan::NativePlan> {
    let options = plan::options(engine_named(engine)?, placement, gravity, max_linear_speed);
    plan::make(py, &scene.scene, &options)
}

/// The scene's gravity where `engine` holds it (within its working range), else None.
#[pyfunction]
fn world_gravity(scene: &NativeScene, engine: &str) -> PyResult<Option<(f32, f32)>> {
    let gravity = box2scene::plan::world_gravity(&scene.scene, engine_named(engine)?);
    Ok(gravity.map(|g| (g.x, g.y)))
}

/// The scene of what a builder read of a live world of `engine` (dicts in the plan's terms:
/// each body with its shapes, the joints, the scene joints the build skipped), labelled from
/// `level`, the scene the world was built from; and the reports as
/// (code, object, index, name, message) tuples.
#[pyfunction]
#[pyo3(signature = (engine, gravity, bodies, joints, skipped=Vec::new(), level=None))]
fn capture(
    py: Python<'_>,
    engine: &str,
    gravity: (f32, f32),
    bodies: Vec<held::BodyIn>,
    joints: Vec<held::JointIn>,
    skipped: Vec<u32>,
    level: Option<&NativeScene>,
) -> PyResult<(NativeScene, Vec<plan::ReportTuple>)> {
    let level = level.map(|l| &l.scene);
    let captured =
        held::capture(engine_named(engine)?, gravity, &bodies, &joints, &skipped, level)?;
    captured.map(|(scene, reports)| (NativeScene { scene }, reports)).map_err(|e| error(py, e))
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<NativeScene>()?;
    m.add_class::<NativeBuilder>()?;
    m.add_function(wrap_pyfunction!(load_bytes, m)?)?;
    m.add_function(wrap_pyfunction!(load_path, m)?)?;
    m.add_function(wrap_pyfunction!(defaults, m)?)?;
    m.add_function(wrap_pyfunction!(filter_widths, m)?)?;
    m.add_function(wrap_pyfunction!(cosf, m)?)?;
    m.add_function(wrap_pyfunction!(sinf, m)?)?;
    m.add_function(wrap_pyfunction!(atan2f, m)?)?;
    m.add_function(wrap_pyfunction!(nextafterf, m)?)?;
    m.add_function(wrap_pyfunction!(working_range, m)?)?;
    m.add_function(wrap_pyfunction!(make_plan, m)?)?;
    m.add_function(wrap_pyfunction!(world_gravity, m)?)?;
    m.add_function(wrap_pyfunction!(capture, m)?)?;
    m.add_class::<plan::NativePlan>()?;
    m.add_class::<plan::NativePlanBody>()?;
    m.add_class::<plan::NativePlanShape>()?;
    m.add_class::<plan::NativePlanJoint>()?;
    Ok(())
}
