// The adapter's working range (box2scene::working_range): a value beyond it never reaches
// Box2D; its object is not created and reported beyond-box2d-range, naming the field and
// the value, and what depends on it is reported skipped-dependent. What Box2D would assert
// against or turn into NaN, whatever the bounds, is refused the same way.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string>

#include "test_macros.h"
#include "test_scenes.hpp"
#include "test_worlds.hpp"

/// The number of reports with `code` about `object`.
static int count_reports(const box2scene::Built& built, b2s_code code, const char* object) {
    int count = 0;
    for (const box2scene::Report& report : built.reports) {
        count += report.code == code && std::string(report.object) == object;
    }
    return count;
}

/// Whether a report with `code` about `object` `index` says every one of `words`.
static bool reported(const box2scene::Built& built, b2s_code code, const char* object,
                     uint32_t index, std::initializer_list<const char*> words) {
    for (const box2scene::Report& report : built.reports) {
        if (report.code != code || std::string(report.object) != object ||
            report.index != index) {
            continue;
        }
        bool all = true;
        for (const char* word : words) {
            all = all && report.message.find(word) != std::string::npos;
        }
        if (all) {
            return true;
        }
        std::fprintf(stderr, "report: %s\n", report.message.c_str());
    }
    return false;
}

/// Steps a second of the world: what was created must stay finite.
static bool stays_finite(World& w) {
    return holds_for_steps(w.world, 60, [&] {
        for (const b2Body* body : w.built.bodies) {
            if (body != nullptr && !(std::isfinite(body->GetPosition().x) &&
                                     std::isfinite(body->GetPosition().y) &&
                                     std::isfinite(body->GetAngle()))) {
                return false;
            }
        }
        return true;
    });
}

static const char* const kBall =
    R"(<Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape>)";

static int a_body_beyond_range_takes_its_fixtures_joints_and_gears_along() {
    std::string xml = std::string(R"(<World Version="2"><Shapes>)") + kBall + R"(</Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Static" />
        <Body Type="Dynamic"><Position>0 2</Position><LinearVelocity>3.40282347e+38 0</LinearVelocity>
          <Fixtures><ID>0</ID><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>3 2</Position><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>6 2</Position><GravityScale>200</GravityScale>
          <Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints>
        <Joint Type="Revolute"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 2</LocalAnchorA></Joint>
        <Joint Type="Revolute"><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>3 2</LocalAnchorA></Joint>
        <Joint Type="Gear"><BodyA>1</BodyA><BodyB>2</BodyB><JointA>0</JointA><JointB>1</JointB></Joint>
      </Joints></World>)";
    World w(xml.c_str());
    ENSURE(w.scene != nullptr);
    ENSURE(w.body(1) == nullptr);
    ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "body", 1,
                    {"LinearVelocity (3.40282347e+38, 0)", "+-1000 m/s", "not created"}));
    ENSURE_EQ(count_reports(w.built, B2S_CODE_SKIPPED_DEPENDENT, "fixture"), 2 + 1);
    ENSURE(w.joint(0) == nullptr && w.joint(2) == nullptr);
    ENSURE(reported(w.built, B2S_CODE_SKIPPED_DEPENDENT, "joint", 0, {"body 1"}));
    ENSURE(reported(w.built, B2S_CODE_SKIPPED_DEPENDENT, "joint", 2, {"joint 0"}));
    // With the world's gravity of (0, -10), a GravityScale of 200 pulls at 2000 m/s^2.
    ENSURE(w.body(3) == nullptr);
    ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "body", 3,
                    {"GravityScale times the world's gravity (0, -2000)"}));
    ENSURE(w.body(2) != nullptr && w.joint(1) != nullptr);
    ENSURE(stays_finite(w));
    return 0;
}

