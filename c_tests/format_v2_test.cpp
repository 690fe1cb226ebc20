// The whole format in Box2D 2.4: the Farseer-written Version 2 and 3 files load, build with
// exactly the reports they deserve, map their constructs onto the right Box2D objects and
// stay finite; and small Version 2 scenes (a car on wheel springs, a rope, a loop, a motor
// joint, a soft weld, a chain missing a ghost vertex) behave as their fields say.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <algorithm>
#include <cmath>

#include "test_macros.h"
#include "test_worlds.hpp"

static World farseer_v2() {
    return World(load_project_file("tests/fixtures/scenes/farseer-v2.xml"));
}

static World farseer_v3() {
    return World(load_project_file("tests/fixtures/scenes/farseer-v3.xml"));
}

/// Whether every body has a finite position and angle.
// ---- farseer-v2.xml: every field written, True/False, Breakpoint on every joint

static int farseer_v2_reports_only_its_two_farseer_joints() {
    World w = farseer_v2();
    ENSURE(w.scene != nullptr);
    ENSURE_EQ(view_of(w.scene).version, 2);
    ENSURE_EQ(w.built.reports.size(), 2);
    // Joint 10 is the Angle joint, 11 the Slider; indices stay those of the file.
    for (uint32_t i = 0; i < 2; ++i) {
        const box2scene::Report& report = w.built.reports[i];
        ENSURE_EQ(report.code, B2S_CODE_SKIPPED_JOINT);
        ENSURE_STR(report.object, "joint");
        ENSURE_EQ(report.index, 10 + i);
        ENSURE(w.joint(10 + i) == nullptr);
    }
    ENSURE_EQ(w.world.GetBodyCount(), 4);
    ENSURE_EQ(w.world.GetJointCount(), 11); // 13 minus the two skipped
    return 0;
}

static int farseer_v2_edge_with_one_ghost_is_two_sided() {
    World w = farseer_v2();
    ENSURE(w.scene != nullptr);
    // Slot 1 is the ground body's second fixture: HasVertex0 True, HasVertex3 False.
    ENSURE_EQ(w.built.fixtures[1]->GetType(), b2Shape::e_edge);
    auto* edge = static_cast<b2EdgeShape*>(w.built.fixtures[1]->GetShape());
    ENSURE(!edge->m_oneSided);
    ENSURE_FLOAT(edge->m_vertex1.x, 20.0f);
    ENSURE_FLOAT(edge->m_vertex2.x, 25.0f);
    ENSURE_FLOAT(edge->m_vertex2.y, 2.0f);
    return 0;
}

static int farseer_v2_chain_keeps_its_ghosts_and_loop_closes() {
    World w = farseer_v2();
    ENSURE(w.scene != nullptr);
    ENSURE_EQ(w.built.fixtures[2]->GetType(), b2Shape::e_chain);
    auto* chain = static_cast<b2ChainShape*>(w.built.fixtures[2]->GetShape());
    ENSURE_EQ(chain->m_count, 3);
    ENSURE_FLOAT(chain->m_prevVertex.x, -35.0f);
    ENSURE_FLOAT(chain->m_prevVertex.y, 15.0f);
    ENSURE_FLOAT(chain->m_nextVertex.x, -15.0f);
    ENSURE_FLOAT(chain->m_nextVertex.y, 4.0f);

    // Type="Loop": four vertices, and Box2D repeats the first to close it.
    ENSURE_EQ(w.built.fixtures[3]->GetType(), b2Shape::e_chain);
    auto* loop = static_cast<b2ChainShape*>(w.built.fixtures[3]->GetShape());
    ENSURE_EQ(loop->m_count, 5);
    ENSURE_FLOAT(loop->m_vertices[4].x, -5.0f);
    ENSURE_FLOAT(loop->m_vertices[4].y, 20.0f);
    ENSURE_FLOAT(loop->m_vertices[3].x, -5.0f);
    ENSURE_FLOAT(loop->m_vertices[3].y, 30.0f);
    return 0;
}

static int farseer_v2_thirty_two_bit_mask_reaches_box2d_as_all_bits() {
    World w = farseer_v2();
    ENSURE(w.scene != nullptr);
    // Slot 5 is body 2's ball: MaskBits 4294967295, CategoryBits 2, GroupIndex -1.
    const b2Filter& filter = w.built.fixtures[5]->GetFilterData();
    ENSURE_EQ(filter.categoryBits, 2);
    ENSURE_EQ(filter.maskBits, 0xFFFF);
    ENSURE_EQ(filter.groupIndex, -1);
    ENSURE_FLOAT(w.body(1)->GetGravityScale(), 0.5f);
    return 0;
}

