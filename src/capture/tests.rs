//! The capture's unit tests: a scene planned for an engine, its plan read back as an
//! engine that makes exactly the plan would hold it, captured, and the scene compared.

use super::*;
use crate::Builder;
use crate::error::Code;
use crate::plan::{
    PlanJoint, PlanJointKind, PlanOptions, PlanShape, PlanShapeKind, Rot, Transform,
};
use crate::scene::{Body, BodyKind, Fixture, Joint, JointKind, NONE, Shape, ShapeKind, UserData};

/// The records an engine holds once it has made `plan` (nothing stepped): the plan's own,
/// labelled by nothing.
pub(super) struct Engine2 {
    pub(super) bodies: Vec<HeldBody>,
    pub(super) shapes: Vec<HeldShape>,
    pub(super) points: Vec<Vec2>,
    pub(super) joints: Vec<HeldJoint>,
    pub(super) skipped: Vec<u32>,
}

fn unlabelled() -> HeldLabel {
    HeldLabel {
        name: Str::NULL,
        user_data: UserData { raw: Str::NULL, type_name: Str::NULL, value: Str::NULL },
    }
}

fn options(engine: Engine) -> PlanOptions {
    PlanOptions {
        engine: engine as u32,
        placement: Transform { p: Vec2::ZERO, q: Rot { c: 1.0, s: 0.0 } },
        gravity: Vec2::new(0.0, -10.0),
        max_linear_speed: f32::MAX,
        name_bytes: 0,
    }
}

/// A shape as the engine holds it: with its skin, a polygon with a centroid (its mass's
/// where the plan keeps the engine's own).
fn as_held(shape: PlanShape, plan: &crate::plan::Plan) -> PlanShape {
    if shape.kind == PlanShapeKind::Circle as u32 {
        return shape;
    }
    let shape = PlanShape { radius: 0.01, ..shape };
    if shape.kind != PlanShapeKind::Polygon as u32 || !shape.center.x.is_nan() {
        return shape;
    }
    let hull = crate::rules::polygon_hull(plan.points(&shape));
    let reference = crate::plan::box2d2::version::PolygonReference::First;
    let mass = crate::plan::box2d2::polygon::mass(&hull, 1.0, reference);
    PlanShape { center: mass.center, ..shape }
}

/// A joint as the engine holds it: a prismatic joint's axis normalised, 2.4's distance
/// joint's lengths raised to the linear slop.
fn joint_as_held(joint: PlanJoint) -> PlanJoint {
    if joint.kind == PlanJointKind::Prismatic as u32 {
        // b2PrismaticJoint's constructor normalises its axis
        return PlanJoint { axis: crate::plan::box2d2::math::normalized(joint.axis), ..joint };
    }
    if joint.kind != PlanJointKind::Distance as u32 {
        return joint;
    }
    let slop = crate::rules::LINEAR_SLOP;
    PlanJoint { length: joint.length.max(slop), min_length: joint.min_length.max(slop), ..joint }
}

pub(super) fn held_of(scene: &Scene, engine: Engine) -> Engine2 {
    let plan = crate::plan::make(scene, &options(engine)).unwrap();
    assert_eq!(plan.reports(), [], "the level is planned whole");
    read_back(scene, engine)
}

/// What the engine holds once it has made the plan of `scene`, whatever the plan reports.
pub(super) fn read_back(scene: &Scene, engine: Engine) -> Engine2 {
    let plan = crate::plan::make(scene, &options(engine)).unwrap();
    let bodies = plan.bodies().iter().map(|&body| HeldBody { body, label: unlabelled() }).collect();
    let shapes = plan
        .shapes()
        .iter()
        .map(|&shape| HeldShape {
            shape: as_held(shape, &plan),
            category_bits: u64::from(shape.filter.category_bits),
            mask_bits: u64::from(shape.filter.mask_bits),
            group_index: i32::from(shape.filter.group_index),
            restitution_threshold: if engine == Engine::Box2d24 { 1.0 } else { f32::NAN },
            chain: NONE,
            other: Str::NULL,
            label: unlabelled(),
            shape_name: Str::NULL,
        })
        .collect();
    let joints = plan
        .joints()
        .iter()
        .map(|&joint| HeldJoint {
            joint: joint_as_held(joint),
            linear_hertz: 0.0,
            linear_damping_ratio: 0.0,
            linear_velocity: Vec2::ZERO,
            angular_velocity: 0.0,
            max_velocity_force: 0.0,
            max_velocity_torque: 0.0,
            other: Str::NULL,
            label: unlabelled(),
        })
        .collect();
    Engine2 { bodies, shapes, points: plan.point_pool().to_vec(), joints, skipped: Vec::new() }
}

