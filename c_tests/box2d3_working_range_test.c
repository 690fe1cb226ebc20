/*
 * Box2D v3's working range where it was measured to matter (docs/working-range.md): what
 * v3 holds calmly is built, what it cannot hold is left out and reported beyond-box2d-range,
 * naming the joint and why; every world built stays finite for 600 steps (v3 is built with
 * its assertions on: one that fires ends the test).
 */
#include "box2d3_support.h"

#include <sys/wait.h>
#include <unistd.h>

static const char* const TRIANGLES =
    "<World Version=\"2\"><Gravity>0 -10</Gravity>"
    "<Shapes><Shape Type=\"Polygon\"><Vertices><Vertex>-0.5 -0.288675</Vertex>"
    "<Vertex>0.5 -0.288675</Vertex><Vertex>0 0.57735</Vertex></Vertices></Shape></Shapes>"
    "<Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>"
    "<Bodies><Body Type=\"Dynamic\"><Fixtures><ID>0</ID></Fixtures></Body>"
    "<Body Type=\"Dynamic\"><Position>%s</Position><Fixtures><ID>0</ID></Fixtures></Body>"
    "</Bodies><Joints>%s</Joints></World>";

/* TRIANGLES with body B at `position` and `joints`, built; NULL scene on failure. */
static v3_world build_with(const char* position, const char* joints, b2s_scene** scene) {
    static char xml[4096];
    snprintf(xml, sizeof xml, TRIANGLES, position, joints);
    *scene = load_text(xml);
    return build_v3(*scene);
}

static bool finite_for_600_steps(const v3_world* w) {
    for (int i = 0; i < 600; ++i) {
        step_v3(w, 1);
        if (!bodies_finite(w)) {
            return false;
        }
    }
    return true;
}

static bool report_says(const b2s_box2d3_reports* reports, b2s_code code, uint32_t joint,
                        const char* words) {
    for (uint32_t i = 0; i < reports->count; ++i) {
        const b2s_box2d3_report* r = &reports->items[i];
        if (r->code == code && strcmp(r->object, "joint") == 0 && r->index == joint &&
            strstr(r->message, words) != NULL) {
            return true;
        }
    }
    print_reports(reports);
    return false;
}

/* `scene` (freed here) built: its one joint, joint 0, left out with the one report
 * beyond-box2d-range saying `words`, and the rest stepping 600 steps finite. */
