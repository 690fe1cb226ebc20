//! The library's capture for Python: what a builder reads of a live world through its
//! engine's getters, as dicts in the plan's terms, turned into a scene and the reports of
//! what it cannot hold exactly. Every inverse, label, order and report is the library's.

use box2scene::capture::{self, Held, HeldBody, HeldJoint, HeldLabel, HeldShape, Label};
use box2scene::plan::{
    PlanBody, PlanJoint, PlanJointKind, PlanMass, PlanShape, PlanShapeKind, Rot,
};
use box2scene::{Engine, Filter, NONE, Range, Scene, Str, UserData, Vec2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::plan::{ReportTuple, reports};

type Pair = (f32, f32);

fn vec2((x, y): Pair) -> Vec2 {
    Vec2::new(x, y)
}

/// One shape of a body as the engine holds it, with its fixture's material and labels.
#[derive(FromPyObject)]
#[pyo3(from_item_all)]
pub struct ShapeIn {
    slot: u32,
    /// "circle", "polygon", "segment", "chain" or "loop" (see the plan's shapes).
    kind: String,
    points: Vec<Pair>,
    center: Pair,
    radius: f32,
    density: f32,
    friction: f32,
    restitution: f32,
    is_sensor: bool,
    category_bits: u64,
    mask_bits: u64,
    group_index: i32,
    restitution_threshold: f32,
    /// The fixture's name.
    name: Option<String>,
    shape_name: Option<String>,
    /// What the shape is where the format has no form for it.
    other: Option<String>,
}

/// One body as the engine holds it, with its shapes in the order they were created.
#[derive(FromPyObject)]
#[pyo3(from_item_all)]
pub struct BodyIn {
    body: u32,
    kind: u32,
    position: Pair,
    angle: f32,
    rotation: Pair,
    linear_velocity: Pair,
    angular_velocity: f32,
    linear_damping: f32,
    angular_damping: f32,
    gravity_scale: f32,
    mass: f32,
    center: Pair,
    inertia: f32,
    allow_sleep: bool,
    awake: bool,
    fixed_rotation: bool,
    bullet: bool,
    enabled: bool,
    name: Option<String>,
    shapes: Vec<ShapeIn>,
}

/// One joint as the engine holds it: every field of the plan's joint of its kind.
#[derive(FromPyObject)]
#[pyo3(from_item_all)]
pub struct JointIn {
    joint: u32,
    /// The plan's joint kinds' names.
    kind: String,
    body_a: u32,
    body_b: u32,
    joint_a: u32,
    joint_b: u32,
    anchor_a: Pair,
    anchor_b: Pair,
    axis: Pair,
    reference_angle: f32,
    ground_anchor_a: Pair,
    ground_anchor_b: Pair,
    length_a: f32,
    length_b: f32,
    ratio: f32,
    lower: f32,
    upper: f32,
    length: f32,
    min_length: f32,
    max_length: f32,
    motor_speed: f32,
    max_motor: f32,
    stiffness: f32,
    damping: f32,
    hertz: f32,
    damping_ratio: f32,
    linear_offset: Pair,
    angular_offset: f32,
    max_force: f32,
    max_torque: f32,
    correction_factor: f32,
    collide_connected: bool,
    enable_limit: bool,
    enable_motor: bool,
    /// Whether a v3 joint's spring is on (a v3 builder's; a 2.x one gives none).
    #[pyo3(default)]
    enable_spring: bool,
    /// Hz: a v3 weld joint's linear spring.
    #[pyo3(default)]
    linear_hertz: f32,
    /// Its damping ratio.
    #[pyo3(default)]
    linear_damping_ratio: f32,
    name: Option<String>,
    other: Option<String>,
}

const SHAPE_KINDS: [(&str, u32); 5] = [
    ("circle", PlanShapeKind::Circle as u32),
    ("polygon", PlanShapeKind::Polygon as u32),
    ("segment", PlanShapeKind::Segment as u32),
    ("chain", PlanShapeKind::Chain as u32),
    ("loop", PlanShapeKind::Loop as u32),
];

const JOINT_KINDS: [(&str, u32); 10] = [
    ("revolute", PlanJointKind::Revolute as u32),
    ("prismatic", PlanJointKind::Prismatic as u32),
    ("distance", PlanJointKind::Distance as u32),
    ("pulley", PlanJointKind::Pulley as u32),
    ("gear", PlanJointKind::Gear as u32),
    ("wheel", PlanJointKind::Wheel as u32),
    ("weld", PlanJointKind::Weld as u32),
    ("friction", PlanJointKind::Friction as u32),
    ("motor", PlanJointKind::Motor as u32),
    ("rope", PlanJointKind::Rope as u32),
];

/// The number of a kind's name; an object of no kind (`other`) reads none.
fn kind_number(table: &[(&str, u32)], name: &str, other: bool) -> PyResult<u32> {
    match table.iter().find(|(n, _)| *n == name) {
        Some((_, kind)) => Ok(*kind),
        None if other => Ok(0),
        None => Err(PyValueError::new_err(format!("unknown held kind {name:?}"))),
    }
}

fn unlabelled() -> HeldLabel {
    HeldLabel {
        name: Str::NULL,
        user_data: UserData { raw: Str::NULL, type_name: Str::NULL, value: Str::NULL },
    }
}

fn named(name: &Option<String>) -> Label<'_> {
    Label { name: name.as_deref(), ..Label::default() }
}