/// The captured scene of what `e` holds, with its labels empty but where `others` says.
pub(super) fn capture_of(
    e: &Engine2,
    engine: Engine,
    level: Option<&Scene>,
    joint_others: &[Option<&str>],
) -> Captured {
    let none = |n: usize| vec![Label::default(); n];
    let (body_labels, fixture_labels, joint_labels) =
        (none(e.bodies.len()), none(e.shapes.len()), none(e.joints.len()));
    let mut others = vec![None; e.joints.len()];
    others[..joint_others.len()].copy_from_slice(joint_others);
    let held = Held {
        engine,
        gravity: Vec2::new(0.0, -10.0),
        bodies: &e.bodies,
        shapes: &e.shapes,
        points: &e.points,
        joints: &e.joints,
        skipped_joints: &e.skipped,
        body_labels: &body_labels,
        fixture_labels: &fixture_labels,
        shape_names: &vec![None; e.shapes.len()],
        shape_others: &vec![None; e.shapes.len()],
        joint_labels: &joint_labels,
        joint_others: &others,
    };
    capture(&held, level).unwrap()
}

pub(super) fn messages(c: &Captured) -> Vec<String> {
    c.reports().iter().map(|r| c.text(r.message).unwrap_or_default().to_owned()).collect()
}

pub(super) fn square() -> Shape {
    Shape { ..Shape::new(ShapeKind::Polygon) }
}

pub(super) fn square_vertices() -> [Vec2; 4] {
    [Vec2::new(1.0, -1.0), Vec2::new(1.0, 1.0), Vec2::new(-1.0, 1.0), Vec2::new(-1.0, -1.0)]
}

/// A ground and two boxes on one shared shape and fixture, named, with UserData; a wheel
/// joint of FrequencyHz 4 and DampingRatio 0.7, a revolute joint, and a rope.
pub(super) fn level() -> Scene {
    let mut b = Builder::new();
    let shape = b.add_shape(&square(), Some("crate"), &square_vertices()).unwrap();
    let data = b.add_user_data(None, Some("System.String"), Some("wood")).unwrap();
    let fixture = Fixture { shape, density: 2.0, user_data: data, ..Fixture::default() };
    let fixture = b.add_fixture(&fixture, Some("crate skin")).unwrap();
    let ground = b.add_body(&Body::new(BodyKind::Static), Some("ground"), &[]).unwrap();
    let a = Body { position: Vec2::new(1.5, 2.0), ..Body::new(BodyKind::Dynamic) };
    let a = b.add_body(&a, Some("chassis"), &[fixture]).unwrap();
    let c = Body { position: Vec2::new(4.0, 2.0), angle: 0.3, ..Body::new(BodyKind::Dynamic) };
    let c = b.add_body(&c, Some("wheel"), &[fixture]).unwrap();
    let wheel = Joint {
        body_a: a,
        body_b: c,
        local_anchor_a: Vec2::new(2.5, 0.0),
        local_axis_a: Vec2::new(0.0, 1.0),
        frequency_hz: 4.0,
        damping_ratio: 0.7,
        ..Joint::new(JointKind::Wheel)
    };
    b.add_joint(&wheel, Some("suspension")).unwrap();
    let hinge = Joint {
        body_a: ground,
        body_b: a,
        local_anchor_a: Vec2::new(1.5, 2.0),
        ..Joint::new(JointKind::Revolute)
    };
    b.add_joint(&hinge, Some("hinge")).unwrap();
    let rope = Joint { body_a: a, body_b: c, max_length: 3.0, ..Joint::new(JointKind::Rope) };
    b.add_joint(&rope, Some("rope")).unwrap();
    b.finish()
}

fn names(scene: &Scene, of: impl Fn(&Scene) -> Vec<Str>) -> Vec<Option<String>> {
    of(scene).into_iter().map(|s| scene.text(s).map(str::to_owned)).collect()
}

#[test]
fn a_capture_of_a_built_world_keeps_the_level_s_names_user_data_and_springs() {
    let level = level();
    let e = held_of(&level, Engine::Box2d24);
    let c = capture_of(&e, Engine::Box2d24, Some(&level), &[]);
    assert_eq!(messages(&c), Vec::<String>::new());
    let s = &c.scene;
    let bodies = |s: &Scene| s.bodies().iter().map(|b| b.name).collect();
    let joints = |s: &Scene| s.joints().iter().map(|j| j.name).collect();
    assert_eq!(names(s, bodies), names(&level, bodies));
    assert_eq!(names(s, joints), names(&level, joints));
    assert_eq!(s.shapes().len(), 1, "equal shapes are written once");
    assert_eq!(s.fixtures().len(), 1, "equal fixtures are written once");
    assert_eq!(s.text(s.shapes()[0].name), Some("crate"));
    let fixture = &s.fixtures()[0];
    assert_eq!(s.text(fixture.name), Some("crate skin"));
    let data = s.user_data_at(fixture.user_data).unwrap();
    assert_eq!(s.text(data.value), Some("wood"));
    let wheel = &s.joints()[0];
    assert_eq!((wheel.frequency_hz, wheel.damping_ratio), (4.0, 0.7));
    assert_eq!(s.joints()[2].kind, JointKind::Rope as u32);
    assert_eq!(s.joints()[2].max_length, 3.0);
}

