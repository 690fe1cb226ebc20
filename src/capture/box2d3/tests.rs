//! Each inverse against the plan it inverts: a scene planned for a version, the plan's
//! records read back as an engine holds them, and what the capture writes planned again
//! gives the same bits.

use super::bodies::angle_of;
use crate::capture::world::said;
use crate::capture::{HeldBody, HeldJoint, HeldLabel, HeldShape};
use crate::error::Code;
use crate::plan::box2d3::V3;
use crate::plan::box2d3::bodies::center_velocity;
use crate::plan::box2d3::math::rotation;
use crate::plan::{
    Engine, Object, Plan, PlanBody, PlanJoint, PlanJointKind, PlanMass, PlanOptions, PlanShape,
    PlanShapeKind, Rot, Transform, make,
};
use crate::scene::{
    BodyKind, Filter, Joint, JointKind, NONE, Range, ShapeKind, Str, UserData, Vec2,
};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

const UNLABELLED: HeldLabel = HeldLabel {
    name: Str::NULL,
    user_data: UserData { raw: Str::NULL, type_name: Str::NULL, value: Str::NULL },
};

/// The plan of a Version 2 scene of these parts.
fn plan(engine: Engine, shapes: &str, fixtures: &str, bodies: &str, joints: &str) -> Plan {
    let text = format!(
        "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>{shapes}</Shapes><Fixtures>\
         {fixtures}</Fixtures><Bodies>{bodies}</Bodies><Joints>{joints}</Joints></World>"
    );
    let scene = crate::load(text.as_bytes(), &Default::default()).unwrap();
    let options = PlanOptions {
        engine: engine as u32,
        placement: Transform { p: v(0.0, 0.0), q: Rot { c: 1.0, s: 0.0 } },
        gravity: v(0.0, -10.0),
        max_linear_speed: 1500.0,
        name_bytes: 0,
    };
    make(&scene, &options).unwrap()
}

fn held_shape(shape: PlanShape, chain: u32) -> HeldShape {
    HeldShape {
        shape,
        category_bits: 1,
        mask_bits: u64::MAX,
        group_index: 0,
        restitution_threshold: f32::NAN,
        chain,
        other: Str::NULL,
        label: UNLABELLED,
        shape_name: Str::NULL,
    }
}

fn held_joint(joint: PlanJoint) -> HeldJoint {
    HeldJoint {
        joint,
        linear_hertz: 0.0,
        linear_damping_ratio: 0.0,
        linear_velocity: v(0.0, 0.0),
        angular_velocity: 0.0,
        max_velocity_force: 0.0,
        max_velocity_torque: 0.0,
        other: Str::NULL,
        label: UNLABELLED,
    }
}

/// What a family says, as its messages (every one lossy-capture), and its result.
fn saying<T>(run: impl FnOnce(&mut crate::capture::world::Say) -> T) -> (T, Vec<String>) {
    let (out, said) = said(run);
    assert!(said.iter().all(|(code, _)| *code == Code::LossyCapture), "{said:?}");
    (out, said.into_iter().map(|(_, message)| message).collect())
}

#[test]
fn an_angle_whose_rotation_is_the_held_one_and_one_report_for_those_none_gives() {
    for angle in [0.0f32, 0.1, -1.0, 1.5707964, 3.1415925, -3.0, 2.0e-3] {
        let q = rotation(angle);
        let found = angle_of(q).unwrap();
        assert_eq!(rotation(found), q, "{angle}");
    }
    // A rotation the solver leaves: normalised, but no float angle has it as cosf and sinf.
    let q = Rot { c: 1.0, s: 0.001 };
    let nearest = angle_of(q).unwrap_err();
    assert_eq!(nearest, 0.001f32.atan2(1.0));
    let turned = HeldBody { body: PlanBody { rotation: q, ..static_body() }, label: UNLABELLED };
    assert_eq!(super::body(V3::V31, &turned, &[], &[]).angle, nearest);
    let exact = HeldBody { body: PlanBody { rotation: rotation(0.25), ..static_body() }, ..turned };
    let bodies = [exact, exact, exact, turned, exact, turned];
    let ((), said) = saying(|say| super::turned(&bodies, say));
    assert_eq!(
        said,
        ["rotations no angle gives exactly, as the solver turns bodies: 2 of the bodies (the \
             first body 3) were written at the nearest angle, at most 1.59e-11 rad from the \
             rotation"]
    );
    let ((), none) = saying(|say| super::turned(&bodies[..3], say));
    assert!(none.is_empty());
}

/// A static body A that has not turned.
fn unturned() -> HeldBody {
    HeldBody { body: static_body(), label: UNLABELLED }
}

