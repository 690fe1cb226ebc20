/*
 * The v3 mapping (docs/format.md, "Onto Box2D v3.1", and docs/box2d.md, "How each version
 * maps"), row by row, against real Box2D v3.1.1 and v3.2 with their assertions on: one source
 * compiled once per version (V3_SUPPORT names its support header), a V3_MINOR block wherever
 * the versions differ. Each test builds a small inline scene, steps the world and checks what the
 * physics must do (positions, angles, velocities), exactly where the mapping is exact, with a
 * tolerance only where the solver needs one; every report is checked by its code, object and
 * index; every world must stay finite.
 */
#include V3_SUPPORT

#if V3_MINOR == 2
#include <box2d/constants.h>
#endif

/* ---- scenes */

/* A scene from its parts (attributes in single quotes); `gravity` NULL leaves it out. */
static b2s_scene* scene_of(const char* version, const char* gravity, const char* shapes,
                           const char* fixtures, const char* bodies, const char* joints) {
    size_t size = strlen(shapes) + strlen(fixtures) + strlen(bodies) + strlen(joints) + 512;
    char* text = (char*)malloc(size);
    if (text == NULL) {
        return NULL;
    }
    snprintf(text, size,
             "<World Version='%s'>%s%s%s<Shapes>%s</Shapes><Fixtures>%s</Fixtures>"
             "<Bodies>%s</Bodies><Joints>%s</Joints></World>",
             version, gravity != NULL ? "<Gravity>" : "", gravity != NULL ? gravity : "",
             gravity != NULL ? "</Gravity>" : "", shapes, fixtures, bodies, joints);
    b2s_scene* scene = load_text(text);
    free(text);
    return scene;
}

typedef struct scene_world {
    b2s_scene* scene;
    v3_world v3;
} scene_world;

/* A world built from a scene made with the C builder (for what the loader refuses). */
#define OPEN_SCENE(w, made)                                                                  \
    do {                                                                                     \
        (w).scene = (made);                                                                  \
        ENSURE((w).scene != NULL);                                                           \
        (w).v3 = build_v3((w).scene);                                                        \
        ENSURE((w).v3.built != NULL);                                                        \
    } while (0)

/* A world built from a scene made of its parts (scene_of). */
#define OPEN(w, ...) OPEN_SCENE(w, scene_of(__VA_ARGS__))

static void close_world(scene_world* w) {
    free_v3(&w->v3);
    b2s_scene_free(w->scene);
}

#define BODY(w, i) ((w).v3.built->bodies[i])
#define JOINT(w, i) ((w).v3.built->joints[i])
#define REPORTS(w) (&(w).v3.built->reports)

/* The pool slot of a body's k-th fixture: where built->shapes and the chain segments hold it. */
static uint32_t slot_of(const scene_world* w, uint32_t body, uint32_t k) {
    return b2s_scene_get_view(w->scene)->bodies[body].fixtures.first + k;
}

#define SHAPE(w, body, k) ((w).v3.built->shapes[slot_of(&(w), (body), (k))])
/* How many chain segments a body's k-th fixture made, and up to `capacity` of them in `out`. */
#define CHAIN_SEGMENTS(w, body, k, out, capacity) \
    v3_chain_segments((w).v3.built, slot_of(&(w), (body), (k)), (out), (capacity))
#if V3_MINOR == 1
/* The v3 chain a body's k-th fixture made (v3.1 has chains of its own). */
#define CHAIN(w, body, k) ((w).v3.built->chains[slot_of(&(w), (body), (k))])
#else
/* The loose chain segments a body's k-th fixture made, and the i-th of them. */
#define SEGMENTS(w, body, k) ((w).v3.built->segments[slot_of(&(w), (body), (k))])
#define SEGMENT(w, body, k, i) ((w).v3.built->segment_pool[SEGMENTS(w, body, k).first + (i)])
#endif

#define ENSURE_FINITE(w) ENSURE(bodies_finite(&(w).v3))

/* Exactly `expected` reports in all (the ones the test then checks one by one). */
#define ENSURE_REPORT_COUNT(w, expected)                                                     \
    do {                                                                                     \
        if (REPORTS(w)->count != (uint32_t)(expected)) {                                     \
            print_reports(REPORTS(w));                                                       \
        }                                                                                    \
        ENSURE_EQ(REPORTS(w)->count, (expected));                                            \
    } while (0)

static float angle_of(b2BodyId body) {
    b2Rot q = b2Body_GetRotation(body);
    return atan2f(q.s, q.c);
}

/* How far a free body falls from rest in `steps` steps of TIME_STEP with SUB_STEPS
 * substeps under `g`: v3 integrates each substep symplectically (velocity, then position),
 * so after n substeps of h the drop is g h^2 n (n + 1) / 2. */
static double free_fall(double g, int steps) {
    double h = (double)TIME_STEP / SUB_STEPS;
    double n = (double)steps * SUB_STEPS;
    return g * h * h * n * (n + 1.0) / 2.0;
}

/* Scene parts used by many tests. */
#define GROUND_BOX                                                                           \
    "<Shape Type='Polygon'><Vertices><Vertex>-50 -1</Vertex><Vertex>50 -1</Vertex>"          \
    "<Vertex>50 0</Vertex><Vertex>-50 0</Vertex></Vertices></Shape>"
#define CIRCLE(r) "<Shape Type='Circle'><Radius>" r "</Radius><Position>0 0</Position></Shape>"
#define BOX(hx, hy)                                                                          \
    "<Shape Type='Polygon'><Vertices><Vertex>-" hx " -" hy "</Vertex><Vertex>" hx " -" hy    \
    "</Vertex><Vertex>" hx " " hy "</Vertex><Vertex>-" hx " " hy "</Vertex></Vertices></Shape>"

/* ---- bodies */

