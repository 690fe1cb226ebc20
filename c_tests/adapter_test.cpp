// The adapter's mapping of what the bit-for-bit scene (Version 1) does not cover: Version 2
// shapes and joints, spring stiffness computed after MassData, and what it reports instead
// of creating.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cfloat>

#include "test_macros.h"
#include "test_scenes.hpp"

static int null_scene_builds_nothing() {
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(nullptr, world);
    ENSURE(built.bodies.empty() && built.fixtures.empty() && built.joints.empty());
    ENSURE(built.reports.empty());
    ENSURE_EQ(world.GetBodyCount(), 0);
    b2Vec2 gravity = box2scene::scene_gravity(nullptr, b2Vec2(1.0f, 2.0f));
    ENSURE_FLOAT(gravity.x, 1.0f);
    ENSURE_FLOAT(gravity.y, 2.0f);
    return 0;
}

static int edges_are_one_sided_only_with_both_ghosts() {
    ScenePtr scene = load_text(R"(<World Version="2">
      <Shapes>
        <Shape Type="Edge"><Vertex1>0 0</Vertex1><Vertex2>1 0</Vertex2>
          <Vertex0>-1 0.5</Vertex0><HasVertex0>true</HasVertex0>
          <Vertex3>2 0.5</Vertex3><HasVertex3>true</HasVertex3></Shape>
        <Shape Type="Edge"><Vertex1>0 0</Vertex1><Vertex2>1 0</Vertex2>
          <Vertex3>2 0.5</Vertex3><HasVertex3>true</HasVertex3></Shape>
        <Shape Type="Edge"><Vertex1>0 0</Vertex1><Vertex2>1 0</Vertex2>
          <Vertex0>-1 0.5</Vertex0><HasVertex0>false</HasVertex0>
          <Vertex3>2 0.5</Vertex3><HasVertex3>true</HasVertex3></Shape>
      </Shapes>
      <Fixtures>
        <Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape></Fixture>
        <Fixture><Shape>2</Shape></Fixture>
      </Fixtures>
      <Bodies><Body Type="Static"><Fixtures><ID>0</ID><ID>1</ID><ID>2</ID></Fixtures></Body></Bodies>
      <Joints />
    </World>)");
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE(built.reports.empty());
    auto* smooth = static_cast<b2EdgeShape*>(built.fixtures[0]->GetShape());
    ENSURE(smooth->m_oneSided);
    ENSURE_FLOAT(smooth->m_vertex0.x, -1.0f);
    ENSURE_FLOAT(smooth->m_vertex0.y, 0.5f);
    ENSURE_FLOAT(smooth->m_vertex1.x, 0.0f);
    ENSURE_FLOAT(smooth->m_vertex2.x, 1.0f);
    ENSURE_FLOAT(smooth->m_vertex3.x, 2.0f);
    for (int i = 1; i <= 2; ++i) {
        auto* plain = static_cast<b2EdgeShape*>(built.fixtures[i]->GetShape());
        ENSURE(!plain->m_oneSided);
        ENSURE_FLOAT(plain->m_vertex2.x, 1.0f);
    }
    return 0;
}

