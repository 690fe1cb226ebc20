//! The Box2D 2.4 mapping on small scenes: what the plan holds and what it reports, to the
//! bit and to the letter (the C++ tests build the same plans in Box2D).

use crate::error::Code;
use crate::plan::records::{PlanJointKind, PlanOptions, PlanShapeKind, Rot, Transform};
use crate::plan::{Engine, Plan, make};
use crate::scene::{NONE, Vec2};

fn options(placement: Transform) -> PlanOptions {
    PlanOptions {
        engine: Engine::Box2d24 as u32,
        placement,
        gravity: Vec2::new(0.0, -10.0),
        max_linear_speed: f32::MAX,
        name_bytes: 0,
    }
}

pub(super) fn identity() -> Transform {
    Transform { p: Vec2::ZERO, q: Rot { c: 1.0, s: 0.0 } }
}

fn plan_at(xml: &str, placement: Transform) -> Plan {
    let scene = crate::load(xml.as_bytes(), &Default::default()).unwrap_or_else(|e| panic!("{e}"));
    make(&scene, &options(placement)).expect("a 2.4 plan is made")
}

fn plan(xml: &str) -> Plan {
    plan_at(xml, identity())
}

/// Every report as (its code's number, object, index, message).
pub(super) fn reports(plan: &Plan) -> Vec<(u32, String, u32, String)> {
    plan.reports()
        .iter()
        .map(|r| {
            let object = plan_object(r.object);
            (r.code, object, r.index, plan.text(r.message).unwrap_or_default().to_owned())
        })
        .collect()
}

fn plan_object(s: crate::scene::Str) -> String {
    ["world", "shape", "fixture", "body", "joint"]
        .into_iter()
        .find(|name| {
            let object = match *name {
                "world" => crate::plan::Object::World,
                "shape" => crate::plan::Object::Shape,
                "fixture" => crate::plan::Object::Fixture,
                "body" => crate::plan::Object::Body,
                _ => crate::plan::Object::Joint,
            };
            object.name().as_ptr() == s.as_ptr()
        })
        .unwrap_or("?")
        .to_owned()
}

pub(super) const BOX: &str = "<Shape Type=\"Polygon\"><Vertices><Vertex>-0.5 -0.5</Vertex><Vertex>0.5 -0.5\
                   </Vertex><Vertex>0.5 0.5</Vertex><Vertex>-0.5 0.5</Vertex></Vertices></Shape>";

pub(super) fn one_body(body: &str) -> String {
    format!(
        "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>{BOX}</Shapes><Fixtures><Fixture>\
         <Shape>0</Shape><Density>2</Density></Fixture></Fixtures><Bodies>{body}</Bodies></World>"
    )
}

#[test]
fn a_placement_that_is_no_rotation_plans_nothing_but_its_report() {
    let xml = one_body("<Body Type=\"Dynamic\"><Fixtures><ID>0</ID></Fixtures></Body>");
    let skewed = Transform { p: Vec2::new(1.0, 2.0), q: Rot { c: 1.0, s: 1.0 } };
    let plan = plan_at(&xml, skewed);
    assert!(!plan.placed());
    assert!(plan.bodies().is_empty() && plan.shapes().is_empty());
    assert_eq!(
        reports(&plan),
        vec![(
            Code::InvalidArgument as u32,
            "world".to_owned(),
            0,
            "the placement (1, 2) turned by (1, 1) is not finite, not within +-100000 m or not \
             a normalised rotation; nothing was built"
                .to_owned()
        )]
    );
}