fn static_body() -> PlanBody {
    PlanBody {
        body: NONE,
        kind: BodyKind::Static as u32,
        position: v(0.0, 0.0),
        angle: 0.0,
        rotation: Rot { c: 1.0, s: 0.0 },
        linear_velocity: v(0.0, 0.0),
        angular_velocity: 0.0,
        linear_damping: 0.0,
        angular_damping: 0.0,
        gravity_scale: 1.0,
        name: Str::NULL,
        shapes: Range::default(),
        mass: PlanMass::default(),
        velocity_after_mass: v(0.0, 0.0),
        allow_sleep: true,
        awake: true,
        fixed_rotation: false,
        bullet: false,
        enabled: true,
        apply_mass_from_shapes: false,
        set_mass: false,
        set_velocity: false,
    }
}

/// The held body of a planned dynamic body as v3 holds it: its centre's velocity, and the
/// mass the plan predicts.
fn held_body(plan: &Plan, index: usize) -> (HeldBody, Vec<HeldShape>) {
    let mut body = plan.bodies()[index];
    let transform = Transform { p: body.position, q: body.rotation };
    body.linear_velocity =
        center_velocity(transform, body.mass.center, body.angular_velocity, body.linear_velocity);
    let shapes =
        plan.shapes()[body.shapes.indices()].iter().map(|&s| held_shape(s, NONE)).collect();
    (HeldBody { body, label: UNLABELLED }, shapes)
}

const BOX: &str = "<Shape Type=\"Polygon\"><Vertices><Vertex>-1 -0.5</Vertex><Vertex>1.3 -0.5</Vertex>\
    <Vertex>1.3 0.7</Vertex><Vertex>-1 0.7</Vertex></Vertices></Shape>\
    <Shape Type=\"Circle\"><Radius>0.3</Radius><Position>0.7 0.1</Position></Shape>";
const BOX_FIXTURES: &str = "<Fixture><Shape>0</Shape><Density>1.3</Density></Fixture>\
    <Fixture><Shape>1</Shape><Density>2.1</Density></Fixture>";

#[test]
fn the_origin_velocity_whose_shift_gives_the_held_centre_velocity() {
    for engine in [Engine::Box2d31, Engine::Box2d32] {
        let body = "<Body Type=\"Dynamic\"><Angle>0.7</Angle><Position>3 1</Position>\
            <LinearVelocity>1.1 -2.3</LinearVelocity><AngularVelocity>3.7</AngularVelocity>\
            <Fixtures><ID>0</ID><ID>1</ID></Fixtures></Body>";
        let plan = plan(engine, BOX, BOX_FIXTURES, body, "");
        let (held, shapes) = held_body(&plan, 0);
        let points = plan.points(&plan.shapes()[0]);
        // The polygon's points are its own range in the plan's pool: hand the pool whole.
        let pool: Vec<Vec2> = pool_of(&plan);
        let _ = points;
        let body = super::body(V3::of(engine).unwrap(), &held, &shapes, &pool);
        let b = held.body;
        let transform = Transform { p: b.position, q: b.rotation };
        let back =
            center_velocity(transform, b.mass.center, b.angular_velocity, body.linear_velocity);
        assert_eq!(back, b.linear_velocity, "{engine:?}");
        assert_eq!(body.linear_velocity, plan.bodies()[0].linear_velocity);
        // The mass is what the shapes give: not written.
        assert!(!body.mass_data.mass_given && !body.mass_data.inertia_given, "{engine:?}");
        assert_eq!(body.angle, 0.7);
    }
}

/// The plan's point pool (every shape's range indexes it).
fn pool_of(plan: &Plan) -> Vec<Vec2> {
    let end = plan.shapes().iter().map(|s| s.points.first + s.points.count).max().unwrap_or(0);
    let mut pool = vec![v(f32::NAN, f32::NAN); end as usize];
    for s in plan.shapes() {
        pool[s.points.indices()].copy_from_slice(plan.points(s));
    }
    pool
}