static int farseer_v2_line_with_a_spring_is_a_wheel() {
    World w = farseer_v2();
    ENSURE(w.scene != nullptr);
    ENSURE_EQ(w.joint(4)->GetType(), e_wheelJoint);
    auto* wheel = static_cast<b2WheelJoint*>(w.joint(4));
    float stiffness, damping;
    wheel_spring_22(5.0f, 0.8f, w.body(1), w.body(2), wheel->GetLocalAnchorA(),
                    wheel->GetLocalAnchorB(), wheel->GetLocalAxisA(), stiffness, damping);
    ENSURE_FLOAT(wheel->GetStiffness(), stiffness);
    ENSURE_FLOAT(wheel->GetDamping(), damping);
    ENSURE(stiffness > 0.0f);
    // A wheel's motor turns the wheel, which is what Farseer's MaxMotorTorque meant.
    ENSURE(wheel->IsMotorEnabled());
    ENSURE_FLOAT(wheel->GetMaxMotorTorque(), 20.0f);
    ENSURE_FLOAT(wheel->GetMotorSpeed(), -4.0f);
    ENSURE_FLOAT(wheel->GetLocalAxisA().x, 0.0f); // spelled LocalXAxis
    ENSURE_FLOAT(wheel->GetLocalAxisA().y, 1.0f);
    return 0;
}

static int farseer_v2_farseer_spellings_reach_box2d() {
    World w = farseer_v2();
    ENSURE(w.scene != nullptr);
    auto* prismatic = static_cast<b2PrismaticJoint*>(w.joint(1)); // LocalXAxis1
    ENSURE_FLOAT(prismatic->GetLocalAxisA().y, 1.0f);
    ENSURE(prismatic->IsLimitEnabled());
    auto* pulley = static_cast<b2PulleyJoint*>(w.joint(3)); // WorldAnchorA/B
    ENSURE_FLOAT(pulley->GetGroundAnchorA().x, -1.0f);
    ENSURE_FLOAT(pulley->GetGroundAnchorB().x, 1.0f);
    ENSURE_FLOAT(pulley->GetGroundAnchorB().y, 10.0f);
    auto* wheel = static_cast<b2WheelJoint*>(w.joint(5)); // Axis
    ENSURE_FLOAT(wheel->GetLocalAxisA().y, 1.0f);
    auto* gear = static_cast<b2GearJoint*>(w.joint(8));
    ENSURE(gear->GetJoint1() == w.joint(0) && gear->GetJoint2() == w.joint(1));
    return 0;
}

static int farseer_v2_rope_is_a_distance_joint_slack_up_to_nine() {
    World w = farseer_v2();
    ENSURE(w.scene != nullptr);
    ENSURE_EQ(w.joint(9)->GetType(), e_distanceJoint);
    auto* rope = static_cast<b2DistanceJoint*>(w.joint(9));
    ENSURE_FLOAT(rope->GetMaxLength(), 9.0f);
    ENSURE_FLOAT(rope->GetMinLength(), b2_linearSlop); // the adapter's 0, raised by Box2D
    ENSURE_FLOAT(rope->GetStiffness(), 0.0f);
    ENSURE_FLOAT(rope->GetLocalAnchorA().y, 10.0f);
    return 0;
}

static int farseer_v2_motor_joint_keeps_its_offsets_and_maxima() {
    World w = farseer_v2();
    ENSURE(w.scene != nullptr);
    ENSURE_EQ(w.joint(12)->GetType(), e_motorJoint);
    auto* motor = static_cast<b2MotorJoint*>(w.joint(12));
    ENSURE_FLOAT(motor->GetLinearOffset().x, -1.0f);
    ENSURE_FLOAT(motor->GetLinearOffset().y, 2.0f);
    ENSURE_FLOAT(motor->GetAngularOffset(), 0.5f);
    ENSURE_FLOAT(motor->GetMaxForce(), 50.0f);
    ENSURE_FLOAT(motor->GetMaxTorque(), 20.0f);
    ENSURE_FLOAT(motor->GetCorrectionFactor(), 0.4f);
    return 0;
}

static int farseer_v2_stays_finite_for_600_steps() {
    World w = farseer_v2();
    ENSURE(w.scene != nullptr);
    ENSURE(holds_for_steps(w.world, 600, [&] { return bodies_finite(w); }));
    return 0;
}