static int chains_get_their_ghosts_or_extrapolated_ones() {
    ScenePtr scene = load_text(R"(<World Version="2">
      <Shapes>
        <Shape Type="Chain"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>2 1</Vertex></Vertices>
          <PrevVertex>-1 1</PrevVertex><HasPrevVertex>true</HasPrevVertex></Shape>
        <Shape Type="Loop"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>1 1</Vertex></Vertices></Shape>
        <Shape Type="Chain"><Loop>true</Loop>
          <Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>1 1</Vertex><Vertex>0 1</Vertex></Vertices></Shape>
      </Shapes>
      <Fixtures>
        <Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape></Fixture>
        <Fixture><Shape>2</Shape></Fixture>
      </Fixtures>
      <Bodies><Body Type="Static"><Fixtures><ID>0</ID><ID>1</ID><ID>2</ID></Fixtures></Body></Bodies>
      <Joints />
    </World>)");
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE(built.reports.empty());
    auto* open = static_cast<b2ChainShape*>(built.fixtures[0]->GetShape());
    ENSURE_EQ(open->m_count, 3);
    ENSURE_FLOAT(open->m_prevVertex.x, -1.0f);
    ENSURE_FLOAT(open->m_prevVertex.y, 1.0f);
    // No NextVertex: the last segment (1,0)->(2,1) continued by its own length.
    ENSURE_FLOAT(open->m_nextVertex.x, 3.0f);
    ENSURE_FLOAT(open->m_nextVertex.y, 2.0f);
    // A loop repeats its first vertex at the end.
    auto* loop = static_cast<b2ChainShape*>(built.fixtures[1]->GetShape());
    ENSURE_EQ(loop->m_count, 4);
    auto* square = static_cast<b2ChainShape*>(built.fixtures[2]->GetShape());
    ENSURE_EQ(square->m_count, 5);
    ENSURE_FLOAT(square->m_vertices[4].x, 0.0f);
    ENSURE_FLOAT(square->m_vertices[4].y, 0.0f);
    return 0;
}

/// Two bodies with a joint of `joint` between them; body 1's mass is overridden to 4 kg,
/// so stiffness computed before MassData would differ.
static ScenePtr pair_with(const char* joint) {
    std::string xml = R"(<World Version="2">
      <Shapes><Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Static" />
        <Body Type="Dynamic"><Position>0 3</Position><GravityScale>0.5</GravityScale>
          <MassData><Mass>4</Mass></MassData><Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints>)";
    xml += joint;
    xml += "</Joints></World>";
    return load_text(xml.c_str());
}

static int springs_use_the_final_masses() {
    ScenePtr scene = pair_with(R"(
      <Joint Type="Distance"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorB>0 0.5</LocalAnchorB>
        <Length>2.5</Length><FrequencyHz>3</FrequencyHz><DampingRatio>0.4</DampingRatio></Joint>
      <Joint Type="Wheel"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAxisA>0 1</LocalAxisA>
        <EnableMotor>true</EnableMotor><MaxMotorTorque>7</MaxMotorTorque><MotorSpeed>-3</MotorSpeed>
        <FrequencyHz>5</FrequencyHz><DampingRatio>0.9</DampingRatio></Joint>
      <Joint Type="Weld"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 3</LocalAnchorA>
        <FrequencyHz>6</FrequencyHz><DampingRatio>0.2</DampingRatio></Joint>)");
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE(built.reports.empty());
    b2Body* ground = built.bodies[0];
    b2Body* body = built.bodies[1];
    ENSURE_FLOAT(body->GetMass(), 4.0f);
    ENSURE_FLOAT(body->GetGravityScale(), 0.5f);

    float stiffness, damping;
    auto* spring = static_cast<b2DistanceJoint*>(built.joints[0]);
    b2LinearStiffness(stiffness, damping, 3.0f, 0.4f, ground, body);
    ENSURE_FLOAT(spring->GetStiffness(), stiffness);
    ENSURE_FLOAT(spring->GetDamping(), damping);
    ENSURE_FLOAT(spring->GetLength(), 2.5f);
    ENSURE_FLOAT(spring->GetMaxLength(), FLT_MAX);
    ENSURE(spring->GetMinLength() < 0.01f); // 0, raised to b2_linearSlop by Box2D

    auto* wheel = static_cast<b2WheelJoint*>(built.joints[1]);
    b2LinearStiffness(stiffness, damping, 5.0f, 0.9f, ground, body);
    ENSURE_FLOAT(wheel->GetStiffness(), stiffness);
    ENSURE_FLOAT(wheel->GetDamping(), damping);
    ENSURE(wheel->IsMotorEnabled());
    ENSURE_FLOAT(wheel->GetMaxMotorTorque(), 7.0f);
    ENSURE_FLOAT(wheel->GetMotorSpeed(), -3.0f);
    ENSURE_FLOAT(wheel->GetLocalAxisA().x, 0.0f);
    ENSURE_FLOAT(wheel->GetLocalAxisA().y, 1.0f);

    auto* weld = static_cast<b2WeldJoint*>(built.joints[2]);
    b2AngularStiffness(stiffness, damping, 6.0f, 0.2f, ground, body);
    ENSURE_FLOAT(weld->GetStiffness(), stiffness);
    ENSURE_FLOAT(weld->GetDamping(), damping);
    ENSURE(stiffness > 0.0f);
    return 0;
}