#[test]
fn a_placed_body_is_moved_turned_and_given_the_mass_box2d_sums() {
    let xml = one_body(
        "<Body Type=\"Dynamic\"><Position>1 0</Position><Angle>0.25</Angle><LinearVelocity>2 0\
         </LinearVelocity><AngularVelocity>3</AngularVelocity><Fixtures><ID>0</ID></Fixtures>\
         </Body>",
    );
    let quarter = std::f32::consts::FRAC_PI_2;
    let turn = Rot { c: quarter.cos(), s: quarter.sin() };
    let plan = plan_at(&xml, Transform { p: Vec2::new(10.0, 0.0), q: turn });
    assert!(reports(&plan).is_empty());
    let body = plan.bodies()[0];
    assert_eq!(body.position, Vec2::new(turn.c * 1.0 + 10.0, turn.s * 1.0));
    assert_eq!(body.angle, 0.25 + turn.s.atan2(turn.c));
    assert_eq!(body.rotation, Rot { c: body.angle.cos(), s: body.angle.sin() });
    assert_eq!(body.linear_velocity, Vec2::new(turn.c * 2.0 - turn.s * 0.0, turn.s * 2.0));
    assert_eq!(body.angular_velocity, 3.0);
    assert!(body.apply_mass_from_shapes && !body.set_mass && !body.set_velocity);
    // a unit box at 2 kg/m^2: 2 kg, inertia 2 (1 + 1) / 12 about its centre, the origin
    assert_eq!(body.mass.mass, 2.0);
    assert_eq!(body.mass.center, Vec2::ZERO);
    assert!((body.mass.inertia - 1.0 / 3.0).abs() < 1e-6, "{}", body.mass.inertia);
    assert_eq!((body.shapes.first, body.shapes.count), (0, 1));
    let shape = plan.shapes()[0];
    assert_eq!(shape.kind, PlanShapeKind::Polygon as u32);
    assert_eq!(plan.points(&shape).len(), 4);
    assert!(shape.center.x.is_nan(), "no Centroid given: the engine keeps its own");
    assert_eq!(shape.density, 2.0);
}

#[test]
fn negative_damping_and_mass_data_box2d_rejects_are_reported_in_the_adapter_s_words() {
    let xml = one_body(
        "<Body Type=\"Dynamic\"><LinearDamping>-0.5</LinearDamping><MassData><Mass>2</Mass>\
         <Center>3 0</Center><Inertia>1</Inertia></MassData><Fixtures><ID>0</ID></Fixtures>\
         </Body>",
    );
    let plan = plan(&xml);
    let found = reports(&plan);
    assert_eq!(found.len(), 2, "{found:?}");
    assert_eq!(
        found[0],
        (
            Code::NegativeValue as u32,
            "body".to_owned(),
            0,
            "LinearDamping -0.500000 is negative, which Box2D 2.4 does not allow; 0 was used"
                .to_owned()
        )
    );
    assert_eq!(found[1].0, Code::InconsistentMassData as u32);
    let body = plan.bodies()[0];
    assert_eq!(body.linear_damping, 0.0);
    assert!(!body.set_mass, "the mass computed from the fixtures is kept");
}

#[test]
fn a_body_beyond_the_range_takes_its_fixtures_with_it() {
    let xml = one_body(
        "<Body Type=\"Dynamic\"><Position>1e6 0</Position><Fixtures><ID>0</ID></Fixtures></Body>",
    );
    let plan = plan(&xml);
    assert!(plan.bodies().is_empty());
    assert_eq!(
        reports(&plan),
        vec![
            (
                Code::BeyondBox2dRange as u32,
                "body".to_owned(),
                0,
                "Position (1000000, 0) lies beyond Box2D 2.4's working range (each component \
                 within +-100000 m); body not created"
                    .to_owned()
            ),
            (
                Code::SkippedDependent as u32,
                "fixture".to_owned(),
                0,
                "fixture 0 of body 0: the body was not created; fixture skipped".to_owned()
            ),
        ]
    );
}