static int shapes_and_fixtures_beyond_range_are_not_made() {
    World w(R"(<World Version="2">
      <Shapes>
        <Shape Type="Circle"><Radius>1e30</Radius><Position>0 0</Position></Shape>
        <Shape Type="Polygon"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>0 200000</Vertex></Vertices></Shape>
        <Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape>
      </Shapes>
      <Fixtures>
        <Fixture><Shape>0</Shape></Fixture>
        <Fixture><Shape>1</Shape></Fixture>
        <Fixture><Shape>2</Shape><Density>1e30</Density></Fixture>
        <Fixture><Shape>2</Shape><Density>1</Density><Restitution>1.40129846e-45</Restitution></Fixture>
      </Fixtures>
      <Bodies><Body Type="Dynamic"><Fixtures><ID>0</ID><ID>1</ID><ID>2</ID><ID>3</ID></Fixtures></Body></Bodies>
      <Joints /></World>)");
    ENSURE(w.scene != nullptr);
    ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "shape", 0,
                    {"Radius 1.00000002e+30", "shape not created"}));
    ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "shape", 1, {"Vertex 2 (0, 200000)"}));
    ENSURE(reported(w.built, B2S_CODE_SKIPPED_DEPENDENT, "fixture", 0, {"shape 0"}));
    ENSURE(reported(w.built, B2S_CODE_SKIPPED_DEPENDENT, "fixture", 1, {"shape 1"}));
    ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "fixture", 2,
                    {"fixture 2 of body 0", "Density 1.00000002e+30", "fixture not created"}));
    // A subnormal restitution is no danger: the body keeps that fixture alone.
    ENSURE(w.built.fixtures[3] != nullptr);
    ENSURE(w.built.fixtures[0] == nullptr && w.built.fixtures[1] == nullptr &&
           w.built.fixtures[2] == nullptr);
    ENSURE_NEAR(w.body(0)->GetMass(), b2_pi * 0.25, 1e-6);
    ENSURE(stays_finite(w));
    return 0;
}

static int gravity_beyond_range_leaves_the_hosts() {
    World w(R"(<World Version="1"><Gravity>0 -1e30</Gravity>
      <Shapes /><Fixtures /><Bodies /><Joints /></World>)");
    ENSURE(w.scene != nullptr);
    b2Vec2 gravity = box2scene::scene_gravity(w.scene.get(), b2Vec2(0.0f, -9.8f));
    ENSURE_FLOAT(gravity.y, -9.8f);
    ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "world", 0,
                    {"Gravity (0, -1.00000002e+30)", "fallback"}));
    return 0;
}

/// Masses Box2D would assert against: one it divides by into infinity (its centre of mass
/// becomes 0 * infinity), and a tiny ball 1 km from its body's origin, which leaves no
/// inertia about the centre in floats.
static int masses_box2d_cannot_take_are_refused() {
    World w(R"(<World Version="2">
      <Shapes>
        <Shape Type="Circle"><Radius>1</Radius><Position>0 0</Position></Shape>
        <Shape Type="Circle"><Radius>0.001</Radius><Position>1000 0</Position></Shape>
      </Shapes>
      <Fixtures>
        <Fixture><Shape>0</Shape><Density>1e-44</Density></Fixture>
        <Fixture><Shape>1</Shape><Density>1</Density></Fixture>
      </Fixtures>
      <Bodies>
        <Body Type="Dynamic"><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Fixtures><ID>1</ID></Fixtures></Body>
        <Body Type="Dynamic"><FixedRotation>true</FixedRotation><Fixtures><ID>1</ID></Fixtures></Body>
      </Bodies>
      <Joints /></World>)");
    ENSURE(w.scene != nullptr);
    ENSURE(w.body(0) == nullptr && w.body(1) == nullptr);
    for (uint32_t body : {0u, 1u}) {
        ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "body", body,
                        {"with fixture", "no positive inertia about its centre of mass"}));
    }
    // Without rotation, Box2D uses no inertia and asserts nothing.
    ENSURE(w.body(2) != nullptr);
    ENSURE(stays_finite(w));
    return 0;
}