#[test]
fn a_mass_other_than_the_shapes_give_is_written_with_the_origin_inertia_the_plan_turns_back() {
    for engine in [Engine::Box2d31, Engine::Box2d32] {
        let body = "<Body Type=\"Dynamic\"><MassData><Mass>3.3</Mass><Center>0.21 -0.13</Center>\
            <Inertia>2.9</Inertia></MassData><Fixtures><ID>0</ID><ID>1</ID></Fixtures></Body>";
        let plan = plan(engine, BOX, BOX_FIXTURES, body, "");
        let (held, shapes) = held_body(&plan, 0);
        let body = super::body(V3::of(engine).unwrap(), &held, &shapes, &pool_of(&plan));
        let m = body.mass_data;
        assert!(m.mass_given && m.center_given && m.inertia_given);
        assert_eq!((m.mass, m.center), (3.3, v(0.21, -0.13)));
        // Planned again, the written MassData gives the held mass to the bit.
        let again = format!(
            "<Body Type=\"Dynamic\"><MassData><Mass>{}</Mass><Center>{} {}</Center><Inertia>{}\
             </Inertia></MassData><Fixtures><ID>0</ID><ID>1</ID></Fixtures></Body>",
            crate::plan::printf::G9(m.mass),
            crate::plan::printf::G9(m.center.x),
            crate::plan::printf::G9(m.center.y),
            crate::plan::printf::G9(m.inertia)
        );
        let replanned = plan_again(engine, &again);
        assert_eq!(replanned.bodies()[0].mass, held.body.mass, "{engine:?}");
    }
}

fn plan_again(engine: Engine, body: &str) -> Plan {
    plan(engine, BOX, BOX_FIXTURES, body, "")
}

fn segment(points: &mut Vec<Vec2>, run: [Vec2; 4], chain: u32) -> HeldShape {
    let first = points.len() as u32;
    points.extend_from_slice(&run);
    let shape = PlanShape {
        slot: NONE,
        fixture: NONE,
        shape: NONE,
        kind: PlanShapeKind::Segment as u32,
        points: Range { first, count: 4 },
        center: v(0.0, 0.0),
        radius: 0.0,
        density: 0.0,
        friction: 0.6,
        restitution: 0.0,
        filter: Filter::default(),
        is_sensor: false,
    };
    held_shape(shape, chain)
}

/// The segments v3 makes of a chain's points: open `[ghost, vertices..., ghost]`, or a
/// loop's vertices.
fn segments(points: &mut Vec<Vec2>, p: &[Vec2], is_loop: bool, chain: u32) -> Vec<HeldShape> {
    let n = p.len();
    let count = if is_loop { n } else { n - 3 };
    (0..count)
        .map(|i| {
            let run = if is_loop {
                [p[(i + n - 1) % n], p[i], p[(i + 1) % n], p[(i + 2) % n]]
            } else {
                [p[i], p[i + 1], p[i + 2], p[i + 3]]
            };
            segment(points, run, chain)
        })
        .collect()
}

#[test]
fn chains_regrouped_from_their_segments_a_loop_where_the_last_continues_into_the_first() {
    let square = [v(0.0, 0.0), v(2.0, 0.0), v(2.0, 2.0), v(0.0, 2.0)];
    let open = [v(-1.0, 1.0), v(0.0, 0.0), v(1.0, 0.0), v(2.0, 0.5), v(3.0, 1.0)];
    for v3 in [V3::V31, V3::V32] {
        let mut points = Vec::new();
        let mut held = segments(&mut points, &square, true, 0);
        held.extend(segments(&mut points, &square, true, 0));
        held.extend(segments(&mut points, &open, false, 1));
        // v3.2: the two loops of the same points, marked alike, stop at the closing edge.
        let first = if v3 == V3::V31 { 4 } else { super::chain_length(v3, &held, &points) };
        assert_eq!(first, 4);
        let ((shape, vertices), said) =
            saying(|say| super::shape(v3, &held[..4], &points, say).unwrap());
        assert!(said.is_empty());
        assert!(shape.is_loop && shape.kind == ShapeKind::Chain as u32);
        assert_eq!(vertices, square);
        let tail = &held[8..];
        assert_eq!(super::chain_length(v3, tail, &points), 2);
        let ((shape, vertices), _) = saying(|say| super::shape(v3, tail, &points, say).unwrap());
        assert!(!shape.is_loop && shape.has_prev_vertex && shape.has_next_vertex);
        assert_eq!((shape.prev_vertex, shape.next_vertex), (open[0], open[4]));
        assert_eq!(vertices, open[1..4]);
        let fixture = saying(|say| super::fixture(&tail[0], say)).0;
        assert_eq!((fixture.density, fixture.friction), (0.0, 0.6));
        // One segment alone: v3.1 made a chain of it, v3.2 is given an edge.
        let ((lone, vertices), _) =
            saying(|say| super::shape(v3, &tail[..1], &points, say).unwrap());
        let kind = if v3 == V3::V31 { ShapeKind::Chain } else { ShapeKind::Edge };
        assert_eq!(lone.kind, kind as u32);
        assert_eq!(vertices, open[1..3]);
        assert_eq!((lone.prev_vertex, lone.next_vertex), (open[0], open[3]));
    }
    // v3.2: a segment that does not continue the one before starts another chain.
    let v3 = V3::V32;
    let mut points = Vec::new();
    let mut held = segments(&mut points, &open, false, 0);
    held.extend(segments(&mut points, &square.map(|p| v(p.x + 9.0, p.y)), false, 0));
    assert_eq!(super::chain_length(v3, &held, &points), 2);
    assert_eq!(super::chain_length(v3, &held[2..], &points), 1);
}

