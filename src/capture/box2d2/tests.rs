//! The 2.x inverses: a scene planned for Box2D 2.4 (and 2.3), read back as the engine holds
//! the plan, captured; the capture planned again gives the engine the same bits.

use crate::Builder;
use crate::capture::tests::{
    Engine2, capture_of, held_of, messages, read_back, square, square_vertices,
};
use crate::capture::{Captured, HeldShape};
use crate::plan::{Engine, PlanJoint, PlanMass, PlanShapeKind};
use crate::scene::{Body, BodyKind, Fixture, Joint, JointKind, Scene, Shape, ShapeKind, Vec2};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// A ground, a box `a` at (0, 5) and a box `b` at (2, 5), and `joints` between them.
fn scene_with(joints: &[Joint]) -> Scene {
    let mut b = Builder::new();
    let shape = b.add_shape(&square(), None, &square_vertices()).unwrap();
    let fixture = b.add_fixture(&Fixture { shape, density: 1.5, ..Fixture::default() }, None);
    let fixture = fixture.unwrap();
    b.add_body(&Body::new(BodyKind::Static), Some("ground"), &[]).unwrap();
    for x in [0.0, 2.0] {
        let body = Body { position: v(x, 5.0), ..Body::new(BodyKind::Dynamic) };
        b.add_body(&body, None, &[fixture]).unwrap();
    }
    for joint in joints {
        b.add_joint(joint, None).unwrap();
    }
    b.finish()
}

/// A joint of `kind` from body `a` to body `b`, anchored where they meet (1, 5).
fn between_boxes(kind: JointKind) -> Joint {
    Joint {
        body_a: 1,
        body_b: 2,
        local_anchor_a: v(1.0, 0.0),
        local_anchor_b: v(-1.0, 0.0),
        ..Joint::new(kind)
    }
}

/// The capture of what the engine holds once it has made `scene`, without the level, and
/// what the engine holds once it has made the capture.
fn round_trip(scene: &Scene, engine: Engine) -> (Engine2, Captured, Engine2) {
    let held = held_of(scene, engine);
    let captured = capture_of(&held, engine, None, &[]);
    let again = held_of(&captured.scene, engine);
    (held, captured, again)
}

fn same_joints(a: &Engine2, b: &Engine2) {
    // the scene joint each was made from aside: the capture writes a gear after its joints
    let bits = |j: &PlanJoint| format!("{:?}", PlanJoint { joint: 0, ..*j });
    let first: Vec<String> = a.joints.iter().map(|j| bits(&j.joint)).collect();
    let second: Vec<String> = b.joints.iter().map(|j| bits(&j.joint)).collect();
    assert_eq!(first, second);
}

#[test]
fn every_joint_kind_comes_back_to_the_bit_through_a_capture() {
    let axis = Joint { local_axis_a: v(3.0, 4.0), ..between_boxes(JointKind::Prismatic) };
    let prismatic = Joint { enable_limit: true, lower_limit: -1.0, upper_limit: 2.0, ..axis };
    let revolute = Joint {
        body_a: 0,
        body_b: 1,
        local_anchor_a: v(0.0, 5.0),
        enable_motor: true,
        motor_speed: 1.5,
        max_motor_torque: 7.0,
        ..Joint::new(JointKind::Revolute)
    };
    let gear = Joint {
        body_a: 1,
        body_b: 2,
        joint_a: 0,
        joint_b: 1,
        ratio: 2.5,
        ..Joint::new(JointKind::Gear)
    };
    let wheel = Joint {
        local_axis_a: v(0.0, 1.0),
        frequency_hz: 4.0,
        damping_ratio: 0.7,
        enable_motor: true,
        motor_speed: 2.0,
        max_motor_torque: 9.0,
        ..between_boxes(JointKind::Wheel)
    };
    let weld = Joint { frequency_hz: 2.0, damping_ratio: 0.3, ..between_boxes(JointKind::Weld) };
    let friction = Joint { max_force: 3.0, max_torque: 1.0, ..between_boxes(JointKind::Friction) };
    let motor = Joint {
        body_a: 1,
        body_b: 2,
        linear_offset: v(2.0, 0.0),
        max_force: 5.0,
        max_torque: 2.0,
        correction_factor: 0.3,
        ..Joint::new(JointKind::Motor)
    };
    let pulley = Joint {
        body_a: 1,
        body_b: 2,
        ground_anchor_a: v(0.0, 10.0),
        ground_anchor_b: v(2.0, 10.0),
        length_a: 5.0,
        length_b: 5.0,
        ratio: 1.0,
        ..Joint::new(JointKind::Pulley)
    };
    let distance = |frequency_hz| Joint {
        body_a: 1,
        body_b: 2,
        length: 2.0,
        frequency_hz,
        damping_ratio: 0.5,
        ..Joint::new(JointKind::Distance)
    };
    let rope = Joint { body_a: 1, body_b: 2, max_length: 2.5, ..Joint::new(JointKind::Rope) };
    let joints = [
        revolute,
        prismatic,
        gear,
        wheel,
        weld,
        friction,
        motor,
        pulley,
        distance(3.0),
        distance(0.0),
        rope,
    ];
    let scene = scene_with(&joints);
    for engine in [Engine::Box2d24, Engine::Box2d23] {
        let (held, captured, again) = round_trip(&scene, engine);
        assert_eq!(messages(&captured), Vec::<String>::new(), "{engine:?}");
        same_joints(&held, &again);
        let kinds: Vec<u32> = captured.scene.joints().iter().map(|j| j.kind).collect();
        // in creation order: the build makes a gear after every other joint
        let expected: Vec<u32> =
            held.joints.iter().map(|h| joints[h.joint.joint as usize].kind).collect();
        assert_eq!(kinds, expected, "{engine:?}: each joint in its own form");
    }
}

