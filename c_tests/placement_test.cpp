// Building at a placement (box2scene::build_world_at) in Box2D 2.4: one scene built twice
// into one world, at two placements, evolves bit for bit like the scene built alone and moved
// by hand (each body's position, angle and velocity turned and moved) over 600 steps; a
// pulley's ground anchors, world points, move with the placement.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cmath>

#include "test_macros.h"
#include "test_worlds.hpp"

static const int steps = 600;

// A ground, a box thrown spinning onto it, and a ball hanging from the ground by a
// revolute joint.
static const char* const scene_text = R"(<World Version="2"><Gravity>0 -10</Gravity><Shapes>
  <Shape Type="Polygon"><Vertices><Vertex>-10 -1</Vertex><Vertex>10 -1</Vertex>
    <Vertex>10 0</Vertex><Vertex>-10 0</Vertex></Vertices></Shape>
  <Shape Type="Polygon"><Vertices><Vertex>-0.5 -0.5</Vertex><Vertex>0.5 -0.5</Vertex>
    <Vertex>0.5 0.5</Vertex><Vertex>-0.5 0.5</Vertex></Vertices></Shape>
  <Shape Type="Circle"><Radius>0.25</Radius><Position>0 0</Position></Shape></Shapes>
  <Fixtures><Fixture><Shape>0</Shape><Friction>0.5</Friction></Fixture>
    <Fixture><Shape>1</Shape><Density>2</Density><Friction>0.5</Friction></Fixture>
    <Fixture><Shape>2</Shape><Density>1</Density><Friction>0.5</Friction></Fixture></Fixtures>
  <Bodies>
    <Body Type="Static"><Fixtures><ID>0</ID></Fixtures></Body>
    <Body Type="Dynamic"><Position>1 3</Position><Angle>0.3</Angle>
      <LinearVelocity>2 -1</LinearVelocity><AngularVelocity>1.5</AngularVelocity>
      <Fixtures><ID>1</ID></Fixtures></Body>
    <Body Type="Dynamic"><Position>4 4</Position><Fixtures><ID>2</ID></Fixtures></Body>
  </Bodies>
  <Joints><Joint Type="Revolute"><BodyA>0</BodyA><BodyB>2</BodyB>
    <LocalAnchorA>4 5</LocalAnchorA><LocalAnchorB>0 1</LocalAnchorB></Joint></Joints></World>)";

static b2Transform placement(float x, float y, float angle) {
    return b2Transform(b2Vec2(x, y), b2Rot(angle));
}

// The bodies of a build at the identity moved by hand to where `at` puts the scene.
static void move_by_hand(const box2scene::Built& built, const b2s_scene* scene,
                         const b2Transform& at) {
    const b2s_scene_view* view = b2s_scene_get_view(scene);
    for (uint32_t i = 0; i < view->body_count; ++i) {
        const b2s_body& body = view->bodies[i];
        b2Body* moved = built.bodies[i];
        moved->SetTransform(b2Mul(at, b2Vec2(body.position.x, body.position.y)),
                            body.angle + at.q.GetAngle());
        // A body at rest is at rest wherever it is placed.
        bool moving = body.linear_velocity.x != 0.0f || body.linear_velocity.y != 0.0f;
        if (body.kind != B2S_BODY_KIND_STATIC && moving) {
            moved->SetLinearVelocity(
                b2Mul(at.q, b2Vec2(body.linear_velocity.x, body.linear_velocity.y)));
        }
    }
}

static int two_placed_instances_evolve_as_the_scene_moved_by_hand() {
    ScenePtr scene = load_text(scene_text);
    ENSURE(scene != nullptr);
    const b2Transform at[2] = {placement(100.0f, 0.0f, 0.5f), placement(-100.0f, 50.0f, -2.0f)};
    b2World placed(b2Vec2(0.0f, -10.0f)), by_hand(b2Vec2(0.0f, -10.0f));
    box2scene::Built built[2], hand[2];
    for (int k = 0; k < 2; ++k) {
        built[k] = box2scene::build_world_at(scene.get(), placed, at[k]);
        ENSURE_EQ(built[k].reports.size(), size_t{0});
        hand[k] = box2scene::build_world(scene.get(), by_hand);
        move_by_hand(hand[k], scene.get(), at[k]);
    }
    // The anchors are local: the hinge holds the ball 1 m under the placed anchor.
    b2Vec2 anchor = built[0].bodies[0]->GetWorldPoint(b2Vec2(4.0f, 5.0f));
    b2Vec2 ball = built[0].bodies[2]->GetWorldPoint(b2Vec2(0.0f, 1.0f));
    ENSURE_NEAR(b2Distance(anchor, ball), 0.0, 1e-4);
    for (int step = 0; step <= steps; ++step) {
        for (int k = 0; k < 2; ++k) {
            for (size_t i = 0; i < 3; ++i) {
                if (ensure_same_state(i, built[k].bodies[i], hand[k].bodies[i]) != 0) {
                    std::fprintf(stderr, "instance %d differs after %d steps\n", k, step);
                    return 1;
                }
            }
        }
        step_once(placed);
        step_once(by_hand);
    }
    // and they moved: the thrown box is not where it started
    ENSURE(b2Distance(built[1].bodies[1]->GetPosition(), b2Mul(at[1], b2Vec2(1.0f, 3.0f))) >
           0.5f);
    return 0;
}

