use super::*;
use crate::error::Position;
use crate::scene::{Range, SceneBuilder, UserDataText};

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
    ground.vertices = Range { first: 0, count: 2 };
    b.vertices.extend([Vec2::new(-40.0, 0.0), Vec2::new(40.0, 0.0)]);
    let mut chain = Shape::new(ShapeKind::Chain);
    chain.vertices = Range { first: 2, count: 2 };
    chain.has_next_vertex = true;
    chain.next_vertex = Vec2::new(2.0, 0.5);
    b.vertices.extend([Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.25)]);
    let ground_name = Some(b.add_str("ground \"flat\""));
    b.push_shape(ground, ground_name);
    b.push_shape(chain, None);

    let raw = b.add_str("<Type>System.String</Type><Value><string>Ground</string></Value>");
    let type_name = b.add_str("System.String");
    let value = b.add_str("Ground");
    b.user_data.push(UserDataText { raw, type_name: Some(type_name), value: Some(value) });
    b.push_fixture(Fixture { shape: 0, user_data: 0, ..Fixture::default() }, None);

    let mut body = Body::new(BodyKind::Dynamic);
    body.fixtures = Range { first: 0, count: 2 };
    body.mass_data.mass = 2.5;
    body.mass_data.mass_given = true;
    b.fixture_ids.extend([0, 0]);
    let body_name = Some(b.add_str("crate\t1"));
    b.push_body(body, body_name);

    let mut gear = Joint::new(JointKind::Gear);
    gear.body_a = 0;
    gear.body_b = 0;
    gear.joint_a = 1;
    b.push_joint(gear, None);

    let at = Position { line: 7, column: 5, byte_offset: 120 };
    b.push_warning(Code::UnknownElement, at, "unknown element <Foo>");
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
    b.push_shape(Shape { kind: 9, ..Shape::new(ShapeKind::Circle) }, None);
    let json = to_json(&b.freeze());
    assert!(json.contains("\"kind\": 9, \"name\": null"), "{json}");
}
