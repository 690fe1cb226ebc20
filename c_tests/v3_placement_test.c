/*
 * Building at a placement (build_world_at), compiled once per v3 adapter (V3_SUPPORT names its
 * support header): one scene built twice into one world, at two placements, evolves bit for
 * bit like the same bodies, shapes and joints built by hand through the engine's own API at
 * the placed poses (the position and the velocity turned and
 * moved, the rotation turned; anchors, local to their bodies, unchanged), over 600 steps.
 */
#include V3_SUPPORT

#define STEPS 600

/* A ground, a box thrown spinning onto it, and a ball hanging from the ground by a
 * revolute joint. */
static const char* const scene_text =
    "<World Version='2'><Gravity>0 -10</Gravity><Shapes>"
    "<Shape Type='Polygon'><Vertices><Vertex>-10 -1</Vertex><Vertex>10 -1</Vertex>"
    "<Vertex>10 0</Vertex><Vertex>-10 0</Vertex></Vertices></Shape>"
    "<Shape Type='Polygon'><Vertices><Vertex>-0.5 -0.5</Vertex><Vertex>0.5 -0.5</Vertex>"
    "<Vertex>0.5 0.5</Vertex><Vertex>-0.5 0.5</Vertex></Vertices></Shape>"
    "<Shape Type='Circle'><Radius>0.25</Radius><Position>0 0</Position></Shape></Shapes>"
    "<Fixtures><Fixture><Shape>0</Shape><Friction>0.5</Friction></Fixture>"
    "<Fixture><Shape>1</Shape><Density>2</Density><Friction>0.5</Friction></Fixture>"
    "<Fixture><Shape>2</Shape><Density>1</Density><Friction>0.5</Friction></Fixture>"
    "</Fixtures><Bodies>"
    "<Body Type='Static'><Fixtures><ID>0</ID></Fixtures></Body>"
    "<Body Type='Dynamic'><Position>1 3</Position><Angle>0.3</Angle><LinearVelocity>2 -1"
    "</LinearVelocity><AngularVelocity>1.5</AngularVelocity><Fixtures><ID>1</ID></Fixtures>"
    "</Body>"
    "<Body Type='Dynamic'><Position>4 4</Position><Fixtures><ID>2</ID></Fixtures></Body>"
    "</Bodies><Joints><Joint Type='Revolute'><BodyA>0</BodyA><BodyB>2</BodyB>"
    "<LocalAnchorA>4 5</LocalAnchorA><LocalAnchorB>0 1</LocalAnchorB></Joint></Joints></World>";

static b2Rot rotation_of(float angle) {
    return (b2Rot){cosf(angle), sinf(angle)};
}