#[test]
fn a_distance_joint_s_lengths_that_no_form_holds_are_reported() {
    let rope = Joint { body_a: 1, body_b: 2, max_length: 2.5, ..Joint::new(JointKind::Rope) };
    let mut held = held_of(&scene_with(&[rope]), Engine::Box2d24);
    held.joints[0].joint.min_length = 0.5;
    let captured = capture_of(&held, Engine::Box2d24, None, &[]);
    assert_eq!(
        messages(&captured),
        [
            "its length limits [0.5, 2.5] have no Box2Scene form; written as a rope without the lower one"
        ]
    );
    held.joints[0].joint.stiffness = 10.0;
    let captured = capture_of(&held, Engine::Box2d24, None, &[]);
    let spring = &captured.scene.joints()[0];
    assert_eq!(spring.kind, JointKind::Distance as u32);
    assert_eq!(
        messages(&captured)[1],
        "its length limits [0.5, 2.5] have no Box2Scene form; written as a spring without them"
    );
}

#[test]
fn a_wheel_with_a_limit_is_a_line_unless_sprung_or_driven() {
    let line = Joint {
        local_axis_a: v(0.0, 1.0),
        enable_limit: true,
        lower_limit: -0.5,
        upper_limit: 0.5,
        ..between_boxes(JointKind::Line)
    };
    let (held, captured, again) = round_trip(&scene_with(&[line]), Engine::Box2d24);
    assert_eq!(captured.scene.joints()[0].kind, JointKind::Line as u32);
    same_joints(&held, &again);
    let mut held = held;
    held.joints[0].joint.stiffness = 50.0;
    held.joints[0].joint.damping = 1.0;
    let captured = capture_of(&held, Engine::Box2d24, None, &[]);
    let wheel = &captured.scene.joints()[0];
    assert_eq!(wheel.kind, JointKind::Wheel as u32);
    let said = messages(&captured);
    assert_eq!(
        said.last().unwrap(),
        "a wheel with a spring or motor has no limit in the format; its limit [-0.5, 0.5] was dropped"
    );
}

#[test]
fn a_stiffness_no_frequency_gives_is_reported_with_the_nearest() {
    let wheel =
        Joint { local_axis_a: v(0.0, 1.0), frequency_hz: 4.0, ..between_boxes(JointKind::Wheel) };
    let mut held = held_of(&scene_with(&[wheel]), Engine::Box2d24);
    held.joints[0].joint.damping = f32::MIN_POSITIVE;
    let captured = capture_of(&held, Engine::Box2d24, None, &[]);
    let said = messages(&captured);
    assert_eq!(said.len(), 1);
    assert!(
        said[0].starts_with("no FrequencyHz and DampingRatio give back its stiffness "),
        "{said:?}"
    );
    assert!(said[0].ends_with(" exactly; the nearest were written"));
}

#[test]
fn an_axis_no_vector_normalises_to_is_written_as_it_is_and_reported() {
    let prismatic = Joint { local_axis_a: v(1.0, 0.0), ..between_boxes(JointKind::Prismatic) };
    let mut held = held_of(&scene_with(&[prismatic]), Engine::Box2d24);
    held.joints[0].joint.axis = v(0.5, 0.5);
    let captured = capture_of(&held, Engine::Box2d24, None, &[]);
    assert_eq!(captured.scene.joints()[0].local_axis_a, v(0.5, 0.5));
    assert_eq!(
        messages(&captured),
        ["no axis normalises to its axis (0.5, 0.5) exactly; it was written as it is"]
    );
}