#[test]
fn a_rounded_polygon_and_a_filter_beyond_the_formats_bits_are_reported() {
    let v3 = V3::V31;
    let mut points = vec![v(0.0, 0.0), v(1.0, 0.0), v(0.0, 1.0)];
    let mut shape = segment(&mut points, [v(0.0, 0.0); 4], NONE);
    shape.shape.kind = PlanShapeKind::Polygon as u32;
    shape.shape.points = Range { first: 0, count: 3 };
    shape.shape.radius = 0.1;
    shape.category_bits = 0x1_0000_0002;
    shape.mask_bits = u64::MAX;
    shape.group_index = -40000;
    let run = [shape];
    let ((polygon, vertices), said) = saying(|say| super::shape(v3, &run, &points, say).unwrap());
    assert_eq!(polygon.kind, ShapeKind::Polygon as u32);
    assert_eq!(vertices, points[..3]);
    let (fixture, filter_said) = saying(|say| super::fixture(&run[0], say));
    assert_eq!(
        fixture.filter,
        Filter { category_bits: 2, mask_bits: u32::MAX, group_index: i16::MIN }
    );
    assert_eq!(
        [said, filter_said].concat(),
        [
            "a rounded polygon (radius 0.100000001 m): written without its rounding".to_owned(),
            "its filter (category 0x100000002, mask 0xffffffffffffffff, group -40000) has bits \
                 above the format's 32 or a group beyond 16 bits; the low 32 bits were written"
                .to_owned(),
        ]
    );
    // Every higher mask bit set is "all": nothing lost.
    let mut all = run[0];
    all.category_bits = 0x8000_0000;
    all.group_index = -3;
    let (fixture, said) = saying(|say| super::fixture(&all, say));
    assert!(said.is_empty());
    assert_eq!(fixture.filter.group_index, -3);
    // A kind no plan shape has is not written, and said.
    let unknown = [HeldShape { shape: PlanShape { kind: 99, ..run[0].shape }, ..run[0] }];
    let (none, said) = saying(|say| super::shape(V3::V31, &unknown, &points, say));
    assert!(none.is_none());
    assert_eq!(said, ["a shape of kind 99 has no Box2Scene form; not written"]);
}

const BODIES: &str = "<Body Type=\"Static\"/><Body Type=\"Dynamic\">\
    <Fixtures><ID>0</ID></Fixtures></Body>";
const BALL: (&str, &str) = (
    "<Shape Type=\"Circle\"><Radius>0.5</Radius><Position>0 0</Position></Shape>",
    "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
);

fn joint_xml(kind: &str, rest: &str) -> String {
    format!("<Joint Type=\"{kind}\"><BodyA>0</BodyA><BodyB>1</BodyB>{rest}</Joint>")
}

/// The joints of `joints` planned for `engine`, held as the engine holds them, captured.
fn captured(
    engine: Engine,
    joints: &str,
    hold: impl Fn(&mut HeldJoint),
) -> Vec<(Joint, Vec<String>)> {
    let plan = plan(engine, BALL.0, BALL.1, BODIES, joints);
    let v3 = V3::of(engine).unwrap();
    plan.joints()
        .iter()
        .map(|&j| {
            let mut held = held_joint(j);
            hold(&mut held);
            let (joint, said) = saying(|say| super::joint(v3, &held, &unturned(), None, say));
            (joint.unwrap(), said)
        })
        .collect()
}