static int rods_and_ropes_are_distance_joints() {
    ScenePtr scene = pair_with(R"(
      <Joint Type="Distance"><BodyA>0</BodyA><BodyB>1</BodyB><Length>3</Length></Joint>
      <Joint Type="Rope"><BodyA>0</BodyA><BodyB>1</BodyB><MaxLength>4</MaxLength>
        <CollideConnected>true</CollideConnected></Joint>)");
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE(built.reports.empty());
    auto* rod = static_cast<b2DistanceJoint*>(built.joints[0]);
    ENSURE_FLOAT(rod->GetLength(), 3.0f);
    ENSURE_FLOAT(rod->GetMinLength(), 3.0f);
    ENSURE_FLOAT(rod->GetMaxLength(), 3.0f);
    ENSURE_FLOAT(rod->GetStiffness(), 0.0f);
    ENSURE(!rod->GetCollideConnected());

    ENSURE_EQ(built.joints[1]->GetType(), e_distanceJoint);
    auto* rope = static_cast<b2DistanceJoint*>(built.joints[1]);
    ENSURE_FLOAT(rope->GetLength(), 4.0f);
    ENSURE_FLOAT(rope->GetMaxLength(), 4.0f);
    ENSURE(rope->GetMinLength() < 0.01f);
    ENSURE_FLOAT(rope->GetStiffness(), 0.0f);
    ENSURE_FLOAT(rope->GetLocalAnchorA().x, -1.0f); // the Rope defaults
    ENSURE_FLOAT(rope->GetLocalAnchorB().x, 1.0f);
    ENSURE(rope->GetCollideConnected());
    return 0;
}

static int line_joint_is_a_springless_wheel_whose_motor_is_reported() {
    ScenePtr scene = pair_with(R"(
      <Joint Type="Line"><Name>slide</Name><BodyA>0</BodyA><BodyB>1</BodyB>
        <LocalAxisA>0 1</LocalAxisA><EnableLimit>true</EnableLimit>
        <LowerTranslation>-1</LowerTranslation><UpperTranslation>2</UpperTranslation>
        <EnableMotor>true</EnableMotor><MaxMotorForce>30</MaxMotorForce><MotorSpeed>2</MotorSpeed></Joint>)");
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE_EQ(built.joints[0]->GetType(), e_wheelJoint);
    auto* line = static_cast<b2WheelJoint*>(built.joints[0]);
    ENSURE_FLOAT(line->GetStiffness(), 0.0f);
    ENSURE_FLOAT(line->GetDamping(), 0.0f);
    ENSURE(line->IsLimitEnabled());
    ENSURE_FLOAT(line->GetLowerLimit(), -1.0f);
    ENSURE_FLOAT(line->GetUpperLimit(), 2.0f);
    ENSURE(!line->IsMotorEnabled());
    ENSURE_EQ(built.reports.size(), 1);
    const box2scene::Report& report = built.reports[0];
    ENSURE_EQ(report.code, B2S_CODE_LOSSY_LINE_MOTOR);
    ENSURE_STR(report.object, "joint");
    ENSURE_EQ(report.index, 0);
    ENSURE(report.name == "slide");
    ENSURE(!report.message.empty());
    return 0;
}