// ---- farseer-v3.xml: densities on shapes, fixtures as templates, bodies as Bindings

static int farseer_v3_builds_without_reports() {
    World w = farseer_v3();
    ENSURE(w.ok());
    ENSURE_EQ(view_of(w.scene).version, 3);
    ENSURE_EQ(w.world.GetBodyCount(), 3);
    ENSURE_EQ(w.world.GetJointCount(), 1);
    return 0;
}

static int farseer_v3_fixtures_have_their_shapes_densities() {
    World w = farseer_v3();
    ENSURE(w.ok());
    // Body 1 binds template 1 to the box (Density="1") and to the circle (Density="2.5").
    const b2Fixture* box = w.built.fixtures[1];
    const b2Fixture* ball = w.built.fixtures[2];
    ENSURE_EQ(box->GetType(), b2Shape::e_polygon);
    ENSURE_FLOAT(box->GetDensity(), 1.0f);
    ENSURE_EQ(ball->GetType(), b2Shape::e_circle);
    ENSURE_FLOAT(ball->GetDensity(), 2.5f);
    ENSURE_FLOAT(box->GetFriction(), 0.8f); // the template's
    ENSURE_FLOAT(ball->GetRestitution(), 0.25f);
    ENSURE_EQ(ball->GetFilterData().groupIndex, -2);
    ENSURE_NEAR(w.body(1)->GetMass(), 2.0 * 1.0 + 2.5 * b2_pi * 0.25, 1e-5);
    // Body 2 binds template 0 to the same circle.
    const b2Fixture* other = w.built.fixtures[3];
    ENSURE_FLOAT(other->GetDensity(), 2.5f);
    ENSURE_FLOAT(other->GetFriction(), 0.2f);
    ENSURE_FLOAT(w.built.fixtures[0]->GetDensity(), 0.0f);
    return 0;
}

static int farseer_v3_stays_finite_for_600_steps() {
    World w = farseer_v3();
    ENSURE(w.ok());
    ENSURE(holds_for_steps(w.world, 600, [&] { return bodies_finite(w); }));
    return 0;
}

// ---- Version 2 physics

static int car_settles_on_its_wheel_springs_at_the_predicted_sag() {
    // The wheel joints start at rest length: chassis centre 0.8 above each wheel centre,
    // wheels touching the ground.
    World w(R"(<World Version="2">
      <Gravity>0 -10</Gravity>
      <Shapes>
        <Shape Type="Edge"><Vertex1>-20 0</Vertex1><Vertex2>20 0</Vertex2></Shape>
        <Shape Type="Polygon"><Vertices>
          <Vertex>-2 -0.25</Vertex><Vertex>2 -0.25</Vertex><Vertex>2 0.25</Vertex><Vertex>-2 0.25</Vertex>
        </Vertices></Shape>
        <Shape Type="Circle"><Radius>0.4</Radius><Position>0 0</Position></Shape>
      </Shapes>
      <Fixtures>
        <Fixture><Shape>0</Shape><Friction>0.9</Friction></Fixture>
        <Fixture><Shape>1</Shape><Density>1</Density></Fixture>
        <Fixture><Shape>2</Shape><Density>1</Density><Friction>0.9</Friction></Fixture>
      </Fixtures>
      <Bodies>
        <Body Type="Static"><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>0 1.2</Position><Fixtures><ID>1</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>-1.5 0.4</Position><Fixtures><ID>2</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>1.5 0.4</Position><Fixtures><ID>2</ID></Fixtures></Body>
      </Bodies>
      <Joints>
        <Joint Type="Wheel"><BodyA>1</BodyA><BodyB>2</BodyB><LocalAnchorA>-1.5 -0.8</LocalAnchorA>
          <LocalAxisA>0 1</LocalAxisA><FrequencyHz>2</FrequencyHz><DampingRatio>0.7</DampingRatio></Joint>
        <Joint Type="Wheel"><BodyA>1</BodyA><BodyB>3</BodyB><LocalAnchorA>1.5 -0.8</LocalAnchorA>
          <LocalAxisA>0 1</LocalAxisA><FrequencyHz>2</FrequencyHz><DampingRatio>0.7</DampingRatio></Joint>
      </Joints>
    </World>)");
    ENSURE(w.ok());
    b2Body* chassis = w.body(1);
    // The prediction. Box2D 2.2's wheel spring turns the frequency into k = m_eff (2 pi f)^2
    // with m_eff the effective mass along the axis, 1 / (1/M + 1/m + sAx^2 / I): M the
    // chassis, 4 x 0.5 x 1 = 2 kg, I = M (4^2 + 0.5^2) / 12 = 2.71 kg m^2; m a wheel,
    // pi 0.4^2 = 0.503 kg; sAx = 1.5 m the anchor's lever across the vertical axis:
    // m_eff = 0.301 kg, k = 47.6 N/m (b2LinearStiffness's reduced mass M m / (M + m) would
    // give 63.5). At rest each wheel stands on the ground and each spring holds half the
    // chassis weight, M g / 2 = 10 N (the chassis is symmetric about its centre and the
    // wheels sit at +-1.5; a wheel's own weight goes straight into the ground, not through
    // its spring). Box2D's soft constraint applies exactly k * C once at rest, so each spring
    // compresses by sag = (M g / 2) / k = 0.21 m.
    const float M = chassis->GetMass();
    const float m = w.body(2)->GetMass();
    const float I = M * (16.0f + 0.25f) / 12.0f;
    const float omega = 2.0f * b2_pi * 2.0f;
    const float k = omega * omega / (1.0f / M + 1.0f / m + 1.5f * 1.5f / I);
    ENSURE_NEAR(static_cast<b2WheelJoint*>(w.joint(0))->GetStiffness(), k, 1e-4 * k);
    const float predicted = M * 10.0f / 2.0f / k;

    step_for(w.world, 600);
    for (int wheel = 2; wheel <= 3; ++wheel) {
        float sag = 0.8f - (chassis->GetPosition().y - w.body(wheel)->GetPosition().y);
        ENSURE_NEAR(sag, predicted, 0.05 * predicted);
    }
    ENSURE_NEAR(chassis->GetAngle(), 0.0, 1e-3);
    return 0;
}

