//! Where the Box2D 2.3 plan (pybox2d) differs from 2.4's, to the bit and to the letter: the
//! Python tests build the same plans in pybox2d.

use super::tests::{BOX, identity, one_body, reports, with_joints};
use crate::error::Code;
use crate::plan::records::{PlanJointKind, PlanOptions};
use crate::plan::{Engine, Plan, make};
use crate::scene::Vec2;

fn plan_for(engine: Engine, xml: &str) -> Plan {
    let scene = crate::load(xml.as_bytes(), &Default::default()).unwrap_or_else(|e| panic!("{e}"));
    let options = PlanOptions {
        engine: engine as u32,
        placement: identity(),
        gravity: Vec2::new(0.0, -10.0),
        max_linear_speed: f32::MAX,
        name_bytes: 0,
    };
    make(&scene, &options).expect("a 2.x plan is made")
}

fn plan(xml: &str) -> Plan {
    plan_for(Engine::Box2d23, xml)
}

#[test]
fn springs_are_given_in_hertz_and_a_rope_is_2_3_s_rope_joint() {
    let plan = plan(&with_joints(
        "<Joint Type=\"Rope\"><BodyA>0</BodyA><BodyB>1</BodyB><MaxLength>3</MaxLength></Joint>\
         <Joint Type=\"Distance\"><BodyA>1</BodyA><BodyB>2</BodyB><Length>4.1231055</Length>\
         <FrequencyHz>2</FrequencyHz><DampingRatio>0.5</DampingRatio></Joint>\
         <Joint Type=\"Weld\"><BodyA>1</BodyA><BodyB>2</BodyB><LocalAnchorA>2 0.5</LocalAnchorA>\
         <FrequencyHz>5</FrequencyHz><DampingRatio>0.7</DampingRatio></Joint>\
         <Joint Type=\"Wheel\"><BodyA>1</BodyA><BodyB>2</BodyB><LocalAnchorA>4 1</LocalAnchorA>\
         <LocalAxisA>0 2</LocalAxisA><FrequencyHz>4</FrequencyHz><DampingRatio>0.25\
         </DampingRatio></Joint>",
    ));
    assert!(reports(&plan).is_empty(), "{:?}", reports(&plan));
    let [rope, distance, weld, wheel] = plan.joints() else { panic!("four joints") };
    assert_eq!((rope.kind, rope.length), (PlanJointKind::Rope as u32, 3.0));
    assert_eq!((distance.kind, distance.length), (PlanJointKind::Distance as u32, 4.1231055));
    assert_eq!((distance.hertz, distance.damping_ratio), (2.0, 0.5));
    assert_eq!((weld.hertz, weld.damping_ratio), (5.0, 0.7));
    assert_eq!((wheel.hertz, wheel.damping_ratio, wheel.axis), (4.0, 0.25, Vec2::new(0.0, 1.0)));
    for joint in [rope, distance, weld, wheel] {
        assert_eq!((joint.stiffness, joint.damping), (0.0, 0.0));
        assert_eq!((joint.min_length, joint.max_length), (0.0, 0.0));
    }
    let in_24 = plan_for(
        Engine::Box2d24,
        &with_joints(
            "<Joint Type=\"Rope\"><BodyA>0</BodyA><BodyB>1</BodyB><MaxLength>3</MaxLength></Joint>",
        ),
    );
    assert_eq!(in_24.joints()[0].kind, PlanJointKind::Distance as u32);
}

#[test]
fn a_line_joint_loses_its_motor_and_limit_and_gets_a_stand_in_spring() {
    let plan = plan(&with_joints(
        "<Joint Type=\"Line\"><BodyA>1</BodyA><BodyB>2</BodyB><LocalAxisA>0 1</LocalAxisA>\
         <LocalAnchorA>4 1</LocalAnchorA><EnableMotor>true</EnableMotor><EnableLimit>true\
         </EnableLimit><UpperTranslation>1</UpperTranslation></Joint>",
    ));
    let wheel = plan.joints()[0];
    assert_eq!(wheel.kind, PlanJointKind::Wheel as u32);
    assert!(!wheel.enable_limit && !wheel.enable_motor);
    assert_eq!((wheel.hertz, wheel.damping_ratio, wheel.upper), (1e-3, 0.0, 0.0));
    let lossy =
        |code: Code, message: &str| (code as u32, "joint".to_owned(), 0, message.to_owned());
    assert_eq!(
        reports(&plan),
        vec![
            lossy(
                Code::LossyLineMotor,
                "Box2D 2.3 has no linear motor on a line (wheel) joint; the motor is off"
            ),
            lossy(
                Code::LossyJoint,
                "Box2D 2.3's wheel joint has no translation limit; the line joint's limit is off"
            ),
            lossy(
                Code::LossyJoint,
                "Box2D 2.3's wheel joint without a spring reads uninitialised memory; a spring \
                 of 0.001 Hz, undamped, stands in for none (about 1e-6 N s per metre and kg a \
                 step)"
            ),
        ]
    );
}

#[test]
fn a_dynamic_body_without_mass_weighs_one_kilogram_in_2_3_and_nothing_in_2_4() {
    let xml = one_body("<Body Type=\"Dynamic\"/>");
    assert_eq!(plan(&xml).bodies()[0].mass.mass, 1.0);
    assert_eq!(plan_for(Engine::Box2d24, &xml).bodies()[0].mass.mass, 0.0);
}