#[test]
fn v32_frames_give_back_the_reference_angles_and_axes_the_plan_turned_into_them() {
    let joints = joint_xml(
        "Revolute",
        "<ReferenceAngle>0.3</ReferenceAngle><LocalAnchorA>1 2</LocalAnchorA>",
    ) + &joint_xml("Weld", "<ReferenceAngle>-2.9</ReferenceAngle>")
        + &joint_xml(
            "Prismatic",
            "<LocalAxisA>0.6 0.8</LocalAxisA><ReferenceAngle>1.1</ReferenceAngle>",
        )
        + &joint_xml(
            "Prismatic",
            "<LocalAxisA>3 1</LocalAxisA><ReferenceAngle>-0.4</ReferenceAngle>",
        )
        + &joint_xml("Wheel", "<LocalAxisA>0.1 0.9</LocalAxisA>");
    let out = captured(Engine::Box2d32, &joints, |_| {});
    let plan = plan(Engine::Box2d32, BALL.0, BALL.1, BODIES, &joints);
    for ((joint, said), planned) in out.iter().zip(plan.joints()) {
        assert!(said.is_empty(), "{said:?}");
        let again = crate::plan::box2d3::joints::planned_frames(V3::V32, joint);
        assert_eq!((again.frame_a, again.frame_b), (planned.frame_a, planned.frame_b));
    }
    assert_eq!(out[0].0.local_anchor_a, v(1.0, 2.0));
    assert_eq!((out[0].0.reference_angle, out[1].0.reference_angle), (0.3, -2.9));
    assert_eq!(out[1].0.kind, JointKind::Weld as u32);
    assert_eq!(out[4].0.kind, JointKind::Wheel as u32);
    // A frame the plan never makes: written as the nearest and said.
    let lossy = captured(Engine::Box2d32, &joint_xml("Revolute", ""), |held| {
        held.joint.frame_a.q = Rot { c: 1.0, s: 0.001 };
        held.joint.frame_b.q = Rot { c: 0.0, s: 1.0 };
    });
    let messages: Vec<&str> = lossy[0].1.iter().map(String::as_str).collect();
    assert_eq!(
        messages,
        [
            "a turn of its frame B has no Box2Scene form; written without it",
            "no angle has exactly the rotation of its frame A; the nearest, 0.000999999698 rad, was \
             written as ReferenceAngle",
        ]
    );
}

#[test]
fn the_motor_joint_read_back_as_friction_or_motor_in_each_version() {
    let joints = joint_xml(
        "Motor",
        "<LinearOffset>0.5 -1</LinearOffset><AngularOffset>0.3</AngularOffset>\
        <CorrectionFactor>0.3</CorrectionFactor><MaxForce>7</MaxForce><MaxTorque>2</MaxTorque>",
    ) + &joint_xml("Friction", "<MaxForce>5</MaxForce><MaxTorque>1.5</MaxTorque>");
    // v3.2: springs of the plan's hertz on both axes, the friction joint's limits on the
    // velocity drive.
    let out = captured(Engine::Box2d32, &joints, |held| {
        if held.joint.kind == PlanJointKind::Motor as u32 {
            held.linear_hertz = held.joint.hertz;
            held.linear_damping_ratio = held.joint.damping_ratio;
        } else {
            held.joint.kind = PlanJointKind::Motor as u32;
            held.max_velocity_force = held.joint.max_force;
            held.max_velocity_torque = held.joint.max_torque;
            held.joint.max_force = 0.0;
            held.joint.max_torque = 0.0;
        }
    });
    let (motor, said) = &out[0];
    assert!(said.is_empty(), "{said:?}");
    assert_eq!(motor.kind, JointKind::Motor as u32);
    assert_eq!((motor.linear_offset, motor.angular_offset), (v(0.5, -1.0), 0.3));
    assert_eq!((motor.correction_factor, motor.max_force, motor.max_torque), (0.3, 7.0, 2.0));
    let (friction, said) = &out[1];
    assert!(said.is_empty());
    assert_eq!(friction.kind, JointKind::Friction as u32);
    assert_eq!((friction.max_force, friction.max_torque), (5.0, 1.5));
    // One driving a velocity is neither: the nearest Motor, said.
    let driven = captured(Engine::Box2d32, &joints, |held| held.angular_velocity = 1.0);
    assert_eq!(driven[0].0.kind, JointKind::Motor as u32);
    assert_eq!(
        driven[0].1,
        ["a motor joint other than the build makes of a Motor joint: written as the nearest, \
             from the offsets of its frame A, its spring limits and a CorrectionFactor from its \
             linear spring's frequency"
            .to_owned()]
    );
    // v3.1 holds 2.3's fields: a motor holding nothing is the friction joint.
    let out =
        captured(Engine::Box2d31, &joints, |held| held.joint.kind = PlanJointKind::Motor as u32);
    assert_eq!(out[0].0.kind, JointKind::Motor as u32);
    assert_eq!(out[0].0.correction_factor, 0.3);
    assert_eq!(out[1].0.kind, JointKind::Friction as u32);
    assert_eq!((out[1].0.max_force, out[1].0.max_torque), (5.0, 1.5));
}