static int motor_and_friction_joints_keep_their_fields() {
    ScenePtr scene = pair_with(R"(
      <Joint Type="Motor"><BodyA>0</BodyA><BodyB>1</BodyB><LinearOffset>0.5 3</LinearOffset>
        <AngularOffset>0.25</AngularOffset><MaxForce>40</MaxForce><MaxTorque>9</MaxTorque>
        <CorrectionFactor>0.6</CorrectionFactor></Joint>
      <Joint Type="Friction"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 3</LocalAnchorA>
        <MaxForce>5</MaxForce><MaxTorque>2</MaxTorque></Joint>)");
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE(built.reports.empty());
    auto* motor = static_cast<b2MotorJoint*>(built.joints[0]);
    ENSURE_FLOAT(motor->GetLinearOffset().x, 0.5f);
    ENSURE_FLOAT(motor->GetLinearOffset().y, 3.0f);
    ENSURE_FLOAT(motor->GetAngularOffset(), 0.25f);
    ENSURE_FLOAT(motor->GetMaxForce(), 40.0f);
    ENSURE_FLOAT(motor->GetMaxTorque(), 9.0f);
    ENSURE_FLOAT(motor->GetCorrectionFactor(), 0.6f);
    auto* friction = static_cast<b2FrictionJoint*>(built.joints[1]);
    ENSURE_FLOAT(friction->GetLocalAnchorA().y, 3.0f);
    ENSURE_FLOAT(friction->GetMaxForce(), 5.0f);
    ENSURE_FLOAT(friction->GetMaxTorque(), 2.0f);
    return 0;
}

static int farseer_only_joints_are_skipped_and_reported() {
    ScenePtr scene = pair_with(R"(
      <Joint Type="Angle"><Name>angle</Name><BodyA>0</BodyA><BodyB>1</BodyB>
        <TargetAngle>1</TargetAngle></Joint>
      <Joint Type="Revolute"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>)");
    ENSURE(scene != nullptr);
    ENSURE_EQ(view_of(scene).joints[0].kind, B2S_JOINT_KIND_UNSUPPORTED);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE_EQ(built.joints.size(), 2);
    ENSURE(built.joints[0] == nullptr);
    ENSURE(built.joints[1] != nullptr);
    ENSURE_EQ(world.GetJointCount(), 1);
    ENSURE_EQ(built.reports.size(), 1);
    ENSURE_EQ(built.reports[0].code, B2S_CODE_SKIPPED_JOINT);
    ENSURE_EQ(built.reports[0].index, 0);
    ENSURE(built.reports[0].name == "angle");
    return 0;
}

/// Box2D 2.1's pulley limits become ropes held by the scene's first static body: without
/// one, or for a limit under the linear slop, the side stays unlimited and is reported.
static int pulley_limits_2_4_cannot_hold_are_reported() {
    auto pulley = [](const char* ground, const char* limits) {
        std::string xml = R"(<World Version="1">
          <Shapes><Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes>
          <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
          <Bodies>
            <Body Type="Dynamic"><Position>-2 0</Position><Fixtures><ID>0</ID></Fixtures></Body>
            <Body Type="Dynamic"><Position>2 0</Position><Fixtures><ID>0</ID></Fixtures></Body>)";
        xml += ground;
        xml += R"(</Bodies>
          <Joints><Joint Type="Pulley"><BodyA>0</BodyA><BodyB>1</BodyB>
            <GroundAnchorA>-2 5</GroundAnchorA><GroundAnchorB>2 5</GroundAnchorB>
            <LengthA>5</LengthA><LengthB>5</LengthB><Ratio>1</Ratio>)";
        xml += limits;
        xml += "</Joint></Joints></World>";
        return load_text(xml.c_str());
    };
    ScenePtr ungrounded = pulley("", "<MaxLengthA>6</MaxLengthA>");
    ENSURE(ungrounded != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(ungrounded.get(), world);
    ENSURE_EQ(world.GetJointCount(), 1);
    ENSURE_EQ(built.reports.size(), 1);
    ENSURE_EQ(built.reports[0].code, B2S_CODE_LOSSY_JOINT);
    ENSURE(built.reports[0].message.find("without a static body") != std::string::npos);

    ScenePtr short_side = pulley("<Body Type=\"Static\" />",
                                 "<MaxLengthA>6</MaxLengthA><MaxLengthB>0.001</MaxLengthB>");
    ENSURE(short_side != nullptr);
    b2World grounded(b2Vec2(0.0f, -10.0f));
    built = box2scene::build_world(short_side.get(), grounded);
    ENSURE_EQ(grounded.GetJointCount(), 2); // the pulley and side A's rope
    ENSURE_EQ(built.reports.size(), 1);
    ENSURE_EQ(built.reports[0].code, B2S_CODE_LOSSY_JOINT);
    ENSURE(built.reports[0].message.find("MaxLengthB 0.001") != std::string::npos);
    ENSURE(built.reports[0].message.find("shorter than the linear slop") != std::string::npos);
    return 0;
}

