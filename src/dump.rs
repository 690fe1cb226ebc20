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
    let kind = s.kind().map(shape_kind_name);
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
    let kind = b.kind().map(body_kind_name);
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
    let kind = j.kind().map(joint_kind_name);
    vec![
        vec![
            ("kind", enum_text(kind, j.kind)),
            ("name", text(scene, j.name)),
            ("body_a", index(j.body_a)),
            ("body_b", index(j.body_b)),
            ("collide_connected", j.collide_connected.to_string()),
        ],
        vec![("joint_a", index(j.joint_a)), ("joint_b", index(j.joint_b))],
        vec![
            ("local_anchor_a", vec2(j.local_anchor_a)),
            ("local_anchor_b", vec2(j.local_anchor_b)),
            ("local_axis_a", vec2(j.local_axis_a)),
        ],
        vec![
            ("ground_anchor_a", vec2(j.ground_anchor_a)),
            ("ground_anchor_b", vec2(j.ground_anchor_b)),
            ("linear_offset", vec2(j.linear_offset)),
        ],
        vec![
            ("reference_angle", float(j.reference_angle)),
            ("enable_limit", j.enable_limit.to_string()),
            ("lower_limit", float(j.lower_limit)),
            ("upper_limit", float(j.upper_limit)),
        ],
        vec![
            ("enable_motor", j.enable_motor.to_string()),
            ("motor_speed", float(j.motor_speed)),
            ("max_motor_torque", float(j.max_motor_torque)),
            ("max_motor_force", float(j.max_motor_force)),
        ],
        vec![
            ("length", float(j.length)),
            ("frequency_hz", float(j.frequency_hz)),
            ("damping_ratio", float(j.damping_ratio)),
        ],
        vec![
            ("length_a", float(j.length_a)),
            ("length_b", float(j.length_b)),
            ("max_length_a", float(j.max_length_a)),
            ("max_length_b", float(j.max_length_b)),
            ("ratio", float(j.ratio)),
        ],
        vec![
            ("max_force", float(j.max_force)),
            ("max_torque", float(j.max_torque)),
            ("max_length", float(j.max_length)),
            ("angular_offset", float(j.angular_offset)),
            ("correction_factor", float(j.correction_factor)),
        ],
        vec![("user_data", user_data(scene, j.user_data))],
    ]
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

fn shape_kind_name(kind: ShapeKind) -> &'static str {
    match kind {
        ShapeKind::Circle => "circle",
        ShapeKind::Polygon => "polygon",
        ShapeKind::Edge => "edge",
        ShapeKind::Chain => "chain",
    }
}

fn body_kind_name(kind: BodyKind) -> &'static str {
    match kind {
        BodyKind::Static => "static",
        BodyKind::Kinematic => "kinematic",
        BodyKind::Dynamic => "dynamic",
    }
}

fn joint_kind_name(kind: JointKind) -> &'static str {
    match kind {
        JointKind::Revolute => "revolute",
        JointKind::Prismatic => "prismatic",
        JointKind::Distance => "distance",
        JointKind::Pulley => "pulley",
        JointKind::Line => "line",
        JointKind::Weld => "weld",
        JointKind::Friction => "friction",
        JointKind::Gear => "gear",
        JointKind::Wheel => "wheel",
        JointKind::Rope => "rope",
        JointKind::Motor => "motor",
        JointKind::Unsupported => "unsupported",
    }
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
mod tests {
    use super::*;
    use crate::scene::Diagnostic;
    use crate::scene::{Range, SceneBuilder, UserData};

    #[test]
    fn float_is_the_shortest_round_trip_text() {
        assert_eq!(float(0.2), "0.2");
        assert_eq!(float(1.0), "1.0");
        assert_eq!(float(-0.0), "-0.0");
        assert_eq!(float(8.369571e-36), "8.369571e-36");
        assert_eq!(float(1.001022e-38), "1.001022e-38");
        assert_eq!(float(-800.0), "-800.0");
        assert_eq!(float(0.65), "0.65");
        assert_eq!(float(1e20), "1e20");
        assert_eq!(float(f32::MAX), "3.4028235e38");
        assert_eq!(float(f32::from_bits(1)), "1e-45");
    }

    #[test]
    fn float_text_reads_back_to_the_same_bits() {
        let samples = [0.1f32, 1.0 / 3.0, 1.001022e-38, 16_777_217.0, f32::MIN_POSITIVE, -123.456];
        for value in samples {
            let back: f32 = float(value).parse().expect("the text is a float");
            assert_eq!(back.to_bits(), value.to_bits(), "{value:?}");
        }
    }

    #[test]
    fn float_writes_non_finite_values_as_null() {
        assert_eq!(float(f32::NAN), "null");
        assert_eq!(float(f32::INFINITY), "null");
        assert_eq!(float(f32::NEG_INFINITY), "null");
    }

    #[test]
    fn absent_references_and_overrides_are_null() {
        assert_eq!(index(NONE), "null");
        assert_eq!(index(0), "0");
        assert_eq!(given_vec2(false, Vec2::new(1.0, 2.0)), "null");
        assert_eq!(given_vec2(true, Vec2::new(1.0, 2.0)), "[1.0, 2.0]");
    }

