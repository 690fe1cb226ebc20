//! The library's plan of a scene for one engine version, as Python objects: every body (with
//! its shapes), joint and report in the order the builders create them (a report also as a
//! capture gives it). The Python builders
//! carry it out through their engine's own calls; every conversion, check and predicted
//! mass stays the library's.

use box2scene::plan::{
    self, Object, Plan, PlanBody, PlanJoint, PlanJointKind, PlanOptions, PlanShape, PlanShapeKind,
    Rot, Transform,
};
use box2scene::{Code, Engine, Scene, Vec2};
use pyo3::prelude::*;
use pyo3::types::PyTuple;

type Pair = (f32, f32);

fn pair(v: Vec2) -> Pair {
    (v.x, v.y)
}

/// One shape to create on a body (a fixture of the scene on it).
#[pyclass(frozen, get_all, module = "box2scene._native")]
pub struct NativePlanShape {
    slot: u32,
    fixture: u32,
    shape: u32,
    /// "circle", "polygon", "segment", "chain" or "loop".
    kind: &'static str,
    points: Vec<Pair>,
    center: Pair,
    radius: f32,
    density: f32,
    friction: f32,
    restitution: f32,
    category_bits: u32,
    mask_bits: u32,
    group_index: i16,
    is_sensor: bool,
    /// The scene fixture's Name.
    name: Option<String>,
    /// The scene fixture's IsSensor (a sensor chain the plan makes solid, and reports).
    fixture_is_sensor: bool,
}

/// One body to create, its shapes, and the mass and velocity to give it after them.
#[pyclass(frozen, get_all, module = "box2scene._native")]
pub struct NativePlanBody {
    body: u32,
    /// The engine's body type number (0 static, 1 kinematic, 2 dynamic).
    kind: u32,
    position: Pair,
    angle: f32,
    rotation: Pair,
    linear_velocity: Pair,
    angular_velocity: f32,
    linear_damping: f32,
    angular_damping: f32,
    gravity_scale: f32,
    name: Option<String>,
    shapes: Py<PyTuple>,
    mass: f32,
    center: Pair,
    inertia: f32,
    velocity_after_mass: Pair,
    allow_sleep: bool,
    awake: bool,
    fixed_rotation: bool,
    bullet: bool,
    enabled: bool,
    apply_mass_from_shapes: bool,
    set_mass: bool,
    set_velocity: bool,
}

/// One joint to create: every field its kind's def has in the engine version.
#[pyclass(frozen, get_all, module = "box2scene._native")]
pub struct NativePlanJoint {
    joint: u32,
    /// The scene joint's Name.
    name: Option<String>,
    /// "revolute", "prismatic", "distance", "pulley", "gear", "wheel", "weld", "friction",
    /// "motor" or "rope".
    kind: &'static str,
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
    enable_spring: bool,
}

/// A plan: `bodies` and `joints` in the order to create them, `reports` as
/// (code, object, index, name, message) tuples in the order the plan met them; the counts of
/// the scene's bodies, fixture slots and joints, which a builder's results are indexed by.
#[pyclass(frozen, get_all, module = "box2scene._native")]
pub struct NativePlan {
    bodies: Py<PyTuple>,
    joints: Py<PyTuple>,
    reports: Py<PyTuple>,
    placed: bool,
    body_count: usize,
    slot_count: usize,
    joint_count: usize,
    /// Whether a fixture of the scene is a sensor.
    has_sensor: bool,
}

fn shape_kind(kind: u32) -> &'static str {
    match PlanShapeKind::try_from(kind) {
        Ok(PlanShapeKind::Circle) => "circle",
        Ok(PlanShapeKind::Polygon) => "polygon",
        Ok(PlanShapeKind::Segment) => "segment",
        Ok(PlanShapeKind::Chain) => "chain",
        Ok(PlanShapeKind::Loop) => "loop",
        Err(_) => "unknown",
    }
}

fn joint_kind(kind: u32) -> &'static str {
    match PlanJointKind::try_from(kind) {
        Ok(PlanJointKind::Revolute) => "revolute",
        Ok(PlanJointKind::Prismatic) => "prismatic",
        Ok(PlanJointKind::Distance) => "distance",
        Ok(PlanJointKind::Pulley) => "pulley",
        Ok(PlanJointKind::Gear) => "gear",
        Ok(PlanJointKind::Wheel) => "wheel",
        Ok(PlanJointKind::Weld) => "weld",
        Ok(PlanJointKind::Friction) => "friction",
        Ok(PlanJointKind::Motor) => "motor",
        Ok(PlanJointKind::Rope) => "rope",
        Err(_) => "unknown",
    }
}

fn shape(scene: &Scene, plan: &Plan, s: &PlanShape) -> NativePlanShape {
    let fixture = scene.fixtures().get(s.fixture as usize);
    NativePlanShape {
        slot: s.slot,
        fixture: s.fixture,
        shape: s.shape,
        kind: shape_kind(s.kind),
        points: plan.points(s).iter().map(|&p| pair(p)).collect(),
        center: pair(s.center),
        radius: s.radius,
        density: s.density,
        friction: s.friction,
        restitution: s.restitution,
        category_bits: s.filter.category_bits,
        mask_bits: s.filter.mask_bits,
        group_index: s.filter.group_index,
        is_sensor: s.is_sensor,
        name: fixture.and_then(|f| scene.text(f.name)).map(str::to_owned),
        fixture_is_sensor: fixture.is_some_and(|f| f.is_sensor),
    }
}