fn shape(s: &ShapeIn, points: &mut Vec<Vec2>) -> PyResult<HeldShape> {
    let first = points.len();
    points.extend(s.points.iter().map(|&p| vec2(p)));
    let kind = kind_number(&SHAPE_KINDS, &s.kind, s.other.is_some())?;
    Ok(HeldShape {
        shape: PlanShape {
            slot: s.slot,
            fixture: NONE,
            shape: NONE,
            kind,
            points: Range { first: first as u32, count: s.points.len() as u32 },
            center: vec2(s.center),
            radius: s.radius,
            density: s.density,
            friction: s.friction,
            restitution: s.restitution,
            filter: Filter::default(),
            is_sensor: s.is_sensor,
        },
        category_bits: s.category_bits,
        mask_bits: s.mask_bits,
        group_index: s.group_index,
        restitution_threshold: s.restitution_threshold,
        chain: NONE,
        other: Str::NULL,
        label: unlabelled(),
        shape_name: Str::NULL,
    })
}

fn body(b: &BodyIn, shapes: Range) -> HeldBody {
    HeldBody {
        body: PlanBody {
            body: b.body,
            kind: b.kind,
            position: vec2(b.position),
            angle: b.angle,
            rotation: Rot { c: b.rotation.0, s: b.rotation.1 },
            linear_velocity: vec2(b.linear_velocity),
            angular_velocity: b.angular_velocity,
            linear_damping: b.linear_damping,
            angular_damping: b.angular_damping,
            gravity_scale: b.gravity_scale,
            name: Str::NULL,
            shapes,
            mass: PlanMass { mass: b.mass, center: vec2(b.center), inertia: b.inertia },
            velocity_after_mass: Vec2::ZERO,
            allow_sleep: b.allow_sleep,
            awake: b.awake,
            fixed_rotation: b.fixed_rotation,
            bullet: b.bullet,
            enabled: b.enabled,
            apply_mass_from_shapes: false,
            set_mass: false,
            set_velocity: false,
        },
        label: unlabelled(),
    }
}

fn joint(j: &JointIn) -> PyResult<HeldJoint> {
    Ok(HeldJoint {
        joint: PlanJoint {
            joint: j.joint,
            kind: kind_number(&JOINT_KINDS, &j.kind, j.other.is_some())?,
            body_a: j.body_a,
            body_b: j.body_b,
            joint_a: j.joint_a,
            joint_b: j.joint_b,
            anchor_a: vec2(j.anchor_a),
            anchor_b: vec2(j.anchor_b),
            axis: vec2(j.axis),
            reference_angle: j.reference_angle,
            ground_anchor_a: vec2(j.ground_anchor_a),
            ground_anchor_b: vec2(j.ground_anchor_b),
            length_a: j.length_a,
            length_b: j.length_b,
            ratio: j.ratio,
            lower: j.lower,
            upper: j.upper,
            length: j.length,
            min_length: j.min_length,
            max_length: j.max_length,
            motor_speed: j.motor_speed,
            max_motor: j.max_motor,
            stiffness: j.stiffness,
            damping: j.damping,
            hertz: j.hertz,
            damping_ratio: j.damping_ratio,
            linear_offset: vec2(j.linear_offset),
            angular_offset: j.angular_offset,
            max_force: j.max_force,
            max_torque: j.max_torque,
            correction_factor: j.correction_factor,
            collide_connected: j.collide_connected,
            enable_limit: j.enable_limit,
            enable_motor: j.enable_motor,
            enable_spring: j.enable_spring,
            ..PlanJoint::default()
        },
        linear_hertz: j.linear_hertz,
        linear_damping_ratio: j.linear_damping_ratio,
        linear_velocity: Vec2::ZERO,
        angular_velocity: 0.0,
        max_velocity_force: 0.0,
        max_velocity_torque: 0.0,
        other: Str::NULL,
        label: unlabelled(),
    })
}

/// The scene of what `bodies` and `joints` hold and the reports, labelled from `level`.
pub fn capture(
    engine: Engine,
    gravity: Pair,
    bodies: &[BodyIn],
    joints: &[JointIn],
    skipped: &[u32],
    level: Option<&Scene>,
) -> PyResult<Result<(Scene, Vec<ReportTuple>), box2scene::Error>> {
    let mut held_bodies = Vec::with_capacity(bodies.len());
    let mut held_shapes = Vec::new();
    let mut points = Vec::new();
    for b in bodies {
        let first = held_shapes.len();
        for s in &b.shapes {
            held_shapes.push(shape(s, &mut points)?);
        }
        let range = Range { first: first as u32, count: (held_shapes.len() - first) as u32 };
        held_bodies.push(body(b, range));
    }
    let shapes: Vec<&ShapeIn> = bodies.iter().flat_map(|b| &b.shapes).collect();
    let held_joints = joints.iter().map(joint).collect::<PyResult<Vec<_>>>()?;
    let body_labels: Vec<Label> = bodies.iter().map(|b| named(&b.name)).collect();
    let fixture_labels: Vec<Label> = shapes.iter().map(|s| named(&s.name)).collect();
    let shape_names: Vec<Option<&str>> = shapes.iter().map(|s| s.shape_name.as_deref()).collect();
    let shape_others: Vec<Option<&str>> = shapes.iter().map(|s| s.other.as_deref()).collect();
    let joint_labels: Vec<Label> = joints.iter().map(|j| named(&j.name)).collect();
    let joint_others: Vec<Option<&str>> = joints.iter().map(|j| j.other.as_deref()).collect();
    let held = Held {
        engine,
        gravity: vec2(gravity),
        bodies: &held_bodies,
        shapes: &held_shapes,
        points: &points,
        joints: &held_joints,
        skipped_joints: skipped,
        body_labels: &body_labels,
        fixture_labels: &fixture_labels,
        shape_names: &shape_names,
        shape_others: &shape_others,
        joint_labels: &joint_labels,
        joint_others: &joint_others,
    };
    Ok(capture::capture(&held, level).map(|c| {
        let said = reports(&c.reports);
        (c.scene, said)
    }))
}