/// MassData is written only where the fixtures do not give the mass the body holds.
#[test]
fn mass_data_is_written_only_where_it_differs_from_the_fixtures() {
    let mut b = Builder::from_scene(&scene_with(&[]));
    let mass_only = Body {
        position: v(5.0, 5.0),
        mass_data: crate::scene::MassData { mass: 7.0, mass_given: true, ..Default::default() },
        ..Body::new(BodyKind::Dynamic)
    };
    b.add_body(&mass_only, None, &[0]).unwrap();
    let all = Body {
        position: v(8.0, 5.0),
        mass_data: crate::scene::MassData {
            mass: 3.0,
            center: v(0.25, -0.5),
            inertia: 5.0,
            mass_given: true,
            center_given: true,
            inertia_given: true,
        },
        ..Body::new(BodyKind::Dynamic)
    };
    b.add_body(&all, None, &[0]).unwrap();
    let scene = b.finish();
    for engine in [Engine::Box2d24, Engine::Box2d23] {
        let (held, captured, again) = round_trip(&scene, engine);
        assert_eq!(messages(&captured), Vec::<String>::new());
        let data: Vec<_> = captured.scene.bodies().iter().map(|b| b.mass_data).collect();
        assert!(!(data[1].mass_given || data[1].center_given || data[1].inertia_given));
        assert!(data[3].mass_given && !data[3].center_given);
        assert!(data[4].mass_given && data[4].center_given && data[4].inertia_given);
        for (first, second) in held.bodies.iter().zip(&again.bodies) {
            let bits = |m: PlanMass| [m.mass, m.center.x, m.center.y, m.inertia].map(f32::to_bits);
            assert_eq!(bits(first.body.mass), bits(second.body.mass), "{engine:?}");
        }
    }
}

#[test]
fn an_inertia_set_mass_data_cannot_give_back_is_reported() {
    let mut held = held_of(&scene_with(&[]), Engine::Box2d24);
    // about the origin, less than m|c|^2: no positive inertia about the centre
    held.bodies[1].body.mass = PlanMass { mass: 2.0, center: v(1.0, 0.0), inertia: 1.0 };
    let captured = capture_of(&held, Engine::Box2d24, None, &[]);
    assert_eq!(
        messages(&captured),
        ["its MassData Inertia 1 does not come back exactly through Box2D's SetMassData"]
    );
}

#[test]
fn a_skin_radius_and_a_vertex_order_the_build_does_not_give_are_reported() {
    let mut held = held_of(&scene_with(&[]), Engine::Box2d24);
    held.shapes[0].shape.radius = 0.02;
    let first = held.shapes[0].shape.points.first as usize;
    held.points[first..first + 4].rotate_left(1);
    let captured = capture_of(&held, Engine::Box2d24, None, &[]);
    assert_eq!(
        messages(&captured),
        [
            "b2PolygonShape::Set, which build_world uses, orders these vertices from another first vertex (as after SetAsBox): the same polygon, but its contacts may be solved in another order",
            "its skin radius 0.0199999996 is not Box2D's b2_polygonRadius, which the format implies",
        ]
    );
    assert_eq!(captured.scene.shapes().len(), 1, "said once for the shape both boxes share");
}

#[test]
fn a_restitution_threshold_the_format_has_not_is_reported_per_fixture() {
    let mut held = held_of(&scene_with(&[]), Engine::Box2d24);
    for shape in &mut held.shapes {
        shape.restitution_threshold = 0.5;
    }
    let captured = capture_of(&held, Engine::Box2d24, None, &[]);
    let expected = "the format has no restitution threshold; 0.5 becomes Box2D's default";
    assert_eq!(messages(&captured), [expected, expected]);
    let indices: Vec<u32> = captured.reports().iter().map(|r| r.index).collect();
    assert_eq!(indices, [0, 1]);
}

