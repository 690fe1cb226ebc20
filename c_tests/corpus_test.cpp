// The four real files of the Box2CS editor (tests/fixtures/corpus/, byte-for-byte copies of
// the shared corpus): what the loader must find in them, and the worlds the adapter
// builds from them. The counts were taken by reading the files.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cstddef>
#include <cstring>

#include "test_macros.h"
#include "test_scenes.hpp"

static const char* const kRenderer = "tests/fixtures/corpus/renderer-scene-v1.xml";
static const char* const kLegacy = "tests/fixtures/corpus/legacy-unversioned.xml";
static const char* const kAllFields = "tests/fixtures/corpus/revolute-all-fields-v1.xml";
static const char* const kDefaultsOmitted =
    "tests/fixtures/corpus/revolute-defaults-omitted-v1.xml";

static bool has_diagnostic(const struct b2s_scene_view& view, b2s_code code) {
    for (uint32_t i = 0; i < view.diagnostic_count; ++i) {
        if (view.diagnostics[i].code == code) {
            return true;
        }
    }
    return false;
}

/// The editor's ground user data: <Type>System.String</Type><Value><string>Ground</string>.
static int ensure_ground_user_data(const struct b2s_scene_view& view, uint32_t index) {
    ENSURE(index < view.user_data_count);
    const b2s_user_data& data = view.user_data[index];
    ENSURE_STR(data.type_name, "System.String");
    ENSURE_STR(data.value, "Ground");
    ENSURE(data.raw != nullptr);
    ENSURE(std::strstr(data.raw, "<Type>System.String</Type>") != nullptr);
    ENSURE(std::strstr(data.raw, "<string>Ground</string>") != nullptr);
    return 0;
}

/// What renderer-scene-v1.xml and legacy-unversioned.xml share: the same 38 shapes, 38
/// fixtures, 17 bodies and 12 joints.
static int ensure_renderer_scene(const struct b2s_scene_view& view) {
    ENSURE_EQ(view.shape_count, 38);
    ENSURE_EQ(view.fixture_count, 38);
    ENSURE_EQ(view.body_count, 17);
    ENSURE_EQ(view.joint_count, 12);
    ENSURE_EQ(view.vertex_count, 80);
    ENSURE_EQ(view.fixture_id_count, 39);
    ENSURE_EQ(view.user_data_count, 3);

    const b2s_shape& box = view.shapes[5];
    ENSURE_EQ(box.kind, B2S_SHAPE_KIND_POLYGON);
    ENSURE_EQ(box.vertices.count, 4);
    ENSURE(box.centroid_given);
    ENSURE_FLOAT(box.centroid.x, 1.0f);
    ENSURE_FLOAT(box.centroid.y, -0.25f);
    ENSURE_FLOAT(view.vertices[view.shapes[15].vertices.first + 2].x, -0.9999998f);
    const b2s_shape& segment = view.shapes[24];
    ENSURE_EQ(segment.kind, B2S_SHAPE_KIND_POLYGON);
    ENSURE_EQ(segment.vertices.count, 2);
    ENSURE_FLOAT(view.vertices[segment.vertices.first + 1].x, 21.0f);
    const b2s_shape& circle = view.shapes[33];
    ENSURE_EQ(circle.kind, B2S_SHAPE_KIND_CIRCLE);
    ENSURE_FLOAT(circle.radius, 25.0f);
    ENSURE_FLOAT(circle.position.x, 27.0f);
    ENSURE_FLOAT(circle.position.y, -18.0f);

    ENSURE_FLOAT(view.fixtures[0].density, 20.0f);
    ENSURE_FLOAT(view.fixtures[0].friction, 0.65f);
    ENSURE_FLOAT(view.fixtures[13].density, 0.35f);
    ENSURE_FLOAT(view.fixtures[28].restitution, 2.0f);
    ENSURE_FLOAT(view.fixtures[24].density, 0.0f);
    ENSURE_FLOAT(view.fixtures[1].friction, 0.2f);

    const b2s_body& kinematic = view.bodies[6];
    ENSURE_EQ(kinematic.kind, B2S_BODY_KIND_KINEMATIC);
    ENSURE_FLOAT(kinematic.angular_velocity, -0.5f);
    ENSURE_FLOAT(kinematic.position.x, 23.0f);
    ENSURE_FLOAT(kinematic.position.y, 17.0f);
    ENSURE_EQ(kinematic.fixtures.count, 8);
    for (uint32_t i = 0; i < 8; ++i) {
        ENSURE_EQ(view.fixture_ids[kinematic.fixtures.first + i], 5 + i);
    }
    // Two bodies share fixture 0 (the editor de-duplicates equal fixtures).
    ENSURE_EQ(view.fixture_ids[view.bodies[0].fixtures.first], 0);
    ENSURE_EQ(view.fixture_ids[view.bodies[1].fixtures.first], 0);
    ENSURE_EQ(view.bodies[15].kind, B2S_BODY_KIND_STATIC);
    ENSURE_EQ(view.bodies[15].fixtures.count, 14);
    ENSURE_EQ(view.bodies[16].fixtures.count, 0);
    ENSURE(ensure_ground_user_data(view, view.bodies[16].user_data) == 0);

    const b2s_joint& first = view.joints[0];
    ENSURE_EQ(first.kind, B2S_JOINT_KIND_REVOLUTE);
    ENSURE_EQ(first.body_a, 14);
    ENSURE_EQ(first.body_b, 15);
    ENSURE_FLOAT(first.local_anchor_b.x, -11.0f);
    ENSURE_FLOAT(first.local_anchor_b.y, 34.75f);
    ENSURE(!first.collide_connected);
    const b2s_joint& weld = view.joints[7];
    ENSURE_EQ(weld.kind, B2S_JOINT_KIND_WELD);
    ENSURE_EQ(weld.body_a, 8);
    ENSURE_EQ(weld.body_b, 9);
    ENSURE(weld.collide_connected);
    ENSURE_FLOAT(weld.local_anchor_a.x, 31.2f);
    ENSURE_FLOAT(weld.local_anchor_a.y, 34.3f);
    ENSURE_STR(view.user_data[view.joints[10].user_data].value, "lwheel");
    ENSURE_STR(view.user_data[view.joints[11].user_data].value, "rwheel");
    ENSURE_EQ(view.joints[11].body_a, 0);
    ENSURE_EQ(view.joints[11].body_b, 2);
    return 0;
}