#[test]
fn edges_and_chains_carry_their_ghosts() {
    let xml = "<World Version=\"2\"><Shapes>\
        <Shape Type=\"Edge\"><Vertex1>0 0</Vertex1><Vertex2>1 0</Vertex2>\
        <Vertex0>-1 0.5</Vertex0><HasVertex0>true</HasVertex0>\
        <Vertex3>2 0.5</Vertex3><HasVertex3>true</HasVertex3></Shape>\
        <Shape Type=\"Chain\"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>2 1\
        </Vertex></Vertices><PrevVertex>-1 1</PrevVertex><HasPrevVertex>true</HasPrevVertex>\
        </Shape></Shapes><Fixtures><Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape>\
        </Fixture></Fixtures><Bodies><Body Type=\"Static\"><Fixtures><ID>0</ID><ID>1</ID>\
        </Fixtures></Body></Bodies></World>";
    let plan = plan(xml);
    let (edge, chain) = (plan.shapes()[0], plan.shapes()[1]);
    assert_eq!(edge.kind, PlanShapeKind::Segment as u32);
    let v = Vec2::new;
    assert_eq!(plan.points(&edge), [v(-1.0, 0.5), v(0.0, 0.0), v(1.0, 0.0), v(2.0, 0.5)]);
    assert_eq!(chain.kind, PlanShapeKind::Chain as u32);
    // no NextVertex: the last segment continued
    assert_eq!(
        plan.points(&chain),
        [v(-1.0, 1.0), v(0.0, 0.0), v(1.0, 0.0), v(2.0, 1.0), v(3.0, 2.0)]
    );
    assert!(!plan.bodies()[0].apply_mass_from_shapes);
}

pub(super) const TWO_BOXES: &str = "<Shapes>{BOX}</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>2\
    </Density></Fixture><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>\
    <Bodies><Body Type=\"Static\"/><Body Type=\"Dynamic\"><Position>-2 3</Position><Fixtures>\
    <ID>0</ID></Fixtures></Body><Body Type=\"Dynamic\"><Position>2 4</Position><Fixtures><ID>1\
    </ID></Fixtures></Body></Bodies>";

pub(super) fn with_joints(joints: &str) -> String {
    format!(
        "<World Version=\"1\"><Gravity>0 -10</Gravity>{}<Joints>{joints}</Joints></World>",
        TWO_BOXES.replace("{BOX}", BOX)
    )
}

#[test]
fn a_pulley_s_limit_becomes_a_rope_from_the_first_static_body() {
    let plan = plan(&with_joints(
        "<Joint Type=\"Pulley\"><BodyA>1</BodyA><BodyB>2</BodyB><GroundAnchorA>-2 8\
         </GroundAnchorA><GroundAnchorB>2 8</GroundAnchorB><LengthA>5</LengthA><LengthB>4\
         </LengthB><MaxLengthA>5.5</MaxLengthA><Ratio>1</Ratio></Joint>",
    ));
    assert!(reports(&plan).is_empty(), "{:?}", reports(&plan));
    let joints = plan.joints();
    assert_eq!(joints.len(), 2);
    assert_eq!(joints[0].kind, PlanJointKind::Pulley as u32);
    assert_eq!(joints[0].ground_anchor_a, Vec2::new(-2.0, 8.0));
    let rope = joints[1];
    assert_eq!((rope.joint, rope.kind), (NONE, PlanJointKind::Distance as u32));
    assert_eq!((rope.body_a, rope.body_b), (0, 1));
    assert_eq!(rope.anchor_a, Vec2::new(-2.0, 8.0));
    assert_eq!((rope.length, rope.min_length, rope.max_length), (5.5, 0.0, 5.5));
}