/// A one-sided edge, an open chain with its ghosts and a loop, each as the engine holds it.
#[test]
fn edges_and_chains_come_back_in_their_forms() {
    let mut b = Builder::new();
    let edge = Shape {
        prev_vertex: v(-1.0, 0.5),
        next_vertex: v(3.0, 0.5),
        has_prev_vertex: true,
        has_next_vertex: true,
        ..Shape::new(ShapeKind::Edge)
    };
    let edge = b.add_shape(&edge, None, &[v(0.0, 0.0), v(2.0, 0.0)]).unwrap();
    let two_sided = b.add_shape(&Shape::new(ShapeKind::Edge), None, &[v(0.0, 1.0), v(2.0, 1.0)]);
    let chain = Shape {
        prev_vertex: v(-1.0, 3.0),
        next_vertex: v(4.0, 3.0),
        has_prev_vertex: true,
        has_next_vertex: true,
        ..Shape::new(ShapeKind::Chain)
    };
    let points = [v(0.0, 2.0), v(1.0, 2.5), v(2.0, 2.0), v(3.0, 2.5)];
    let chain = b.add_shape(&chain, None, &points).unwrap();
    let looped = Shape { is_loop: true, ..Shape::new(ShapeKind::Chain) };
    let looped = b.add_shape(&looped, None, &[v(5.0, 0.0), v(6.0, 0.0), v(6.0, 1.0), v(5.0, 1.0)]);
    let mut fixtures = Vec::new();
    for shape in [edge, two_sided.unwrap(), chain, looped.unwrap()] {
        fixtures.push(b.add_fixture(&Fixture { shape, ..Fixture::default() }, None).unwrap());
    }
    b.add_body(&Body::new(BodyKind::Static), None, &fixtures).unwrap();
    let scene = b.finish();
    for engine in [Engine::Box2d24, Engine::Box2d23] {
        let mut held = held_of(&scene, engine);
        // the engine holds a loop as CreateLoop lays it out: the first vertex repeated at the
        // end, the ghosts next to the seam
        let loop_shape = held.shapes[3].shape;
        let vertices = held.points[loop_shape.points.indices()].to_vec();
        let mut layout = vec![vertices[3]];
        layout.extend_from_slice(&vertices);
        layout.extend([vertices[0], vertices[1]]);
        let first = held.points.len() as u32;
        held.points.extend_from_slice(&layout);
        held.shapes[3] = HeldShape {
            shape: crate::plan::PlanShape {
                kind: PlanShapeKind::Chain as u32,
                points: crate::scene::Range { first, count: layout.len() as u32 },
                ..loop_shape
            },
            ..held.shapes[3]
        };
        let captured = capture_of(&held, engine, None, &[]);
        assert_eq!(messages(&captured), Vec::<String>::new(), "{engine:?}");
        let shapes = captured.scene.shapes();
        let original = scene.shapes();
        for (got, want) in shapes.iter().zip(original) {
            // a two-sided edge is Version 1's two-vertex polygon
            let two_sided = want.kind == ShapeKind::Edge as u32 && !want.has_prev_vertex;
            let kind = if two_sided { ShapeKind::Polygon as u32 } else { want.kind };
            assert_eq!(got.kind, kind, "{engine:?}");
            let same = Shape { name: got.name, vertices: want.vertices, kind: want.kind, ..*got };
            assert_eq!(same, *want, "{engine:?}");
        }
        for (got, want) in shapes.iter().zip(original) {
            assert_eq!(captured.scene.vertices(got), scene.vertices(want), "{engine:?}");
        }
    }
}

/// Box2D 2.3's wheel joint without a spring gets a stand-in spring, which is none; a line
/// joint comes back a Line where the level has one.
#[test]
fn box2d_2_3_s_stand_in_spring_is_no_spring_and_the_level_s_line_stays_a_line() {
    let line = Joint { local_axis_a: v(0.0, 1.0), ..between_boxes(JointKind::Line) };
    let scene = scene_with(&[line]);
    let held = read_back(&scene, Engine::Box2d23);
    assert_eq!(held.joints[0].joint.hertz, 1e-3, "the plan's stand-in");
    let alone = capture_of(&held, Engine::Box2d23, None, &[]);
    let wheel = alone.scene.joints()[0];
    assert_eq!((wheel.kind, wheel.frequency_hz), (JointKind::Wheel as u32, 0.0));
    let labelled = capture_of(&held, Engine::Box2d23, Some(&scene), &[]);
    let line = labelled.scene.joints()[0];
    assert_eq!((line.kind, line.enable_limit), (JointKind::Line as u32, false));
    assert_eq!(messages(&labelled), Vec::<String>::new());
}

/// pybox2d's Box2D 2.3 makes a loop without ghost vertices: its first vertex repeated at
/// the end is what tells it.
#[test]
fn a_loop_without_ghosts_is_a_loop() {
    let mut held = held_of(&scene_with(&[]), Engine::Box2d23);
    let first = held.points.len() as u32;
    let nan = v(f32::NAN, f32::NAN);
    held.points.extend([nan, v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 0.0), nan]);
    let loop_shape = crate::plan::PlanShape {
        kind: PlanShapeKind::Chain as u32,
        points: crate::scene::Range { first, count: 6 },
        density: 0.0,
        ..held.shapes[0].shape
    };
    held.shapes[0] = HeldShape { shape: loop_shape, ..held.shapes[0] };
    let captured = capture_of(&held, Engine::Box2d23, None, &[]);
    let shape = captured.scene.shapes()[0];
    assert!(shape.is_loop);
    assert_eq!(captured.scene.vertices(&shape), [v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0)]);
}