static int renderer_scene_loads() {
    ScenePtr scene = load_project_file(kRenderer);
    ENSURE(scene != nullptr);
    const struct b2s_scene_view& view = view_of(scene);
    ENSURE_EQ(view.version, 1);
    ENSURE(view.gravity_given);
    ENSURE_FLOAT(view.gravity.x, 8.369571E-36f);
    ENSURE_FLOAT(view.gravity.y, 1.001022E-38f);
    ENSURE(ensure_renderer_scene(view) == 0);
    ENSURE_STR(view.bodies[6].name, "Kinematic test");
    ENSURE_EQ(b2s_scene_find_body(scene.get(), "Kinematic test"), 6);
    ENSURE_EQ(b2s_scene_find_body(scene.get(), "kinematic test"), B2S_NONE);
    ENSURE(view.bodies[0].name == nullptr);
    ENSURE_EQ(view.diagnostic_count, 0);
    return 0;
}

static int legacy_file_loads_with_a_warning() {
    ScenePtr scene = load_project_file(kLegacy);
    ENSURE(scene != nullptr);
    const struct b2s_scene_view& view = view_of(scene);
    ENSURE_EQ(view.version, 0);
    ENSURE(!view.gravity_given);
    ENSURE(has_diagnostic(view, B2S_CODE_LEGACY_UNVERSIONED));
    for (uint32_t i = 0; i < view.diagnostic_count; ++i) {
        ENSURE_EQ(view.diagnostics[i].severity, B2S_SEVERITY_WARNING);
    }
    // JointA/JointB are body indices in these files.
    ENSURE(ensure_renderer_scene(view) == 0);
    ENSURE(view.bodies[6].name == nullptr);
    b2Vec2 fallback(0.0f, -10.0f);
    b2Vec2 gravity = box2scene::scene_gravity(scene.get(), fallback);
    ENSURE_FLOAT(gravity.x, fallback.x);
    ENSURE_FLOAT(gravity.y, fallback.y);
    return 0;
}