#[test]
fn distance_rope_wheel_line_and_weld_and_what_they_hold_beyond_the_format() {
    let joints = joint_xml(
        "Distance",
        "<Length>2</Length><FrequencyHz>3</FrequencyHz><DampingRatio>0.4</DampingRatio>",
    ) + &joint_xml("Rope", "<MaxLength>2.5</MaxLength>")
        + &joint_xml(
            "Wheel",
            "<FrequencyHz>4</FrequencyHz><DampingRatio>0.7</DampingRatio><EnableMotor>true</EnableMotor><MotorSpeed>2</MotorSpeed><MaxMotorTorque>9</MaxMotorTorque>",
        )
        + &joint_xml(
            "Line",
            "<EnableLimit>true</EnableLimit><LowerTranslation>-1</LowerTranslation><UpperTranslation>1</UpperTranslation>",
        )
        + &joint_xml(
            "Weld",
            "<FrequencyHz>5</FrequencyHz><DampingRatio>0.2</DampingRatio><ReferenceAngle>0.5</ReferenceAngle>",
        );
    for engine in [Engine::Box2d31, Engine::Box2d32] {
        let out = captured(engine, &joints, |_| {});
        let kinds: Vec<u32> = out.iter().map(|(j, _)| j.kind).collect();
        let expected = [
            JointKind::Distance,
            JointKind::Rope,
            JointKind::Wheel,
            JointKind::Line,
            JointKind::Weld,
        ];
        assert_eq!(kinds, expected.map(|k| k as u32));
        assert!(out.iter().all(|(_, said)| said.is_empty()), "{engine:?}");
        let (d, r, w, l, weld) = (&out[0].0, &out[1].0, &out[2].0, &out[3].0, &out[4].0);
        assert_eq!((d.length, d.frequency_hz, d.damping_ratio), (2.0, 3.0, 0.4));
        assert_eq!(r.max_length, 2.5);
        assert_eq!((w.frequency_hz, w.motor_speed, w.max_motor_torque), (4.0, 2.0, 9.0));
        assert!(w.enable_motor && l.enable_limit);
        assert_eq!((l.lower_limit, l.upper_limit, l.local_axis_a), (-1.0, 1.0, v(1.0, 0.0)));
        assert_eq!((weld.frequency_hz, weld.damping_ratio, weld.reference_angle), (5.0, 0.2, 0.5));
    }
    let lossy = captured(Engine::Box2d31, &joints, |held| {
        held.joint.enable_motor = true;
        held.joint.enable_limit = !held.joint.enable_limit;
        held.linear_hertz = 1.0;
    });
    let messages: Vec<Vec<&str>> =
        lossy.iter().map(|(_, said)| said.iter().map(String::as_str).collect()).collect();
    assert_eq!(
        messages,
        [
            vec![
                "a distance joint's length range has no Box2Scene form; written without it",
                "a distance joint's motor has no Box2Scene form; written without it",
            ],
            vec![
                "a slack distance joint without its length limit has no Box2Scene form; written \
                 without it",
                "a distance joint's motor has no Box2Scene form; written without it",
            ],
            vec![
                "a wheel joint's limit beside its spring has no Box2Scene form; written without it"
            ],
            vec![
                "a springless wheel joint's rotation motor has no Box2Scene form; written without it"
            ],
            vec!["a weld joint's linear spring has no Box2Scene form; written without it"],
        ]
    );
}

#[test]
fn a_revolute_or_prismatic_spring_is_said_and_a_kind_unknown_not_written() {
    let joints = joint_xml(
        "Revolute",
        "<EnableLimit>true</EnableLimit><LowerAngle>-1</LowerAngle><UpperAngle>1</UpperAngle>",
    ) + &joint_xml(
        "Prismatic",
        "<EnableMotor>true</EnableMotor><MaxMotorForce>4</MaxMotorForce>",
    );
    let out = captured(Engine::Box2d31, &joints, |held| held.joint.enable_spring = true);
    assert_eq!((out[0].0.lower_limit, out[0].0.upper_limit), (-1.0, 1.0));
    assert_eq!(out[1].0.max_motor_force, 4.0);
    assert_eq!(out[0].1[0], "a revolute joint's spring has no Box2Scene form; written without it");
    assert_eq!(out[1].1[0], "a prismatic joint's spring has no Box2Scene form; written without it");
    let mut held =
        held_joint(PlanJoint { kind: PlanJointKind::Pulley as u32, ..PlanJoint::default() });
    held.joint.kind = 99;
    let (joint, said) = saying(|say| super::joint(V3::V32, &held, &unturned(), None, say));
    assert!(joint.is_none());
    assert_eq!(
        said,
        ["a joint of a kind this adapter does not know has no Box2Scene form; not written"
            .to_owned()]
    );
}