static int the_identity_placement_is_the_plain_build() {
    ScenePtr scene = load_text(scene_text);
    ENSURE(scene != nullptr);
    b2World plain(b2Vec2(0.0f, -10.0f)), placed(b2Vec2(0.0f, -10.0f));
    box2scene::Built a = box2scene::build_world(scene.get(), plain);
    box2scene::Built b = box2scene::build_world_at(scene.get(), placed, placement(0, 0, 0));
    step_for(plain, steps);
    step_for(placed, steps);
    for (size_t i = 0; i < a.bodies.size(); ++i) {
        ENSURE_EQ(ensure_same_state(i, b.bodies[i], a.bodies[i]), 0);
    }
    return 0;
}

// A pulley's ground anchors are world points: the placement moves them with its bodies.
static int a_pulley_ground_anchors_move_with_the_placement() {
    ScenePtr scene = load_text(R"(<World Version="2"><Shapes>
      <Shape Type="Circle"><Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes>
      <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>
      <Bodies>
        <Body Type="Dynamic"><Position>-2 0</Position><Fixtures><ID>0</ID></Fixtures></Body>
        <Body Type="Dynamic"><Position>2 0</Position><Fixtures><ID>0</ID></Fixtures></Body>
      </Bodies>
      <Joints><Joint Type="Pulley"><BodyA>0</BodyA><BodyB>1</BodyB>
        <LocalAnchorA>0 0</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB><GroundAnchorA>-2 5</GroundAnchorA><GroundAnchorB>2 5</GroundAnchorB>
        <LengthA>5</LengthA><LengthB>5</LengthB><Ratio>1</Ratio></Joint></Joints></World>)");
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    b2Transform at = placement(30.0f, -7.0f, 1.0f);
    box2scene::Built built = box2scene::build_world_at(scene.get(), world, at);
    ENSURE_EQ(built.reports.size(), size_t{0});
    auto* pulley = static_cast<b2PulleyJoint*>(built.joints[0]);
    ENSURE(same_bits(pulley->GetGroundAnchorA(), b2Mul(at, b2Vec2(-2.0f, 5.0f))));
    ENSURE(same_bits(pulley->GetGroundAnchorB(), b2Mul(at, b2Vec2(2.0f, 5.0f))));
    ENSURE_NEAR(pulley->GetCurrentLengthA(), 5.0, 1e-5);
    ENSURE_NEAR(pulley->GetCurrentLengthB(), 5.0, 1e-5);
    return 0;
}

// A placement Box2D 2.4 cannot take builds nothing and says so.
static int a_placement_2_4_cannot_take_builds_nothing() {
    ScenePtr scene = load_text(scene_text);
    ENSURE(scene != nullptr);
    b2Transform bad[3] = {placement(0, 0, 0), placement(NAN, 0, 0), placement(2e5f, 0, 0)};
    bad[0].q.c = 2.0f;
    for (const b2Transform& t : bad) {
        b2World world(b2Vec2(0.0f, -10.0f));
        box2scene::Built built = box2scene::build_world_at(scene.get(), world, t);
        ENSURE_EQ(built.reports.size(), size_t{1});
        ENSURE_EQ(built.reports[0].code, B2S_CODE_INVALID_ARGUMENT);
        ENSURE_EQ(world.GetBodyCount(), 0);
    }
    return 0;
}

int main() {
    int failed = 0;
    failed += RUN_TEST(two_placed_instances_evolve_as_the_scene_moved_by_hand);
    failed += RUN_TEST(the_identity_placement_is_the_plain_build);
    failed += RUN_TEST(a_pulley_ground_anchors_move_with_the_placement);
    failed += RUN_TEST(a_placement_2_4_cannot_take_builds_nothing);
    return failed;
}