#[test]
fn a_gear_on_a_joint_left_out_is_skipped_and_springs_come_from_the_masses() {
    let plan = plan(&with_joints(
        "<Joint Type=\"Gear\"><BodyA>1</BodyA><BodyB>2</BodyB><JointA>1</JointA><JointB>2\
         </JointB><Ratio>2</Ratio></Joint>\
         <Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>-2 3\
         </LocalAnchorA><ReferenceAngle>1e9</ReferenceAngle></Joint>\
         <Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>2 4\
         </LocalAnchorA></Joint>\
         <Joint Type=\"Distance\"><BodyA>1</BodyA><BodyB>2</BodyB><Length>4.1231055</Length>\
         <FrequencyHz>2</FrequencyHz><DampingRatio>0.5</DampingRatio></Joint>",
    ));
    let found = reports(&plan);
    assert_eq!(found.len(), 2, "{found:?}");
    assert_eq!((found[0].0, found[0].2), (Code::BeyondBox2dRange as u32, 1));
    assert!(found[0].3.starts_with("ReferenceAngle 1e+09 lies beyond Box2D 2.4's working range"));
    assert_eq!(
        found[1],
        (
            Code::SkippedDependent as u32,
            "joint".to_owned(),
            0,
            "the gear couples joint 1, which was not created; gear skipped".to_owned()
        )
    );
    let joints = plan.joints();
    assert_eq!(joints.len(), 2);
    let spring = joints[1];
    assert_eq!(spring.kind, PlanJointKind::Distance as u32);
    let omega = 2.0 * crate::plan::range::PI * 2.0;
    let mass = 2.0f32 * 1.0 / (2.0 + 1.0);
    assert_eq!(spring.stiffness, mass * omega * omega);
    assert_eq!(spring.damping, 2.0 * mass * 0.5 * omega);
    assert_eq!((spring.min_length, spring.max_length), (0.0, f32::MAX));
}

#[test]
fn a_gear_on_two_revolute_joints_names_them_by_their_place_in_the_plan() {
    let plan = plan(&with_joints(
        "<Joint Type=\"Gear\"><BodyA>1</BodyA><BodyB>2</BodyB><JointA>1</JointA><JointB>2\
         </JointB><Ratio>2</Ratio></Joint>\
         <Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>-2 3\
         </LocalAnchorA></Joint>\
         <Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>2 4\
         </LocalAnchorA></Joint>",
    ));
    assert!(reports(&plan).is_empty(), "{:?}", reports(&plan));
    let gear = plan.joints()[2];
    assert_eq!((gear.joint, gear.kind), (0, PlanJointKind::Gear as u32));
    assert_eq!((gear.joint_a, gear.joint_b, gear.ratio), (0, 1, 2.0));
}

#[test]
fn a_gear_on_a_joint_to_a_disabled_body_is_skipped() {
    let xml = with_joints(
        "<Joint Type=\"Gear\"><BodyA>1</BodyA><BodyB>2</BodyB><JointA>1</JointA><JointB>2\
         </JointB><Ratio>2</Ratio></Joint>\
         <Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>-2 3\
         </LocalAnchorA></Joint>\
         <Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>2 4\
         </LocalAnchorA></Joint>",
    )
    .replacen("<Body Type=\"Dynamic\">", "<Body Type=\"Dynamic\"><Active>False</Active>", 1);
    let plan = plan(&xml);
    assert_eq!(plan.joints().len(), 2);
    assert_eq!(
        reports(&plan),
        vec![(
            Code::BadGearJoint as u32,
            "joint".to_owned(),
            0,
            "the gear couples joint 1, one of whose bodies is not Active: Box2D 2.x's gear \
             reads that body's place in an island it never joins; gear skipped"
                .to_owned()
        )]
    );
}

#[test]
fn a_gear_acts_on_the_bodies_b_of_its_joints_whatever_its_own_say() {
    let plan = plan(&with_joints(
        "<Joint Type=\"Gear\"><BodyA>2</BodyA><BodyB>0</BodyB><JointA>1</JointA><JointB>2\
         </JointB><Ratio>2</Ratio></Joint>\
         <Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>-2 3\
         </LocalAnchorA></Joint>\
         <Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>2 4\
         </LocalAnchorA></Joint>",
    ));
    let gear = plan.joints()[2];
    assert_eq!((gear.body_a, gear.body_b), (1, 2));
    assert_eq!(
        reports(&plan),
        vec![(
            Code::LossyJoint as u32,
            "joint".to_owned(),
            0,
            "BodyA 2 and BodyB 0 are not the bodies the joints it couples move, 1 and 2, on \
             which Box2D 2.x's gear acts: it was made between those"
                .to_owned()
        )]
    );
}

