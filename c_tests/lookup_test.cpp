// The 2.4 adapter's lookups: the engine object of a named body, fixture or joint in one call
// (nullptr where none was made), the scene record an engine object came from, and
// box2scene::Scene, which owns a scene.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cstring>
#include <type_traits>
#include <utility>

#include "test_macros.h"
#include "test_scenes.hpp"

/// A fixture two bodies share, a chain, and a joint 2.4 cannot hold (a motor torque beyond
/// its working range), so that it is skipped.
static const char* const kLevel = R"(<World Version="2">
  <Shapes>
    <Shape Type="Polygon"><Vertices><Vertex>-0.5 -0.5</Vertex><Vertex>0.5 -0.5</Vertex>
      <Vertex>0.5 0.5</Vertex><Vertex>-0.5 0.5</Vertex></Vertices></Shape>
    <Shape Type="Chain"><Vertices><Vertex>-5 0</Vertex><Vertex>0 0</Vertex><Vertex>5 0</Vertex></Vertices></Shape>
    <Shape Type="Circle"><Radius>0.4</Radius><Position>0 0</Position></Shape>
  </Shapes>
  <Fixtures>
    <Fixture><Name>Track</Name><Shape>1</Shape></Fixture>
    <Fixture><Name>CrateSkin</Name><Shape>0</Shape><Density>1</Density></Fixture>
    <Fixture><Name>Tyre</Name><Shape>2</Shape><Density>1</Density></Fixture>
  </Fixtures>
  <Bodies>
    <Body Type="Static"><Name>Ground</Name><Fixtures><ID>0</ID></Fixtures></Body>
    <Body Type="Dynamic"><Name>CrateA</Name><Position>-2 1</Position><Fixtures><ID>1</ID></Fixtures></Body>
    <Body Type="Dynamic"><Name>CrateB</Name><Position>2 1</Position><Fixtures><ID>1</ID></Fixtures></Body>
    <Body Type="Dynamic"><Name>Wheel</Name><Position>0 3</Position><Fixtures><ID>2</ID></Fixtures></Body>
  </Bodies>
  <Joints>
    <Joint Type="Revolute"><Name>Hinge</Name><BodyA>1</BodyA><BodyB>2</BodyB>
      <LocalAnchorA>2 0</LocalAnchorA><LocalAnchorB>-2 0</LocalAnchorB></Joint>
    <Joint Type="Revolute"><Name>Overdriven</Name><BodyA>0</BodyA><BodyB>3</BodyB>
      <LocalAnchorA>0 3</LocalAnchorA><EnableMotor>true</EnableMotor>
      <MaxMotorTorque>1e30</MaxMotorTorque></Joint>
  </Joints>
</World>)";

static int named_records_reach_their_engine_objects() {
    ScenePtr scene = load_text(kLevel);
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE(built.joints.size() == 2 && built.joints[1] == nullptr); // skipped, reported

    ENSURE(box2scene::find_body(built, scene.get(), "CrateB") == built.bodies[2]);
    ENSURE(box2scene::find_body(built, scene.get(), "Wheel") == built.bodies[3]);
    ENSURE(built.bodies[2] != nullptr);
    // CrateSkin serves CrateA and CrateB: the first body's, entry 1 of the pool.
    b2Fixture* skin = box2scene::find_fixture(built, scene.get(), "CrateSkin");
    ENSURE(skin != nullptr && skin == built.fixtures[1] && skin->GetBody() == built.bodies[1]);
    b2Fixture* track = box2scene::find_fixture(built, scene.get(), "Track");
    ENSURE(track != nullptr && track->GetType() == b2Shape::e_chain);
    ENSURE(box2scene::find_joint(built, scene.get(), "Hinge") == built.joints[0]);
    ENSURE(built.joints[0] != nullptr);
    return 0;
}