#[test]
fn a_mass_data_without_central_inertia_leaves_the_body_out_in_2_3() {
    let xml = one_body(
        "<Body Type=\"Dynamic\"><MassData><Mass>1</Mass><Center>3 0</Center><Inertia>1\
         </Inertia></MassData><Fixtures><ID>0</ID></Fixtures></Body>",
    );
    let plan = plan(&xml);
    assert!(plan.bodies().is_empty());
    assert_eq!(
        reports(&plan)[0],
        (
            Code::BeyondBox2dRange as u32,
            "body".to_owned(),
            0,
            "its MassData leaves no positive inertia about the centre of mass (Inertia <= Mass \
             * |Center|^2), which Box2D 2.3 asserts against; body not created"
                .to_owned()
        )
    );
    let in_24 = plan_for(Engine::Box2d24, &xml);
    assert_eq!(in_24.bodies().len(), 1);
    assert_eq!(reports(&in_24)[0].0, Code::InconsistentMassData as u32);
}

#[test]
fn ghost_vertices_are_kept_each_on_its_own_nan_where_the_file_gives_none() {
    let xml = "<World Version=\"2\"><Shapes>\
        <Shape Type=\"Edge\"><Vertex1>0 0</Vertex1><Vertex2>1 0</Vertex2>\
        <Vertex0>-1 0.5</Vertex0><HasVertex0>true</HasVertex0></Shape>\
        <Shape Type=\"Chain\"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>2 1\
        </Vertex></Vertices><NextVertex>5 3</NextVertex><HasNextVertex>true</HasNextVertex>\
        </Shape></Shapes><Fixtures><Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape>\
        </Fixture></Fixtures><Bodies><Body Type=\"Static\"><Fixtures><ID>0</ID><ID>1</ID>\
        </Fixtures></Body></Bodies></World>";
    let plan = plan(xml);
    let (edge, chain) = (plan.points(&plan.shapes()[0]), plan.points(&plan.shapes()[1]));
    let v = Vec2::new;
    assert_eq!(edge.len(), 4);
    assert_eq!(edge[..3], [v(-1.0, 0.5), v(0.0, 0.0), v(1.0, 0.0)]);
    assert!(edge[3].x.is_nan() && edge[3].y.is_nan());
    assert!(chain[0].x.is_nan(), "no PrevVertex: none extrapolated");
    assert_eq!(chain[1..], [v(0.0, 0.0), v(1.0, 0.0), v(2.0, 1.0), v(5.0, 3.0)]);
}

#[test]
fn a_spinning_body_gets_its_origin_s_velocity_back_once_its_mass_is_final() {
    let offset = "<Shape Type=\"Circle\"><Radius>0.5</Radius><Position>1 0</Position></Shape>";
    let xml = one_body(
        "<Body Type=\"Dynamic\"><Position>3 4</Position><Angle>0.5</Angle><LinearVelocity>1 2\
         </LinearVelocity><AngularVelocity>3</AngularVelocity><Fixtures><ID>0</ID></Fixtures>\
         </Body>",
    )
    .replace(BOX, offset);
    let body = plan(&xml).bodies()[0];
    assert!(body.set_velocity);
    // v + w x (c - p), c the centre of mass (1, 0) turned by 0.5 rad, in floats
    let (c, s) = (0.5f32.cos(), 0.5f32.sin());
    let arm = Vec2::new((c * 1.0 - s * 0.0 + 3.0) - 3.0, (s * 1.0 + c * 0.0 + 4.0) - 4.0);
    assert_eq!(body.velocity_after_mass, Vec2::new(1.0 + -3.0 * arm.y, 2.0 + 3.0 * arm.x));
    assert!(!plan_for(Engine::Box2d24, &xml).bodies()[0].set_velocity);
}

#[test]
fn only_the_16_filter_bits_2_x_holds_are_planned() {
    let xml = one_body("<Body Type=\"Static\"><Fixtures><ID>0</ID></Fixtures></Body>").replace(
        "<Density>2</Density>",
        "<Density>2</Density><FilterData><CategoryBits>65538</CategoryBits><MaskBits>4294967295\
         </MaskBits></FilterData>",
    );
    let plan = plan(&xml);
    let filter = plan.shapes()[0].filter;
    assert_eq!((filter.category_bits, filter.mask_bits), (2, 0xFFFF));
    assert_eq!(reports(&plan)[0].0, Code::LossyFilter as u32);
    assert!(reports(&plan)[0].3.contains("above Box2D 2.3's 16 filter bits"));
}

#[test]
fn a_disabled_inverted_prismatic_limit_is_swapped_as_2_3_s_set_limits_wants_it() {
    let plan = plan(&with_joints(
        "<Joint Type=\"Prismatic\"><BodyA>1</BodyA><BodyB>2</BodyB><LocalAnchorA>4 1\
         </LocalAnchorA><LowerTranslation>2</LowerTranslation><UpperTranslation>1\
         </UpperTranslation></Joint>",
    ));
    assert_eq!((plan.joints()[0].lower, plan.joints()[0].upper), (1.0, 2.0));
    assert_eq!(
        reports(&plan),
        vec![(
            Code::BadLimit as u32,
            "joint".to_owned(),
            0,
            "its disabled limit has LowerTranslation 2 above UpperTranslation 1, which Box2D \
             2.3's SetLimits asserts against; they were passed swapped"
                .to_owned()
        )]
    );
}