/// A pulley whose side hangs from the scene's first static body: that body would hold the
/// side's rope itself, which Box2D 2.4 asserts against (a joint needs two bodies).
static int pulley_limit_on_the_holding_static_body_is_reported() {
    ScenePtr scene = load_text(R"(<World Version="1">
      <Shapes><Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Static"><Position>-2 0</Position></Body>
        <Body Type="Dynamic"><Position>2 0</Position><Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints><Joint Type="Pulley"><BodyA>0</BodyA><BodyB>1</BodyB>
        <GroundAnchorA>-2 5</GroundAnchorA><GroundAnchorB>2 5</GroundAnchorB>
        <LengthA>5</LengthA><LengthB>5</LengthB><Ratio>1</Ratio>
        <MaxLengthA>6</MaxLengthA><MaxLengthB>6</MaxLengthB></Joint></Joints></World>)");
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE_EQ(world.GetJointCount(), 2); // the pulley and side B's rope
    ENSURE(built.joints[0] != nullptr);
    ENSURE_EQ(built.reports.size(), 1);
    const box2scene::Report& report = built.reports[0];
    ENSURE_EQ(report.code, B2S_CODE_LOSSY_JOINT);
    ENSURE_EQ(report.index, 0);
    ENSURE_STR(report.message.c_str(),
               "MaxLengthA 6 gives a limit of 6 m, which Box2D 2.4 cannot hold on body 0, the "
               "static body that would hold its rope (a joint needs two bodies); the side is "
               "unlimited");
    return 0;
}

static int mass_data_box2d_would_reject_is_reported() {
    // Moving the centre 3 m away leaves the computed inertia about the origin smaller than
    // mass * |centre|^2: Box2D 2.4 would assert on the negative central inertia.
    ScenePtr scene = load_text(R"(<World Version="1">
      <Shapes><Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Dynamic"><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Name>off centre</Name><Fixtures><ID>0</ID></Fixtures>
          <MassData><Center>3 0</Center></MassData></Body>
      </Bodies>
      <Joints />
    </World>)");
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE_EQ(built.reports.size(), 1);
    ENSURE_EQ(built.reports[0].code, B2S_CODE_INCONSISTENT_MASS_DATA);
    ENSURE_STR(built.reports[0].object, "body");
    ENSURE_EQ(built.reports[0].index, 1);
    ENSURE(built.reports[0].name == "off centre");
    ENSURE_FLOAT(built.bodies[1]->GetMass(), built.bodies[0]->GetMass());
    ENSURE_FLOAT(built.bodies[1]->GetLocalCenter().x, 0.0f);
    return 0;
}