static int ensure_revolute_scene(const struct b2s_scene_view& view) {
    ENSURE_EQ(view.version, 1);
    ENSURE_EQ(view.shape_count, 2);
    ENSURE_EQ(view.fixture_count, 2);
    ENSURE_EQ(view.body_count, 3);
    ENSURE_EQ(view.joint_count, 1);
    ENSURE_EQ(view.vertex_count, 2);
    ENSURE_EQ(view.fixture_id_count, 2);
    ENSURE_EQ(view.user_data_count, 1);
    ENSURE_EQ(view.diagnostic_count, 0);

    const b2s_shape& ball = view.shapes[0];
    ENSURE_EQ(ball.kind, B2S_SHAPE_KIND_CIRCLE);
    ENSURE_FLOAT(ball.radius, 0.5f);
    const b2s_shape& ground = view.shapes[1];
    ENSURE_EQ(ground.kind, B2S_SHAPE_KIND_POLYGON);
    ENSURE_EQ(ground.vertices.count, 2);
    ENSURE_FLOAT(view.vertices[ground.vertices.first].x, -40.0f);
    ENSURE_FLOAT(view.vertices[ground.vertices.first + 1].x, 40.0f);
    ENSURE(ground.centroid_given);

    const b2s_fixture& fixture = view.fixtures[0];
    ENSURE_EQ(fixture.shape, 0);
    ENSURE_FLOAT(fixture.density, 5.0f);
    ENSURE_FLOAT(fixture.friction, 0.2f);
    ENSURE_FLOAT(fixture.restitution, 0.0f);
    ENSURE_EQ(fixture.filter.category_bits, 1);
    ENSURE_EQ(fixture.filter.mask_bits, 0xFFFF);
    ENSURE_EQ(fixture.filter.group_index, 0);
    ENSURE(!fixture.is_sensor);

    const b2s_body& ball_body = view.bodies[0];
    ENSURE_EQ(ball_body.kind, B2S_BODY_KIND_DYNAMIC);
    ENSURE_FLOAT(ball_body.angular_velocity, 100.0f);
    ENSURE_FLOAT(ball_body.linear_velocity.x, -800.0f);
    ENSURE_FLOAT(ball_body.position.y, 20.0f);
    ENSURE(ball_body.active && ball_body.allow_sleep && ball_body.awake);
    ENSURE(!ball_body.bullet && !ball_body.fixed_rotation);
    ENSURE_FLOAT(ball_body.inertia_scale, 1.0f);
    ENSURE_EQ(view.bodies[2].fixtures.count, 0);
    ENSURE(ensure_ground_user_data(view, view.bodies[2].user_data) == 0);

    const b2s_joint& joint = view.joints[0];
    ENSURE_EQ(joint.kind, B2S_JOINT_KIND_REVOLUTE);
    ENSURE_EQ(joint.body_a, 1);
    ENSURE_EQ(joint.body_b, 0);
    ENSURE(joint.collide_connected);
    ENSURE(joint.enable_limit);
    ENSURE(!joint.enable_motor);
    ENSURE_FLOAT(joint.local_anchor_a.x, 0.0f);
    ENSURE_FLOAT(joint.local_anchor_a.y, 12.0f);
    ENSURE_FLOAT(joint.local_anchor_b.x, 0.0f);
    ENSURE_FLOAT(joint.local_anchor_b.y, -8.0f);
    ENSURE_FLOAT(joint.lower_limit, -0.7853982f);
    ENSURE_FLOAT(joint.upper_limit, 1.570796f);
    ENSURE_FLOAT(joint.motor_speed, 3.141593f);
    ENSURE_FLOAT(joint.max_motor_torque, 10000.0f);
    ENSURE_FLOAT(joint.reference_angle, 0.0f);
    return 0;
}