static int rope_never_stretches_beyond_its_max_length() {
    // A 20 kg box starts 3 m from the anchor, falls until the 5 m rope catches it, and swings.
    World w(R"(<World Version="2">
      <Shapes><Shape Type="Polygon"><Vertices>
        <Vertex>-0.5 -0.5</Vertex><Vertex>0.5 -0.5</Vertex><Vertex>0.5 0.5</Vertex><Vertex>-0.5 0.5</Vertex>
      </Vertices></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>20</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Static"><Position>0 10</Position></Body>
        <Body Type="Dynamic"><Position>3 9.5</Position><LinearVelocity>0 -2</LinearVelocity>
          <Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints>
        <Joint Type="Rope"><BodyA>0</BodyA><BodyB>1</BodyB>
          <LocalAnchorA>0 0</LocalAnchorA><LocalAnchorB>0 0.5</LocalAnchorB><MaxLength>5</MaxLength></Joint>
      </Joints>
    </World>)");
    ENSURE(w.ok());
    b2Joint* rope = w.joint(0);
    b2Body* box = w.body(1);
    float longest = 0.0f;
    float leftmost = box->GetPosition().x;
    ENSURE(holds_for_steps(w.world, 600, [&] {
        float length = b2Distance(rope->GetAnchorA(), rope->GetAnchorB());
        longest = std::max(longest, length);
        leftmost = std::min(leftmost, box->GetPosition().x);
        return length <= 5.0f + b2_linearSlop;
    }));
    ENSURE(longest > 5.0f - b2_linearSlop); // it went taut
    ENSURE(leftmost < 0.0f);                // and swung through the bottom
    return 0;
}

static int ball_dropped_in_a_loop_stays_inside() {
    // Box2D 2.4 chains collide on one side only, to the right of each segment: this loop is
    // wound clockwise so that side faces in. Its closing segment, (5 0) back to (-5 0), is
    // the floor the ball lands on: a loop left open would drop it.
    World w(R"(<World Version="2">
      <Shapes>
        <Shape Type="Loop"><Vertices>
          <Vertex>-5 0</Vertex><Vertex>-5 10</Vertex><Vertex>5 10</Vertex><Vertex>5 0</Vertex>
        </Vertices></Shape>
        <Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape>
      </Shapes>
      <Fixtures>
        <Fixture><Shape>0</Shape></Fixture>
        <Fixture><Shape>1</Shape><Density>1</Density><Restitution>0.7</Restitution></Fixture>
      </Fixtures>
      <Bodies>
        <Body Type="Static"><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>0 8</Position><LinearVelocity>15 5</LinearVelocity>
          <Fixtures><ID>1</ID></Fixtures></Body>
      </Bodies>
      <Joints />
    </World>)");
    ENSURE(w.ok());
    b2Body* ball = w.body(1);
    ENSURE(holds_for_steps(w.world, 600, [&] {
        b2Vec2 p = ball->GetPosition();
        return p.x > -5.0f && p.x < 5.0f && p.y > 0.0f && p.y < 10.0f;
    }));
    ENSURE(ball->GetPosition().y < 1.0f); // at rest on the closing segment
    return 0;
}