static int negative_damping_never_reaches_box2d() {
    // The spec does not forbid a negative damping, so the scene keeps it; Box2D 2.4 asserts
    // against it, so the adapter reports it and uses 0.
    ScenePtr scene = load_text(R"(<World Version="1"><Shapes /><Fixtures /><Bodies>
      <Body Type="Dynamic"><LinearDamping>-0.5</LinearDamping><AngularDamping>0.25</AngularDamping>
      </Body></Bodies><Joints /></World>)");
    ENSURE(scene != nullptr);
    ENSURE_FLOAT(view_of(scene).bodies[0].linear_damping, -0.5f);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE_EQ(built.reports.size(), 1u);
    ENSURE_EQ(built.reports[0].code, B2S_CODE_NEGATIVE_VALUE);
    ENSURE_STR(built.reports[0].object, "body");
    ENSURE_FLOAT(built.bodies[0]->GetLinearDamping(), 0.0f);
    ENSURE_FLOAT(built.bodies[0]->GetAngularDamping(), 0.25f);
    return 0;
}

static int wheel_and_line_axes_are_directions() {
    ScenePtr scene = load_text(R"(<World Version="2"><Shapes /><Fixtures />
      <Bodies><Body Type="Static" /><Body Type="Dynamic" /></Bodies>
      <Joints>
        <Joint Type="Wheel"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAxisA>0 2</LocalAxisA></Joint>
        <Joint Type="Line"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAxisA>-3 0</LocalAxisA></Joint>
      </Joints></World>)");
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    const b2Vec2 wheel = static_cast<b2WheelJoint*>(built.joints[0])->GetLocalAxisA();
    const b2Vec2 line = static_cast<b2WheelJoint*>(built.joints[1])->GetLocalAxisA();
    ENSURE_FLOAT(wheel.x, 0.0f);
    ENSURE_FLOAT(wheel.y, 1.0f);
    ENSURE_FLOAT(line.x, -1.0f);
    ENSURE_FLOAT(line.y, 0.0f);
    return 0;
}

static int body_flags_reach_box2d() {
    ScenePtr scene = load_text(R"(<World Version="1">
      <Shapes><Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density><IsSensor>true</IsSensor>
        <FilterData><CategoryBits>0x8</CategoryBits><MaskBits>6</MaskBits>
          <GroupIndex>-7</GroupIndex></FilterData>
      </Fixture></Fixtures>
      <Bodies>
        <Body Type="Dynamic"><Active>false</Active><AllowSleep>false</AllowSleep>
          <Awake>false</Awake><Bullet>true</Bullet><FixedRotation>true</FixedRotation>
          <Angle>0.5</Angle>
          <Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints />
    </World>)");
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE(built.reports.empty());
    const b2Body* body = built.bodies[0];
    ENSURE(!body->IsEnabled());
    ENSURE(!body->IsSleepingAllowed());
    ENSURE(!body->IsAwake());
    ENSURE(body->IsBullet());
    ENSURE(body->IsFixedRotation());
    ENSURE_FLOAT(body->GetAngle(), 0.5f);
    const b2Fixture* fixture = built.fixtures[0];
    ENSURE(fixture->IsSensor());
    ENSURE_EQ(fixture->GetFilterData().categoryBits, 8);
    ENSURE_EQ(fixture->GetFilterData().maskBits, 6);
    ENSURE_EQ(fixture->GetFilterData().groupIndex, -7);
    return 0;
}

/// Box2D 2.4 has no names: the adapter leaves every user data pointer 0 (it is the host's),
/// and a host finds a named body as Built::bodies at the scene body's index.
static int names_are_not_user_data() {
    ScenePtr scene = load_text(R"(<World Version="1">
      <Shapes><Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes>
      <Fixtures><Fixture><Name>rim</Name><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Static"><Name>Ground</Name></Body>
        <Body Type="Dynamic"><Name>Door</Name><Position>2 0</Position>
          <Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints><Joint Type="Revolute"><Name>hinge</Name><BodyA>0</BodyA><BodyB>1</BodyB>
        <LocalAnchorA>2 0</LocalAnchorA></Joint></Joints>
    </World>)");
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE(built.reports.empty());
    ENSURE_EQ(world.GetBodyCount(), 2);
    for (b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext()) {
        ENSURE_EQ(body->GetUserData().pointer, 0);
        for (b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) {
            ENSURE_EQ(f->GetUserData().pointer, 0);
        }
    }
    ENSURE_EQ(built.joints[0]->GetUserData().pointer, 0);
    const b2s_scene_view* view = b2s_scene_get_view(scene.get());
    ENSURE(std::string(view->bodies[1].name) == "Door");
    ENSURE_FLOAT(built.bodies[1]->GetPosition().x, 2.0f);
    ENSURE(built.bodies[1]->GetType() == b2_dynamicBody);
    return 0;
}