static int revolute_all_fields_loads() {
    ScenePtr scene = load_project_file(kAllFields);
    ENSURE(scene != nullptr);
    const struct b2s_scene_view& view = view_of(scene);
    ENSURE(view.gravity_given);
    ENSURE_FLOAT(view.gravity.x, 8.134473E-36f);
    ENSURE_FLOAT(view.gravity.y, 1.001022E-38f);
    b2Vec2 gravity = box2scene::scene_gravity(scene.get(), b2Vec2(0.0f, -10.0f));
    ENSURE_FLOAT(gravity.x, 8.134473E-36f);
    ENSURE(ensure_revolute_scene(view) == 0);
    // <Name /> is a name, the empty one.
    ENSURE_STR(view.fixtures[0].name, "");
    return 0;
}

static int revolute_defaults_omitted_loads() {
    ScenePtr scene = load_project_file(kDefaultsOmitted);
    ENSURE(scene != nullptr);
    const struct b2s_scene_view& view = view_of(scene);
    ENSURE_FLOAT(view.gravity.x, 8.369571E-36f);
    ENSURE(ensure_revolute_scene(view) == 0);
    ENSURE(view.fixtures[0].name == nullptr);
    return 0;
}

/// Bytes [from, to) of two records compare equal. Only for spans without padding, whose
/// content is unspecified.
template <class Record>
static bool same_span(const Record& a, const Record& b, size_t from, size_t to) {
    const char* bytes_a = reinterpret_cast<const char*>(&a);
    const char* bytes_b = reinterpret_cast<const char*>(&b);
    return std::memcmp(bytes_a + from, bytes_b + from, to - from) == 0;
}

/// Omitting every default must give the same scene as writing every field (names and
/// pool positions aside).
static int omitted_defaults_are_the_written_ones() {
    ScenePtr all = load_project_file(kAllFields);
    ScenePtr omitted = load_project_file(kDefaultsOmitted);
    ENSURE(all != nullptr && omitted != nullptr);
    const struct b2s_scene_view& a = view_of(all);
    const struct b2s_scene_view& o = view_of(omitted);
    for (uint32_t i = 0; i < a.fixture_count; ++i) {
        // The filter ends in padding after its group index.
        size_t group_end = offsetof(b2s_fixture, filter) + offsetof(b2s_filter, group_index) +
                           sizeof(int16_t);
        ENSURE(same_span(a.fixtures[i], o.fixtures[i], offsetof(b2s_fixture, shape), group_end));
        ENSURE_EQ(a.fixtures[i].is_sensor, o.fixtures[i].is_sensor);
    }
    for (uint32_t i = 0; i < a.body_count; ++i) {
        const b2s_body& ba = a.bodies[i];
        const b2s_body& bo = o.bodies[i];
        size_t mass_data_end =
            offsetof(b2s_body, mass_data) + offsetof(b2s_mass_data, inertia_given) + 1;
        ENSURE(same_span(ba, bo, offsetof(b2s_body, kind), mass_data_end));
        ENSURE(same_span(ba, bo, offsetof(b2s_body, active),
                         offsetof(b2s_body, fixed_rotation) + 1));
        ENSURE_EQ(ba.fixtures.count, bo.fixtures.count);
    }
    ENSURE(same_span(a.joints[0], o.joints[0], offsetof(b2s_joint, kind),
                     offsetof(b2s_joint, enable_motor) + 1));
    return 0;
}

/// Builds the file's world and steps it: everything created, nothing reported.
static int ensure_builds(const char* file, int expected_fixtures) {
    ScenePtr scene = load_project_file(file);
    ENSURE(scene != nullptr);
    const struct b2s_scene_view& view = view_of(scene);
    b2World world(box2scene::scene_gravity(scene.get(), b2Vec2(0.0f, -10.0f)));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE_EQ(built.reports.size(), 0);
    ENSURE_EQ(built.bodies.size(), view.body_count);
    ENSURE_EQ(built.joints.size(), view.joint_count);
    ENSURE_EQ(built.fixtures.size(), view.fixture_id_count);
    ENSURE_EQ(world.GetBodyCount(), view.body_count);
    ENSURE_EQ(world.GetJointCount(), view.joint_count);
    int fixtures = 0;
    for (b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext()) {
        for (b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) {
            ++fixtures;
        }
    }
    ENSURE_EQ(fixtures, expected_fixtures);
    for (b2Fixture* fixture : built.fixtures) {
        ENSURE(fixture != nullptr);
    }
    for (int i = 0; i < 60; ++i) {
        world.Step(1.0f / 60.0f, 8, 3);
    }
    return 0;
}