static int motor_joint_reaches_its_offsets() {
    // The 1 kg box starts on the ground body's origin; the motor's 50 N beat its weight.
    World w(R"(<World Version="2">
      <Shapes><Shape Type="Polygon"><Vertices>
        <Vertex>-0.5 -0.5</Vertex><Vertex>0.5 -0.5</Vertex><Vertex>0.5 0.5</Vertex><Vertex>-0.5 0.5</Vertex>
      </Vertices></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Static"><Position>1 1</Position></Body>
        <Body Type="Dynamic"><Position>1 1</Position><Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints>
        <Joint Type="Motor"><BodyA>0</BodyA><BodyB>1</BodyB><LinearOffset>2 3</LinearOffset>
          <AngularOffset>0.5</AngularOffset><MaxForce>50</MaxForce><MaxTorque>10</MaxTorque>
          <CorrectionFactor>0.3</CorrectionFactor></Joint>
      </Joints>
    </World>)");
    ENSURE(w.ok());
    b2Body* box = w.body(1);
    step_for(w.world, 600);
    ENSURE_NEAR(box->GetPosition().x, 3.0, 0.01);
    ENSURE_NEAR(box->GetPosition().y, 4.0, 0.01);
    ENSURE_NEAR(box->GetAngle(), 0.5, 0.01);
    return 0;
}

/// The beam's angle relative to the static body it is welded to.
static float weld_angle(const World& w) {
    return w.body(1)->GetAngle() - w.body(0)->GetAngle();
}

static int soft_weld_bends_under_load_and_recovers() {
    // A 2 m beam welded by its end to a static body at (0 5), at the reference angle 0.2,
    // with a 1.26 kg ball hanging from its tip. GravityScale 0 leaves the ball as its only
    // load, so once the ball is gone the spring has nothing left to hold.
    World w(R"(<World Version="2">
      <Shapes>
        <Shape Type="Polygon"><Vertices>
          <Vertex>-1 -0.1</Vertex><Vertex>1 -0.1</Vertex><Vertex>1 0.1</Vertex><Vertex>-1 0.1</Vertex>
        </Vertices></Shape>
        <Shape Type="Circle"><Radius>0.2</Radius><Position>0 0</Position></Shape>
      </Shapes>
      <Fixtures>
        <Fixture><Shape>0</Shape><Density>1</Density></Fixture>
        <Fixture><Shape>1</Shape><Density>10</Density></Fixture>
      </Fixtures>
      <Bodies>
        <Body Type="Static"><Position>0 5</Position></Body>
        <Body Type="Dynamic"><Position>0.980067 5.198669</Position><Angle>0.2</Angle>
          <GravityScale>0</GravityScale><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>1.960133 4.397339</Position><Fixtures><ID>1</ID></Fixtures></Body>
      </Bodies>
      <Joints>
        <Joint Type="Weld"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorB>-1 0</LocalAnchorB>
          <ReferenceAngle>0.2</ReferenceAngle><FrequencyHz>4</FrequencyHz><DampingRatio>0.7</DampingRatio></Joint>
        <Joint Type="Revolute"><BodyA>1</BodyA><BodyB>2</BodyB>
          <LocalAnchorA>1 0</LocalAnchorA><LocalAnchorB>0 1</LocalAnchorB></Joint>
      </Joints>
    </World>)");
    ENSURE(w.ok());
    ENSURE(static_cast<b2WeldJoint*>(w.joint(0))->GetStiffness() > 0.0f);
    step_for(w.world, 300);
    float loaded = weld_angle(w);
    w.world.DestroyBody(w.body(2));
    step_for(w.world, 300);
    float recovered = weld_angle(w);
    ENSURE(loaded < 0.2f - 0.1f); // bent down, by a tenth of a radian at least
    ENSURE_NEAR(recovered, 0.2, 0.005);
    return 0;
}