    #[test]
    fn an_empty_scene_lists_every_top_level_key() {
        let mut b = SceneBuilder::default();
        b.version = 1;
        let scene = b.freeze();
        let expected = "\
{
  \"version\": 1,
  \"dialect\": \"box2scene\",
  \"gravity\": null,
  \"shapes\": [],
  \"fixtures\": [],
  \"bodies\": [],
  \"joints\": [],
  \"diagnostics\": []
}
";
        assert_eq!(to_json(&scene), expected);
    }

    /// One record of each kind, with names, user data, pools and a diagnostic, so that the
    /// whole layout is pinned in one place.
    fn sample_scene() -> Scene {
        let mut b = SceneBuilder::default();
        b.version = 2;
        b.gravity = Some(Vec2::new(0.0, -10.0));
        let mut ground = Shape::new(ShapeKind::Polygon);
        ground.name = b.add_str("ground \"flat\"");
        ground.vertices = Range { first: 0, count: 2 };
        b.vertices.extend([Vec2::new(-40.0, 0.0), Vec2::new(40.0, 0.0)]);
        let mut chain = Shape::new(ShapeKind::Chain);
        chain.vertices = Range { first: 2, count: 2 };
        chain.has_next_vertex = true;
        chain.next_vertex = Vec2::new(2.0, 0.5);
        b.vertices.extend([Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.25)]);
        b.shapes.extend([ground, chain]);

        let raw = b.add_str("<Type>System.String</Type><Value><string>Ground</string></Value>");
        let type_name = b.add_str("System.String");
        let value = b.add_str("Ground");
        b.user_data.push(UserData { raw, type_name, value });
        b.fixtures.push(Fixture { shape: 0, user_data: 0, ..Fixture::default() });

        let mut body = Body::new(BodyKind::Dynamic);
        body.name = b.add_str("crate\t1");
        body.fixtures = Range { first: 0, count: 2 };
        body.mass_data.mass = 2.5;
        body.mass_data.mass_given = true;
        b.fixture_ids.extend([0, 0]);
        b.bodies.push(body);

        let mut gear = Joint::new(JointKind::Gear);
        gear.body_a = 0;
        gear.body_b = 0;
        gear.joint_a = 1;
        b.joints.push(gear);

        let message = b.add_str("unknown element <Foo>");
        b.diagnostics.push(Diagnostic {
            message,
            byte_offset: 120,
            code: Code::UnknownElement as u32,
            severity: Severity::Warning as u32,
            line: 7,
            column: 5,
        });
        b.freeze()
    }

    #[test]
    fn a_scene_is_written_with_every_field_in_a_fixed_layout() {
        let expected = r#"{
  "version": 2,
  "dialect": "box2scene",
  "gravity": [0.0, -10.0],
  "shapes": [
    {
      "kind": "polygon", "name": "ground \"flat\"",
      "radius": 0.0, "position": [0.0, 0.0],
      "vertices": [[-40.0, 0.0], [40.0, 0.0]],
      "centroid": null, "prev_vertex": null, "next_vertex": null, "is_loop": false
    },
    {
      "kind": "chain", "name": null,
      "radius": 0.0, "position": [0.0, 0.0],
      "vertices": [[0.0, 0.0], [1.0, 0.25]],
      "centroid": null, "prev_vertex": null, "next_vertex": [2.0, 0.5], "is_loop": false
    }
  ],
  "fixtures": [
    {
      "shape": 0, "name": null,
      "density": 0.0, "friction": 0.2, "restitution": 0.0, "is_sensor": false,
      "filter": {"category_bits": 1, "mask_bits": 65535, "group_index": 0},
      "user_data": {"raw": "<Type>System.String</Type><Value><string>Ground</string></Value>", "type_name": "System.String", "value": "Ground"}
    }
  ],
  "bodies": [
    {
      "kind": "dynamic", "name": "crate\t1",
      "active": true, "allow_sleep": true, "awake": true, "bullet": false, "fixed_rotation": false,
      "position": [0.0, 0.0], "angle": 0.0, "linear_velocity": [0.0, 0.0], "angular_velocity": 0.0,
      "linear_damping": 0.0, "angular_damping": 0.0, "gravity_scale": 1.0, "inertia_scale": 1.0,
      "mass_data": {"mass": 2.5, "center": null, "inertia": null},
      "fixtures": [0, 0],
      "user_data": null
    }
  ],
  "joints": [
    {
      "kind": "gear", "name": null, "body_a": 0, "body_b": 0, "collide_connected": false,
      "joint_a": 1, "joint_b": null,
      "local_anchor_a": [0.0, 0.0], "local_anchor_b": [0.0, 0.0], "local_axis_a": [0.0, 0.0],
      "ground_anchor_a": [0.0, 0.0], "ground_anchor_b": [0.0, 0.0], "linear_offset": [0.0, 0.0],
      "reference_angle": 0.0, "enable_limit": false, "lower_limit": 0.0, "upper_limit": 0.0,
      "enable_motor": false, "motor_speed": 0.0, "max_motor_torque": 0.0, "max_motor_force": 0.0,
      "length": 0.0, "frequency_hz": 0.0, "damping_ratio": 0.0,
      "length_a": 0.0, "length_b": 0.0, "max_length_a": 0.0, "max_length_b": 0.0, "ratio": 1.0,
      "max_force": 0.0, "max_torque": 0.0, "max_length": 0.0, "angular_offset": 0.0, "correction_factor": 0.0,
      "user_data": null
    }
  ],
  "diagnostics": [
    {"severity": "warning", "code": "unknown-element", "line": 7, "column": 5, "byte_offset": 120, "message": "unknown element <Foo>"}
  ]
}
"#;
        assert_eq!(to_json(&sample_scene()), expected);
    }

    #[test]
    fn kinds_without_a_name_are_written_as_their_number() {
        let mut b = SceneBuilder::default();
        b.shapes.push(Shape { kind: 9, ..Shape::new(ShapeKind::Circle) });
        let json = to_json(&b.freeze());
        assert!(json.contains("\"kind\": 9, \"name\": null"), "{json}");
    }
}