/// Joints whose solver would overflow, lose every bit to cancellation, or assert.
static int joints_box2d_cannot_take_are_refused() {
    std::string xml = std::string(R"(<World Version="2"><Shapes>)") + kBall + R"(</Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Static" />
        <Body Type="Dynamic"><Position>0 2</Position><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Static"><Position>5 0</Position></Body>
        <Body Type="Dynamic"><Position>3 2</Position><Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints>
        <Joint Type="Weld"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 2</LocalAnchorA>
          <LocalAnchorB>50 0</LocalAnchorB></Joint>
        <Joint Type="Distance"><BodyA>0</BodyA><BodyB>2</BodyB><FrequencyHz>2</FrequencyHz></Joint>
        <Joint Type="Prismatic"><BodyA>0</BodyA><BodyB>3</BodyB><LocalAnchorA>3 2</LocalAnchorA>
          <LowerTranslation>1</LowerTranslation><UpperTranslation>-1</UpperTranslation></Joint>
        <Joint Type="Revolute"><BodyA>3</BodyA><BodyB>2</BodyB></Joint>
        <Joint Type="Revolute"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 2</LocalAnchorA></Joint>
        <Joint Type="Gear"><BodyA>3</BodyA><BodyB>1</BodyB><JointA>3</JointA><JointB>4</JointB></Joint>
        <Joint Type="Motor"><BodyA>0</BodyA><BodyB>1</BodyB><CorrectionFactor>2</CorrectionFactor></Joint>
        <Joint Type="Wheel"><BodyA>0</BodyA><BodyB>3</BodyB><LocalAxisA>1e-9 0</LocalAxisA></Joint>
      </Joints></World>)";
    World w(xml.c_str());
    ENSURE(w.scene != nullptr);
    // 50 m out on a ball of radius 0.5 m: 141 radii of gyration, past a weld's 75.
    ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "joint", 0,
                    {"LocalAnchorB", "radii of gyration", "at most 75"}));
    ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "joint", 1,
                    {"spring", "without mass"}));
    // A disabled limit the wrong way round: Box2D asserts, so it gets the limits swapped.
    ENSURE(w.joint(2) != nullptr);
    ENSURE(reported(w.built, B2S_CODE_BAD_LIMIT, "joint", 2, {"swapped"}));
    auto* prismatic = static_cast<b2PrismaticJoint*>(w.joint(2));
    ENSURE_FLOAT(prismatic->GetLowerLimit(), -1.0f);
    ENSURE_FLOAT(prismatic->GetUpperLimit(), 1.0f);
    // Joint 3's body B is static: Box2D asserts against a gear on it.
    ENSURE(w.joint(3) != nullptr && w.joint(5) == nullptr);
    ENSURE(reported(w.built, B2S_CODE_BAD_GEAR_JOINT, "joint", 5, {"joint 3", "not dynamic"}));
    ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "joint", 6,
                    {"CorrectionFactor 2", "[0, 1]"}));
    ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "joint", 7,
                    {"The length of LocalAxisA", "at least 1e-06"}));
    ENSURE(stays_finite(w));
    return 0;
}

/// Box2D 2.4 keeps the velocity a static body is made with, and moves the body by it once
/// a joint puts it in an island.
static int static_bodies_stay_put() {
    std::string xml = std::string(R"(<World Version="1"><Shapes>)") + kBall + R"(</Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Static"><LinearVelocity>1 0</LinearVelocity><AngularVelocity>1</AngularVelocity></Body>
        <Body Type="Dynamic"><Position>0 3</Position><Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints><Joint Type="Revolute"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 3</LocalAnchorA></Joint></Joints>
    </World>)";
    World w(xml.c_str());
    ENSURE(w.ok());
    step_for(w.world, 60);
    ENSURE_FLOAT(w.body(0)->GetPosition().x, 0.0f);
    ENSURE_FLOAT(w.body(0)->GetAngle(), 0.0f);
    return 0;
}

/// Steps 600 times: every body must stay finite.
static bool finite_for_600_steps(World& w) {
    return holds_for_steps(w.world, 600, [&] { return bodies_finite(w); });
}

static int a_second_joint_that_starts_violated_on_a_body_is_left_out() {
    // Two dynamic 1 m off-centre triangles 3 m apart (within max_violation), a distance
    // joint, a weld, a line and a friction joint between them, all anchored at the origins:
    // Box2D 2.4's position solver tears such a pair to NaN.
    World w(R"(<World Version="2"><Gravity>0 -10</Gravity>
      <Shapes><Shape Type="Polygon"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex>
        <Vertex>0 1</Vertex></Vertices></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies><Body Type="Dynamic"><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>0 3</Position><Fixtures><ID>0</ID></Fixtures></Body></Bodies>
      <Joints>
        <Joint Type="Weld"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>
        <Joint Type="Distance"><BodyA>0</BodyA><BodyB>1</BodyB><Length>1</Length></Joint>
        <Joint Type="Line"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>
        <Joint Type="Friction"><BodyA>0</BodyA><BodyB>1</BodyB><MaxForce>10</MaxForce></Joint>
      </Joints></World>)");
    ENSURE(w.scene != nullptr);
    ENSURE(w.joint(0) != nullptr);
    for (uint32_t joint : {1u, 2u}) {
        ENSURE(w.joint(joint) == nullptr);
        ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "joint", joint,
                        {"from satisfied", "joint 0 already pulls body"}));
    }
    ENSURE(w.joint(3) != nullptr); // friction holds nothing in place
    ENSURE(finite_for_600_steps(w));
    return 0;
}