static int what_was_not_made_or_not_named_is_null() {
    ScenePtr scene = load_text(kLevel);
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE(box2scene::find_joint(built, scene.get(), "Overdriven") == nullptr);
    ENSURE(box2scene::find_body(built, scene.get(), "Nobody") == nullptr);
    ENSURE(box2scene::find_fixture(built, scene.get(), "Nothing") == nullptr);
    ENSURE(box2scene::find_joint(built, scene.get(), nullptr) == nullptr);
    ENSURE(box2scene::find_body(built, nullptr, "CrateA") == nullptr);
    // A result of another scene, with other counts, finds nothing rather than a stranger.
    box2scene::Built empty;
    ENSURE(box2scene::find_body(empty, scene.get(), "Wheel") == nullptr);
    ENSURE(box2scene::find_fixture(empty, scene.get(), "Tyre") == nullptr);
    ENSURE(box2scene::find_joint(empty, scene.get(), "Hinge") == nullptr);
    return 0;
}

static int engine_objects_name_their_scene_records() {
    ScenePtr scene = load_text(kLevel);
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    const b2s_scene_view& view = view_of(scene);
    for (uint32_t i = 0; i < view.body_count; ++i) {
        ENSURE_EQ(box2scene::body_index(built, built.bodies[i]), i);
    }
    // Each body's copy of the shared fixture names its own entry, and both the one fixture.
    uint32_t b_slot = box2scene::fixture_slot(built, built.bodies[2]->GetFixtureList());
    ENSURE_EQ(b_slot, 2);
    ENSURE_EQ(view.fixture_ids[b_slot], 1);
    ENSURE_EQ(box2scene::fixture_slot(built, built.fixtures[1]), 1);
    ENSURE_EQ(box2scene::joint_index(built, built.joints[0]), 0);
    // What the host made itself, and nothing, came from no record.
    b2BodyDef def;
    b2Body* own = world.CreateBody(&def);
    b2CircleShape dot;
    dot.m_radius = 0.1f;
    b2Fixture* own_fixture = own->CreateFixture(&dot, 1.0f);
    b2RevoluteJointDef hinge;
    hinge.Initialize(own, built.bodies[3], b2Vec2(0.0f, 3.0f));
    b2Joint* own_joint = world.CreateJoint(&hinge);
    ENSURE_EQ(box2scene::body_index(built, own), B2S_NONE);
    ENSURE_EQ(box2scene::fixture_slot(built, own_fixture), B2S_NONE);
    ENSURE_EQ(box2scene::joint_index(built, own_joint), B2S_NONE);
    ENSURE_EQ(box2scene::body_index(built, nullptr), B2S_NONE);
    ENSURE_EQ(box2scene::joint_index(built, nullptr), B2S_NONE);
    return 0;
}

static int scene_owner_frees_once_and_moves() {
    static_assert(!std::is_copy_constructible<box2scene::Scene>::value, "one owner");
    static_assert(!std::is_copy_assignable<box2scene::Scene>::value, "one owner");
    static_assert(std::is_nothrow_move_constructible<box2scene::Scene>::value, "movable");
    static_assert(std::is_nothrow_move_assignable<box2scene::Scene>::value, "movable");
    box2scene::Scene scene;
    ENSURE(!scene);
    ENSURE_EQ(b2s_load_memory(reinterpret_cast<const uint8_t*>(kLevel), std::strlen(kLevel),
                              nullptr, scene.out(), nullptr),
              B2S_CODE_OK);
    ENSURE(scene);
    b2s_scene* held = scene.get();
    box2scene::Scene moved(std::move(scene));
    ENSURE(!scene && moved.get() == held);
    box2scene::Scene other(load_text(kLevel).release());
    other = std::move(moved); // frees other's own scene (the leak checkers see it)
    ENSURE(other.get() == held && !moved);
    ENSURE(box2scene::find_body(box2scene::Built{}, other.get(), "Wheel") == nullptr);
    b2s_scene* released = other.release();
    ENSURE(released == held && !other);
    other.reset(released); // owned again, freed at the end of the scope
    ENSURE(other.get() == held);
    return 0;
}

int main() {
    int failed = 0;
    failed += RUN_TEST(named_records_reach_their_engine_objects);
    failed += RUN_TEST(what_was_not_made_or_not_named_is_null);
    failed += RUN_TEST(engine_objects_name_their_scene_records);
    failed += RUN_TEST(scene_owner_frees_once_and_moves);
    return failed;
}