static int chain_missing_a_ghost_gets_one_continuing_its_end_segment() {
    // Written the way Farseer writes it: HasPrevVertex False beside a PrevVertex of "0 0",
    // which must not be used. The chain runs right to left, so its collision side (the
    // right of each segment in Box2D 2.4) faces up: a flat top from (10 4) to (6 4), then a
    // slope down to (0 0). The ball rolls to the right, off the chain's first vertex.
    World w(R"(<World Version="2">
      <Shapes>
        <Shape Type="Chain">
          <Vertices><Vertex>10 4</Vertex><Vertex>6 4</Vertex><Vertex>0 0</Vertex></Vertices>
          <HasPrevVertex>False</HasPrevVertex><HasNextVertex>True</HasNextVertex>
          <PrevVertex>0 0</PrevVertex><NextVertex>-3 -4</NextVertex>
        </Shape>
        <Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape>
      </Shapes>
      <Fixtures>
        <Fixture><Shape>0</Shape></Fixture>
        <Fixture><Shape>1</Shape><Density>1</Density></Fixture>
      </Fixtures>
      <Bodies>
        <Body Type="Static"><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>8 4.51</Position><LinearVelocity>1 0</LinearVelocity>
          <Fixtures><ID>1</ID></Fixtures></Body>
      </Bodies>
      <Joints />
    </World>)");
    ENSURE(w.ok());
    auto* chain = static_cast<b2ChainShape*>(w.built.fixtures[0]->GetShape());
    // The adapter's extrapolation: the first vertex plus (first - second) = (14 4).
    ENSURE_FLOAT(chain->m_prevVertex.x, 14.0f);
    ENSURE_FLOAT(chain->m_prevVertex.y, 4.0f);
    ENSURE_FLOAT(chain->m_nextVertex.x, -3.0f);
    ENSURE_FLOAT(chain->m_nextVertex.y, -4.0f);

    // A ghost that continues the top straight tells Box2D there is no corner to roll
    // around: the ball leaves the end at the speed it rolled, in free fall. (A ghost
    // bending down, such as the unused "0 0", makes it round the corner and speeds it up.)
    b2Body* ball = w.body(1);
    float rolling = 0.0f;
    ENSURE(holds_for_steps(w.world, 240, [&] {
        b2Vec2 p = ball->GetPosition();
        if (p.x < 10.0f) {
            rolling = ball->GetLinearVelocity().x;
            return p.y > 4.5f;
        }
        return true;
    }));
    ENSURE(ball->GetPosition().x > 10.0f && ball->GetPosition().y < 4.0f);
    ENSURE(rolling > 0.5f);
    ENSURE_NEAR(ball->GetLinearVelocity().x, rolling, 1e-3);
    return 0;
}

int main() {
    int failed = 0;
    failed += RUN_TEST(farseer_v2_reports_only_its_two_farseer_joints);
    failed += RUN_TEST(farseer_v2_edge_with_one_ghost_is_two_sided);
    failed += RUN_TEST(farseer_v2_chain_keeps_its_ghosts_and_loop_closes);
    failed += RUN_TEST(farseer_v2_thirty_two_bit_mask_reaches_box2d_as_all_bits);
    failed += RUN_TEST(farseer_v2_line_with_a_spring_is_a_wheel);
    failed += RUN_TEST(farseer_v2_farseer_spellings_reach_box2d);
    failed += RUN_TEST(farseer_v2_rope_is_a_distance_joint_slack_up_to_nine);
    failed += RUN_TEST(farseer_v2_motor_joint_keeps_its_offsets_and_maxima);
    failed += RUN_TEST(farseer_v2_stays_finite_for_600_steps);
    failed += RUN_TEST(farseer_v3_builds_without_reports);
    failed += RUN_TEST(farseer_v3_fixtures_have_their_shapes_densities);
    failed += RUN_TEST(farseer_v3_stays_finite_for_600_steps);
    failed += RUN_TEST(car_settles_on_its_wheel_springs_at_the_predicted_sag);
    failed += RUN_TEST(rope_never_stretches_beyond_its_max_length);
    failed += RUN_TEST(ball_dropped_in_a_loop_stays_inside);
    failed += RUN_TEST(motor_joint_reaches_its_offsets);
    failed += RUN_TEST(soft_weld_bends_under_load_and_recovers);
    failed += RUN_TEST(chain_missing_a_ghost_gets_one_continuing_its_end_segment);
    return failed;
}