static int a_body_pulled_from_far_keeps_neither_pull() {
    // Three dynamic boxes: a weld that starts 68 m from satisfied, then a distance joint
    // that starts 20 m off on the middle box, as in a level in which Box2D 2.4's position
    // solver moved a body 170 km in the first step: both lie beyond max_violation (4 m).
    World w(R"(<World Version="2"><Gravity>0 -10</Gravity>
      <Shapes><Shape Type="Polygon"><Vertices><Vertex>-0.5 -0.5</Vertex><Vertex>0.5 -0.5</Vertex>
        <Vertex>0.5 0.5</Vertex><Vertex>-0.5 0.5</Vertex></Vertices></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies><Body Type="Dynamic"><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>68 0</Position><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>68 21</Position><Fixtures><ID>0</ID></Fixtures></Body></Bodies>
      <Joints>
        <Joint Type="Weld"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>
        <Joint Type="Distance"><BodyA>1</BodyA><BodyB>2</BodyB><Length>1</Length></Joint>
      </Joints></World>)");
    ENSURE(w.scene != nullptr);
    ENSURE(w.joint(0) == nullptr);
    ENSURE(w.joint(1) == nullptr);
    ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "joint", 0,
                    {"starts 68 m from satisfied", "a joint further than 4 m"}));
    ENSURE(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "joint", 1,
                    {"starts 20 m from satisfied", "a joint further than 4 m"}));
    ENSURE(finite_for_600_steps(w));
    return 0;
}

/// A 1 m ball with MassData `inertia` on a prismatic joint 0.001 rad from satisfied.
static int tiny_inertia_on_a_prismatic_joint(const char* inertia, bool built) {
    std::string xml = std::string(R"(<World Version="2"><Gravity>0 -10</Gravity>
      <Shapes><Shape Type="Circle"><Radius>1</Radius><Position>0 0</Position></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies><Body Type="Static"/><Body Type="Dynamic"><Angle>0.001</Angle>
        <MassData><Inertia>)") + inertia + R"(</Inertia></MassData>
        <Fixtures><ID>0</ID></Fixtures></Body></Bodies>
      <Joints><Joint Type="Prismatic"><BodyA>0</BodyA><BodyB>1</BodyB></Joint></Joints></World>)";
    World w(xml.c_str());
    ENSURE(w.scene != nullptr);
    ENSURE_EQ(w.body(1) != nullptr, built);
    ENSURE_EQ(reported(w.built, B2S_CODE_BEYOND_BOX2D_RANGE, "body", 1, {"inertia"}), !built);
    ENSURE(finite_for_600_steps(w));
    return 0;
}

static int an_inertia_box2d_cannot_hold_is_refused() {
    ENSURE(tiny_inertia_on_a_prismatic_joint("1e-20", false) == 0);
    ENSURE(tiny_inertia_on_a_prismatic_joint("1e-16", false) == 0);
    ENSURE(tiny_inertia_on_a_prismatic_joint("1e-12", true) == 0);
    return 0;
}

int main() {
    int failed = 0;
    failed += RUN_TEST(a_body_beyond_range_takes_its_fixtures_joints_and_gears_along);
    failed += RUN_TEST(shapes_and_fixtures_beyond_range_are_not_made);
    failed += RUN_TEST(gravity_beyond_range_leaves_the_hosts);
    failed += RUN_TEST(masses_box2d_cannot_take_are_refused);
    failed += RUN_TEST(joints_box2d_cannot_take_are_refused);
    failed += RUN_TEST(static_bodies_stay_put);
    failed += RUN_TEST(a_second_joint_that_starts_violated_on_a_body_is_left_out);
    failed += RUN_TEST(a_body_pulled_from_far_keeps_neither_pull);
    failed += RUN_TEST(an_inertia_box2d_cannot_hold_is_refused);
    return failed;
}