static int every_corpus_file_builds() {
    ENSURE(ensure_builds(kRenderer, 39) == 0);
    ENSURE(ensure_builds(kLegacy, 39) == 0);
    ENSURE(ensure_builds(kAllFields, 2) == 0);
    ENSURE(ensure_builds(kDefaultsOmitted, 2) == 0);
    return 0;
}

/// The revolute file as Box2D objects: the two-vertex ground is an edge, the joint keeps
/// its limits and anchors, the kinematic body of the renderer scene turns.
static int revolute_world_is_what_the_file_says() {
    ScenePtr scene = load_project_file(kAllFields);
    ENSURE(scene != nullptr);
    b2World world(b2Vec2(0.0f, -10.0f));
    box2scene::Built built = box2scene::build_world(scene.get(), world);
    ENSURE_EQ(built.joints.size(), 1);
    b2Fixture* ground = built.fixtures[1];
    ENSURE(ground != nullptr);
    ENSURE_EQ(ground->GetType(), b2Shape::e_edge);
    ENSURE(ground->GetBody() == built.bodies[1]);
    auto* edge = static_cast<b2EdgeShape*>(ground->GetShape());
    ENSURE_FLOAT(edge->m_vertex1.x, -40.0f);
    ENSURE_FLOAT(edge->m_vertex2.x, 40.0f);
    ENSURE(!edge->m_oneSided);
    ENSURE_EQ(built.joints[0]->GetType(), e_revoluteJoint);
    auto* joint = static_cast<b2RevoluteJoint*>(built.joints[0]);
    ENSURE(joint->GetBodyA() == built.bodies[1]);
    ENSURE(joint->GetBodyB() == built.bodies[0]);
    ENSURE(joint->GetCollideConnected());
    ENSURE(joint->IsLimitEnabled());
    ENSURE(!joint->IsMotorEnabled());
    ENSURE_FLOAT(joint->GetLowerLimit(), -0.7853982f);
    ENSURE_FLOAT(joint->GetUpperLimit(), 1.570796f);
    ENSURE_FLOAT(joint->GetMotorSpeed(), 3.141593f);
    ENSURE_FLOAT(joint->GetMaxMotorTorque(), 10000.0f);
    ENSURE_FLOAT(joint->GetLocalAnchorA().y, 12.0f);
    ENSURE_FLOAT(joint->GetLocalAnchorB().y, -8.0f);
    ENSURE_FLOAT(built.bodies[0]->GetAngularVelocity(), 100.0f);
    ENSURE_FLOAT(built.bodies[0]->GetLinearVelocity().x, -800.0f);

    ScenePtr renderer = load_project_file(kRenderer);
    ENSURE(renderer != nullptr);
    b2World renderer_world(b2Vec2(0.0f, -10.0f));
    box2scene::Built renderer_built = box2scene::build_world(renderer.get(), renderer_world);
    b2Body* kinematic = renderer_built.bodies[6];
    ENSURE_EQ(kinematic->GetType(), b2_kinematicBody);
    ENSURE_FLOAT(kinematic->GetAngularVelocity(), -0.5f);
    ENSURE_FLOAT(renderer_built.fixtures[view_of(renderer).bodies[15].fixtures.first + 4]
                     ->GetRestitution(),
                 2.0f);
    return 0;
}

int main() {
    int failed = 0;
    failed += RUN_TEST(renderer_scene_loads);
    failed += RUN_TEST(legacy_file_loads_with_a_warning);
    failed += RUN_TEST(revolute_all_fields_loads);
    failed += RUN_TEST(revolute_defaults_omitted_loads);
    failed += RUN_TEST(omitted_defaults_are_the_written_ones);
    failed += RUN_TEST(every_corpus_file_builds);
    failed += RUN_TEST(revolute_world_is_what_the_file_says);
    return failed;
}