/// What the engine holds of a capture without the level: its plan gives back the
/// stiffness and damping bits the first plan gave.
#[test]
fn a_capture_without_the_level_finds_a_spring_that_gives_the_same_bits() {
    let level = level();
    let e = held_of(&level, Engine::Box2d24);
    let c = capture_of(&e, Engine::Box2d24, None, &[]);
    assert_eq!(messages(&c), Vec::<String>::new());
    assert!(c.scene.bodies().iter().all(|b| b.name.is_null()));
    let again = held_of(&c.scene, Engine::Box2d24);
    let (first, second) = (&e.joints[0].joint, &again.joints[0].joint);
    assert_eq!(first.stiffness.to_bits(), second.stiffness.to_bits());
    assert_eq!(first.damping.to_bits(), second.damping.to_bits());
    assert_eq!(e.bodies[1].body.mass, again.bodies[1].body.mass);
    assert!(!c.scene.bodies()[1].mass_data.mass_given, "the fixtures give the mass");
}

#[test]
fn a_joint_the_build_skipped_is_written_back_in_its_place() {
    let level = level();
    let mut e = held_of(&level, Engine::Box2d24);
    e.joints.remove(1);
    e.skipped.push(1);
    let c = capture_of(&e, Engine::Box2d24, Some(&level), &[]);
    let joints = |s: &Scene| s.joints().iter().map(|j| j.name).collect();
    assert_eq!(names(&c.scene, joints), names(&level, joints));
    assert_eq!(c.scene.joints()[1], Joint { name: c.scene.joints()[1].name, ..level.joints()[1] });
}

#[test]
fn a_joint_with_no_form_and_one_on_a_body_not_written_are_reported() {
    let level = level();
    let mut e = held_of(&level, Engine::Box2d24);
    e.joints[2].joint.body_b = 7;
    let c = capture_of(&e, Engine::Box2d24, None, &[Some("a mouse joint (a host's drag)")]);
    let codes: Vec<u32> = c.reports().iter().map(|r| r.code).collect();
    assert_eq!(codes, [Code::SkippedJoint as u32, Code::SkippedDependent as u32]);
    assert_eq!(
        messages(&c),
        [
            "a mouse joint (a host's drag) has no Box2Scene form; not written",
            "one of its bodies was not written; not written",
        ]
    );
    assert_eq!(c.reports()[1].index, 2);
    assert_eq!(c.scene.joints().len(), 1);
}

#[test]
fn a_gear_whose_joint_was_not_written_is_not_written() {
    let mut b = Builder::from_scene(&level());
    let gear = Joint {
        body_a: 0,
        body_b: 1,
        joint_a: 1,
        joint_b: 1,
        ratio: 2.0,
        ..Joint::new(JointKind::Gear)
    };
    b.add_joint(&gear, Some("gear")).unwrap();
    let level = b.finish();
    let e = held_of(&level, Engine::Box2d24);
    let c = capture_of(&e, Engine::Box2d24, Some(&level), &[None, Some("Box2D joint type 99")]);
    assert_eq!(messages(&c)[1], "a joint the gear couples was not written; not written");
    assert_eq!(c.text(c.reports()[1].name), Some("gear"));
}

/// A label the builder refuses (a character XML does not allow in a name) is reported with
/// the builder's code; the body is not written, nor the joints on it.
#[test]
fn a_record_the_builder_refuses_is_reported_and_what_needs_it_is_not_written() {
    let level = level();
    let e = held_of(&level, Engine::Box2d24);
    let mut body_labels = vec![Label::default(); e.bodies.len()];
    body_labels[1] = Label { name: Some("bad\u{1}name"), ..Label::default() };
    let none = |n: usize| vec![Label::default(); n];
    let held = Held {
        engine: Engine::Box2d24,
        gravity: Vec2::new(0.0, -10.0),
        bodies: &e.bodies,
        shapes: &e.shapes,
        points: &e.points,
        joints: &e.joints,
        skipped_joints: &[],
        body_labels: &body_labels,
        fixture_labels: &none(e.shapes.len()),
        shape_names: &[],
        shape_others: &[],
        joint_labels: &none(e.joints.len()),
        joint_others: &[],
    };
    let c = capture(&held, None).unwrap();
    let first = c.reports()[0];
    // what the builder says of a second body of that name
    let mut builder = crate::Builder::new();
    builder.add_body(&Body::new(BodyKind::Static), None, &[]).unwrap();
    let refusal =
        builder.add_body(&Body::new(BodyKind::Static), Some("bad\u{1}name"), &[]).unwrap_err();
    assert_eq!((first.code, first.index), (refusal.code as u32, 1));
    assert_eq!(c.text(first.message), Some(format!("{}; not written", refusal.message).as_str()));
    assert_eq!(c.scene.bodies().len(), 2);
    let dependent = messages(&c)
        .iter()
        .filter(|m| *m == "one of its bodies was not written; not written")
        .count();
    assert_eq!(dependent, 3, "every joint is on the chassis");
}