static b2Polygon box(float x0, float y0, float x1, float y1) {
    b2Vec2 points[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    b2Hull hull = b2ComputeHull(points, 4);
    return b2MakePolygon(&hull, 0.0f);
}

static b2ShapeDef shape_def(float density) {
    b2ShapeDef def = b2DefaultShapeDef();
    def.density = density;
    def.material.friction = 0.5f;
    def.enableSensorEvents = true;
    def.updateBodyMass = false;
    return def;
}

/* The scene's bodies at `placement`, built by hand: `bodies` gets the three. */
static void build_by_hand(b2WorldId world, b2Transform placement, b2BodyId* bodies) {
    b2BodyDef def = b2DefaultBodyDef();
    def.position = v3_pos(b2TransformPoint(placement, (b2Vec2){0.0f, 0.0f}));
    def.rotation = b2MulRot(placement.q, rotation_of(0.0f));
    bodies[0] = b2CreateBody(world, &def);
    b2ShapeDef ground = shape_def(0.0f);
    b2Polygon ground_box = box(-10.0f, -1.0f, 10.0f, 0.0f);
    b2CreatePolygonShape(bodies[0], &ground, &ground_box);

    def.type = b2_dynamicBody;
    def.position = v3_pos(b2TransformPoint(placement, (b2Vec2){1.0f, 3.0f}));
    def.rotation = b2MulRot(placement.q, rotation_of(0.3f));
    def.linearVelocity = b2RotateVector(placement.q, (b2Vec2){2.0f, -1.0f});
    def.angularVelocity = 1.5f;
    bodies[1] = b2CreateBody(world, &def);
    b2ShapeDef thrown = shape_def(2.0f);
    b2Polygon thrown_box = box(-0.5f, -0.5f, 0.5f, 0.5f);
    b2CreatePolygonShape(bodies[1], &thrown, &thrown_box);
    b2Body_ApplyMassFromShapes(bodies[1]);

    def.position = v3_pos(b2TransformPoint(placement, (b2Vec2){4.0f, 4.0f}));
    def.rotation = b2MulRot(placement.q, rotation_of(0.0f));
    def.linearVelocity = b2RotateVector(placement.q, (b2Vec2){0.0f, 0.0f});
    def.angularVelocity = 0.0f;
    bodies[2] = b2CreateBody(world, &def);
    b2ShapeDef ball = shape_def(1.0f);
    b2Circle circle = {{0.0f, 0.0f}, 0.25f};
    b2CreateCircleShape(bodies[2], &ball, &circle);
    b2Body_ApplyMassFromShapes(bodies[2]);

    b2RevoluteJointDef hinge =
        v3_revolute_def(bodies[0], bodies[2], (b2Vec2){4.0f, 5.0f}, (b2Vec2){0.0f, 1.0f});
    b2CreateRevoluteJoint(world, &hinge);
}

static bool same_state(b2BodyId a, b2BodyId b) {
    b2Transform ta = b2Body_GetTransform(a), tb = b2Body_GetTransform(b);
    b2Vec2 va = b2Body_GetLinearVelocity(a), vb = b2Body_GetLinearVelocity(b);
    float wa = b2Body_GetAngularVelocity(a), wb = b2Body_GetAngularVelocity(b);
    return memcmp(&ta, &tb, sizeof ta) == 0 && memcmp(&va, &vb, sizeof va) == 0 &&
           memcmp(&wa, &wb, sizeof wa) == 0;
}

static int two_placed_instances_evolve_as_built_by_hand(void) {
    b2s_scene* scene = load_text(scene_text);
    ENSURE(scene != NULL);
    const b2Transform placements[2] = {{{100.0f, 0.0f}, {cosf(0.5f), sinf(0.5f)}},
                                       {{-100.0f, 50.0f}, {cosf(-2.0f), sinf(-2.0f)}}};
    b2WorldDef def = V3_ADAPTER(world_def)(scene, (b2Vec2){0.0f, -10.0f});
    b2WorldId placed = b2CreateWorld(&def), by_hand = b2CreateWorld(&def);
    v3_built* built[2];
    b2BodyId hand[2][3];
    for (int k = 0; k < 2; ++k) {
        built[k] = V3_ADAPTER(build_world_at)(scene, placed, placements[k]);
        ENSURE(built[k] != NULL);
        if (built[k]->reports.count != 0) {
            print_reports(&built[k]->reports);
        }
        ENSURE_EQ(built[k]->reports.count, 0);
        build_by_hand(by_hand, placements[k], hand[k]);
    }
    /* The anchors are local: the hinge holds the ball 1 m under the placed anchor. */
    b2Vec2 anchor =
        b2TransformPoint(b2Body_GetTransform(built[0]->bodies[0]), (b2Vec2){4.0f, 5.0f});
    b2Vec2 ball = b2TransformPoint(b2Body_GetTransform(built[0]->bodies[2]), (b2Vec2){0.0f, 1.0f});
    ENSURE_NEAR(b2Distance(anchor, ball), 0.0, 1e-4);
    for (int step = 0; step <= STEPS; ++step) {
        for (int k = 0; k < 2; ++k) {
            for (int i = 0; i < 3; ++i) {
                if (!same_state(built[k]->bodies[i], hand[k][i])) {
                    fprintf(stderr, "instance %d, body %d differs after %d steps\n", k, i, step);
                    return 1;
                }
            }
        }
        b2World_Step(placed, TIME_STEP, SUB_STEPS);
        b2World_Step(by_hand, TIME_STEP, SUB_STEPS);
    }
    /* and they moved: the thrown box is not where it started */
    b2Vec2 start = b2TransformPoint(placements[1], (b2Vec2){1.0f, 3.0f});
    ENSURE(b2Distance(v3_position(built[1]->bodies[1]), start) > 0.5f);
    for (int k = 0; k < 2; ++k) {
        V3_ADAPTER(built_free)(built[k]);
    }
    b2DestroyWorld(placed);
    b2DestroyWorld(by_hand);
    b2s_scene_free(scene);
    return 0;
}

static int the_identity_placement_is_the_plain_build(void) {
    b2s_scene* scene = load_text(scene_text);
    ENSURE(scene != NULL);
    v3_world plain = build_v3(scene);
    b2WorldDef def = V3_ADAPTER(world_def)(scene, (b2Vec2){0.0f, -10.0f});
    b2WorldId world = b2CreateWorld(&def);
    v3_built* at = V3_ADAPTER(build_world_at)(scene, world, b2Transform_identity);
    ENSURE(at != NULL);
    for (int step = 0; step < STEPS; ++step) {
        b2World_Step(plain.id, TIME_STEP, SUB_STEPS);
        b2World_Step(world, TIME_STEP, SUB_STEPS);
    }
    for (uint32_t i = 0; i < at->body_count; ++i) {
        ENSURE(same_state(plain.built->bodies[i], at->bodies[i]));
    }
    V3_ADAPTER(built_free)(at);
    b2DestroyWorld(world);
    free_v3(&plain);
    b2s_scene_free(scene);
    return 0;
}

/* A placement v3 cannot take (a rotation not normalised, a translation not finite or
 * beyond the working range) builds nothing and says so. */
static int a_placement_v3_cannot_take_builds_nothing(void) {
    b2s_scene* scene = load_text(scene_text);
    ENSURE(scene != NULL);
    const b2Transform bad[3] = {{{0.0f, 0.0f}, {2.0f, 0.0f}},
                                {{NAN, 0.0f}, {1.0f, 0.0f}},
                                {{2e4f, 0.0f}, {1.0f, 0.0f}}};
    for (int k = 0; k < 3; ++k) {
        b2WorldDef def = b2DefaultWorldDef();
        b2WorldId world = b2CreateWorld(&def);
        v3_built* built = V3_ADAPTER(build_world_at)(scene, world, bad[k]);
        ENSURE(built != NULL);
        ENSURE_EQ(built->reports.count, 1);
        ENSURE_EQ(count_reports(&built->reports, B2S_CODE_INVALID_ARGUMENT, "world", 0), 1);
        ENSURE_EQ(b2World_GetCounters(world).bodyCount, 0);
        ENSURE(B2_IS_NULL(built->bodies[0]));
        V3_ADAPTER(built_free)(built);
        b2DestroyWorld(world);
    }
    b2s_scene_free(scene);
    return 0;
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(two_placed_instances_evolve_as_built_by_hand);
    failed += RUN_TEST(the_identity_placement_is_the_plain_build);
    failed += RUN_TEST(a_placement_v3_cannot_take_builds_nothing);
    return failed;
}