static int refused_and_the_world_holds(b2s_scene* scene, const char* words) {
    ENSURE(scene != NULL);
    v3_world w = build_v3(scene);
    ENSURE(B2_IS_NULL(w.built->joints[0]));
    ENSURE_EQ(w.built->reports.count, 1);
    ENSURE(report_says(&w.built->reports, B2S_CODE_BEYOND_BOX2D_RANGE, 0, words));
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

static int line_joint_that_starts_violated_is_left_out(void) {
    b2s_scene* scene = NULL;
    v3_world w = build_with("0 5",
                            "<Joint Type=\"Line\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>",
                            &scene);
    ENSURE(scene != NULL);
    ENSURE(B2_IS_NULL(w.built->joints[0]));
    ENSURE(report_says(&w.built->reports, B2S_CODE_BEYOND_BOX2D_RANGE, 0, "starts 5 m"));
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

static int line_joint_with_anchors_far_along_its_axis_stays_finite(void) {
    b2s_scene* scene = NULL;
    v3_world w = build_with("5 0", "<Joint Type=\"Line\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>",
                            &scene);
    ENSURE(scene != NULL);
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

/* A joint other than a line or wheel joint that starts more than the range's max_violation
 * (0.5 m) from satisfied is left out, whatever else acts on its bodies: the dialect fixtures'
 * weld 8.4 m off among five other joints on its body made v3.1 assert. */
static int four_joints_on_one_pair_keep_the_satisfied_ones(void) {
    b2s_scene* scene = NULL;
    v3_world w = build_with(
        "0 5",
        "<Joint Type=\"Line\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>"
        "<Joint Type=\"Distance\"><BodyA>0</BodyA><BodyB>1</BodyB><Length>5</Length></Joint>"
        "<Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>"
        "<Joint Type=\"Friction\"><BodyA>0</BodyA><BodyB>1</BodyB><MaxForce>10</MaxForce></Joint>",
        &scene);
    ENSURE(scene != NULL);
    ENSURE(B2_IS_NULL(w.built->joints[0]));
    ENSURE(B2_IS_NON_NULL(w.built->joints[1])); /* satisfied */
    ENSURE(B2_IS_NULL(w.built->joints[2]));     /* 5 m from satisfied */
    ENSURE(report_says(&w.built->reports, B2S_CODE_BEYOND_BOX2D_RANGE, 2,
                       "a joint further than 0.5 m from satisfied"));
    ENSURE(B2_IS_NON_NULL(w.built->joints[3]));
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

static int joints_that_start_violated_are_left_out(void) {
    b2s_scene* scene = NULL;
    v3_world w = build_with(
        "0 5",
        "<Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>"
        "<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>",
        &scene);
    ENSURE(scene != NULL);
    for (uint32_t i = 0; i < 2; ++i) {
        ENSURE(B2_IS_NULL(w.built->joints[i]));
        ENSURE(report_says(&w.built->reports, B2S_CODE_BEYOND_BOX2D_RANGE, i,
                           "it starts 5 m from satisfied"));
    }
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

static const char* const SMALL_PAIR =
    "<World Version=\"2\"><Gravity>0 -10</Gravity>"
    "<Shapes><Shape Type=\"Polygon\"><Vertices><Vertex>-0.25 -0.25</Vertex><Vertex>0.25 -0.25</Vertex>"
    "<Vertex>0.25 0.25</Vertex><Vertex>-0.25 0.25</Vertex></Vertices></Shape>"
    "<Shape Type=\"Circle\"><Radius>0.2</Radius><Position>0 0</Position></Shape></Shapes>"
    "<Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture>"
    "<Fixture><Shape>1</Shape><Density>1</Density></Fixture></Fixtures>"
    "<Bodies>%s</Bodies><Joints>%s</Joints></World>";

static int satisfied_joints_far_from_small_bodies_are_built(void) {
    static char xml[4096];
    /* A weld between two 0.5 m boxes 3 m apart; a rope on 20 cm balls with the format's
     * default anchors; a friction joint whose anchors v3 does not use. */
    snprintf(xml, sizeof xml, SMALL_PAIR,
             "<Body Type=\"Dynamic\"><Fixtures><ID>0</ID></Fixtures></Body>"
             "<Body Type=\"Dynamic\"><Position>3 0</Position><Fixtures><ID>0</ID></Fixtures></Body>"
             "<Body Type=\"Static\"><Position>0 5</Position><Fixtures><ID>1</ID></Fixtures></Body>"
             "<Body Type=\"Dynamic\"><Position>2 5</Position><Fixtures><ID>1</ID></Fixtures></Body>",
             "<Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>1.5 0</LocalAnchorA>"
             "<LocalAnchorB>-1.5 0</LocalAnchorB></Joint>"
             "<Joint Type=\"Rope\"><BodyA>2</BodyA><BodyB>3</BodyB><MaxLength>4</MaxLength></Joint>"
             "<Joint Type=\"Friction\"><BodyA>2</BodyA><BodyB>3</BodyB><LocalAnchorA>10 0</LocalAnchorA>"
             "<MaxForce>1</MaxForce></Joint>");
    b2s_scene* scene = load_text(xml);
    ENSURE(scene != NULL);
    v3_world w = build_v3(scene);
    ENSURE_EQ(count_reports(&w.built->reports, B2S_CODE_BEYOND_BOX2D_RANGE, NULL, 0), 0);
    for (uint32_t i = 0; i < 3; ++i) {
        ENSURE(B2_IS_NON_NULL(w.built->joints[i]));
    }
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

/* A 1 m ball with a tiny MassData inertia on a prismatic joint 0.001 rad from satisfied. */
static int tiny_inertia_on_a_prismatic_joint(const char* inertia, bool built) {
    static char xml[2048];
    snprintf(xml, sizeof xml,
             "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes><Shape Type=\"Circle\">"
             "<Radius>1</Radius><Position>0 0</Position></Shape></Shapes>"
             "<Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>"
             "<Bodies><Body Type=\"Static\"/><Body Type=\"Dynamic\"><Angle>0.001</Angle>"
             "<MassData><Inertia>%s</Inertia></MassData><Fixtures><ID>0</ID></Fixtures></Body>"
             "</Bodies><Joints><Joint Type=\"Prismatic\"><BodyA>0</BodyA><BodyB>1</BodyB>"
             "</Joint></Joints></World>",
             inertia);
    b2s_scene* scene = load_text(xml);
    ENSURE(scene != NULL);
    v3_world w = build_v3(scene);
    ENSURE_EQ(B2_IS_NON_NULL(w.built->bodies[1]), built);
    ENSURE_EQ(count_reports(&w.built->reports, B2S_CODE_BEYOND_BOX2D_RANGE, "body", 1), !built);
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

static int an_inertia_v3_cannot_hold_is_refused(void) {
    ENSURE(tiny_inertia_on_a_prismatic_joint("1e-20", false) == 0);
    ENSURE(tiny_inertia_on_a_prismatic_joint("1e-16", false) == 0);
    ENSURE(tiny_inertia_on_a_prismatic_joint("1e-12", true) == 0);
    return 0;
}

static int a_prismatic_lever_reaches_body_bs_anchor(void) {
    static char xml[4096];
    /* A 20 cm ball as body A; body B's anchor 12 m along the axis: 85 radii of gyration. */
    snprintf(xml, sizeof xml, SMALL_PAIR,
             "<Body Type=\"Dynamic\"><Fixtures><ID>1</ID></Fixtures></Body>"
             "<Body Type=\"Dynamic\"><Position>12 0</Position><Fixtures><ID>0</ID></Fixtures></Body>",
             "<Joint Type=\"Prismatic\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>");
    b2s_scene* scene = load_text(xml);
    ENSURE(scene != NULL);
    v3_world w = build_v3(scene);
    ENSURE(report_says(&w.built->reports, B2S_CODE_BEYOND_BOX2D_RANGE, 0, "as body A's lever"));
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

/* Found by the generated levels: a dynamic body whose rotation is fixed, given a spin, and
 * a line joint 5.5 m out on it. With a revolute joint 14 m out on the line joint's other
 * body, the level goes NaN in Box2D 2.4 and v3.1 alike (the spin drags the assembly
 * around): the stress levels no longer hang joints from such a body. This part of it holds,
 * with the spin the file gives, which v3.1 keeps as 2.x does (spec section 13). The other
 * body's ball is centred on its origin, where the joint acts: the level's ball sat 1 m off
 * it, 4.8 radii of gyration, beyond the 3 a line or wheel joint to a body that does not
 * turn may act at in v3.1. */
static int a_fixed_rotation_body_keeps_its_spin_and_its_line_joint_holds(void) {
    b2s_scene* scene = load_text(
        "<World Version='2'><Gravity>0 -10</Gravity><Shapes><Shape Type='Circle'>"
        "<Radius>0.29715237</Radius><Position>0 0</Position></Shape></Shapes>"
        "<Fixtures><Fixture><Shape>0</Shape><Density>2.9804273</Density></Fixture></Fixtures>"
        "<Bodies><Body Type='Dynamic'><Position>1.8121862 0.1941328</Position>"
        "<Angle>-2.7758546</Angle><AngularVelocity>-3.6846924</AngularVelocity>"
        "<FixedRotation>true</FixedRotation><LinearVelocity>-6.984515 5.297557</LinearVelocity>"
        "</Body><Body Type='Dynamic'><Position>7.0367346 2.0797052</Position>"
        "<Angle>0.67746687</Angle><AngularVelocity>4.0827465</AngularVelocity>"
        "<LinearVelocity>-6.605772 -3.3665886</LinearVelocity><Fixtures><ID>0</ID></Fixtures>"
        "</Body></Bodies><Joints><Joint Type='Line'><BodyA>0</BodyA><BodyB>1</BodyB>"
        "<CollideConnected>true</CollideConnected>"
        "<LocalAnchorA>-5.5533504 0.10763967</LocalAnchorA>"
        "<LocalAxisA>-0.67890894 0.5784466</LocalAxisA><EnableLimit>true</EnableLimit>"
        "<LowerTranslation>-1.2518371</LowerTranslation>"
        "<UpperTranslation>1.2518371</UpperTranslation><EnableMotor>true</EnableMotor>"
        "<MotorSpeed>-2.0851588</MotorSpeed><MaxMotorForce>20.753616</MaxMotorForce>"
        "</Joint></Joints></World>");
    ENSURE(scene != NULL);
    v3_world w = build_v3(scene);
    ENSURE(!B2_IS_NULL(w.built->joints[0]));
    ENSURE_FLOAT(b2Body_GetAngularVelocity(w.built->bodies[0]), -3.6846924f);
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

/* Two dynamic 0.2 m triangles (radius of gyration 0.062 m), body B `gap` m across the axis
 * of a line joint anchored at their origins. */
static b2s_scene* small_line_pair(float gap) {
    static char xml[2048];
    snprintf(xml, sizeof xml,
             "<World Version='2'><Gravity>0 -10</Gravity><Shapes><Shape Type='Polygon'>"
             "<Vertices><Vertex>-0.1 -0.1</Vertex><Vertex>0.1 -0.1</Vertex><Vertex>0 0.1"
             "</Vertex></Vertices></Shape></Shapes><Fixtures><Fixture><Shape>0</Shape>"
             "<Density>1</Density></Fixture></Fixtures><Bodies>"
             "<Body Type='Dynamic'><Fixtures><ID>0</ID></Fixtures></Body>"
             "<Body Type='Dynamic'><Position>%.9g 0</Position><Fixtures><ID>0</ID></Fixtures>"
             "</Body></Bodies><Joints><Joint Type='Line'><BodyA>0</BodyA><BodyB>1</BodyB>"
             "<LocalAxisA>0 1</LocalAxisA></Joint></Joints></World>",
             (double)gap);
    return load_text(xml);
}

/* pyb2d3 (on Box2D v3.1.1) measured that a line or wheel joint between two dynamic bodies
 * throws them apart from 4.5 radii of gyration of the smaller off its axis, at every scale;
 * v3.1's table bounded it only by 0.5 m, which lets small bodies start far more radii off.
 * 0.4 m is 6.4 radii of these triangles: refused; 0.14 m (2.2 radii, within the range's 2.4)
 * is built and holds. */
static int a_line_joint_between_small_bodies_far_off_its_axis_is_refused(void) {
    b2s_scene* scene = small_line_pair(0.4f);
    ENSURE(scene != NULL);
    v3_world w = build_v3(scene);
    ENSURE(B2_IS_NULL(w.built->joints[0]));
    ENSURE(report_says(&w.built->reports, B2S_CODE_BEYOND_BOX2D_RANGE, 0, "radii of gyration"));
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    scene = small_line_pair(0.14f);
    ENSURE(scene != NULL);
    w = build_v3(scene);
    ENSURE(!B2_IS_NULL(w.built->joints[0]));
    ENSURE_EQ(w.built->reports.count, 0);
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

/* A body whose rotation is fixed, spinning at 3 rad/s: 2.x and v3.1 built by hand turn it
 * 3 rad in 1 s, and so must the adapter's (it created the body without its spin, silently). */
static int a_fixed_rotation_body_keeps_turning_at_its_angular_velocity(void) {
    b2s_scene* scene = load_text(
        "<World Version='2'><Gravity>0 0</Gravity><Shapes><Shape Type='Circle'>"
        "<Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes>"
        "<Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>"
        "<Bodies><Body Type='Dynamic'><FixedRotation>true</FixedRotation>"
        "<AngularVelocity>3</AngularVelocity><Fixtures><ID>0</ID></Fixtures></Body></Bodies>"
        "</World>");
    ENSURE(scene != NULL);
    v3_world w = build_v3(scene);
    ENSURE_EQ(w.built->reports.count, 0);
    step_v3(&w, 60);
    ENSURE_NEAR(b2Rot_GetAngle(b2Body_GetRotation(w.built->bodies[0])), 3.0, 1e-3);
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

/* A stress level of v3.2's stream (box2d3_stress_test): a wheel joint 51 radii of gyration
 * out on a light body, to a body with fixed rotation, gave a NaN angular velocity in v3.1's
 * first step (its assertion stopped the program). A body that cannot turn bounds the lever
 * of a line or wheel joint as a static one does (v3.1's range: 3). */
static int a_wheel_to_a_body_that_cannot_turn_has_the_short_lever(void) {
    b2s_scene* scene = load_text(
        "<World Version='2'><Gravity>-12.283044 11.090363</Gravity><Shapes>"
        "<Shape Type='Polygon'><Vertices><Vertex>0.18535013 -0.056597352</Vertex>"
        "<Vertex>0.05903176 0.23567976</Vertex><Vertex>-0.24655235 0.31476894</Vertex>"
        "<Vertex>-0.502051 0.11341128</Vertex><Vertex>-0.5091145 -0.19972612</Vertex>"
        "<Vertex>-0.24713 -0.41258976</Vertex><Vertex>0.057919357 -0.33704275</Vertex>"
        "</Vertices></Shape></Shapes><Fixtures><Fixture><Shape>0</Shape>"
        "<Density>0.8116647</Density><IsSensor>true</IsSensor></Fixture></Fixtures><Bodies>"
        "<Body Type='Dynamic'><AllowSleep>false</AllowSleep><Angle>-0.13634157</Angle>"
        "<AngularVelocity>4.513324</AngularVelocity><LinearVelocity>8.37212 -2.060833"
        "</LinearVelocity><Position>4.6106596 4.7750406</Position><Fixtures><ID>0</ID>"
        "</Fixtures></Body><Body Type='Dynamic'><Angle>0.25004768</Angle>"
        "<FixedRotation>true</FixedRotation><LinearVelocity>6.263666 8.580727</LinearVelocity>"
        "<Position>13.238903 -3.9475727</Position><Fixtures><ID>0</ID><ID>0</ID></Fixtures>"
        "</Body></Bodies><Joints><Joint Type='Wheel'><BodyA>0</BodyA><BodyB>1</BodyB>"
        "<LocalAnchorA>9.733746 -7.4689193</LocalAnchorA>"
        "<LocalAxisA>0.4653573 0.59141827</LocalAxisA><MotorSpeed>0.6062412</MotorSpeed>"
        "<MaxMotorTorque>38.72096</MaxMotorTorque><FrequencyHz>5.6326857</FrequencyHz>"
        "<DampingRatio>0.058253527</DampingRatio></Joint></Joints></World>");
    ENSURE(scene != NULL);
    v3_world w = build_v3(scene);
    ENSURE(B2_IS_NULL(w.built->joints[0]));
    ENSURE_EQ(count_reports(&w.built->reports, B2S_CODE_BEYOND_BOX2D_RANGE, "joint", 0), 1u);
    ENSURE(strstr(w.built->reports.items[0].message, "radii of gyration") != NULL);
    ENSURE(strstr(w.built->reports.items[0].message, "(at most 3)") != NULL);
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

/* ---- the v3.1 levels, built by hand through v3.1's own calls */

/* A ball of `radius` m, density 1, at `position`. */
static b2BodyId ball_by_hand(b2WorldId world, b2Vec2 position, float radius) {
    b2BodyDef def = b2DefaultBodyDef();
    def.type = b2_dynamicBody;
    def.position = position;
    b2BodyId body = b2CreateBody(world, &def);
    b2ShapeDef shape = b2DefaultShapeDef();
    shape.density = 1.0f;
    b2Circle circle = {{0.0f, 0.0f}, radius};
    b2CreateCircleShape(body, &shape, &circle);
    return body;
}

/* `body` pinned to a static ground at its centre by a revolute joint, as the plan makes it. */
static void pin_by_hand(b2WorldId world, b2BodyId body) {
    b2BodyDef def = b2DefaultBodyDef();
    b2BodyId ground = b2CreateBody(world, &def);
    b2RevoluteJointDef pin = b2DefaultRevoluteJointDef();
    pin.bodyIdA = ground;
    pin.bodyIdB = body;
    pin.localAnchorA = b2Body_GetPosition(body);
    b2CreateRevoluteJoint(world, &pin);
}

/* A world as the adapter's world def makes it: v3's defaults, gravity (0, -10), and the
 * range's maximum linear speed. */
static b2WorldId world_by_hand(void) {
    b2WorldDef def = b2DefaultWorldDef();
    def.maximumLinearSpeed = b2s_engine_working_range(B2S_ENGINE_BOX2D31)->world_max_linear_speed;
    return b2CreateWorld(&def);
}

/* Whether a world `build` makes by hand dies within 600 steps, run in a child: an assertion
 * of v3, or the body `build` returns beyond 1e4 m or NaN. */
static bool dies_by_hand(b2BodyId (*build)(b2WorldId world)) {
    fflush(NULL);
    pid_t child = fork();
    if (child == 0) {
        b2WorldId world = world_by_hand();
        b2BodyId body = build(world);
        for (int i = 0; i < 600; ++i) {
            b2World_Step(world, TIME_STEP, SUB_STEPS);
            b2Vec2 p = b2Body_GetPosition(body);
            if (!(fabsf(p.x) <= 1e4f && fabsf(p.y) <= 1e4f)) {
                _exit(1);
            }
        }
        _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    return WIFSIGNALED(status) || WEXITSTATUS(status) != 0;
}

/* Two 0.1 m balls, body A pinned at the origin, body B 20 m along the axis of a prismatic
 * joint whose limit holds it within 1 m: 19 m from satisfied. */
static b2BodyId prismatic_20_m_past_its_limit_by_hand(b2WorldId world) {
    b2BodyId a = ball_by_hand(world, (b2Vec2){0.0f, 0.0f}, 0.1f);
    b2BodyId b = ball_by_hand(world, (b2Vec2){20.0f, 0.0f}, 0.1f);
    pin_by_hand(world, a);
    b2PrismaticJointDef def = b2DefaultPrismaticJointDef();
    def.bodyIdA = a;
    def.bodyIdB = b;
    def.localAxisA = (b2Vec2){1.0f, 0.0f};
    def.enableLimit = true;
    def.lowerTranslation = -1.0f;
    def.upperTranslation = 1.0f;
    b2CreatePrismaticJoint(world, &def);
    return b;
}

/* Two balls of `radius` m on joint 1, body A (1) pinned to the ground (0) by joint 0, body B
 * (2) at `position`; `joint` is the second joint's XML, between bodies 1 and 2. */
static b2s_scene* pinned_pair(float radius, const char* position, const char* joint) {
    static char xml[2048];
    snprintf(xml, sizeof xml,
             "<World Version='2'><Gravity>0 -10</Gravity><Shapes><Shape Type='Circle'>"
             "<Radius>%.9g</Radius><Position>0 0</Position></Shape></Shapes>"
             "<Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>"
             "<Bodies><Body Type='Static'/><Body Type='Dynamic'><Fixtures><ID>0</ID></Fixtures>"
             "</Body><Body Type='Dynamic'><Position>%s</Position><Fixtures><ID>0</ID>"
             "</Fixtures></Body></Bodies><Joints><Joint Type='Revolute'><BodyA>0</BodyA>"
             "<BodyB>1</BodyB><LocalAnchorA>0 0</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB>"
             "</Joint>%s</Joints></World>",
             (double)radius, position, joint);
    return load_text(xml);
}

/* One of the levels that v3.1 dies of (SIGILL) when built by hand: a prismatic joint
 * 19 m past its limit on a pinned 0.1 m ball. The adapter leaves the prismatic joint out,
 * and what it builds holds. */
static int a_prismatic_20_m_past_its_limit_on_a_pinned_ball_is_refused(void) {
    ENSURE(dies_by_hand(prismatic_20_m_past_its_limit_by_hand));
    b2s_scene* scene = pinned_pair(
        0.1f, "20 0",
        "<Joint Type='Prismatic'><BodyA>1</BodyA><BodyB>2</BodyB><LocalAnchorA>0 0</LocalAnchorA>"
        "<LocalAnchorB>0 0</LocalAnchorB><LocalAxisA>1 0</LocalAxisA><EnableLimit>true"
        "</EnableLimit><LowerTranslation>-1</LowerTranslation><UpperTranslation>1"
        "</UpperTranslation></Joint>");
    ENSURE(scene != NULL);
    v3_world w = build_v3(scene);
    ENSURE(B2_IS_NON_NULL(w.built->joints[0]));
    ENSURE(B2_IS_NULL(w.built->joints[1]));
    ENSURE_EQ(w.built->reports.count, 1);
    ENSURE_EQ(count_reports(&w.built->reports, B2S_CODE_BEYOND_BOX2D_RANGE, "joint", 1), 1);
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

/* 0.3 m balls, body A pinned at the origin, body B 50 m along the axis of a wheel joint with
 * the format's spring (2 Hz, 0.7), anchored at their centres: satisfied. */
static b2BodyId wheel_50_m_along_its_axis_by_hand(b2WorldId world) {
    b2BodyId a = ball_by_hand(world, (b2Vec2){0.0f, 0.0f}, 0.3f);
    b2BodyId b = ball_by_hand(world, (b2Vec2){50.0f, 0.0f}, 0.3f);
    pin_by_hand(world, a);
    b2WheelJointDef def = b2DefaultWheelJointDef();
    def.bodyIdA = a;
    def.bodyIdB = b;
    def.localAxisA = (b2Vec2){1.0f, 0.0f};
    def.enableSpring = true;
    def.hertz = 2.0f;
    def.dampingRatio = 0.7f;
    b2CreateWheelJoint(world, &def);
    return b;
}

/* One of the levels that v3.1 dies of (SIGILL) when built by hand: a satisfied wheel
 * joint with body B 50 m along its axis from a pinned 0.3 m ball. v3's wheel solver turns
 * body A about body B's anchor (wheel_joint.c: b2Cross(d + rA, axis)), 236 radii of
 * gyration out: the lever a prismatic joint's axis gives body A. The adapter built it; it
 * leaves it out now, and what it builds holds. */
static int a_wheel_50_m_along_its_axis_from_a_pinned_ball_is_refused(void) {
    ENSURE(dies_by_hand(wheel_50_m_along_its_axis_by_hand));
    b2s_scene* scene = pinned_pair(
        0.3f, "50 0",
        "<Joint Type='Wheel'><BodyA>1</BodyA><BodyB>2</BodyB><LocalAnchorA>0 0</LocalAnchorA>"
        "<LocalAnchorB>0 0</LocalAnchorB><LocalAxisA>1 0</LocalAxisA></Joint>");
    ENSURE(scene != NULL);
    v3_world w = build_v3(scene);
    ENSURE(B2_IS_NON_NULL(w.built->joints[0]));
    ENSURE(B2_IS_NULL(w.built->joints[1]));
    ENSURE_EQ(w.built->reports.count, 1);
    ENSURE(report_says(&w.built->reports, B2S_CODE_BEYOND_BOX2D_RANGE, 1, "as body A's lever"));
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

/* A 0.3 m ball at the origin (pinned to a static ground at its centre by a revolute joint,
 * or free) and a 1 m ball hanging 10 m below a point 10 m out on it, on a satisfied rope
 * 10 m long anchored there and at the 1 m ball's centre, as the plan makes a rope: v3.1's
 * distance joint with its spring on at 0 Hz and its upper limit at the length. Whether the
 * world dies within 600 steps, in a child: an assertion, or a ball beyond 1e4 m or NaN. */
static bool rope_10_m_out_dies_by_hand(bool pinned) {
    fflush(NULL);
    pid_t child = fork();
    if (child == 0) {
        b2WorldId world = world_by_hand();
        b2BodyId a = ball_by_hand(world, (b2Vec2){0.0f, 0.0f}, 0.3f);
        b2BodyId b = ball_by_hand(world, (b2Vec2){10.0f, -10.0f}, 1.0f);
        if (pinned) {
            pin_by_hand(world, a);
        }
        b2DistanceJointDef rope = b2DefaultDistanceJointDef();
        rope.bodyIdA = a;
        rope.bodyIdB = b;
        rope.localAnchorA = (b2Vec2){10.0f, 0.0f};
        rope.length = 10.0f;
        rope.enableSpring = true;
        rope.hertz = 0.0f;
        rope.enableLimit = true;
        rope.minLength = 0.0f;
        rope.maxLength = 10.0f;
        b2CreateDistanceJoint(world, &rope);
        for (int i = 0; i < 600; ++i) {
            b2World_Step(world, TIME_STEP, SUB_STEPS);
            b2BodyId bodies[2] = {a, b};
            for (int k = 0; k < 2; ++k) {
                b2Vec2 p = b2Body_GetPosition(bodies[k]);
                if (!(fabsf(p.x) <= 1e4f && fabsf(p.y) <= 1e4f)) {
                    _exit(1);
                }
            }
        }
        _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    return WIFSIGNALED(status) || WEXITSTATUS(status) != 0;
}

/* The same level as a file: joint 0 the rope, joint 1 the pin where `pinned`. */
static b2s_scene* rope_10_m_out(bool pinned) {
    static char xml[2048];
    snprintf(xml, sizeof xml,
             "<World Version='2'><Gravity>0 -10</Gravity><Shapes><Shape Type='Circle'>"
             "<Radius>0.3</Radius><Position>0 0</Position></Shape><Shape Type='Circle'>"
             "<Radius>1</Radius><Position>0 0</Position></Shape></Shapes><Fixtures><Fixture>"
             "<Shape>0</Shape><Density>1</Density></Fixture><Fixture><Shape>1</Shape>"
             "<Density>1</Density></Fixture></Fixtures><Bodies><Body Type='Static'/>"
             "<Body Type='Dynamic'><Fixtures><ID>0</ID></Fixtures></Body><Body Type='Dynamic'>"
             "<Position>10 -10</Position><Fixtures><ID>1</ID></Fixtures></Body></Bodies>"
             "<Joints><Joint Type='Rope'><BodyA>1</BodyA><BodyB>2</BodyB><LocalAnchorA>10 0"
             "</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB><MaxLength>10</MaxLength></Joint>"
             "%s</Joints></World>",
             pinned ? "<Joint Type='Revolute'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 0"
                      "</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB></Joint>"
                    : "");
    return load_text(xml);
}

/* The case no bound covered: a satisfied rope 10 m out on a pinned 0.3 m ball (47
 * radii of gyration, within the 75 of every joint) throws the balls off in v3.1 built by
 * hand, and the adapter built it. A distance joint on a body a revolute or weld joint holds
 * to the ground now has its own bound (max_lever_pinned_distance): the rope is left out and
 * the pinned ball holds. */
static int a_rope_10_m_out_on_a_pinned_ball_is_refused(void) {
    ENSURE(rope_10_m_out_dies_by_hand(true));
    b2s_scene* scene = rope_10_m_out(true);
    ENSURE(scene != NULL);
    v3_world w = build_v3(scene);
    ENSURE(B2_IS_NULL(w.built->joints[0]));
    ENSURE(B2_IS_NON_NULL(w.built->joints[1]));
    ENSURE_EQ(w.built->reports.count, 1);
    ENSURE(report_says(&w.built->reports, B2S_CODE_BEYOND_BOX2D_RANGE, 0,
                       "which a revolute or weld joint holds to a body that does not move"));
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

/* The same rope on the same ball left free holds by hand, and the adapter builds it. */
static int a_rope_10_m_out_on_a_free_ball_is_built_and_holds(void) {
    ENSURE(!rope_10_m_out_dies_by_hand(false));
    b2s_scene* scene = rope_10_m_out(false);
    ENSURE(scene != NULL);
    v3_world w = build_v3(scene);
    ENSURE(B2_IS_NON_NULL(w.built->joints[0]));
    ENSURE_EQ(w.built->reports.count, 0);
    ENSURE(finite_for_600_steps(&w));
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

/* ---- line joints that start off their axis, to the ground and from it */

/* A static ground at the origin and a 0.5 m ball, density 1, whose centre starts 1.5 m below
 * the x axis of a line joint anchored at the ground's origin and the ball's centre: ball
 * first when `ball_is_a` (its anchor then on its rim, (0.5, 0), and the axis turns with it),
 * else the ground first. */
static b2s_scene* line_to_the_ground_1_5_m_off(bool ball_is_a) {
    static char xml[2048];
    const char* ball = ball_is_a ? "<Body Type='Dynamic'><Position>-0.5 -1.5</Position>"
                                   "<Fixtures><ID>0</ID></Fixtures></Body>"
                                 : "<Body Type='Dynamic'><Position>0 -1.5</Position>"
                                   "<Fixtures><ID>0</ID></Fixtures></Body>";
    snprintf(xml, sizeof xml,
             "<World Version='2'><Gravity>0 -10</Gravity><Shapes><Shape Type='Circle'>"
             "<Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes><Fixtures><Fixture>"
             "<Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>%s%s</Bodies>"
             "<Joints><Joint Type='Line'><BodyA>0</BodyA><BodyB>1</BodyB>%s</Joint></Joints>"
             "</World>",
             ball_is_a ? ball : "<Body Type='Static'/>", ball_is_a ? "<Body Type='Static'/>" : ball,
             ball_is_a ? "<LocalAnchorA>0.5 0</LocalAnchorA>" : "");
    return load_text(xml);
}

/* The ground-first level by hand: v3.1's wheel joint without its spring, along x (v3's
 * default axis is y). */
static b2BodyId line_to_the_ground_1_5_m_off_by_hand(b2WorldId world) {
    b2BodyDef def = b2DefaultBodyDef();
    b2BodyId ground = b2CreateBody(world, &def);
    b2BodyId ball = ball_by_hand(world, (b2Vec2){0.0f, -1.5f}, 0.5f);
    b2WheelJointDef line = b2DefaultWheelJointDef();
    line.bodyIdA = ground;
    line.bodyIdB = ball;
    line.localAxisA = (b2Vec2){1.0f, 0.0f};
    line.enableSpring = false;
    b2CreateWheelJoint(world, &line);
    return ball;
}

/* The ball-first level by hand. */
static b2BodyId line_from_a_ball_1_5_m_off_the_ground_by_hand(b2WorldId world) {
    b2BodyDef def = b2DefaultBodyDef();
    b2BodyId ground = b2CreateBody(world, &def);
    b2BodyId ball = ball_by_hand(world, (b2Vec2){-0.5f, -1.5f}, 0.5f);
    b2WheelJointDef line = b2DefaultWheelJointDef();
    line.bodyIdA = ball;
    line.bodyIdB = ground;
    line.localAnchorA = (b2Vec2){0.5f, 0.0f};
    line.localAxisA = (b2Vec2){1.0f, 0.0f};
    line.enableSpring = false;
    b2CreateWheelJoint(world, &line);
    return ball;
}

/* The level: a line joint to a static body, its ball 1.5 m off the axis. Built by
 * hand, v3.1 pulls the ball back onto the axis (docs/working-range.md: every such joint on a
 * static or kinematic body A held, up to 20 m off), and the adapter refused it (the 0.5 m of
 * every line or wheel joint, measured on dynamic pairs). It is built, and the ball ends
 * where it ends by hand: on the axis, within a millimetre. */
static int a_line_joint_to_the_ground_1_5_m_off_its_axis_is_built_and_holds(void) {
    ENSURE(!dies_by_hand(line_to_the_ground_1_5_m_off_by_hand));
    b2WorldId world = world_by_hand();
    b2BodyId ball = line_to_the_ground_1_5_m_off_by_hand(world);
    for (int i = 0; i < 600; ++i) {
        b2World_Step(world, TIME_STEP, SUB_STEPS);
    }
    b2Vec2 by_hand = b2Body_GetPosition(ball);
    b2DestroyWorld(world);
    ENSURE(fabsf(by_hand.y) < 1e-3f);

    b2s_scene* scene = line_to_the_ground_1_5_m_off(false);
    ENSURE(scene != NULL);
    v3_world w = build_v3(scene);
    ENSURE(B2_IS_NON_NULL(w.built->joints[0]));
    ENSURE_EQ(w.built->reports.count, 0);
    ENSURE(finite_for_600_steps(&w));
    b2Vec2 built = b2Body_GetPosition(w.built->bodies[1]);
    ENSURE_NEAR(built.x, by_hand.x, 1e-4);
    ENSURE_NEAR(built.y, by_hand.y, 1e-4);
    free_v3(&w);
    b2s_scene_free(scene);
    return 0;
}

/* The same joint the other way round, the ball body A: its axis turns with the ball, and
 * v3.1 throws the ball off (docs/working-range.md: from 3 radii of gyration across the
 * axis). The adapter still leaves it out (it starts 1.5 m from satisfied, beyond 0.5 m), and
 * the ball falls free. */
static int a_line_joint_from_a_ball_to_the_ground_1_5_m_off_its_axis_is_refused(void) {
    ENSURE(dies_by_hand(line_from_a_ball_1_5_m_off_the_ground_by_hand));
    b2s_scene* scene = line_to_the_ground_1_5_m_off(true);
    return refused_and_the_world_holds(
        scene, "a line or wheel joint that turns a body (a dynamic body A");
}

/* A static ground at the origin and a 0.5 m ball whose centre starts 2 m above the x axis of
 * a line joint anchored at the ground's origin and 1.414 m from the ball's centre, along the
 * axis: 4 radii of gyration of the ball. Built by hand, v3.1 spins the ball off (from 2.5
 * radii some balls die, docs/working-range.md). */
static b2BodyId line_2_m_off_far_out_on_its_ball_by_hand(b2WorldId world) {
    b2BodyDef def = b2DefaultBodyDef();
    b2BodyId ground = b2CreateBody(world, &def);
    b2BodyId ball = ball_by_hand(world, (b2Vec2){1.08578646f, 2.0f}, 0.5f);
    b2WheelJointDef line = b2DefaultWheelJointDef();
    line.bodyIdA = ground;
    line.bodyIdB = ball;
    line.localAnchorB = (b2Vec2){1.41421354f, 0.0f};
    line.localAxisA = (b2Vec2){1.0f, 0.0f};
    line.enableSpring = false;
    b2CreateWheelJoint(world, &line);
    return ball;
}

/* The case of a line joint to the ground that v3.1 dies of: the ball turns about an anchor
 * 4 radii of gyration out as the joint pulls it 2 m back onto the axis. The adapter leaves it
 * out, now by the range's max_lever_fixed_wheel (3 radii: v3.1 throws bodies anchored 3.5
 * radii out off from 0.25 m, 4 radii from 0.1 m), and the ball falls free. */
static int a_line_joint_to_the_ground_2_m_off_its_axis_far_out_on_its_ball_is_refused(void) {
    ENSURE(dies_by_hand(line_2_m_off_far_out_on_its_ball_by_hand));
    b2s_scene* scene = load_text(
        "<World Version='2'><Gravity>0 -10</Gravity><Shapes><Shape Type='Circle'>"
        "<Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes><Fixtures><Fixture>"
        "<Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies><Body Type='Static'/>"
        "<Body Type='Dynamic'><Position>1.08578646 2</Position><Fixtures><ID>0</ID></Fixtures>"
        "</Body></Bodies><Joints><Joint Type='Line'><BodyA>0</BodyA><BodyB>1</BodyB>"
        "<LocalAnchorB>1.41421354 0</LocalAnchorB></Joint></Joints></World>");
    return refused_and_the_world_holds(
        scene, "LocalAnchorB: the joint acts 4 radii of gyration from the centre of mass "
               "of body 1, beyond Box2D v3's working range (at most 3)");
}

/* ---- line and wheel joints that v3.1 dies of within 0.5 m of satisfied, or on an anchor
 * between 2 and 3 radii of gyration out */

/* A static ground at the origin, no fixture. */
static b2BodyId ground_by_hand(b2WorldId world) {
    b2BodyDef def = b2DefaultBodyDef();
    return b2CreateBody(world, &def);
}

/* v3.1's line joint: its wheel joint without the spring, along `axis`. */
static b2WheelJointDef line_by_hand(b2BodyId a, b2BodyId b, b2Vec2 axis) {
    b2WheelJointDef line = b2DefaultWheelJointDef();
    line.bodyIdA = a;
    line.bodyIdB = b;
    line.localAxisA = axis;
    line.enableSpring = false;
    return line;
}

/* The format's wheel joint (a spring of 2 Hz, damping ratio 0.7) along y. */
static b2WheelJointDef wheel_by_hand(b2BodyId a, b2BodyId b) {
    b2WheelJointDef wheel = b2DefaultWheelJointDef();
    wheel.bodyIdA = a;
    wheel.bodyIdB = b;
    wheel.localAxisA = (b2Vec2){0.0f, 1.0f};
    wheel.enableSpring = true;
    wheel.hertz = 2.0f;
    wheel.dampingRatio = 0.7f;
    return wheel;
}

/* The radius of gyration of a ball of `radius` m. */
static float ball_gyration(float radius) {
    return radius / sqrtf(2.0f);
}

/* (a) A 0.1 m ball, body A of a line joint along x anchored on its rim, (0.1, 0), and at the
 * ground's origin; the ball's anchor starts 3.5 radii of gyration (0.247 m) below the axis. */
static float ball_3_5_radii_below(void) {
    return 3.5f * ball_gyration(0.1f);
}

static b2BodyId line_from_a_ball_3_5_radii_off_by_hand(b2WorldId world) {
    b2BodyId ground = ground_by_hand(world);
    b2BodyId ball = ball_by_hand(world, (b2Vec2){-0.1f, -ball_3_5_radii_below()}, 0.1f);
    b2WheelJointDef line = line_by_hand(ball, ground, (b2Vec2){1.0f, 0.0f});
    line.localAnchorA = (b2Vec2){0.1f, 0.0f};
    b2CreateWheelJoint(world, &line);
    return ball;
}

/* Built by hand, v3.1 throws the ball off (a body A thrown from 2.8 radii of gyration across
 * the axis, docs/working-range.md); the 0.5 m of a line joint that turns a body let it
 * through, a 0.1 m ball's 3.5 radii being 0.25 m. The range's max_wheel_violation_gyrations
 * (2.4) now counts the radii of a dynamic body A on a body that does not move too. */
static int a_line_joint_from_a_ball_to_the_ground_3_5_radii_off_its_axis_is_refused(void) {
    ENSURE(dies_by_hand(line_from_a_ball_3_5_radii_off_by_hand));
    static char xml[1024];
    snprintf(xml, sizeof xml,
             "<World Version='2'><Gravity>0 -10</Gravity><Shapes><Shape Type='Circle'>"
             "<Radius>0.1</Radius><Position>0 0</Position></Shape></Shapes><Fixtures><Fixture>"
             "<Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
             "<Body Type='Dynamic'><Position>-0.1 %.9g</Position><Fixtures><ID>0</ID>"
             "</Fixtures></Body><Body Type='Static'/></Bodies><Joints><Joint Type='Line'>"
             "<BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0.1 0</LocalAnchorA>"
             "<LocalAxisA>1 0</LocalAxisA></Joint></Joints></World>",
             (double)-ball_3_5_radii_below());
    b2s_scene* scene = load_text(xml);
    return refused_and_the_world_holds(
        scene, "across its axis from a dynamic body A to a body that does not move, "
               "beyond Box2D v3's working range (at most 2.4 radii of gyration");
}

/* (b) A 0.1 m ball, body A of a line joint along x anchored on its rim, and a 1 m ball, body
 * B, anchored at its centre 3 radii of gyration of the smaller ball (0.212 m) above the
 * axis. */
static float pair_3_radii_apart(void) {
    return 3.0f * ball_gyration(0.1f);
}

static b2BodyId line_between_two_balls_3_radii_off_by_hand(b2WorldId world) {
    b2BodyId small = ball_by_hand(world, (b2Vec2){-0.1f, 0.0f}, 0.1f);
    b2BodyId large = ball_by_hand(world, (b2Vec2){0.0f, pair_3_radii_apart()}, 1.0f);
    b2WheelJointDef line = line_by_hand(small, large, (b2Vec2){1.0f, 0.0f});
    line.localAnchorA = (b2Vec2){0.1f, 0.0f};
    b2CreateWheelJoint(world, &line);
    return small;
}

/* Built by hand, v3.1 throws the small ball off (pairs thrown from 2.9 radii of gyration of
 * the smaller, docs/working-range.md), below the range's former 4 radii and the 0.5 m. */
static int a_line_joint_between_two_balls_3_radii_off_its_axis_is_refused(void) {
    ENSURE(dies_by_hand(line_between_two_balls_3_radii_off_by_hand));
    static char xml[1024];
    snprintf(xml, sizeof xml,
             "<World Version='2'><Gravity>0 -10</Gravity><Shapes><Shape Type='Circle'>"
             "<Radius>0.1</Radius><Position>0 0</Position></Shape><Shape Type='Circle'>"
             "<Radius>1</Radius><Position>0 0</Position></Shape></Shapes><Fixtures><Fixture>"
             "<Shape>0</Shape><Density>1</Density></Fixture><Fixture><Shape>1</Shape>"
             "<Density>1</Density></Fixture></Fixtures><Bodies>"
             "<Body Type='Dynamic'><Position>-0.1 0</Position><Fixtures><ID>0</ID></Fixtures>"
             "</Body><Body Type='Dynamic'><Position>0 %.9g</Position><Fixtures><ID>1</ID>"
             "</Fixtures></Body></Bodies><Joints><Joint Type='Line'><BodyA>0</BodyA>"
             "<BodyB>1</BodyB><LocalAnchorA>0.1 0</LocalAnchorA><LocalAxisA>1 0</LocalAxisA>"
             "</Joint></Joints></World>",
             (double)pair_3_radii_apart());
    b2s_scene* scene = load_text(xml);
    return refused_and_the_world_holds(
        scene, "across its axis between two dynamic bodies, beyond Box2D v3's working "
               "range (at most 2.4 radii of gyration");
}

/* A 0.25 or 0.1 m ball on a wheel joint from the ground's origin, along y, anchored `radii`
 * radii of gyration out along x, its anchor `off` m across the axis. */
static b2Vec2 ball_off_the_wheel(float radius, float radii, float off) {
    return (b2Vec2){off - radii * ball_gyration(radius), 2.0f + radius};
}

/* (c) The 0.25 m ball anchored 4 radii of gyration (0.707 m) out toward the axis, its anchor
 * 0.5 m across. */
static b2BodyId wheel_4_radii_out_by_hand(b2WorldId world) {
    b2BodyId ground = ground_by_hand(world);
    b2BodyId ball = ball_by_hand(world, ball_off_the_wheel(0.25f, -4.0f, 0.5f), 0.25f);
    b2WheelJointDef wheel = wheel_by_hand(ground, ball);
    wheel.localAnchorB = (b2Vec2){-4.0f * ball_gyration(0.25f), 0.0f};
    b2CreateWheelJoint(world, &wheel);
    return ball;
}

/* The scene of a wheel from the ground to a ball of `radius` m at `position`, anchored at
 * `anchor` on it. */
static b2s_scene* wheel_to_the_ground(float radius, b2Vec2 position, float anchor) {
    static char xml[1024];
    snprintf(xml, sizeof xml,
             "<World Version='2'><Gravity>0 -10</Gravity><Shapes><Shape Type='Circle'>"
             "<Radius>%.9g</Radius><Position>0 0</Position></Shape></Shapes><Fixtures><Fixture>"
             "<Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
             "<Body Type='Static'/><Body Type='Dynamic'><Position>%.9g %.9g</Position>"
             "<Fixtures><ID>0</ID></Fixtures></Body></Bodies><Joints><Joint Type='Wheel'>"
             "<BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorB>%.9g 0</LocalAnchorB>"
             "<LocalAxisA>0 1</LocalAxisA><FrequencyHz>2</FrequencyHz>"
             "<DampingRatio>0.7</DampingRatio></Joint></Joints></World>",
             (double)radius, (double)position.x, (double)position.y, (double)anchor);
    return load_text(xml);
}

/* Built by hand, v3.1 throws the ball off from 0.5 m across (anchored 4 radii out, bodies
 * died from 0.1 m), which the 0.5 m let through; the range's max_lever_fixed_wheel, 5 radii
 * before, is now 3, below the first death within 0.5 m of satisfied (3.5 radii). */
static int a_wheel_to_the_ground_anchored_4_radii_out_on_its_ball_is_refused(void) {
    ENSURE(dies_by_hand(wheel_4_radii_out_by_hand));
    b2s_scene* scene = wheel_to_the_ground(0.25f, ball_off_the_wheel(0.25f, -4.0f, 0.5f),
                                           -4.0f * ball_gyration(0.25f));
    return refused_and_the_world_holds(
        scene, "LocalAnchorB: the joint acts 4 radii of gyration from the centre of mass "
               "of body 1, beyond Box2D v3's working range (at most 3)");
}

/* The 0.1 m ball anchored 3 radii of gyration (0.212 m) out away from the axis, its anchor
 * 2 m across. */
static b2BodyId wheel_2_m_off_3_radii_out_by_hand(b2WorldId world) {
    b2BodyId ground = ground_by_hand(world);
    b2BodyId ball = ball_by_hand(world, ball_off_the_wheel(0.1f, 3.0f, 2.0f), 0.1f);
    b2WheelJointDef wheel = wheel_by_hand(ground, ball);
    wheel.localAnchorB = (b2Vec2){3.0f * ball_gyration(0.1f), 0.0f};
    b2CreateWheelJoint(world, &wheel);
    return ball;
}

/* Within the lever of a wheel to the ground (3 radii), v3.1 still throws a ball off as the
 * joint pulls it in from 2 m: beyond the range's max_lever_violated_wheel (2 radii), the 0.5 m
 * of a joint that turns a body bounds it, and the adapter leaves it out. */
static int a_wheel_to_the_ground_2_m_off_its_axis_3_radii_out_on_its_ball_is_refused(void) {
    ENSURE(dies_by_hand(wheel_2_m_off_3_radii_out_by_hand));
    b2s_scene* scene = wheel_to_the_ground(0.1f, ball_off_the_wheel(0.1f, 3.0f, 2.0f),
                                           3.0f * ball_gyration(0.1f));
    return refused_and_the_world_holds(
        scene, "or body B about an anchor beyond 2 radii of gyration");
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(line_joint_that_starts_violated_is_left_out);
    failed += RUN_TEST(line_joint_with_anchors_far_along_its_axis_stays_finite);
    failed += RUN_TEST(four_joints_on_one_pair_keep_the_satisfied_ones);
    failed += RUN_TEST(joints_that_start_violated_are_left_out);
    failed += RUN_TEST(satisfied_joints_far_from_small_bodies_are_built);
    failed += RUN_TEST(an_inertia_v3_cannot_hold_is_refused);
    failed += RUN_TEST(a_prismatic_lever_reaches_body_bs_anchor);
    failed += RUN_TEST(a_fixed_rotation_body_keeps_its_spin_and_its_line_joint_holds);
    failed += RUN_TEST(a_wheel_to_a_body_that_cannot_turn_has_the_short_lever);
    failed += RUN_TEST(a_line_joint_between_small_bodies_far_off_its_axis_is_refused);
    failed += RUN_TEST(a_fixed_rotation_body_keeps_turning_at_its_angular_velocity);
    failed += RUN_TEST(a_prismatic_20_m_past_its_limit_on_a_pinned_ball_is_refused);
    failed += RUN_TEST(a_wheel_50_m_along_its_axis_from_a_pinned_ball_is_refused);
    failed += RUN_TEST(a_rope_10_m_out_on_a_pinned_ball_is_refused);
    failed += RUN_TEST(a_rope_10_m_out_on_a_free_ball_is_built_and_holds);
    failed += RUN_TEST(a_line_joint_to_the_ground_1_5_m_off_its_axis_is_built_and_holds);
    failed += RUN_TEST(a_line_joint_from_a_ball_to_the_ground_1_5_m_off_its_axis_is_refused);
    failed += RUN_TEST(a_line_joint_to_the_ground_2_m_off_its_axis_far_out_on_its_ball_is_refused);
    failed += RUN_TEST(a_line_joint_from_a_ball_to_the_ground_3_5_radii_off_its_axis_is_refused);
    failed += RUN_TEST(a_line_joint_between_two_balls_3_radii_off_its_axis_is_refused);
    failed += RUN_TEST(a_wheel_to_the_ground_anchored_4_radii_out_on_its_ball_is_refused);
    failed += RUN_TEST(a_wheel_to_the_ground_2_m_off_its_axis_3_radii_out_on_its_ball_is_refused);
    return failed;
}