#[test]
fn a_gear_of_two_joints_moving_one_body_joins_it_to_the_first_joints_body_a() {
    let joints = "<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>-2 3\
         </LocalAnchorA></Joint>\
         <Joint Type=\"Prismatic\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>-2 3\
         </LocalAnchorA></Joint>";
    let gear = |a: u32, b: u32| {
        format!(
            "{joints}<Joint Type=\"Gear\"><BodyA>{a}</BodyA><BodyB>{b}</BodyB><JointA>0</JointA>\
             <JointB>1</JointB></Joint>"
        )
    };
    let plan_01 = plan(&with_joints(&gear(0, 1)));
    assert!(reports(&plan_01).is_empty(), "{:?}", reports(&plan_01));
    let made = plan_01.joints()[2];
    assert_eq!((made.kind, made.body_a, made.body_b), (PlanJointKind::Gear as u32, 0, 1));
    let plan_12 = plan(&with_joints(&gear(1, 2)));
    let made = plan_12.joints()[2];
    assert_eq!((made.body_a, made.body_b), (1, 0));
    assert_eq!(reports(&plan_12).len(), 1);
    assert_eq!(reports(&plan_12)[0].0, Code::LossyJoint as u32);
}

#[test]
fn a_joint_started_further_than_max_violation_is_refused() {
    let plan = plan(&with_joints(
        "<Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>3 0</LocalAnchorA>\
         </Joint><Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>",
    ));
    assert_eq!(plan.joints().len(), 1);
    assert_eq!(plan.joints()[0].joint, 1);
    assert_eq!(
        reports(&plan),
        vec![(
            Code::BeyondBox2dRange as u32,
            "joint".to_owned(),
            0,
            "it starts 5.83095169 m from satisfied: a joint further than 4 m from satisfied \
             lies beyond Box2D 2.4's working range (its position solver tears a body to NaN \
             once other joints act on it); joint not created"
                .to_owned()
        )]
    );
}

#[test]
fn a_farseer_only_joint_is_skipped_in_the_adapter_s_words() {
    let plan = plan(&with_joints("<Joint Type=\"Angle\"><BodyA>1</BodyA><BodyB>2</BodyB></Joint>"));
    assert!(plan.joints().is_empty());
    assert_eq!(
        reports(&plan),
        vec![(
            Code::SkippedJoint as u32,
            "joint".to_owned(),
            0,
            "a Farseer-only joint has no Box2D 2.4 equivalent; joint skipped".to_owned()
        )]
    );
}

#[test]
fn a_pulley_side_on_the_holding_static_body_gets_no_rope_of_a_body_to_itself() {
    let xml = "<World Version=\"1\"><Shapes><Shape Type=\"Circle\"><Radius>0.5</Radius>\
        <Position>0 0</Position></Shape></Shapes><Fixtures><Fixture><Shape>0</Shape><Density>1\
        </Density></Fixture></Fixtures><Bodies><Body Type=\"Static\"><Position>-2 0</Position>\
        </Body><Body Type=\"Dynamic\"><Position>2 0</Position><Fixtures><ID>0</ID></Fixtures>\
        </Body></Bodies><Joints><Joint Type=\"Pulley\"><BodyA>0</BodyA><BodyB>1</BodyB>\
        <GroundAnchorA>-2 5</GroundAnchorA><GroundAnchorB>2 5</GroundAnchorB><LengthA>5\
        </LengthA><LengthB>5</LengthB><Ratio>1</Ratio><MaxLengthA>6</MaxLengthA><MaxLengthB>6\
        </MaxLengthB></Joint></Joints></World>";
    let plan = plan(xml);
    let ropes: Vec<_> = plan.joints().iter().filter(|j| j.joint == NONE).collect();
    assert_eq!(ropes.len(), 1, "side B's rope only");
    assert_eq!((ropes[0].body_a, ropes[0].body_b), (0, 1));
    assert!(plan.joints().iter().all(|j| j.body_a != j.body_b));
    assert_eq!(
        reports(&plan),
        vec![(
            Code::LossyJoint as u32,
            "joint".to_owned(),
            0,
            "MaxLengthA 6 gives a limit of 6 m, which Box2D 2.4 cannot hold on body 0, the \
             static body that would hold its rope (a joint needs two bodies); the side is \
             unlimited"
                .to_owned()
        )]
    );
}