static int body_fields_are_passed_exactly(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", CIRCLE("0.5"),
         "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         /* 0 */ "<Body Type='Static'><Name>anchor</Name><Position>1.5 -2.25</Position>"
                 "<Angle>0.7</Angle><Fixtures><ID>0</ID></Fixtures></Body>"
         /* 1 */ "<Body Type='Kinematic'><Position>0 5</Position><LinearVelocity>1 2"
                 "</LinearVelocity><AngularVelocity>0.5</AngularVelocity>"
                 "<Fixtures><ID>0</ID></Fixtures></Body>"
         /* 2 */ "<Body Type='Dynamic'><Position>10 5</Position><Angle>-1.25</Angle>"
                 "<LinearVelocity>3 -1</LinearVelocity><AngularVelocity>-2</AngularVelocity>"
                 "<LinearDamping>0.25</LinearDamping><AngularDamping>0.125</AngularDamping>"
                 "<AllowSleep>false</AllowSleep><Bullet>true</Bullet>"
                 "<Fixtures><ID>0</ID></Fixtures></Body>"
         /* 3 */ "<Body Type='Dynamic'><Position>20 5</Position><Awake>false</Awake>"
                 "<Fixtures><ID>0</ID></Fixtures></Body>"
         /* 4 */ "<Body Type='Dynamic'><Position>30 5</Position><Active>false</Active>"
                 "<Fixtures><ID>0</ID></Fixtures></Body>"
         /* 5 */ "<Body Type='Dynamic'><Position>40 5</Position><FixedRotation>true"
                 "</FixedRotation><Fixtures><ID>0</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);

    b2BodyId anchor = BODY(w, 0);
    ENSURE_EQ(b2Body_GetType(anchor), b2_staticBody);
    ENSURE_FLOAT(v3_position(anchor).x, 1.5f);
    ENSURE_FLOAT(v3_position(anchor).y, -2.25f);
    ENSURE_FLOAT(b2Body_GetRotation(anchor).c, cosf(0.7f)); /* not b2MakeRot's approximation */
    ENSURE_FLOAT(b2Body_GetRotation(anchor).s, sinf(0.7f));
    ENSURE_STR(b2Body_GetName(anchor), "anchor");

    b2BodyId kinematic = BODY(w, 1);
    ENSURE_EQ(b2Body_GetType(kinematic), b2_kinematicBody);
    ENSURE_FLOAT(b2Body_GetLinearVelocity(kinematic).x, 1.0f);
    ENSURE_FLOAT(b2Body_GetLinearVelocity(kinematic).y, 2.0f);
    ENSURE_FLOAT(b2Body_GetAngularVelocity(kinematic), 0.5f);
    ENSURE(b2Body_IsSleepEnabled(kinematic)); /* the defaults */
    ENSURE(b2Body_IsAwake(kinematic));
    ENSURE(b2Body_IsEnabled(kinematic));
    ENSURE(!b2Body_IsBullet(kinematic));
    ENSURE(!v3_rotation_fixed(kinematic));
    ENSURE_FLOAT(b2Body_GetGravityScale(kinematic), 1.0f);
    ENSURE_FLOAT(b2Body_GetLinearDamping(kinematic), 0.0f);

    b2BodyId dynamic = BODY(w, 2);
    ENSURE_EQ(b2Body_GetType(dynamic), b2_dynamicBody);
    ENSURE_FLOAT(v3_position(dynamic).x, 10.0f);
    ENSURE_FLOAT(v3_position(dynamic).y, 5.0f);
    ENSURE_FLOAT(b2Body_GetRotation(dynamic).c, cosf(-1.25f));
    ENSURE_FLOAT(b2Body_GetRotation(dynamic).s, sinf(-1.25f));
    ENSURE_FLOAT(b2Body_GetLinearVelocity(dynamic).x, 3.0f); /* a centred circle: the origin's */
    ENSURE_FLOAT(b2Body_GetLinearVelocity(dynamic).y, -1.0f);
    ENSURE_FLOAT(b2Body_GetAngularVelocity(dynamic), -2.0f);
    ENSURE_FLOAT(b2Body_GetLinearDamping(dynamic), 0.25f);
    ENSURE_FLOAT(b2Body_GetAngularDamping(dynamic), 0.125f);
    ENSURE(!b2Body_IsSleepEnabled(dynamic));
    ENSURE(b2Body_IsBullet(dynamic));
    ENSURE(b2Body_IsAwake(dynamic));

    ENSURE(!b2Body_IsAwake(BODY(w, 3)));
    ENSURE(!b2Body_IsEnabled(BODY(w, 4)));
    ENSURE(v3_rotation_fixed(BODY(w, 5)));
    ENSURE(b2Body_IsSleepEnabled(BODY(w, 5)));

    step_v3(&w.v3, 60);
    /* The kinematic body moves at its velocities, unmoved by gravity. */
    ENSURE_NEAR(v3_position(kinematic).x, 1.0, 1e-4);
    ENSURE_NEAR(v3_position(kinematic).y, 7.0, 1e-4);
    ENSURE_NEAR(angle_of(kinematic), 0.5, 1e-4);
    /* The asleep body and the inactive one stay where they were, bit for bit. */
    ENSURE_FLOAT(v3_position(BODY(w, 3)).y, 5.0f);
    ENSURE(!b2Body_IsAwake(BODY(w, 3)));
    ENSURE_FLOAT(v3_position(BODY(w, 4)).y, 5.0f);
    /* The awake one falls. */
    ENSURE_NEAR(v3_position(BODY(w, 5)).y, 5.0 - free_fall(10.0, 60), 1e-3);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int damping_slows_as_v3_integrates_it(void) {
    scene_world w;
    OPEN(w, "1", "0 0", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Dynamic'><LinearVelocity>4 0</LinearVelocity><LinearDamping>0.5"
         "</LinearDamping><AngularVelocity>3</AngularVelocity><AngularDamping>1"
         "</AngularDamping><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>0 10</Position><LinearVelocity>4 0</LinearVelocity>"
         "<AngularVelocity>3</AngularVelocity><Fixtures><ID>0</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    step_v3(&w.v3, 60);
    /* v3 multiplies each substep's velocity by 1 / (1 + h c). */
    double h = (double)TIME_STEP / SUB_STEPS;
    double linear = 4.0 * pow(1.0 / (1.0 + h * 0.5), 60 * SUB_STEPS);
    double angular = 3.0 * pow(1.0 / (1.0 + h * 1.0), 60 * SUB_STEPS);
    ENSURE_NEAR(b2Body_GetLinearVelocity(BODY(w, 0)).x, linear, 1e-4);
    ENSURE_NEAR(b2Body_GetAngularVelocity(BODY(w, 0)), angular, 1e-4);
    ENSURE(linear < 3.2 && angular < 1.2); /* it did slow down noticeably */
    /* Undamped, in zero gravity: exactly unchanged. */
    ENSURE_FLOAT(b2Body_GetLinearVelocity(BODY(w, 1)).x, 4.0f);
    ENSURE_FLOAT(b2Body_GetAngularVelocity(BODY(w, 1)), 3.0f);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int gravity_scale_scales_the_fall(void) {
    scene_world w;
    OPEN(w, "2", "0 -10", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Dynamic'><Position>0 100</Position><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>5 100</Position><GravityScale>0</GravityScale>"
         "<Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>10 100</Position><GravityScale>2</GravityScale>"
         "<Fixtures><ID>0</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    ENSURE_FLOAT(b2Body_GetGravityScale(BODY(w, 1)), 0.0f);
    ENSURE_FLOAT(b2Body_GetGravityScale(BODY(w, 2)), 2.0f);
    step_v3(&w.v3, 60);
    double one = 100.0 - v3_position(BODY(w, 0)).y;
    double two = 100.0 - v3_position(BODY(w, 2)).y;
    ENSURE_NEAR(one, free_fall(10.0, 60), 1e-3);
    ENSURE_FLOAT(v3_position(BODY(w, 1)).y, 100.0f); /* scale 0 does not fall at all */
    ENSURE_FLOAT(b2Body_GetLinearVelocity(BODY(w, 1)).y, 0.0f);
    ENSURE_NEAR(two, 2.0 * one, 2e-3);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int gravity_comes_from_the_file_or_the_host(void) {
    scene_world w;
    OPEN(w, "1", "3 -4", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Dynamic'><Fixtures><ID>0</ID></Fixtures></Body>", "");
    ENSURE_REPORT_COUNT(w, 0);
    ENSURE_FLOAT(b2World_GetGravity(w.v3.id).x, 3.0f);
    ENSURE_FLOAT(b2World_GetGravity(w.v3.id).y, -4.0f);
    step_v3(&w.v3, 60);
    ENSURE_NEAR(v3_position(BODY(w, 0)).x, free_fall(3.0, 60), 1e-3);
    ENSURE_NEAR(v3_position(BODY(w, 0)).y, -free_fall(4.0, 60), 1e-3);
    ENSURE_FINITE(w);
    close_world(&w);

    /* No Gravity: the host's fallback, whatever it is. */
    OPEN(w, "1", NULL, CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Dynamic'><Fixtures><ID>0</ID></Fixtures></Body>", "");
    ENSURE_REPORT_COUNT(w, 0);
    ENSURE_FLOAT(b2World_GetGravity(w.v3.id).x, 0.0f); /* build_v3's fallback (0, -10) */
    ENSURE_FLOAT(b2World_GetGravity(w.v3.id).y, -10.0f);
    b2Vec2 fallback = V3_ADAPTER(scene_gravity)(w.scene, (b2Vec2){1.0f, 2.0f});
    ENSURE_FLOAT(fallback.x, 1.0f);
    ENSURE_FLOAT(fallback.y, 2.0f);
    ENSURE_FLOAT(V3_ADAPTER(world_def)(w.scene, (b2Vec2){0.5f, -3.0f}).gravity.y, -3.0f);
    ENSURE_FLOAT(V3_ADAPTER(world_def)(w.scene, b2Vec2_zero).maximumLinearSpeed,
                 b2s_engine_working_range(V3_ENGINE)->world_max_linear_speed);
    step_v3(&w.v3, 60);
    ENSURE_NEAR(v3_position(BODY(w, 0)).y, -free_fall(10.0, 60), 1e-3);
    ENSURE_FINITE(w);
    close_world(&w);

    /* A gravity beyond the working range: the fallback, and a report. */
    OPEN(w, "1", "0 -5000", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Dynamic'><Fixtures><ID>0</ID></Fixtures></Body>", "");
    ENSURE_REPORT_COUNT(w, 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_BEYOND_BOX2D_RANGE, "world", 0), 1);
    ENSURE_FLOAT(b2World_GetGravity(w.v3.id).y, -10.0f);
    ENSURE(!B2_IS_NULL(BODY(w, 0)));
    step_v3(&w.v3, 60);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int sleep_follows_allow_sleep(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", GROUND_BOX CIRCLE("0.5"),
         "<Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape><Density>1</Density>"
         "</Fixture>",
         "<Body Type='Static'><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>-5 0.5</Position><Fixtures><ID>1</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>5 0.5</Position><AllowSleep>false</AllowSleep>"
         "<Fixtures><ID>1</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    step_v3(&w.v3, 180);
    ENSURE(!b2Body_IsAwake(BODY(w, 1))); /* at rest for far longer than v3's 0.5 s */
    ENSURE(b2Body_IsAwake(BODY(w, 2)));
    ENSURE_NEAR(v3_position(BODY(w, 1)).y, 0.5, 0.02);
    ENSURE_NEAR(v3_position(BODY(w, 2)).y, 0.5, 0.02);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* A ball hits a box above its centre: the box spins, unless its rotation is fixed. */
static int fixed_rotation_does_not_rotate_when_hit_off_centre(void) {
    scene_world w;
    OPEN(w, "1", "0 0", BOX("1", "1") CIRCLE("0.25"),
         "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>"
         "<Fixture><Shape>1</Shape><Density>4</Density></Fixture>",
         "<Body Type='Dynamic'><FixedRotation>true</FixedRotation>"
         "<Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>-3 0.8</Position><LinearVelocity>10 0</LinearVelocity>"
         "<Fixtures><ID>1</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>0 50</Position><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>-3 50.8</Position><LinearVelocity>10 0</LinearVelocity>"
         "<Fixtures><ID>1</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    ENSURE_FLOAT(b2Body_GetRotationalInertia(BODY(w, 0)), 0.0f);
    step_v3(&w.v3, 60);
    ENSURE(v3_position(BODY(w, 0)).x > 0.1f); /* it was hit */
    ENSURE(v3_position(BODY(w, 2)).x > 0.1f);
    ENSURE_FLOAT(b2Body_GetRotation(BODY(w, 0)).c, 1.0f);
    ENSURE_FLOAT(b2Body_GetRotation(BODY(w, 0)).s, 0.0f);
    ENSURE_FLOAT(b2Body_GetAngularVelocity(BODY(w, 0)), 0.0f);
    ENSURE(fabsf(angle_of(BODY(w, 2))) > 0.05f); /* the free box turned */
    ENSURE(fabsf(b2Body_GetAngularVelocity(BODY(w, 2))) > 0.05f);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* An inactive body is not simulated: it does not fall, and nothing collides with it. */
static int inactive_bodies_are_not_simulated(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", GROUND_BOX CIRCLE("0.5"),
         "<Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape><Density>1</Density>"
         "</Fixture>",
         "<Body Type='Static'><Active>false</Active><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>0 2</Position><Fixtures><ID>1</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>5 2</Position><Active>false</Active>"
         "<Fixtures><ID>1</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    ENSURE(!b2Body_IsEnabled(BODY(w, 0)));
    ENSURE(b2Body_IsEnabled(BODY(w, 1)));
    step_v3(&w.v3, 60);
    ENSURE_NEAR(v3_position(BODY(w, 1)).y, 2.0 - free_fall(10.0, 60), 1e-3);
    ENSURE_FLOAT(v3_position(BODY(w, 2)).x, 5.0f);
    ENSURE_FLOAT(v3_position(BODY(w, 2)).y, 2.0f);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* v3 gives a dynamic body without mass nothing; the format's files expect Box2D 2.x's 1 kg. */
static int zero_density_dynamic_body_gets_one_kilogram_and_falls(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", CIRCLE("0.5") BOX("1", "0.5"),
         "<Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape><Density>0</Density>"
         "</Fixture>",
         "<Body Type='Dynamic'><Position>0 10</Position><Fixtures><ID>0</ID><ID>1</ID>"
         "</Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    ENSURE_FLOAT(b2Body_GetMass(BODY(w, 0)), 1.0f);
    ENSURE_FLOAT(b2Shape_GetDensity(SHAPE(w, 0, 0)), 0.0f);
    step_v3(&w.v3, 60);
    ENSURE_NEAR(v3_position(BODY(w, 0)).y, 10.0 - free_fall(10.0, 60), 1e-3);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* MassData: the given mass, the shapes' centre; inertia moved to v3's centre of mass. */
static int partial_mass_data_overrides_only_what_it_gives(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", BOX("1", "0.5"), "<Fixture><Shape>0</Shape><Density>2</Density></Fixture>",
         "<Body Type='Dynamic'><MassData><Mass>3</Mass></MassData>"
         "<Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>5 0</Position><MassData><Center>0.5 0</Center>"
         "<Inertia>4</Inertia></MassData><Fixtures><ID>0</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    ENSURE_FLOAT(b2Body_GetMass(BODY(w, 0)), 3.0f);
    ENSURE_FLOAT(v3_local_center(BODY(w, 0)).x, 0.0f);
    ENSURE_FLOAT(b2Body_GetMass(BODY(w, 1)), 4.0f); /* 2 x 1 m x 2 kg/m^2, from the shape */
    ENSURE_FLOAT(v3_local_center(BODY(w, 1)).x, 0.5f);
    ENSURE_NEAR(b2Body_GetRotationalInertia(BODY(w, 1)), 4.0 - 4.0 * 0.25, 1e-6);
    step_v3(&w.v3, 30);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* ---- fixtures */

static int fixture_material_is_passed_exactly_and_bounces(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", GROUND_BOX CIRCLE("0.5"),
         "<Fixture><Shape>0</Shape></Fixture>"
         "<Fixture><Shape>1</Shape><Density>2.5</Density><Friction>0.35</Friction>"
         "<Restitution>0.6</Restitution></Fixture>"
         "<Fixture><Shape>1</Shape><Density>2.5</Density></Fixture>",
         "<Body Type='Static'><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>-5 5</Position><Fixtures><ID>1</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>5 5</Position><Fixtures><ID>2</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    b2ShapeId ground = SHAPE(w, 0, 0), bouncy = SHAPE(w, 1, 0), plain = SHAPE(w, 2, 0);
    ENSURE_FLOAT(b2Shape_GetDensity(bouncy), 2.5f);
    ENSURE_FLOAT(b2Shape_GetFriction(bouncy), 0.35f);
    ENSURE_FLOAT(b2Shape_GetRestitution(bouncy), 0.6f);
    ENSURE_FLOAT(b2Shape_GetDensity(ground), 0.0f); /* the format's defaults */
    ENSURE_FLOAT(b2Shape_GetFriction(ground), 0.2f);
    ENSURE_FLOAT(b2Shape_GetRestitution(ground), 0.0f);
    ENSURE_FLOAT(b2Shape_GetFriction(plain), 0.2f);
    ENSURE(!b2Shape_IsSensor(plain));
    ENSURE_FLOAT(b2Body_GetMass(BODY(w, 1)), v3_shape_mass_data(bouncy).mass);
    /* Dropped from 4.5 m above the ground: the bouncy ball comes back up, the other not. */
    bool bounced = false, plain_rose = false;
    for (int i = 0; i < 150; ++i) {
        step_v3(&w.v3, 1);
        bounced = bounced || (b2Body_GetLinearVelocity(BODY(w, 1)).y > 3.0f &&
                              v3_position(BODY(w, 1)).y < 2.0f);
        plain_rose = plain_rose || b2Body_GetLinearVelocity(BODY(w, 2)).y > 1.0f;
    }
    ENSURE(bounced);
    ENSURE(!plain_rose);
    ENSURE_NEAR(v3_position(BODY(w, 2)).y, 0.5, 0.02);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int sensors_are_passed_through_and_sense(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", GROUND_BOX CIRCLE("0.5") BOX("5", "0.5"),
         "<Fixture><Shape>0</Shape></Fixture>"
         "<Fixture><Shape>1</Shape><Density>1</Density></Fixture>"
         "<Fixture><Shape>1</Shape><Density>1</Density><IsSensor>true</IsSensor></Fixture>"
         "<Fixture><Shape>2</Shape><IsSensor>true</IsSensor></Fixture>",
         "<Body Type='Static'><Position>0 -10</Position><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Static'><Fixtures><ID>3</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>0 3</Position><Fixtures><ID>1</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>20 3</Position><Fixtures><ID>2</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    b2ShapeId slab = SHAPE(w, 1, 0);
    ENSURE(b2Shape_IsSensor(slab));
    ENSURE(b2Shape_IsSensor(SHAPE(w, 3, 0)));
    ENSURE(!b2Shape_IsSensor(SHAPE(w, 2, 0)));
    ENSURE(b2Shape_AreSensorEventsEnabled(SHAPE(w, 2, 0)));
    int sensed = 0;
    for (int i = 0; i < 180; ++i) {
        step_v3(&w.v3, 1);
        b2SensorEvents events = b2World_GetSensorEvents(w.v3.id);
        for (int e = 0; e < events.beginCount; ++e) {
            if (B2_ID_EQUALS(events.beginEvents[e].sensorShapeId, slab) &&
                B2_ID_EQUALS(events.beginEvents[e].visitorShapeId, SHAPE(w, 2, 0))) {
                sensed += 1;
            }
        }
    }
    ENSURE_EQ(sensed, 1);
    /* Through the sensor slab, onto the ground 10 m below. */
    ENSURE_NEAR(v3_position(BODY(w, 2)).y, -9.5, 0.02);
    /* A sensor ball falls through the ground too (free fall for 3 s). */
    ENSURE_NEAR(v3_position(BODY(w, 3)).y, 3.0 - free_fall(10.0, 180), 1e-2);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int filters_pass_bits_and_groups(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", BOX("5", "0.5") CIRCLE("0.5"),
         /* 0 */ "<Fixture><Shape>0</Shape><FilterData><GroupIndex>-1</GroupIndex></FilterData>"
                 "</Fixture>"
         /* 1 */ "<Fixture><Shape>0</Shape><FilterData><CategoryBits>1</CategoryBits>"
                 "<MaskBits>0xFFF9</MaskBits><GroupIndex>2</GroupIndex></FilterData></Fixture>"
         /* 2 */ "<Fixture><Shape>1</Shape><Density>1</Density><FilterData><GroupIndex>-1"
                 "</GroupIndex></FilterData></Fixture>"
         /* 3 */ "<Fixture><Shape>1</Shape><Density>1</Density></Fixture>"
         /* 4 */ "<Fixture><Shape>1</Shape><Density>1</Density><FilterData><CategoryBits>2"
                 "</CategoryBits></FilterData></Fixture>"
         /* 5 */ "<Fixture><Shape>1</Shape><Density>1</Density><FilterData><CategoryBits>4"
                 "</CategoryBits><GroupIndex>2</GroupIndex></FilterData></Fixture>",
         /* 0 */ "<Body Type='Static'><Position>0 -0.5</Position><Fixtures><ID>0</ID></Fixtures>"
                 "</Body>"
         /* 1 */ "<Body Type='Static'><Position>100 -0.5</Position><Fixtures><ID>1</ID>"
                 "</Fixtures></Body>"
         /* 2: same negative group as the ground: through it */
         "<Body Type='Dynamic'><Position>-2 2</Position><Fixtures><ID>2</ID></Fixtures></Body>"
         /* 3: no group: on it */
         "<Body Type='Dynamic'><Position>2 2</Position><Fixtures><ID>3</ID></Fixtures></Body>"
         /* 4: category 2, which the ground's mask leaves out: through it */
         "<Body Type='Dynamic'><Position>98 2</Position><Fixtures><ID>4</ID></Fixtures></Body>"
         /* 5: category 4, left out too, but the same positive group: on it */
         "<Body Type='Dynamic'><Position>100 2</Position><Fixtures><ID>5</ID></Fixtures></Body>"
         /* 6: category 1: on it */
         "<Body Type='Dynamic'><Position>102 2</Position><Fixtures><ID>3</ID></Fixtures></Body>"
         /* 7, 8: the same negative group, dropped onto each other: one passes through */
         "<Body Type='Dynamic'><Position>-20 0.5</Position><GravityScale>0</GravityScale>"
         "<Fixtures><ID>2</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>-20 3</Position><LinearVelocity>0 -5</LinearVelocity>"
         "<GravityScale>0</GravityScale><Fixtures><ID>2</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    b2Filter filter = b2Shape_GetFilter(SHAPE(w, 1, 0));
    ENSURE_EQ(filter.categoryBits, 1);
    ENSURE_EQ(filter.maskBits, 0xFFF9);
    ENSURE_EQ(filter.groupIndex, 2);
    filter = b2Shape_GetFilter(SHAPE(w, 2, 0));
    ENSURE_EQ(filter.categoryBits, 1);
    ENSURE_EQ(filter.maskBits, 0xFFFF); /* the format's 16 bits, widened */
    ENSURE_EQ(filter.groupIndex, -1);
    ENSURE_EQ(b2Shape_GetFilter(SHAPE(w, 4, 0)).categoryBits, 2);
    step_v3(&w.v3, 120);
    ENSURE(v3_position(BODY(w, 2)).y < -3.0f);
    ENSURE_NEAR(v3_position(BODY(w, 3)).y, 0.5, 0.02);
    ENSURE(v3_position(BODY(w, 4)).y < -3.0f);
    ENSURE_NEAR(v3_position(BODY(w, 5)).y, 0.5, 0.02);
    ENSURE_NEAR(v3_position(BODY(w, 6)).y, 0.5, 0.02);
    /* 8 moved straight through 7, at its speed, and 7 never moved. */
    ENSURE_NEAR(v3_position(BODY(w, 8)).y, 3.0 - 5.0 * 2.0, 1e-3);
    ENSURE_FLOAT(v3_position(BODY(w, 7)).y, 0.5f);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* The scene's 32 filter bits reach v3 whole: a category above bit 16, Farseer's "all" mask. */
static int filters_pass_all_32_bits(void) {
    scene_world w;
    OPEN(w, "2", "0 -10", CIRCLE("0.5"),
         "<Fixture><Shape>0</Shape><FilterData><CategoryBits>0x40000</CategoryBits>"
         "<MaskBits>2147483647</MaskBits></FilterData></Fixture>",
         "<Body Type='Static'><Fixtures><ID>0</ID></Fixtures></Body>", "");
    ENSURE_REPORT_COUNT(w, 0);
    b2Filter filter = b2Shape_GetFilter(SHAPE(w, 0, 0));
    ENSURE_EQ(filter.categoryBits, 0x40000);
    ENSURE_EQ(filter.maskBits, 2147483647);
    close_world(&w);
    return 0;
}

/* ---- shapes */

static int circle_and_polygon_shapes(void) {
    scene_world w;
    OPEN(w, "1", "0 -10",
         GROUND_BOX "<Shape Type='Circle'><Radius>0.75</Radius><Position>0.25 -0.5</Position>"
                    "</Shape>"
                    /* 5 vertices, clockwise, one inside: v3's hull is the 4 corners */
                    "<Shape Type='Polygon'><Vertices><Vertex>1 1</Vertex><Vertex>1 -1</Vertex>"
                    "<Vertex>0.1 0.2</Vertex><Vertex>-1 -1</Vertex><Vertex>-1 1</Vertex>"
                    "</Vertices></Shape>",
         "<Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape><Density>1</Density>"
         "</Fixture><Fixture><Shape>2</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>-5 3</Position><Fixtures><ID>1</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>5 3</Position><Fixtures><ID>2</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    b2ShapeId circle = SHAPE(w, 1, 0);
    ENSURE_EQ(b2Shape_GetType(circle), b2_circleShape);
    ENSURE_FLOAT(b2Shape_GetCircle(circle).radius, 0.75f);
    ENSURE_FLOAT(b2Shape_GetCircle(circle).center.x, 0.25f);
    ENSURE_FLOAT(b2Shape_GetCircle(circle).center.y, -0.5f);

    b2ShapeId box = SHAPE(w, 2, 0);
    ENSURE_EQ(b2Shape_GetType(box), b2_polygonShape);
    b2Polygon polygon = b2Shape_GetPolygon(box);
    ENSURE_EQ(polygon.count, 4);
    ENSURE_FLOAT(polygon.radius, 0.0f);
    bool seen[4] = {false, false, false, false};
    for (int i = 0; i < 4; ++i) {
        b2Vec2 v = polygon.vertices[i];
        ENSURE(fabsf(v.x) == 1.0f && fabsf(v.y) == 1.0f); /* a corner, not the inner point */
        int corner = (v.x > 0.0f ? 1 : 0) + (v.y > 0.0f ? 2 : 0);
        ENSURE(!seen[corner]);
        seen[corner] = true;
        b2Vec2 e1 = b2Sub(polygon.vertices[(i + 1) % 4], v);
        b2Vec2 e2 = b2Sub(polygon.vertices[(i + 2) % 4], polygon.vertices[(i + 1) % 4]);
        ENSURE(b2Cross(e1, e2) > 0.0f); /* counter-clockwise */
        ENSURE_NEAR(b2Length(polygon.normals[i]), 1.0, 1e-6);
    }
    ENSURE_NEAR(polygon.centroid.x, 0.0, 1e-6);
    ENSURE_NEAR(polygon.centroid.y, 0.0, 1e-6);
    ENSURE_NEAR(b2Body_GetMass(BODY(w, 2)), 4.0, 1e-5);

    step_v3(&w.v3, 120);
    /* Each rests on the ground by its own geometry. */
    ENSURE_NEAR(v3_position(BODY(w, 1)).y, 1.25, 0.02);
    ENSURE_NEAR(v3_position(BODY(w, 2)).y, 1.0, 0.02);
    ENSURE_NEAR(angle_of(BODY(w, 2)), 0.0, 1e-3);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* A 2-vertex polygon and an edge without ghosts are two-sided segments: a ball thrown up
 * from below bounces off, a ball dropped from above rests on it. */
static int two_vertex_polygon_and_plain_edge_are_segments(void) {
    scene_world w;
    OPEN(w, "2", "0 -10",
         "<Shape Type='Polygon'><Vertices><Vertex>-3 0</Vertex><Vertex>3 0</Vertex></Vertices>"
         "</Shape><Shape Type='Edge'><Vertex1>-3 0</Vertex1><Vertex2>3 0</Vertex2></Shape>"
         CIRCLE("0.5"),
         "<Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape></Fixture>"
         "<Fixture><Shape>2</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Static'><Position>20 0</Position><Fixtures><ID>1</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>0 2</Position><Fixtures><ID>2</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>20 2</Position><Fixtures><ID>2</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>1 -2</Position><LinearVelocity>0 10</LinearVelocity>"
         "<Fixtures><ID>2</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>21 -2</Position><LinearVelocity>0 10</LinearVelocity>"
         "<Fixtures><ID>2</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    for (uint32_t body = 0; body < 2; ++body) {
        b2ShapeId shape = SHAPE(w, body, 0);
        ENSURE_EQ(CHAIN_SEGMENTS(w, body, 0, NULL, 0), 0);
        ENSURE_EQ(b2Shape_GetType(shape), b2_segmentShape);
        b2Segment segment = b2Shape_GetSegment(shape);
        ENSURE_FLOAT(segment.point1.x, -3.0f);
        ENSURE_FLOAT(segment.point1.y, 0.0f);
        ENSURE_FLOAT(segment.point2.x, 3.0f);
        ENSURE_FLOAT(segment.point2.y, 0.0f);
    }
    float highest[2] = {-2.0f, -2.0f};
    for (int i = 0; i < 120; ++i) {
        step_v3(&w.v3, 1);
        for (int k = 0; k < 2; ++k) {
            highest[k] = fmaxf(highest[k], v3_position(BODY(w, 4 + k)).y);
        }
    }
    ENSURE_NEAR(v3_position(BODY(w, 2)).y, 0.5, 0.02);
    ENSURE_NEAR(v3_position(BODY(w, 3)).y, 0.5, 0.02);
    ENSURE(highest[0] < 0.0f); /* stopped under the segment */
    ENSURE(highest[1] < 0.0f);
    ENSURE(v3_position(BODY(w, 4)).y < -1.0f);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* An edge with both ghosts is one solid chain segment (v3.1: a chain of its own, v3.2: a
 * loose one): one-sided. Written from
 * right to left, its solid side faces up: a ball thrown up from below passes through it,
 * then lands on it from above. */
static int edge_with_ghosts_is_a_one_sided_chain(void) {
    scene_world w;
    OPEN(w, "2", "0 -10",
         "<Shape Type='Edge'><Vertex1>5 0</Vertex1><Vertex2>-5 0</Vertex2><Vertex0>6 0</Vertex0>"
         "<Vertex3>-6 0</Vertex3><HasVertex0>true</HasVertex0><HasVertex3>true</HasVertex3>"
         "</Shape>" CIRCLE("0.5"),
         "<Fixture><Shape>0</Shape><Friction>0.5</Friction></Fixture>"
         "<Fixture><Shape>1</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>-2 2</Position><Fixtures><ID>1</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>2 -2</Position><LinearVelocity>0 10</LinearVelocity>"
         "<Fixtures><ID>1</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
#if V3_MINOR == 1
    b2ChainId chain = CHAIN(w, 0, 0);
    ENSURE(!B2_IS_NULL(chain));
    ENSURE(B2_IS_NULL(SHAPE(w, 0, 0)));
    ENSURE_EQ(b2Chain_GetSegmentCount(chain), 1);
    ENSURE_FLOAT(b2Chain_GetFriction(chain), 0.5f);
    b2ShapeId segment;
    ENSURE_EQ(b2Chain_GetSegments(chain, &segment, 1), 1);
#else
    ENSURE_EQ(SEGMENTS(w, 0, 0).count, 1);
    b2ShapeId segment = SEGMENT(w, 0, 0, 0);
    ENSURE(B2_ID_EQUALS(SHAPE(w, 0, 0), segment));
    ENSURE_EQ(b2Shape_GetType(segment), b2_chainSegmentShape);
    ENSURE(B2_IS_NULL(b2Shape_GetParentChain(segment)));
    ENSURE_FLOAT(b2Shape_GetFriction(segment), 0.5f);
#endif
    b2ChainSegment s = b2Shape_GetChainSegment(segment);
    ENSURE_FLOAT(s.segment.point1.x, 5.0f);
    ENSURE_FLOAT(s.segment.point2.x, -5.0f);
    ENSURE_FLOAT(s.ghost1.x, 6.0f);
    ENSURE_FLOAT(s.ghost2.x, -6.0f);
    float highest = -2.0f;
    for (int i = 0; i < 180; ++i) {
        step_v3(&w.v3, 1);
        highest = fmaxf(highest, v3_position(BODY(w, 2)).y);
    }
    ENSURE(highest > 2.0f); /* went through from below */
    ENSURE_NEAR(v3_position(BODY(w, 1)).y, 0.5, 0.02);
    ENSURE_NEAR(v3_position(BODY(w, 2)).y, 0.5, 0.02); /* and landed on top */
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* An edge with one ghost: still a chain segment, the other ghost extrapolated and reported. */
static int edge_with_one_ghost_extrapolates_the_other(void) {
    scene_world w;
    OPEN(w, "2", "0 -10",
         "<Shape Type='Edge'><Vertex1>5 0</Vertex1><Vertex2>-5 0</Vertex2><Vertex0>6 1</Vertex0>"
         "<HasVertex0>true</HasVertex0></Shape>" CIRCLE("0.5"),
         "<Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape><Density>1</Density>"
         "</Fixture>",
         "<Body Type='Static'><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>0 2</Position><Fixtures><ID>1</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_SHAPE, "shape", 0), 1);
    b2ShapeId segment;
    ENSURE_EQ(CHAIN_SEGMENTS(w, 0, 0, &segment, 1), 1);
    b2ChainSegment s = b2Shape_GetChainSegment(segment);
    ENSURE_FLOAT(s.ghost1.x, 6.0f); /* the given one */
    ENSURE_FLOAT(s.ghost1.y, 1.0f);
    ENSURE_FLOAT(s.ghost2.x, -15.0f); /* Vertex2 + (Vertex2 - Vertex1) */
    ENSURE_FLOAT(s.ghost2.y, 0.0f);
    step_v3(&w.v3, 120);
    ENSURE_NEAR(v3_position(BODY(w, 1)).y, 0.5, 0.02);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int open_chains_with_and_without_ghosts(void) {
    scene_world w;
    OPEN(w, "2", "0 -10",
         /* 0: both ghosts given */
         "<Shape Type='Chain'><Vertices><Vertex>5 0</Vertex><Vertex>0 0</Vertex>"
         "<Vertex>-5 0</Vertex></Vertices><PrevVertex>6 0</PrevVertex><NextVertex>-6 0"
         "</NextVertex><HasPrevVertex>true</HasPrevVertex><HasNextVertex>true</HasNextVertex>"
         "</Shape>"
         /* 1: none: extrapolated, reported */
         "<Shape Type='Chain'><Vertices><Vertex>5 0</Vertex><Vertex>0 0</Vertex>"
         "<Vertex>-5 0</Vertex></Vertices></Shape>"
         /* 2: a ghost without its Has flag does not count: reported too */
         "<Shape Type='Chain'><Vertices><Vertex>5 0</Vertex><Vertex>0 0</Vertex>"
         "<Vertex>-5 0</Vertex></Vertices><PrevVertex>6 0</PrevVertex><HasNextVertex>true"
         "</HasNextVertex><NextVertex>-6 0</NextVertex></Shape>" CIRCLE("0.5"),
         "<Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape></Fixture>"
         "<Fixture><Shape>2</Shape></Fixture><Fixture><Shape>3</Shape><Density>1</Density>"
         "</Fixture>",
         "<Body Type='Static'><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Static'><Position>20 0</Position><Fixtures><ID>1</ID></Fixtures></Body>"
         "<Body Type='Static'><Position>40 0</Position><Fixtures><ID>2</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>-1 2</Position><Fixtures><ID>3</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>19 2</Position><Fixtures><ID>3</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>39 2</Position><Fixtures><ID>3</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 2);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_SHAPE, "shape", 0), 0);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_SHAPE, "shape", 1), 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_SHAPE, "shape", 2), 1);
    b2ShapeId segments[3][2];
    for (uint32_t body = 0; body < 3; ++body) {
        /* both solid segments, ghosts guide */
        ENSURE_EQ(CHAIN_SEGMENTS(w, body, 0, segments[body], 2), 2);
        b2ChainSegment first = b2Shape_GetChainSegment(segments[body][0]);
        b2ChainSegment second = b2Shape_GetChainSegment(segments[body][1]);
        /* each segment's neighbours are its ghosts */
        ENSURE_FLOAT(first.ghost2.x, second.segment.point2.x);
        ENSURE_FLOAT(second.ghost1.x, first.segment.point1.x);
    }
    /* The extrapolated ghost continues the end segment: (5, 0) - (0, 0) gives (10, 0). */
    ENSURE_FLOAT(b2Shape_GetChainSegment(segments[1][0]).ghost1.x, 10.0f);
    ENSURE_FLOAT(b2Shape_GetChainSegment(segments[1][1]).ghost2.x, -10.0f);
    ENSURE_FLOAT(b2Shape_GetChainSegment(segments[2][0]).ghost1.x, 10.0f);
    ENSURE_FLOAT(b2Shape_GetChainSegment(segments[2][1]).ghost2.x, -6.0f);
    step_v3(&w.v3, 120);
    for (uint32_t body = 3; body < 6; ++body) {
        ENSURE_NEAR(v3_position(BODY(w, body)).y, 0.5, 0.02);
    }
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* A 3-vertex loop: v3.1 needs 4 points (one edge is split, the geometry unchanged), v3.2
 * takes three loose chain segments, nothing split. Clockwise
 * its solid sides face in: a ball dropped inside stays inside. Counter-clockwise they face
 * out: a ball dropped on its flat top rests there. */
static int three_vertex_loops_hold_balls(void) {
    scene_world w;
    OPEN(w, "2", "0 -10",
         "<Shape Type='Chain'><Loop>true</Loop><Vertices><Vertex>-4 4</Vertex><Vertex>4 4"
         "</Vertex><Vertex>0 -2</Vertex></Vertices></Shape>"
         "<Shape Type='Loop'><Vertices><Vertex>0 -3</Vertex><Vertex>4 0</Vertex>"
         "<Vertex>-4 0</Vertex></Vertices></Shape>" CIRCLE("0.25"),
         "<Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape></Fixture>"
         "<Fixture><Shape>2</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Static'><Position>20 0</Position><Fixtures><ID>1</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>0.5 2</Position><Fixtures><ID>2</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>20 2</Position><Fixtures><ID>2</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    const struct b2s_scene_view* view = b2s_scene_get_view(w.scene);
    ENSURE(view->shapes[0].is_loop && view->shapes[1].is_loop);
    for (uint32_t body = 0; body < 2; ++body) {
        b2ShapeId segments[4];
        int count = CHAIN_SEGMENTS(w, body, 0, segments, 4);
#if V3_MINOR == 1
        ENSURE_EQ(count, 4);
#else
        ENSURE_EQ(count, 3);
#endif
        /* closed: the last segment's end is the first's start */
        ENSURE_FLOAT(b2Shape_GetChainSegment(segments[count - 1]).segment.point2.x,
                     b2Shape_GetChainSegment(segments[0]).segment.point1.x);
    }
    float lowest = 2.0f;
    for (int i = 0; i < 300; ++i) {
        step_v3(&w.v3, 1);
        lowest = fminf(lowest, v3_position(BODY(w, 2)).y);
    }
    /* Inside the V: never below its tip (less the ball's radius), settled in it. */
    ENSURE(lowest > -2.0f);
    b2Vec2 inside = v3_position(BODY(w, 2));
    ENSURE_NEAR(inside.x, 0.0, 0.05);
    ENSURE(inside.y > -2.0f && inside.y < -1.0f);
    ENSURE_NEAR(v3_position(BODY(w, 3)).y, 0.25, 0.02);
    ENSURE_NEAR(v3_position(BODY(w, 3)).x, 20.0, 1e-3);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int what_v3_shapes_cannot_hold_is_reported(void) {
    scene_world w;
    OPEN(w, "2", "0 -10",
         /* 0: a Centroid other than the polygon's own */
         "<Shape Type='Polygon'><Vertices><Vertex>0 0</Vertex><Vertex>2 0</Vertex>"
         "<Vertex>2 2</Vertex><Vertex>0 2</Vertex></Vertices><Centroid>0.5 0.5</Centroid>"
         "</Shape>"
         /* 1: the same square, its own centroid given: nothing lost */
         "<Shape Type='Polygon'><Vertices><Vertex>0 0</Vertex><Vertex>2 0</Vertex>"
         "<Vertex>2 2</Vertex><Vertex>0 2</Vertex></Vertices><Centroid>1 1</Centroid></Shape>"
         /* 2: a chain, carried by a sensor fixture */
         "<Shape Type='Chain'><Vertices><Vertex>5 0</Vertex><Vertex>-5 0</Vertex></Vertices>"
         "<PrevVertex>6 0</PrevVertex><NextVertex>-6 0</NextVertex><HasPrevVertex>true"
         "</HasPrevVertex><HasNextVertex>true</HasNextVertex></Shape>" CIRCLE("0.5"),
         "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>"
         "<Fixture><Shape>1</Shape><Density>1</Density></Fixture>"
         "<Fixture><Shape>2</Shape><IsSensor>true</IsSensor></Fixture>"
         "<Fixture><Shape>3</Shape><Density>1</Density></Fixture>",
         "<Body Type='Dynamic'><Position>0 10</Position><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>5 10</Position><Fixtures><ID>1</ID></Fixtures></Body>"
         "<Body Type='Static'><Position>20 0</Position><Fixtures><ID>2</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>20 2</Position><Fixtures><ID>3</ID></Fixtures></Body>",
         "");
#if V3_MINOR == 1
    ENSURE_REPORT_COUNT(w, 2);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_SHAPE, "fixture", 2), 1);
#else
    ENSURE_REPORT_COUNT(w, 1);
#endif
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_SHAPE, "shape", 0), 1);
    /* v3 keeps its own centroid. */
    ENSURE_FLOAT(b2Shape_GetPolygon(SHAPE(w, 0, 0)).centroid.x, 1.0f);
    ENSURE_FLOAT(v3_local_center(BODY(w, 0)).y, 1.0f);
#if V3_MINOR == 1
    /* v3.1's chains cannot sense: the sensor chain is a solid chain, and the ball rests on it. */
    ENSURE(!B2_IS_NULL(CHAIN(w, 2, 0)));
    step_v3(&w.v3, 120);
    ENSURE_NEAR(v3_position(BODY(w, 3)).y, 0.5, 0.02);
#else
    /* The sensor chain is a sensor: the ball falls through it. */
    ENSURE(b2Shape_IsSensor(SEGMENT(w, 2, 0, 0)));
    step_v3(&w.v3, 120);
    ENSURE(v3_position(BODY(w, 3)).y < -5.0f);
#endif
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* ---- joints */

static int revolute_hinge_swings_about_its_anchor(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Position>0 10</Position></Body>"
         "<Body Type='Dynamic'><Position>3 10</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Revolute'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorB>-3 0"
         "</LocalAnchorB></Joint>");
    ENSURE_REPORT_COUNT(w, 0);
    ENSURE_EQ(b2Joint_GetType(JOINT(w, 0)), b2_revoluteJoint);
    ENSURE(!b2RevoluteJoint_IsLimitEnabled(JOINT(w, 0)));
    ENSURE(!b2RevoluteJoint_IsMotorEnabled(JOINT(w, 0)));
    b2Vec2 pivot = {0.0f, 10.0f};
    float lowest = 10.0f, worst = 0.0f;
    for (int i = 0; i < 120; ++i) {
        step_v3(&w.v3, 1);
        b2Vec2 p = v3_position(BODY(w, 1));
        lowest = fminf(lowest, p.y);
        worst = fmaxf(worst, fabsf(b2Distance(p, pivot) - 3.0f));
    }
    ENSURE(worst < 0.01f);
    ENSURE(lowest < 7.1f); /* it swung through the bottom */
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int revolute_limit_holds(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Position>0 10</Position></Body>"
         "<Body Type='Dynamic'><Position>3 10</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Revolute'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorB>-3 0"
         "</LocalAnchorB><EnableLimit>true</EnableLimit><LowerAngle>-0.5</LowerAngle>"
         "<UpperAngle>0.25</UpperAngle></Joint>");
    ENSURE_REPORT_COUNT(w, 0);
    b2JointId hinge = JOINT(w, 0);
    ENSURE(b2RevoluteJoint_IsLimitEnabled(hinge));
    ENSURE_FLOAT(b2RevoluteJoint_GetLowerLimit(hinge), -0.5f);
    ENSURE_FLOAT(b2RevoluteJoint_GetUpperLimit(hinge), 0.25f);
    float least = 0.0f;
    for (int i = 0; i < 180; ++i) {
        step_v3(&w.v3, 1);
        least = fminf(least, b2RevoluteJoint_GetAngle(hinge));
    }
    ENSURE(least > -0.5f - 0.03f); /* v3's soft limit: within a few hundredths */
    ENSURE_NEAR(b2RevoluteJoint_GetAngle(hinge), -0.5, 0.01); /* resting on it */
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int revolute_motor_turns_at_its_speed(void) {
    scene_world w;
    OPEN(w, "1", "0 0", CIRCLE("1"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'></Body>"
         "<Body Type='Dynamic'><Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Revolute'><BodyA>0</BodyA><BodyB>1</BodyB><EnableMotor>true</EnableMotor>"
         "<MotorSpeed>2</MotorSpeed><MaxMotorTorque>1000</MaxMotorTorque></Joint>");
    ENSURE_REPORT_COUNT(w, 0);
    b2JointId hinge = JOINT(w, 0);
    ENSURE(b2RevoluteJoint_IsMotorEnabled(hinge));
    ENSURE_FLOAT(b2RevoluteJoint_GetMotorSpeed(hinge), 2.0f);
    ENSURE_FLOAT(b2RevoluteJoint_GetMaxMotorTorque(hinge), 1000.0f);
    step_v3(&w.v3, 60);
    ENSURE_NEAR(b2Body_GetAngularVelocity(BODY(w, 1)), 2.0, 1e-3);
    ENSURE_NEAR(b2RevoluteJoint_GetAngle(hinge), 2.0, 0.05); /* 1 s at 2 rad/s */
    ENSURE_NEAR(v3_position(BODY(w, 1)).x, 0.0, 1e-3);
    ENSURE_NEAR(v3_position(BODY(w, 1)).y, 0.0, 1e-3);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* v3 asserts that a revolute limit lies within +-0.99 pi: an enabled one beyond is clamped
 * and reported, a disabled one is clamped silently (it has no effect). */
static int revolute_limit_beyond_v3s_range_is_clamped(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Position>0 10</Position></Body>"
         "<Body Type='Dynamic'><Position>0 7</Position><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>10 7</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Revolute'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorB>0 3"
         "</LocalAnchorB><EnableLimit>true</EnableLimit><LowerAngle>-3.5</LowerAngle>"
         "<UpperAngle>3.25</UpperAngle></Joint>"
         "<Joint Type='Revolute'><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>10 0"
         "</LocalAnchorA><LocalAnchorB>0 3</LocalAnchorB><LowerAngle>-3.5</LowerAngle>"
         "<UpperAngle>3.25</UpperAngle></Joint>");
    ENSURE_REPORT_COUNT(w, 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_JOINT, "joint", 0), 1);
    const float limit = 0.99f * 3.14159265359f; /* v3's B2_PI */
    ENSURE_FLOAT(b2RevoluteJoint_GetLowerLimit(JOINT(w, 0)), -limit);
    ENSURE_FLOAT(b2RevoluteJoint_GetUpperLimit(JOINT(w, 0)), limit);
    ENSURE(b2RevoluteJoint_IsLimitEnabled(JOINT(w, 0)));
    ENSURE(!b2RevoluteJoint_IsLimitEnabled(JOINT(w, 1)));
    ENSURE(!B2_IS_NULL(JOINT(w, 1)));
    step_v3(&w.v3, 60);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* A disabled revolute limit out of order is passed swapped (bad-limit); a ReferenceAngle
 * beyond pi, which v3 would clamp, loses only its whole turns: the joint angle of a wheel
 * built at that angle is 0, and a limit around it stops the wheel's spin there. */
static int revolute_reference_angle_and_limit_order(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Position>0 10</Position></Body>"
         "<Body Type='Dynamic'><Position>3 10</Position><Angle>7</Angle><AngularVelocity>2"
         "</AngularVelocity><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>13 10</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Revolute'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>3 0"
         "</LocalAnchorA><ReferenceAngle>7</ReferenceAngle><EnableLimit>true</EnableLimit>"
         "<LowerAngle>-0.1</LowerAngle><UpperAngle>0.1</UpperAngle></Joint>"
         "<Joint Type='Revolute'><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>10 0"
         "</LocalAnchorA><LocalAnchorB>-3 0</LocalAnchorB><LowerAngle>1</LowerAngle>"
         "<UpperAngle>-1</UpperAngle></Joint>");
    ENSURE_REPORT_COUNT(w, 2);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_CAPTURE, "body", 1), 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_BAD_LIMIT, "joint", 1), 1);
#if V3_MINOR == 1
    /* v3.1 holds the reference angle itself, less its whole turns. */
    ENSURE_FLOAT(b2Joint_GetReferenceAngle(JOINT(w, 0)),
                 (float)remainder(7.0f, 6.283185307179586));
#else
    /* The reference angle turns frame A, whole turns and all. */
    ENSURE_FLOAT(b2Joint_GetLocalFrameA(JOINT(w, 0)).q.c, cosf(7.0f));
    ENSURE_FLOAT(b2Joint_GetLocalFrameA(JOINT(w, 0)).q.s, sinf(7.0f));
    ENSURE_FLOAT(b2Joint_GetLocalFrameB(JOINT(w, 0)).q.c, 1.0f);
#endif
    ENSURE_NEAR(b2RevoluteJoint_GetAngle(JOINT(w, 0)), 0.0, 1e-5);
    ENSURE(!b2RevoluteJoint_IsLimitEnabled(JOINT(w, 1)));
    ENSURE_FLOAT(b2RevoluteJoint_GetLowerLimit(JOINT(w, 1)), -1.0f);
    ENSURE_FLOAT(b2RevoluteJoint_GetUpperLimit(JOINT(w, 1)), 1.0f);
    float widest = 0.0f, lowest = 10.0f;
    for (int i = 0; i < 120; ++i) {
        step_v3(&w.v3, 1);
        widest = fmaxf(widest, fabsf(b2RevoluteJoint_GetAngle(JOINT(w, 0))));
        lowest = fminf(lowest, v3_position(BODY(w, 2)).y);
    }
    ENSURE(widest > 0.09f && widest < 0.1f + 0.03f); /* it reached the limit, and stopped */
    /* The disabled limit holds nothing: that pendulum swings down, past -1 rad. */
    ENSURE(lowest < 7.5f);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int prismatic_moves_only_along_its_axis(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", BOX("0.5", "0.5"),
         "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Position>0 5</Position></Body>"
         "<Body Type='Dynamic'><Position>0 5</Position><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>20 5</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Prismatic'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAxisA>3 4</LocalAxisA>"
         "</Joint>"
         "<Joint Type='Prismatic'><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>20 0"
         "</LocalAnchorA><LocalAxisA>3 4</LocalAxisA><EnableLimit>true</EnableLimit>"
         "<LowerTranslation>-1</LowerTranslation><UpperTranslation>2</UpperTranslation></Joint>");
    ENSURE_REPORT_COUNT(w, 0);
    b2Vec2 axis = v3_local_axis_a(JOINT(w, 0));
    ENSURE_NEAR(axis.x, 0.6, 1e-6); /* normalised */
    ENSURE_NEAR(axis.y, 0.8, 1e-6);
    b2JointId limited = JOINT(w, 1);
    ENSURE(b2PrismaticJoint_IsLimitEnabled(limited));
    ENSURE_FLOAT(b2PrismaticJoint_GetLowerLimit(limited), -1.0f);
    ENSURE_FLOAT(b2PrismaticJoint_GetUpperLimit(limited), 2.0f);
    float least = 0.0f, off_axis = 0.0f;
    for (int i = 0; i < 60; ++i) {
        step_v3(&w.v3, 1);
        least = fminf(least, b2PrismaticJoint_GetTranslation(limited));
        b2Vec2 d = b2Sub(v3_position(BODY(w, 1)), (b2Vec2){0.0f, 5.0f});
        off_axis = fmaxf(off_axis, fabsf(b2Cross((b2Vec2){0.6f, 0.8f}, d)));
    }
    /* Gravity along the axis is 0.8 g: it slides down the axis as a free body would. */
    b2Vec2 d = b2Sub(v3_position(BODY(w, 1)), (b2Vec2){0.0f, 5.0f});
    ENSURE_NEAR(b2Dot((b2Vec2){0.6f, 0.8f}, d), -free_fall(8.0, 60), 0.01);
    ENSURE(off_axis < 0.005f);
    ENSURE_NEAR(angle_of(BODY(w, 1)), 0.0, 1e-3);
    ENSURE(least > -1.0f - 0.01f);
    ENSURE_NEAR(b2PrismaticJoint_GetTranslation(limited), -1.0, 0.01);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* A disabled prismatic limit with Lower > Upper: v3 asserts lower <= upper, so they are
 * passed swapped, and the limit still has no effect. */
static int prismatic_disabled_limit_out_of_order_is_swapped(void) {
    const char* joint = "<Joint Type='Prismatic'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAxisA>0 1"
                        "</LocalAxisA><LowerTranslation>2</LowerTranslation><UpperTranslation>-1"
                        "</UpperTranslation></Joint>";
    /* The loader accepts it: the format forbids Lower > Upper only with the limit on. */
    scene_world w;
    OPEN(w, "1", "0 -10", BOX("0.5", "0.5"),
         "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Position>0 5</Position></Body>"
         "<Body Type='Dynamic'><Position>0 5</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         joint);
    ENSURE_REPORT_COUNT(w, 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_BAD_LIMIT, "joint", 0), 1);
    b2JointId slider = JOINT(w, 0);
    ENSURE(!B2_IS_NULL(slider));
    ENSURE(!b2PrismaticJoint_IsLimitEnabled(slider));
    ENSURE_FLOAT(b2PrismaticJoint_GetLowerLimit(slider), -1.0f);
    ENSURE_FLOAT(b2PrismaticJoint_GetUpperLimit(slider), 2.0f);
    step_v3(&w.v3, 60);
    /* Free along its vertical axis: it falls past both numbers as if no limit were there. */
    ENSURE_NEAR(b2PrismaticJoint_GetTranslation(slider), -free_fall(10.0, 60), 0.01);
    ENSURE_NEAR(v3_position(BODY(w, 1)).x, 0.0, 1e-4);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* FrequencyHz 0: a rigid rod; the ball swings down on it, its length constant. */
static int rigid_distance_joint_keeps_its_length(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", CIRCLE("0.25"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Position>0 10</Position></Body>"
         "<Body Type='Dynamic'><Position>2 10</Position><LinearVelocity>0 -4</LinearVelocity>"
         "<Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Distance'><BodyA>0</BodyA><BodyB>1</BodyB><Length>2</Length></Joint>");
    ENSURE_REPORT_COUNT(w, 0);
    b2JointId rod = JOINT(w, 0);
    ENSURE_EQ(b2Joint_GetType(rod), b2_distanceJoint);
    ENSURE(!b2DistanceJoint_IsSpringEnabled(rod));
    ENSURE_FLOAT(b2DistanceJoint_GetLength(rod), 2.0f);
    float worst = 0.0f, lowest = 10.0f;
    for (int i = 0; i < 120; ++i) {
        step_v3(&w.v3, 1);
        worst = fmaxf(worst, fabsf(b2DistanceJoint_GetCurrentLength(rod) - 2.0f));
        lowest = fminf(lowest, v3_position(BODY(w, 1)).y);
    }
    ENSURE(worst < 0.01f);
    ENSURE(lowest < 8.1f); /* it swung through the bottom */
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* FrequencyHz > 0: a spring; stretched and let go in zero gravity, its length oscillates
 * around Length (1 Hz: about 4 crossings in 2 s). */
static int spring_distance_joint_oscillates_around_its_length(void) {
    scene_world w;
    OPEN(w, "1", "0 0", CIRCLE("0.25"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'></Body>"
         "<Body Type='Dynamic'><Position>3 0</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Distance'><BodyA>0</BodyA><BodyB>1</BodyB><Length>2</Length>"
         "<FrequencyHz>1</FrequencyHz><DampingRatio>0</DampingRatio></Joint>");
    ENSURE_REPORT_COUNT(w, 0);
    b2JointId spring = JOINT(w, 0);
    ENSURE(b2DistanceJoint_IsSpringEnabled(spring));
    ENSURE_FLOAT(b2DistanceJoint_GetSpringHertz(spring), 1.0f);
    ENSURE_FLOAT(b2DistanceJoint_GetSpringDampingRatio(spring), 0.0f);
    ENSURE_FLOAT(b2DistanceJoint_GetLength(spring), 2.0f);
    float shortest = 3.0f, longest = 0.0f;
    int crossings = 0;
    bool above = true;
    for (int i = 0; i < 120; ++i) {
        step_v3(&w.v3, 1);
        float length = b2DistanceJoint_GetCurrentLength(spring);
        shortest = fminf(shortest, length);
        longest = fmaxf(longest, length);
        if ((length > 2.0f) != above) {
            above = !above;
            crossings += 1;
        }
    }
    ENSURE(shortest < 1.5f); /* it overshot Length, as a spring does */
    ENSURE(longest <= 3.01f);
    ENSURE(crossings >= 3 && crossings <= 5);
    ENSURE_NEAR(v3_position(BODY(w, 1)).y, 0.0, 1e-4); /* radial only */
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int distance_length_below_v3s_minimum_is_reported(void) {
    scene_world w;
    OPEN(w, "1", "0 0", CIRCLE("0.25"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'></Body>"
         "<Body Type='Dynamic'><Position>0.4 0</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Distance'><BodyA>0</BodyA><BodyB>1</BodyB><Length>0.001</Length></Joint>");
    ENSURE_REPORT_COUNT(w, 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_JOINT, "joint", 0), 1);
    ENSURE_FLOAT(b2DistanceJoint_GetLength(JOINT(w, 0)), 0.005f);
    step_v3(&w.v3, 120);
    ENSURE_NEAR(b2DistanceJoint_GetCurrentLength(JOINT(w, 0)), 0.005, 0.01); /* pulled in */
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* A rope is slack below MaxLength (the ball falls freely at first) and never longer. */
static int rope_stops_at_its_max_length(void) {
    scene_world w;
    OPEN(w, "2", "0 -10", CIRCLE("0.25"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Position>0 10</Position></Body>"
         "<Body Type='Dynamic'><Position>1 10</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Rope'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 0</LocalAnchorA>"
         "<LocalAnchorB>0 0</LocalAnchorB><MaxLength>3</MaxLength></Joint>");
    ENSURE_REPORT_COUNT(w, 0);
    b2JointId rope = JOINT(w, 0);
    ENSURE(b2DistanceJoint_IsLimitEnabled(rope));
    ENSURE(b2DistanceJoint_IsSpringEnabled(rope));
    ENSURE_FLOAT(b2DistanceJoint_GetSpringHertz(rope), 0.0f);
    ENSURE_FLOAT(b2DistanceJoint_GetMaxLength(rope), 3.0f);
    step_v3(&w.v3, 10);
    /* Slack: exactly a free fall so far. */
    ENSURE_FLOAT(v3_position(BODY(w, 1)).x, 1.0f);
    ENSURE_NEAR(v3_position(BODY(w, 1)).y, 10.0 - free_fall(10.0, 10), 1e-4);
    float longest = 0.0f;
    for (int i = 0; i < 170; ++i) {
        step_v3(&w.v3, 1);
        longest = fmaxf(longest, b2DistanceJoint_GetCurrentLength(rope));
    }
    ENSURE(longest <= 3.0f + 0.01f);
    ENSURE(longest > 2.95f);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* A 2.1 line joint is a wheel joint without a spring: free along its axis, held across it. */
static int line_joint_is_free_along_its_axis(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", BOX("0.5", "0.5"),
         "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Position>0 5</Position></Body>"
         "<Body Type='Dynamic'><Position>0 5</Position><LinearVelocity>2 0</LinearVelocity>"
         "<Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>0 20</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Line'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAxisA>1 0</LocalAxisA></Joint>"
         "<Joint Type='Line'><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>0 15</LocalAnchorA>"
         "<EnableMotor>true</EnableMotor><MotorSpeed>1</MotorSpeed><MaxMotorForce>10"
         "</MaxMotorForce></Joint>");
    ENSURE_REPORT_COUNT(w, 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_LINE_MOTOR, "joint", 1), 1);
    for (uint32_t j = 0; j < 2; ++j) {
        ENSURE_EQ(b2Joint_GetType(JOINT(w, j)), b2_wheelJoint);
        ENSURE(!b2WheelJoint_IsSpringEnabled(JOINT(w, j)));
        ENSURE(!b2WheelJoint_IsMotorEnabled(JOINT(w, j)));
    }
    step_v3(&w.v3, 60);
    b2Vec2 p = v3_position(BODY(w, 1));
    ENSURE_NEAR(p.x, 2.0, 1e-3); /* 1 s at 2 m/s, nothing holding it along x */
    ENSURE_NEAR(p.y, 5.0, 0.01); /* gravity does not pull it off the axis */
    /* The motor is off: the second body does not move along its axis. */
    ENSURE_NEAR(v3_position(BODY(w, 2)).x, 0.0, 1e-4);
    ENSURE_NEAR(v3_position(BODY(w, 2)).y, 20.0, 0.01);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* A wheel hangs on its spring (2 Hz, 0.7 by default): it settles g / (2 pi f)^2 lower,
 * where an unloaded one stays. */
static int wheel_spring_compresses_under_load(void) {
    scene_world w;
    OPEN(w, "2", "0 -10", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Position>0 5</Position></Body>"
         "<Body Type='Dynamic'><Position>0 5</Position><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>10 5</Position><GravityScale>0</GravityScale>"
         "<Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Wheel'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAxisA>0 1</LocalAxisA>"
         "</Joint>"
         "<Joint Type='Wheel'><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>10 0</LocalAnchorA>"
         "<LocalAxisA>0 1</LocalAxisA></Joint>");
    ENSURE_REPORT_COUNT(w, 0);
    b2JointId wheel = JOINT(w, 0);
    ENSURE(b2WheelJoint_IsSpringEnabled(wheel));
    ENSURE_FLOAT(b2WheelJoint_GetSpringHertz(wheel), 2.0f);
    ENSURE_FLOAT(b2WheelJoint_GetSpringDampingRatio(wheel), 0.7f);
    step_v3(&w.v3, 180);
    double omega = 2.0 * 3.14159265358979 * 2.0;
    ENSURE_NEAR(v3_position(BODY(w, 1)).y, 5.0 - 10.0 / (omega * omega), 0.005);
    ENSURE(v3_position(BODY(w, 1)).y < 4.95f);
    ENSURE_NEAR(b2Body_GetLinearVelocity(BODY(w, 1)).y, 0.0, 0.01);
    ENSURE_NEAR(v3_position(BODY(w, 1)).x, 0.0, 1e-3);
    ENSURE_FLOAT(v3_position(BODY(w, 2)).y, 5.0f);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* A 2 m beam welded by one end: rigid, it stays level; with FrequencyHz it droops on its
 * angular spring but stays attached. */
static int weld_holds_rigid_or_soft(void) {
    scene_world w;
    OPEN(w, "2", "0 -10",
         "<Shape Type='Polygon'><Vertices><Vertex>0 -0.1</Vertex><Vertex>2 -0.1</Vertex>"
         "<Vertex>2 0.1</Vertex><Vertex>0 0.1</Vertex></Vertices></Shape>",
         "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'></Body>"
         "<Body Type='Dynamic'><Position>0 5</Position><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>10 5</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Weld'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 5</LocalAnchorA>"
         "</Joint>"
         "<Joint Type='Weld'><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>10 5</LocalAnchorA>"
         "<FrequencyHz>1</FrequencyHz><DampingRatio>0.5</DampingRatio></Joint>");
    ENSURE_REPORT_COUNT(w, 0);
    ENSURE_FLOAT(b2WeldJoint_GetAngularHertz(JOINT(w, 0)), 0.0f);
    ENSURE_FLOAT(b2WeldJoint_GetLinearHertz(JOINT(w, 0)), 0.0f);
    ENSURE_FLOAT(b2WeldJoint_GetAngularHertz(JOINT(w, 1)), 1.0f);
    ENSURE_FLOAT(b2WeldJoint_GetAngularDampingRatio(JOINT(w, 1)), 0.5f);
    ENSURE_FLOAT(b2WeldJoint_GetLinearHertz(JOINT(w, 1)), 0.0f);
    float rigid_turn = 0.0f, rigid_drift = 0.0f;
    for (int i = 0; i < 180; ++i) {
        step_v3(&w.v3, 1);
        rigid_turn = fmaxf(rigid_turn, fabsf(angle_of(BODY(w, 1))));
        rigid_drift = fmaxf(rigid_drift,
                            b2Distance(v3_position(BODY(w, 1)), (b2Vec2){0.0f, 5.0f}));
    }
    ENSURE(rigid_turn < 0.01f);
    ENSURE(rigid_drift < 0.01f);
    /* The soft one settles where its spring's torque, I (2 pi f)^2 per radian with I the
     * beam's inertia about its centre (as 2.x's b2AngularStiffness), holds gravity's about
     * the anchor, m g (L / 2) cos(angle): about 0.61 rad. */
    double m = b2Body_GetMass(BODY(w, 2)), k = b2Body_GetRotationalInertia(BODY(w, 2)) *
                                                 (2.0 * 3.14159265358979) * (2.0 * 3.14159265358979);
    double expected = 0.0;
    for (int i = 0; i < 100; ++i) {
        expected = m * 10.0 * 1.0 * cos(expected) / k;
    }
    ENSURE_NEAR(angle_of(BODY(w, 2)), -expected, 0.03);
    ENSURE(expected > 0.5);
    ENSURE(b2Distance(v3_position(BODY(w, 2)), (b2Vec2){10.0f, 5.0f}) < 0.02f);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* v3 has no friction joint: a motor joint does its work (v3.1: without offsets or
 * correction, at the body origins; v3.2: driving no velocity, at the anchors). A sliding,
 * spinning puck slows at MaxForce / m and MaxTorque / I; a puck without it keeps its
 * velocities exactly (zero gravity, no damping). */
static int friction_joint_slows_a_puck(void) {
    scene_world w;
    OPEN(w, "1", "0 0", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'></Body>"
         "<Body Type='Dynamic'><LinearVelocity>3 0</LinearVelocity><AngularVelocity>5"
         "</AngularVelocity><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>0 10</Position><LinearVelocity>3 0</LinearVelocity>"
         "<AngularVelocity>5</AngularVelocity><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>0 20</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Friction'><BodyA>0</BodyA><BodyB>1</BodyB><MaxForce>1</MaxForce>"
         "<MaxTorque>0.5</MaxTorque></Joint>"
         "<Joint Type='Friction'><BodyA>0</BodyA><BodyB>3</BodyB><LocalAnchorB>0 0.25"
         "</LocalAnchorB><MaxForce>1</MaxForce></Joint>");
    b2JointId friction = JOINT(w, 0);
    ENSURE_EQ(b2Joint_GetType(friction), b2_motorJoint);
#if V3_MINOR == 1
    ENSURE_REPORT_COUNT(w, 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_JOINT, "joint", 1), 1);
    ENSURE_FLOAT(b2MotorJoint_GetMaxForce(friction), 1.0f);
    ENSURE_FLOAT(b2MotorJoint_GetMaxTorque(friction), 0.5f);
    ENSURE_FLOAT(b2MotorJoint_GetCorrectionFactor(friction), 0.0f);
    ENSURE_FLOAT(b2MotorJoint_GetLinearOffset(friction).x, 0.0f);
#else
    ENSURE_REPORT_COUNT(w, 0);
    ENSURE_FLOAT(b2MotorJoint_GetMaxVelocityForce(friction), 1.0f);
    ENSURE_FLOAT(b2MotorJoint_GetMaxVelocityTorque(friction), 0.5f);
    ENSURE_FLOAT(b2MotorJoint_GetMaxSpringForce(friction), 0.0f);
    ENSURE_FLOAT(b2MotorJoint_GetLinearVelocity(friction).x, 0.0f);
    ENSURE_FLOAT(b2Joint_GetLocalFrameB(JOINT(w, 1)).p.y, 0.25f); /* the anchor, kept */
#endif
    float mass = b2Body_GetMass(BODY(w, 1));
    float inertia = b2Body_GetRotationalInertia(BODY(w, 1));
    step_v3(&w.v3, 30);
    ENSURE_NEAR(b2Body_GetLinearVelocity(BODY(w, 1)).x, 3.0 - 0.5 / mass, 0.01);
    ENSURE_NEAR(b2Body_GetLinearVelocity(BODY(w, 1)).y, 0.0, 1e-4);
    ENSURE_NEAR(b2Body_GetAngularVelocity(BODY(w, 1)), 5.0 - 0.25 / inertia, 0.02);
    ENSURE_FLOAT(b2Body_GetLinearVelocity(BODY(w, 2)).x, 3.0f);
    ENSURE_FLOAT(b2Body_GetAngularVelocity(BODY(w, 2)), 5.0f);
    ENSURE_FLOAT(b2Body_GetLinearVelocity(BODY(w, 3)).x, 0.0f); /* at rest, held there */
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int motor_joint_drives_body_b_to_its_offset(void) {
    scene_world w;
    OPEN(w, "2", "0 0", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'></Body>"
         "<Body Type='Dynamic'><Fixtures><ID>0</ID></Fixtures></Body>",
         "<Joint Type='Motor'><BodyA>0</BodyA><BodyB>1</BodyB><LinearOffset>2 1</LinearOffset>"
         "<AngularOffset>0.5</AngularOffset><MaxForce>50</MaxForce><MaxTorque>50</MaxTorque>"
         "<CorrectionFactor>0.3</CorrectionFactor></Joint>");
    b2JointId motor = JOINT(w, 0);
#if V3_MINOR == 1
    ENSURE_REPORT_COUNT(w, 0);
    ENSURE_FLOAT(b2MotorJoint_GetLinearOffset(motor).x, 2.0f);
    ENSURE_FLOAT(b2MotorJoint_GetLinearOffset(motor).y, 1.0f);
    ENSURE_FLOAT(b2MotorJoint_GetAngularOffset(motor), 0.5f);
    ENSURE_FLOAT(b2MotorJoint_GetCorrectionFactor(motor), 0.3f);
#else
    /* v3.2's motor joint has no offsets or CorrectionFactor: frame A carries the offsets and
     * springs drive body B there, reported as the approximation it is. */
    ENSURE_REPORT_COUNT(w, 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_JOINT, "joint", 0), 1);
    b2Transform frame = b2Joint_GetLocalFrameA(motor);
    ENSURE_FLOAT(frame.p.x, 2.0f);
    ENSURE_FLOAT(frame.p.y, 1.0f);
    ENSURE_FLOAT(frame.q.c, cosf(0.5f));
    ENSURE_FLOAT(frame.q.s, sinf(0.5f));
    ENSURE_FLOAT(b2MotorJoint_GetMaxSpringForce(motor), 50.0f);
    ENSURE_FLOAT(b2MotorJoint_GetMaxSpringTorque(motor), 50.0f);
#endif
    step_v3(&w.v3, 300);
    ENSURE_NEAR(v3_position(BODY(w, 1)).x, 2.0, 0.01);
    ENSURE_NEAR(v3_position(BODY(w, 1)).y, 1.0, 0.01);
    ENSURE_NEAR(angle_of(BODY(w, 1)), 0.5, 0.01);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

static int joints_v3_lacks_are_skipped(void) {
    scene_world w;
    OPEN(w, "2", "0 -10", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Static'><Position>0 10</Position></Body>"
         "<Body Type='Dynamic'><Position>-2 5</Position><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>2 5</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         /* 0 */ "<Joint Type='Revolute'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>-2 -5"
                 "</LocalAnchorA></Joint>"
         /* 1 */ "<Joint Type='Prismatic'><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>2 -5"
                 "</LocalAnchorA><LocalAxisA>0 1</LocalAxisA></Joint>"
         /* 2 */ "<Joint Type='Pulley'><BodyA>1</BodyA><BodyB>2</BodyB><GroundAnchorA>-2 10"
                 "</GroundAnchorA><GroundAnchorB>2 10</GroundAnchorB><LocalAnchorA>0 0"
                 "</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB><LengthA>5</LengthA>"
                 "<LengthB>5</LengthB></Joint>"
         /* 3 */ "<Joint Type='Gear'><BodyA>1</BodyA><BodyB>2</BodyB><JointA>0</JointA>"
                 "<JointB>1</JointB><Ratio>2</Ratio></Joint>"
         /* 4 */ "<Joint Type='Angle'><BodyA>1</BodyA><BodyB>2</BodyB><TargetAngle>1"
                 "</TargetAngle></Joint>");
    ENSURE_REPORT_COUNT(w, 3);
    for (uint32_t j = 2; j < 5; ++j) {
        ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_SKIPPED_JOINT, "joint", j), 1);
        ENSURE(B2_IS_NULL(JOINT(w, j)));
    }
    ENSURE(!B2_IS_NULL(JOINT(w, 0)));
    ENSURE(!B2_IS_NULL(JOINT(w, 1)));
    ENSURE_EQ(b2s_scene_get_view(w.scene)->joints[4].kind, B2S_JOINT_KIND_UNSUPPORTED);
    step_v3(&w.v3, 60);
    /* Without the pulley, the prismatic body falls freely along its axis. */
    ENSURE_NEAR(v3_position(BODY(w, 2)).y, 5.0 - free_fall(10.0, 60), 0.01);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* ---- values v3 cannot take */

static b2s_scene* negative_damping_scene(void) {
    b2s_builder* builder = b2s_builder_new();
    b2s_error error;
    b2s_vec2 gravity = {0.0f, -10.0f};
    b2s_shape shape;
    b2s_fixture fixture;
    b2s_body body;
    uint32_t index = 0;
    if (b2s_builder_set_gravity(builder, &gravity, &error) != B2S_CODE_OK ||
        b2s_shape_default(B2S_SHAPE_KIND_CIRCLE, &shape) != B2S_CODE_OK) {
        b2s_builder_free(builder);
        return NULL;
    }
    shape.radius = 0.5f;
    if (b2s_builder_add_shape(builder, &shape, NULL, 0, &index, &error) != B2S_CODE_OK ||
        b2s_fixture_default(&fixture) != B2S_CODE_OK) {
        fprintf(stderr, "builder: %s\n", error.message);
        b2s_builder_free(builder);
        return NULL;
    }
    fixture.shape = index;
    fixture.density = 1.0f;
    if (b2s_builder_add_fixture(builder, &fixture, &index, &error) != B2S_CODE_OK ||
        b2s_body_default(B2S_BODY_KIND_DYNAMIC, &body) != B2S_CODE_OK) {
        fprintf(stderr, "builder: %s\n", error.message);
        b2s_builder_free(builder);
        return NULL;
    }
    body.position = (b2s_vec2){0.0f, 10.0f};
    body.linear_damping = -0.5f;
    body.angular_damping = -2.0f;
    uint32_t body_index = 0;
    if (b2s_builder_add_body(builder, &body, &index, 1, &body_index, &error) != B2S_CODE_OK) {
        fprintf(stderr, "builder: %s\n", error.message);
        b2s_builder_free(builder);
        return NULL;
    }
    b2s_scene* scene = NULL;
    if (b2s_builder_finish(builder, &scene, &error) != B2S_CODE_OK) {
        fprintf(stderr, "builder: %s\n", error.message);
        return NULL;
    }
    return scene;
}

/* v3 asserts against a negative damping: 0 is used, and each is reported. */
static int negative_damping_is_reported_and_zeroed(void) {
    scene_world w;
    OPEN_SCENE(w, negative_damping_scene());
    ENSURE_REPORT_COUNT(w, 2);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_NEGATIVE_VALUE, "body", 0), 2);
    ENSURE_FLOAT(b2Body_GetLinearDamping(BODY(w, 0)), 0.0f);
    ENSURE_FLOAT(b2Body_GetAngularDamping(BODY(w, 0)), 0.0f);
    step_v3(&w.v3, 60);
    ENSURE_NEAR(v3_position(BODY(w, 0)).y, 10.0 - free_fall(10.0, 60), 1e-3);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* A body at 1e6 m lies beyond v3's working range: not created, and neither are its
 * fixtures or the joint on it; the rest of the scene is built and runs. */
static int beyond_the_working_range_skips_what_depends_on_it(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", GROUND_BOX CIRCLE("0.5"),
         "<Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape><Density>1</Density>"
         "</Fixture><Fixture><Shape>1</Shape><Density>2</Density></Fixture>",
         "<Body Type='Static'><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>1e6 0</Position><Fixtures><ID>1</ID><ID>2</ID>"
         "</Fixtures></Body>"
         "<Body Type='Dynamic'><Position>0 3</Position><Fixtures><ID>1</ID></Fixtures></Body>",
         "<Joint Type='Revolute'><BodyA>0</BodyA><BodyB>1</BodyB></Joint>"
         "<Joint Type='Distance'><BodyA>2</BodyA><BodyB>1</BodyB></Joint>");
    ENSURE_REPORT_COUNT(w, 5);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_BEYOND_BOX2D_RANGE, "body", 1), 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_SKIPPED_DEPENDENT, "fixture", 1), 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_SKIPPED_DEPENDENT, "fixture", 2), 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_SKIPPED_DEPENDENT, "joint", 0), 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_SKIPPED_DEPENDENT, "joint", 1), 1);
    ENSURE(B2_IS_NULL(BODY(w, 1)));
    ENSURE(B2_IS_NULL(SHAPE(w, 1, 0)) && B2_IS_NULL(SHAPE(w, 1, 1)));
    ENSURE(B2_IS_NULL(JOINT(w, 0)) && B2_IS_NULL(JOINT(w, 1)));
    ENSURE(!B2_IS_NULL(BODY(w, 0)) && !B2_IS_NULL(BODY(w, 2)));
    step_v3(&w.v3, 120);
    ENSURE_NEAR(v3_position(BODY(w, 2)).y, 0.5, 0.02);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* v3 keeps a rotation, not an angle: an angle beyond pi is built exactly (its cosine and
 * sine), and its whole turns, which a capture cannot give back, are reported. */
static int angle_beyond_pi_is_reported_lossy_for_capture(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", BOX("1", "0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Dynamic'><Angle>7</Angle><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>5 0</Position><Angle>-4</Angle>"
         "<Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>10 0</Position><Angle>3</Angle>"
         "<Fixtures><ID>0</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 2);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_CAPTURE, "body", 0), 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_CAPTURE, "body", 1), 1);
    ENSURE_FLOAT(b2Body_GetRotation(BODY(w, 0)).c, cosf(7.0f));
    ENSURE_FLOAT(b2Body_GetRotation(BODY(w, 0)).s, sinf(7.0f));
    ENSURE_FLOAT(b2Body_GetRotation(BODY(w, 1)).c, cosf(-4.0f));
    ENSURE_FLOAT(b2Body_GetRotation(BODY(w, 1)).s, sinf(-4.0f));
    ENSURE_FLOAT(b2Body_GetRotation(BODY(w, 2)).c, cosf(3.0f));
    step_v3(&w.v3, 30);
    /* Falling does not turn them: the rotation stays what the file said. */
    ENSURE_NEAR(angle_of(BODY(w, 0)), 7.0 - 2.0 * 3.14159265358979, 1e-5);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

/* ---- what the versions hold otherwise */

/* InertiaScale never had an effect in Box2D 2.x; v3 gets nothing of it either. */
static int inertia_scale_changes_nothing(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", BOX("0.5", "0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Dynamic'><Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>5 0</Position><InertiaScale>5</InertiaScale>"
         "<Fixtures><ID>0</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    ENSURE_FLOAT(b2Body_GetRotationalInertia(BODY(w, 1)),
                 b2Body_GetRotationalInertia(BODY(w, 0)));
    ENSURE_FLOAT(b2Body_GetMass(BODY(w, 1)), b2Body_GetMass(BODY(w, 0)));
    close_world(&w);
    return 0;
}

/* A body named `kept` (as long a name as the version keeps) keeps it; one named `longer` (a
 * byte more) gets no name, not a cut one, and is reported. */
static int names_longer_than_kept_are_reported(const char* kept, const char* longer) {
    char bodies[512];
    snprintf(bodies, sizeof bodies,
             "<Body Type='Dynamic'><Name>%s</Name><Fixtures><ID>0</ID></Fixtures></Body>"
             "<Body Type='Dynamic'><Name>%s</Name><Position>5 0</Position>"
             "<Fixtures><ID>0</ID></Fixtures></Body>",
             kept, longer);
    scene_world w;
    OPEN(w, "1", "0 -10", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         bodies, "");
    ENSURE_REPORT_COUNT(w, 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_BODY, "body", 1), 1);
    ENSURE_STR(b2Body_GetName(BODY(w, 0)), kept);
    ENSURE_STR(b2Body_GetName(BODY(w, 1)), "");
    close_world(&w);
    return 0;
}

#if V3_MINOR == 1
/* v3.1 keeps 31 bytes of a name (body.h: name[32]). */
static int names_longer_than_v31_keeps_are_reported(void) {
    return names_longer_than_kept_are_reported("abcdefghijklmnopqrstuvwxyz01234",
                                               "abcdefghijklmnopqrstuvwxyz012345");
}
#else
/* v3.2 keeps B2_NAME_LENGTH bytes of a name. */
static int names_longer_than_v32_keeps_are_reported(void) {
    ENSURE_EQ(B2_NAME_LENGTH, 10);
    return names_longer_than_kept_are_reported("abcdefghij", "abcdefghijk");
}
#endif

/* Box2D 2.x keeps a body that may not sleep asleep until touched; v3 creates it awake. */
static int awake_false_without_sleep_is_reported(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", CIRCLE("0.5"), "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Dynamic'><Awake>false</Awake><AllowSleep>false</AllowSleep>"
         "<Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>5 0</Position><Awake>false</Awake>"
         "<Fixtures><ID>0</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_BODY, "body", 0), 1);
    ENSURE(b2Body_IsAwake(BODY(w, 0)));
    ENSURE(!b2Body_IsAwake(BODY(w, 1)));
    close_world(&w);
    return 0;
}

/* v3.2 asserts at the step on a body whose shapes left its mass to be computed: every
 * kinematic and dynamic body gets it computed, so that both step (in v3.1 too). */
static int kinematic_and_dynamic_bodies_with_shapes_step(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", BOX("0.5", "0.5"),
         "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Kinematic'><LinearVelocity>1 0</LinearVelocity><Fixtures><ID>0</ID>"
         "</Fixtures></Body>"
         "<Body Type='Dynamic'><Position>5 5</Position><Fixtures><ID>0</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    step_v3(&w.v3, 60);
    ENSURE_NEAR(v3_position(BODY(w, 0)).x, 1.0, 1e-4);
    ENSURE_FLOAT(b2Body_GetMass(BODY(w, 0)), 0.0f);
    ENSURE_FLOAT(b2Body_GetMass(BODY(w, 1)), 1.0f);
    ENSURE_FINITE(w);
    close_world(&w);
    return 0;
}

#if V3_MINOR == 2
/* v3.2's lock keeps the inertia (its later sources zero it): the adapter zeroes it too, so
 * that a locked body's mass is the same in every 3.2. The spin is passed as the file gives
 * it, and the lock stops it at the first step: reported lossy-body (spec section 13). */
static int fixed_rotation_has_no_inertia(void) {
    scene_world w;
    OPEN(w, "1", "0 -10", BOX("0.5", "0.5"),
         "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Dynamic'><FixedRotation>true</FixedRotation><AngularVelocity>2"
         "</AngularVelocity><Fixtures><ID>0</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 1);
    ENSURE_EQ(count_reports(REPORTS(w), B2S_CODE_LOSSY_BODY, "body", 0), 1);
    ENSURE(b2Body_GetMotionLocks(BODY(w, 0)).angularZ);
    ENSURE_FLOAT(b2Body_GetRotationalInertia(BODY(w, 0)), 0.0f);
    ENSURE_FLOAT(b2Body_GetMass(BODY(w, 0)), 1.0f);
    ENSURE_FLOAT(b2Body_GetAngularVelocity(BODY(w, 0)), 2.0f);
    step_v3(&w.v3, 10);
    ENSURE_FLOAT(b2Body_GetAngularVelocity(BODY(w, 0)), 0.0f);
    ENSURE_FLOAT(b2Body_GetRotation(BODY(w, 0)).c, 1.0f);
    close_world(&w);
    return 0;
}
#endif

/* A MassData that moves the centre keeps the velocity of the body's origin the file gives,
 * as Box2D 2.x's SetMassData does: the centre's is the origin's plus w x (c - p). A Mass of
 * 0 is counted as 1 kg, before the inertia is moved to the centre. */
static int mass_data_keeps_the_origins_velocity_and_mass_zero_is_one_kilogram(void) {
    scene_world w;
    OPEN(w, "1", "0 0", BOX("0.5", "0.5"),
         "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
         "<Body Type='Dynamic'><LinearVelocity>1 2</LinearVelocity><AngularVelocity>3"
         "</AngularVelocity><MassData><Center>0.5 0</Center><Inertia>1</Inertia></MassData>"
         "<Fixtures><ID>0</ID></Fixtures></Body>"
         "<Body Type='Dynamic'><Position>5 0</Position><MassData><Mass>0</Mass><Center>0 1"
         "</Center><Inertia>3</Inertia></MassData><Fixtures><ID>0</ID></Fixtures></Body>",
         "");
    ENSURE_REPORT_COUNT(w, 0);
    b2BodyId moved = BODY(w, 0);
    ENSURE_FLOAT(v3_local_center(moved).x, 0.5f);
    b2Vec2 v = b2Body_GetLinearVelocity(moved);
    /* (1, 2) + 3 x (0.5, 0) = (1, 2) + (0, 1.5) */
    ENSURE_FLOAT(v.x, 1.0f);
    ENSURE_FLOAT(v.y, 3.5f);
    b2BodyId massless = BODY(w, 1);
    ENSURE_FLOAT(b2Body_GetMass(massless), 1.0f);
    ENSURE_FLOAT(v3_local_center(massless).y, 1.0f);
    ENSURE_FLOAT(b2Body_GetRotationalInertia(massless), 3.0f - 1.0f);
    close_world(&w);
    return 0;
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(body_fields_are_passed_exactly);
    failed += RUN_TEST(damping_slows_as_v3_integrates_it);
    failed += RUN_TEST(gravity_scale_scales_the_fall);
    failed += RUN_TEST(gravity_comes_from_the_file_or_the_host);
    failed += RUN_TEST(sleep_follows_allow_sleep);
    failed += RUN_TEST(fixed_rotation_does_not_rotate_when_hit_off_centre);
    failed += RUN_TEST(inactive_bodies_are_not_simulated);
    failed += RUN_TEST(zero_density_dynamic_body_gets_one_kilogram_and_falls);
    failed += RUN_TEST(partial_mass_data_overrides_only_what_it_gives);
    failed += RUN_TEST(fixture_material_is_passed_exactly_and_bounces);
    failed += RUN_TEST(sensors_are_passed_through_and_sense);
    failed += RUN_TEST(filters_pass_bits_and_groups);
    failed += RUN_TEST(filters_pass_all_32_bits);
    failed += RUN_TEST(circle_and_polygon_shapes);
    failed += RUN_TEST(two_vertex_polygon_and_plain_edge_are_segments);
    failed += RUN_TEST(edge_with_ghosts_is_a_one_sided_chain);
    failed += RUN_TEST(edge_with_one_ghost_extrapolates_the_other);
    failed += RUN_TEST(open_chains_with_and_without_ghosts);
    failed += RUN_TEST(three_vertex_loops_hold_balls);
    failed += RUN_TEST(what_v3_shapes_cannot_hold_is_reported);
    failed += RUN_TEST(revolute_hinge_swings_about_its_anchor);
    failed += RUN_TEST(revolute_limit_holds);
    failed += RUN_TEST(revolute_motor_turns_at_its_speed);
    failed += RUN_TEST(revolute_limit_beyond_v3s_range_is_clamped);
    failed += RUN_TEST(revolute_reference_angle_and_limit_order);
    failed += RUN_TEST(prismatic_moves_only_along_its_axis);
    failed += RUN_TEST(prismatic_disabled_limit_out_of_order_is_swapped);
    failed += RUN_TEST(rigid_distance_joint_keeps_its_length);
    failed += RUN_TEST(spring_distance_joint_oscillates_around_its_length);
    failed += RUN_TEST(distance_length_below_v3s_minimum_is_reported);
    failed += RUN_TEST(rope_stops_at_its_max_length);
    failed += RUN_TEST(line_joint_is_free_along_its_axis);
    failed += RUN_TEST(wheel_spring_compresses_under_load);
    failed += RUN_TEST(weld_holds_rigid_or_soft);
    failed += RUN_TEST(friction_joint_slows_a_puck);
    failed += RUN_TEST(motor_joint_drives_body_b_to_its_offset);
    failed += RUN_TEST(joints_v3_lacks_are_skipped);
    failed += RUN_TEST(negative_damping_is_reported_and_zeroed);
    failed += RUN_TEST(beyond_the_working_range_skips_what_depends_on_it);
    failed += RUN_TEST(angle_beyond_pi_is_reported_lossy_for_capture);
    failed += RUN_TEST(inertia_scale_changes_nothing);
#if V3_MINOR == 1
    failed += RUN_TEST(names_longer_than_v31_keeps_are_reported);
#else
    failed += RUN_TEST(names_longer_than_v32_keeps_are_reported);
#endif
    failed += RUN_TEST(awake_false_without_sleep_is_reported);
    failed += RUN_TEST(kinematic_and_dynamic_bodies_with_shapes_step);
#if V3_MINOR == 2
    failed += RUN_TEST(fixed_rotation_has_no_inertia);
#endif
    failed += RUN_TEST(mass_data_keeps_the_origins_velocity_and_mass_zero_is_one_kilogram);
    return failed;
}