/// Box2D 2.4 holds 16 filter bits: Farseer's "all" mask (2147483647) over categories in 16
/// bits collides as it says, silently; a category above bit 16, and a mask meeting one, are
/// reported.
static int filter_bits_are_reported_only_where_16_change_what_collides() {
    auto scene_with = [](const char* fixtures) {
        std::string text = std::string(R"(<World Version="2">
          <Shapes><Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes>
          <Fixtures>)") + fixtures + R"(</Fixtures>
          <Bodies><Body Type="Static"><Fixtures><ID>0</ID><ID>1</ID><ID>2</ID></Fixtures></Body>
          </Bodies><Joints /></World>)";
        return load_text(text.c_str());
    };
    auto fixture = [](const char* category, const char* mask) {
        return std::string("<Fixture><Shape>0</Shape><FilterData><CategoryBits>") + category +
               "</CategoryBits><MaskBits>" + mask + "</MaskBits></FilterData></Fixture>";
    };
    std::string all = fixture("1", "2147483647") + fixture("2", "2147483647") + fixture("4", "3");
    ScenePtr farseer = scene_with(all.c_str());
    ENSURE(farseer != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(farseer.get(), world);
    ENSURE(built.reports.empty());
    ENSURE_EQ(built.fixtures[0]->GetFilterData().maskBits, 0xFFFF);
    ENSURE_EQ(built.fixtures[2]->GetFilterData().maskBits, 3);

    std::string wide = fixture("0x10000", "1") + fixture("1", "2147483647") + fixture("2", "3");
    ScenePtr high = scene_with(wide.c_str());
    ENSURE(high != nullptr);
    b2World other(b2Vec2(0.0f, -10.0f));
    built = box2scene::build_world(high.get(), other);
    ENSURE_EQ(built.reports.size(), 2u);
    for (uint32_t i = 0; i < 2; ++i) {
        ENSURE_EQ(built.reports[i].code, B2S_CODE_LOSSY_FILTER);
        ENSURE_STR(built.reports[i].object, "fixture");
        ENSURE_EQ(built.reports[i].index, i);
    }
    return 0;
}

int main() {
    int failed = 0;
    failed += RUN_TEST(null_scene_builds_nothing);
    failed += RUN_TEST(edges_are_one_sided_only_with_both_ghosts);
    failed += RUN_TEST(chains_get_their_ghosts_or_extrapolated_ones);
    failed += RUN_TEST(springs_use_the_final_masses);
    failed += RUN_TEST(rods_and_ropes_are_distance_joints);
    failed += RUN_TEST(line_joint_is_a_springless_wheel_whose_motor_is_reported);
    failed += RUN_TEST(motor_and_friction_joints_keep_their_fields);
    failed += RUN_TEST(farseer_only_joints_are_skipped_and_reported);
    failed += RUN_TEST(mass_data_box2d_would_reject_is_reported);
    failed += RUN_TEST(negative_damping_never_reaches_box2d);
    failed += RUN_TEST(wheel_and_line_axes_are_directions);
    failed += RUN_TEST(body_flags_reach_box2d);
    failed += RUN_TEST(names_are_not_user_data);
    failed += RUN_TEST(pulley_limits_2_4_cannot_hold_are_reported);
    failed += RUN_TEST(pulley_limit_on_the_holding_static_body_is_reported);
    failed += RUN_TEST(filter_bits_are_reported_only_where_16_change_what_collides);
    return failed;
}