/// Two v3 bodies, a capsule on the first and a ball on the second, and joints without
/// a form and to a body not held beside a hinge.
#[test]
fn v3_says_what_is_not_written_as_lossy_once_counting_the_joints_written_before() {
    let plan = plan(Engine::Box2d32, BALL.0, BALL.1, BODIES, "");
    let ball = held_shape(plan.shapes()[0], NONE);
    let capsule = HeldShape { other: Str::NULL, ..ball };
    let mut bodies = [held_body(&plan, 1).0, held_body(&plan, 1).0];
    bodies[0].body.shapes = Range { first: 0, count: 1 };
    bodies[1].body.shapes = Range { first: 1, count: 1 };
    let revolute =
        PlanJoint { kind: PlanJointKind::Revolute as u32, joint: NONE, ..PlanJoint::default() };
    let between = |body_a, body_b| {
        held_joint(PlanJoint {
            body_a,
            body_b,
            frame_a: UNTURNED_FRAME,
            frame_b: UNTURNED_FRAME,
            ..revolute
        })
    };
    let joints = [between(NONE, 0), between(0, 1), between(0, 1), between(0, 1)];
    let shapes = [capsule, ball];
    let points = pool_of(&plan);
    let unlabelled = [crate::capture::Label::default(); 4];
    let held = crate::capture::Held {
        engine: Engine::Box2d32,
        gravity: v(0.0, -10.0),
        bodies: &bodies,
        shapes: &shapes,
        points: &points,
        joints: &joints,
        skipped_joints: &[],
        body_labels: &unlabelled[..2],
        fixture_labels: &unlabelled[..2],
        shape_names: &[None, None],
        shape_others: &[Some("a capsule"), None],
        joint_labels: &unlabelled,
        joint_others: &[None, Some("a filter joint"), None, Some("a filter joint")],
    };
    let captured = crate::capture::capture(&held, None).unwrap();
    assert_eq!(captured.scene.joints().len(), 1);
    assert_eq!(captured.scene.bodies()[0].fixtures.count, 0);
    let reports: Vec<(u32, &str, u32, &str)> = captured
        .reports()
        .iter()
        .map(|r| {
            let objects =
                [Object::World, Object::Shape, Object::Fixture, Object::Body, Object::Joint];
            let object = objects.into_iter().find(|o| o.name().as_ptr() == r.object.as_ptr());
            let object = object.and_then(|o| o.name().to_str().ok()).unwrap_or_default();
            (r.code, object, r.index, captured.text(r.message).unwrap_or_default())
        })
        .collect();
    let lossy = Code::LossyCapture as u32;
    assert_eq!(
        reports,
        [
            (lossy, "shape", 0, "a capsule has no Box2Scene form; not written"),
            (lossy, "joint", 0, "one of its bodies was not written; not written"),
            (lossy, "joint", 0, "a filter joint has no Box2Scene form; not written"),
            (lossy, "joint", 1, "a filter joint has no Box2Scene form; not written"),
        ]
    );
}

const UNTURNED_FRAME: Transform =
    Transform { p: Vec2 { x: 0.0, y: 0.0 }, q: Rot { c: 1.0, s: 0.0 } };

/// A joint the build skipped that names a body not held is said as the v3 adapter said it:
/// lossy-capture, counted among the joints written before it.
#[test]
fn v3_says_a_skipped_joint_it_cannot_write_back_as_lossy() {
    let joints = "<Joint Type=\"Pulley\"><BodyA>0</BodyA><BodyB>1</BodyB><Ratio>1</Ratio></Joint>";
    let text = format!(
        "<World Version=\"2\"><Shapes>{}</Shapes><Fixtures>{}</Fixtures><Bodies>{BODIES}</Bodies>\
         <Joints>{joints}</Joints></World>",
        BALL.0, BALL.1
    );
    let level = crate::load(text.as_bytes(), &Default::default()).unwrap();
    let plan = plan(Engine::Box2d31, BALL.0, BALL.1, BODIES, joints);
    assert!(plan.joints().is_empty(), "v3 has no pulley");
    let bodies = [HeldBody { body: plan.bodies()[0], label: UNLABELLED }];
    let unlabelled = [crate::capture::Label::default()];
    let held = crate::capture::Held {
        engine: Engine::Box2d31,
        gravity: v(0.0, -10.0),
        bodies: &bodies,
        shapes: &[],
        points: &[],
        joints: &[],
        skipped_joints: &[0],
        body_labels: &unlabelled,
        fixture_labels: &[],
        shape_names: &[],
        shape_others: &[],
        joint_labels: &[],
        joint_others: &[],
    };
    let captured = crate::capture::capture(&held, Some(&level)).unwrap();
    assert!(captured.scene.joints().is_empty());
    let reports = captured.reports();
    assert_eq!(reports.len(), 1);
    assert_eq!((reports[0].code, reports[0].index), (Code::LossyCapture as u32, 0));
    assert_eq!(
        captured.text(reports[0].message),
        Some(
            "scene joint 0, which build_world skipped, names a body or joint not written (or has \
             no Box2Scene form); not written"
        )
    );
}