/// A body's name as the plan keeps it: the scene body's own where the plan gives one (the
/// plan keeps it whole or not at all).
fn body_name(scene: &Scene, b: &PlanBody) -> Option<String> {
    if b.name.is_null() {
        return None;
    }
    let body = scene.bodies().get(b.body as usize)?;
    scene.text(body.name).map(str::to_owned)
}

fn body(py: Python<'_>, scene: &Scene, plan: &Plan, b: &PlanBody) -> PyResult<NativePlanBody> {
    let shapes = plan.shapes().get(b.shapes.indices()).unwrap_or(&[]);
    let shapes =
        shapes.iter().map(|s| Py::new(py, shape(scene, plan, s))).collect::<PyResult<Vec<_>>>()?;
    Ok(NativePlanBody {
        body: b.body,
        kind: b.kind,
        position: pair(b.position),
        angle: b.angle,
        rotation: (b.rotation.c, b.rotation.s),
        linear_velocity: pair(b.linear_velocity),
        angular_velocity: b.angular_velocity,
        linear_damping: b.linear_damping,
        angular_damping: b.angular_damping,
        gravity_scale: b.gravity_scale,
        name: body_name(scene, b),
        shapes: PyTuple::new(py, shapes)?.unbind(),
        mass: b.mass.mass,
        center: pair(b.mass.center),
        inertia: b.mass.inertia,
        velocity_after_mass: pair(b.velocity_after_mass),
        allow_sleep: b.allow_sleep,
        awake: b.awake,
        fixed_rotation: b.fixed_rotation,
        bullet: b.bullet,
        enabled: b.enabled,
        apply_mass_from_shapes: b.apply_mass_from_shapes,
        set_mass: b.set_mass,
        set_velocity: b.set_velocity,
    })
}

fn joint(scene: &Scene, j: &PlanJoint) -> NativePlanJoint {
    let name = scene.joints().get(j.joint as usize).and_then(|s| scene.text(s.name));
    NativePlanJoint {
        joint: j.joint,
        name: name.map(str::to_owned),
        kind: joint_kind(j.kind),
        body_a: j.body_a,
        body_b: j.body_b,
        joint_a: j.joint_a,
        joint_b: j.joint_b,
        anchor_a: pair(j.anchor_a),
        anchor_b: pair(j.anchor_b),
        axis: pair(j.axis),
        reference_angle: j.reference_angle,
        ground_anchor_a: pair(j.ground_anchor_a),
        ground_anchor_b: pair(j.ground_anchor_b),
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
        linear_offset: pair(j.linear_offset),
        angular_offset: j.angular_offset,
        max_force: j.max_force,
        max_torque: j.max_torque,
        correction_factor: j.correction_factor,
        collide_connected: j.collide_connected,
        enable_limit: j.enable_limit,
        enable_motor: j.enable_motor,
        enable_spring: j.enable_spring,
    }
}

const OBJECTS: [Object; 5] =
    [Object::World, Object::Shape, Object::Fixture, Object::Body, Object::Joint];

/// The name of the object a report is about (the plan's pointer to its static name).
fn object_name(plan_object: box2scene::Str) -> &'static str {
    OBJECTS
        .iter()
        .find(|o| o.name().as_ptr() == plan_object.as_ptr())
        .and_then(|o| o.name().to_str().ok())
        .unwrap_or("world")
}

pub type ReportTuple = (&'static str, &'static str, u32, Option<String>, String);

pub fn reports(plan: &Plan) -> Vec<ReportTuple> {
    plan.reports()
        .iter()
        .map(|r| {
            let code = Code::from_u32(r.code).map_or("internal-error", Code::name);
            let name = plan.text(r.name).map(str::to_owned);
            let message = plan.text(r.message).unwrap_or_default().to_owned();
            (code, object_name(r.object), r.index, name, message)
        })
        .collect()
}

/// The options of a plan for `engine`, placed at `placement` ((x, y), (cos, sin)).
pub fn options(
    engine: Engine,
    placement: (Pair, Pair),
    gravity: Pair,
    max_linear_speed: f32,
) -> PlanOptions {
    let ((x, y), (c, s)) = placement;
    PlanOptions {
        engine: engine as u32,
        placement: Transform { p: Vec2::new(x, y), q: Rot { c, s } },
        gravity: Vec2::new(gravity.0, gravity.1),
        max_linear_speed,
        name_bytes: 0,
    }
}

/// The plan of `scene` for `options`, as Python objects.
pub fn make(py: Python<'_>, scene: &Scene, options: &PlanOptions) -> Result<NativePlan, PyErr> {
    let plan = plan::make(scene, options).map_err(|e| crate::error(py, e))?;
    let bodies = plan
        .bodies()
        .iter()
        .map(|b| Py::new(py, body(py, scene, &plan, b)?))
        .collect::<PyResult<Vec<_>>>()?;
    let joints =
        plan.joints().iter().map(|j| Py::new(py, joint(scene, j))).collect::<PyResult<Vec<_>>>()?;
    Ok(NativePlan {
        bodies: PyTuple::new(py, bodies)?.unbind(),
        joints: PyTuple::new(py, joints)?.unbind(),
        reports: PyTuple::new(py, reports(&plan))?.unbind(),
        placed: plan.placed(),
        body_count: scene.bodies().len(),
        slot_count: scene.fixture_id_pool().len(),
        joint_count: scene.joints().len(),
        has_sensor: scene.fixtures().iter().any(|f| f.is_sensor),
    })
}
