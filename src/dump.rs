//! The scene as JSON, for golden-file tests and for tools that want the data without the
//! C ABI. Every field of every record is written, in a fixed order, with pool ranges
//! resolved (vertices, fixture IDs, user data inline) and absent values as `null`, so that
//! two dumps differ exactly where the scenes differ.
//!
//! The layout is chosen for diffs: two-space indentation, one record per few lines, related
//! fields of a record on one line. Written by hand because the crate has no JSON dependency
//! and needs none for this.
#![forbid(unsafe_code)]

use crate::error::{Code, Severity};
use crate::escape::json_string;
use crate::scene::Diagnostic;
use crate::scene::joints::{self, Value};
use crate::scene::{
    Body, BodyKind, Fixture, Joint, JointKind, MassData, NONE, Scene, Shape, ShapeKind, Str, Vec2,
};

/// A `"key": value` pair, the value already JSON text.
type Field = (&'static str, String);
/// The fields a record shows on one line.
type Line = Vec<Field>;

/// The scene as a JSON document ending with a newline, so that it is a file as it is.
pub fn to_json(scene: &Scene) -> String {
    let lines = vec![
        vec![("version", scene.version().to_string())],
        vec![("dialect", format!("\"{}\"", scene.dialect().name()))],
        vec![("gravity", optional_vec2(scene.gravity()))],
        vec![("shapes", records(scene.shapes().iter().map(|s| shape(scene, s))))],
        vec![("fixtures", records(scene.fixtures().iter().map(|f| fixture(scene, f))))],
        vec![("bodies", records(scene.bodies().iter().map(|b| body(scene, b))))],
        vec![("joints", records(scene.joints().iter().map(|j| joint(scene, j))))],
        vec![("diagnostics", diagnostics(scene))],
    ];
    let mut json = object(&lines, 0);
    json.push('\n');
    json
}

fn shape(scene: &Scene, s: &Shape) -> Vec<Line> {
    let kind = s.kind().map(ShapeKind::name);
    vec![
        vec![("kind", enum_text(kind, s.kind)), ("name", text(scene, s.name))],
        vec![("radius", float(s.radius)), ("position", vec2(s.position))],
        vec![("vertices", list(scene.vertices(s).iter().map(|&v| vec2(v))))],
        vec![
            ("centroid", given_vec2(s.centroid_given, s.centroid)),
            ("prev_vertex", given_vec2(s.has_prev_vertex, s.prev_vertex)),
            ("next_vertex", given_vec2(s.has_next_vertex, s.next_vertex)),
            ("is_loop", s.is_loop.to_string()),
        ],
    ]
}

fn fixture(scene: &Scene, f: &Fixture) -> Vec<Line> {
    let filter = [
        ("category_bits", f.filter.category_bits.to_string()),
        ("mask_bits", f.filter.mask_bits.to_string()),
        ("group_index", f.filter.group_index.to_string()),
    ];
    vec![
        vec![("shape", index(f.shape)), ("name", text(scene, f.name))],
        vec![
            ("density", float(f.density)),
            ("friction", float(f.friction)),
            ("restitution", float(f.restitution)),
            ("is_sensor", f.is_sensor.to_string()),
        ],
        vec![("filter", inline_object(&filter))],
        vec![("user_data", user_data(scene, f.user_data))],
    ]
}

fn body(scene: &Scene, b: &Body) -> Vec<Line> {
    let kind = b.kind().map(BodyKind::name);
    let fixtures = list(scene.body_fixtures(b).iter().map(|&id| index(id)));
    vec![
        vec![("kind", enum_text(kind, b.kind)), ("name", text(scene, b.name))],
        vec![
            ("active", b.active.to_string()),
            ("allow_sleep", b.allow_sleep.to_string()),
            ("awake", b.awake.to_string()),
            ("bullet", b.bullet.to_string()),
            ("fixed_rotation", b.fixed_rotation.to_string()),
        ],
        vec![
            ("position", vec2(b.position)),
            ("angle", float(b.angle)),
            ("linear_velocity", vec2(b.linear_velocity)),
            ("angular_velocity", float(b.angular_velocity)),
        ],
        vec![
            ("linear_damping", float(b.linear_damping)),
            ("angular_damping", float(b.angular_damping)),
            ("gravity_scale", float(b.gravity_scale)),
            ("inertia_scale", float(b.inertia_scale)),
        ],
        vec![("mass_data", mass_data(&b.mass_data))],
        vec![("fixtures", fixtures)],
        vec![("user_data", user_data(scene, b.user_data))],
    ]
}

/// Each datum the file gave, `null` for the ones it did not (which keep Box2D's values).
fn mass_data(m: &MassData) -> String {
    let given_float = |given: bool, value: f32| if given { float(value) } else { null() };
    inline_object(&[
        ("mass", given_float(m.mass_given, m.mass)),
        ("center", given_vec2(m.center_given, m.center)),
        ("inertia", given_float(m.inertia_given, m.inertia)),
    ])
}

fn joint(scene: &Scene, j: &Joint) -> Vec<Line> {
    let kind = j.kind().map(JointKind::name);
    let mut lines = vec![vec![
        ("kind", enum_text(kind, j.kind)),
        ("name", text(scene, j.name)),
        ("body_a", index(j.body_a)),
        ("body_b", index(j.body_b)),
        ("collide_connected", j.collide_connected.to_string()),
    ]];
    let mut j = *j;
    for group in joints::FIELD_GROUPS {
        lines.push(group.iter().map(|field| (field.name, value(&mut j, field.value))).collect());
    }
    lines.push(vec![("user_data", user_data(scene, j.user_data))]);
    lines
}

/// The JSON text of a joint's field.
fn value(j: &mut Joint, value: Value) -> String {
    match value {
        Value::Vector(at) => vec2(*at(j)),
        Value::Float(at) | Value::NonNegative(at) => float(*at(j)),
        Value::Flag(at) => at(j).to_string(),
        Value::JointIndex(at) => index(*at(j)),
    }
}

fn user_data(scene: &Scene, at: u32) -> String {
    scene.user_data_at(at).map_or_else(null, |u| {
        inline_object(&[
            ("raw", text(scene, u.raw)),
            ("type_name", text(scene, u.type_name)),
            ("value", text(scene, u.value)),
        ])
    })
}

/// One diagnostic per line: they are short and a reader scans them as a list.
fn diagnostics(scene: &Scene) -> String {
    let one = |d: &Diagnostic| {
        inline_object(&[
            ("severity", enum_text(d.severity().map(Severity::name), d.severity)),
            ("code", enum_text(d.code().map(Code::name), d.code)),
            ("line", d.line.to_string()),
            ("column", d.column.to_string()),
            ("byte_offset", d.byte_offset.to_string()),
            ("message", text(scene, d.message)),
        ])
    };
    let items: Vec<String> = scene.diagnostics().iter().map(one).collect();
    array(&items, 1)
}

/// An enumeration by its name; a value with no name (which a loaded scene never holds)
/// as its number, so that the dump shows it rather than hiding it.
fn enum_text(name: Option<&'static str>, value: u32) -> String {
    name.map_or_else(|| value.to_string(), json_string)
}

/// An array of records, one after another, each over its few lines.
fn records(items: impl Iterator<Item = Vec<Line>>) -> String {
    let items: Vec<String> = items.map(|lines| object(&lines, 2)).collect();
    array(&items, 1)
}

/// `{`, each line of fields indented one level deeper than `depth`, `}` at `depth`.
fn object(lines: &[Line], depth: usize) -> String {
    let inner = indent(depth + 1);
    let lines: Vec<String> = lines.iter().map(|line| format!("{inner}{}", fields(line))).collect();
    format!("{{\n{}\n{}}}", lines.join(",\n"), indent(depth))
}

/// Items one per line, indented one level deeper than `depth`; `[]` when there are none.
fn array(items: &[String], depth: usize) -> String {
    if items.is_empty() {
        return "[]".to_owned();
    }
    let inner = indent(depth + 1);
    let items: Vec<String> = items.iter().map(|item| format!("{inner}{item}")).collect();
    format!("[\n{}\n{}]", items.join(",\n"), indent(depth))
}

fn inline_object(pairs: &[Field]) -> String {
    format!("{{{}}}", fields(pairs))
}

fn fields(fields: &[Field]) -> String {
    let pairs: Vec<String> =
        fields.iter().map(|(key, value)| format!("{}: {value}", json_string(key))).collect();
    pairs.join(", ")
}

/// Items on one line: vertex lists and fixture IDs read best as a single row.
fn list(items: impl Iterator<Item = String>) -> String {
    format!("[{}]", items.collect::<Vec<_>>().join(", "))
}

fn indent(depth: usize) -> String {
    "  ".repeat(depth)
}

fn null() -> String {
    "null".to_owned()
}

/// A cross reference: the index, or `null` for [`NONE`].
fn index(value: u32) -> String {
    if value == NONE { null() } else { value.to_string() }
}

fn text(scene: &Scene, s: Str) -> String {
    scene.text(s).map_or_else(null, json_string)
}

fn vec2(v: Vec2) -> String {
    format!("[{}, {}]", float(v.x), float(v.y))
}

fn optional_vec2(v: Option<Vec2>) -> String {
    v.map_or_else(null, vec2)
}

/// An optional override: absent is `null`, never a zero vector (spec: absent is not zero).
fn given_vec2(given: bool, v: Vec2) -> String {
    optional_vec2(given.then_some(v))
}

/// The shortest text that reads back to the same `f32` (Rust's `Debug` form, which is also
/// valid JSON: `0.2`, `1.0`, `-0.0`, `8.369571e-36`). JSON has no NaN or infinity; a loaded
/// scene holds none, and `null` keeps the document valid should one ever appear.
fn float(value: f32) -> String {
    if value.is_finite() { format!("{value:?}") } else { null() }
}

#[cfg(test)]
mod tests;