/// v3.1 holds a Friction joint as a motor joint without anchors (the build reports that it
/// acts at the body origins): a capture of the built world writes the level's anchors back,
/// so that the file builds again as it did.
#[test]
fn a_v31_friction_joint_keeps_the_level_s_anchors() {
    let level = crate::scene::Joint {
        local_anchor_a: Vec2::new(9.0, 0.25),
        local_anchor_b: Vec2::new(-1.0, 0.5),
        max_force: 3.0,
        max_torque: 1.0,
        ..crate::scene::Joint::new(JointKind::Friction)
    };
    let held = held_joint(PlanJoint {
        kind: PlanJointKind::Friction as u32,
        max_force: 3.0,
        max_torque: 1.0,
        ..PlanJoint::default()
    });
    let (joint, said) = saying(|say| super::joint(V3::V31, &held, &unturned(), Some(&level), say));
    let joint = joint.unwrap();
    assert_eq!(said, Vec::<String>::new());
    assert_eq!(joint.kind(), Some(JointKind::Friction));
    assert_eq!(
        (joint.local_anchor_a, joint.local_anchor_b),
        (level.local_anchor_a, level.local_anchor_b)
    );
    let (host, _) = saying(|say| super::joint(V3::V31, &held, &unturned(), None, say));
    assert_eq!(host.unwrap().local_anchor_a, Vec2::ZERO, "a host's friction joint holds none");
}

/// A reader that cannot read a chain's segments' ghosts gives the chain whole, as the plan
/// gave it: open with its ghosts, or a loop.
#[test]
fn a_chain_held_whole_is_the_plans_chain() {
    let open = [v(-1.0, 1.0), v(0.0, 0.0), v(1.0, 0.0), v(2.0, 0.5), v(3.0, 1.0)];
    let mut points = open.to_vec();
    points.extend([v(0.0, 0.0), v(2.0, 0.0), v(0.0, 2.0)]);
    let mut chain = segment(&mut Vec::new(), [v(0.0, 0.0); 4], NONE);
    chain.shape.kind = PlanShapeKind::Chain as u32;
    chain.shape.points = Range { first: 0, count: 5 };
    let ((shape, vertices), said) =
        saying(|say| super::shape(V3::V31, &[chain], &points, say).unwrap());
    assert!(said.is_empty());
    assert!(!shape.is_loop && shape.has_prev_vertex && shape.has_next_vertex);
    assert_eq!((shape.prev_vertex, shape.next_vertex), (open[0], open[4]));
    assert_eq!(vertices, open[1..4]);
    let mut ring = chain;
    ring.shape.kind = PlanShapeKind::Loop as u32;
    ring.shape.points = Range { first: 5, count: 3 };
    let ((shape, vertices), _) =
        saying(|say| super::shape(V3::V31, &[ring], &points, say).unwrap());
    assert!(shape.is_loop && shape.kind == ShapeKind::Chain as u32);
    assert_eq!(vertices, points[5..]);
    chain.shape.points = Range { first: 0, count: 3 };
    let (none, said) = saying(|say| super::shape(V3::V31, &[chain], &points, say));
    assert!(none.is_none());
    assert_eq!(said, ["an open chain of 3 points, where one has 4 or more; not written"]);
}

/// v3.1 holds a Motor's LinearOffset in world axes, the file's turned by body A's rotation as
/// the build makes the joint: the capture turns it back, the level's own where it gives the
/// held bits.
#[test]
fn a_v31_motor_offset_is_turned_back_into_body_a_s_frame() {
    let q = rotation(0.7);
    let a = HeldBody { body: PlanBody { rotation: q, ..static_body() }, label: UNLABELLED };
    let level = crate::scene::Joint {
        linear_offset: v(1.5, -0.25),
        correction_factor: 0.3,
        ..crate::scene::Joint::new(JointKind::Motor)
    };
    let held = held_joint(PlanJoint {
        kind: PlanJointKind::Motor as u32,
        linear_offset: crate::plan::math::rotate(q, level.linear_offset),
        correction_factor: 0.3,
        ..PlanJoint::default()
    });
    let (joint, said) = saying(|say| super::joint(V3::V31, &held, &a, Some(&level), say));
    assert_eq!(said, Vec::<String>::new());
    assert_eq!(joint.unwrap().linear_offset, level.linear_offset);
    let (host, said) = saying(|say| super::joint(V3::V31, &held, &a, None, say));
    let offset = host.unwrap().linear_offset;
    assert_eq!(said, Vec::<String>::new(), "a host's offset is searched");
    assert_eq!(crate::plan::math::rotate(q, offset), held.joint.linear_offset);
    assert!((offset.x - 1.5).abs() < 1e-5 && (offset.y + 0.25).abs() < 1e-5, "{offset:?}");
}
