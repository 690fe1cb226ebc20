/*
 * Capture against real Box2D v3: a world built from a scene, captured, written, loaded and
 * built again evolves bit for bit like the first over 600 steps, for every scene file of the
 * project; and what the format cannot hold (capsules, mouse and filter joints, filter bits
 * above the format's, joints to bodies not named) is reported by code. Compiled once per v3
 * adapter (V3_SUPPORT names its support header) as box2d3_roundtrip_test and
 * box2d32_roundtrip_test.
 */
#include V3_SUPPORT

#define STEPS 600

static bool same_bits(const void* a, const void* b, size_t size) {
    return memcmp(a, b, size) == 0;
}

/* The scene captured from `world` (every body built from the scene, in order; given `level`,
 * the scene it was built from, through capture_built), written and loaded back; NULL on
 * failure (printed). */
static b2s_scene* captured_and_reloaded_from(const v3_world* world, const b2s_scene* level,
                                             v3_reports* reports) {
    b2BodyId* bodies = (b2BodyId*)malloc((world->built->body_count + 1) * sizeof(b2BodyId));
    uint32_t count = 0;
    for (uint32_t i = 0; i < world->built->body_count; ++i) {
        if (!B2_IS_NULL(world->built->bodies[i])) {
            bodies[count++] = world->built->bodies[i];
        }
    }
    b2s_scene* captured = NULL;
    b2s_error error;
    b2s_code code =
        level != NULL
            ? V3_ADAPTER(capture_built)(world->id, world->built, level, &captured, reports, &error)
            : V3_ADAPTER(capture_world)(world->id, bodies, count, &captured, reports, &error);
    free(bodies);
    if (code != B2S_CODE_OK) {
        fprintf(stderr, "capture failed: %s: %s\n", b2s_code_name(code), error.message);
        return NULL;
    }
    char* text = NULL;
    size_t size = 0;
    code = b2s_write_memory(captured, NULL, &text, &size, &error);
    b2s_scene_free(captured);
    if (code != B2S_CODE_OK) {
        fprintf(stderr, "write failed: %s: %s\n", b2s_code_name(code), error.message);
        return NULL;
    }
    b2s_scene* reloaded = load_text(text);
    b2s_text_free(text);
    return reloaded;
}

/* The scene captured from `world` as capture_world captures the bodies built, written and
 * loaded back; NULL on failure (printed). */
static b2s_scene* captured_and_reloaded(const v3_world* world, v3_reports* reports) {
    return captured_and_reloaded_from(world, NULL, reports);
}

/* Every body of `a` and the body of `b` in the same place (the i-th created), bit for bit. */
static int same_state(const v3_world* a, const b2BodyId* b_bodies, uint32_t count,
                      const char* path, int step) {
    uint32_t k = 0;
    for (uint32_t i = 0; i < a->built->body_count; ++i) {
        b2BodyId body = a->built->bodies[i];
        if (B2_IS_NULL(body)) {
            continue;
        }
        ENSURE(k < count);
        b2BodyId other = b_bodies[k++];
        b2Transform ta = b2Body_GetTransform(body), tb = b2Body_GetTransform(other);
        b2Vec2 va = b2Body_GetLinearVelocity(body), vb = b2Body_GetLinearVelocity(other);
        float wa = b2Body_GetAngularVelocity(body), wb = b2Body_GetAngularVelocity(other);
        if (!same_bits(&ta, &tb, sizeof ta) || !same_bits(&va, &vb, sizeof va) ||
            !same_bits(&wa, &wb, sizeof wa)) {
            fprintf(stderr, "%s: body %u differs after %d steps: (%.9g, %.9g) vs (%.9g, %.9g)\n",
                    path, (unsigned)i, step, (double)ta.p.x, (double)ta.p.y, (double)tb.p.x,
                    (double)tb.p.y);
            return 1;
        }
    }
    ENSURE_EQ(k, count);
    return 0;
}

/* How many reports are on an object of this kind. */
static uint32_t reports_on(const v3_reports* reports, const char* object) {
    uint32_t found = 0;
    for (uint32_t i = 0; i < reports->count; ++i) {
        found += strcmp(reports->items[i].object, object) == 0;
    }
    return found;
}

/* `given_level` non-NULL: the capture is given the scene (capture_built). */
static int round_trip(const char* path, const b2s_scene* scene, void* given_level) {
    v3_world first = build_v3(scene);
    ENSURE(first.built != NULL);
    v3_reports reports;
    b2s_scene* reloaded =
        captured_and_reloaded_from(&first, given_level != NULL ? scene : NULL, &reports);
    ENSURE(reloaded != NULL);
    /* a world built from a scene has nothing the format cannot hold; given the scene, the
     * capture writes back the joints the build skipped, and says which it cannot (a gear
     * before its joints, a Farseer-only joint) */
    uint32_t allowed = 0;
    if (given_level != NULL &&
        count_reports(&first.built->reports, B2S_CODE_SKIPPED_JOINT, NULL, 0) > 0) {
        allowed = reports_on(&reports, "joint");
    }
    if (reports.count != allowed) {
        fprintf(stderr, "%s: capture reported:\n", path);
        print_reports(&reports);
    }
    ENSURE_EQ(reports.count, allowed);
    V3_ADAPTER(reports_free)(&reports);

    v3_world second = build_v3(reloaded);
    ENSURE(second.built != NULL);
    uint32_t count = 0;
    b2BodyId* bodies = second.built->bodies;
    for (uint32_t i = 0; i < second.built->body_count; ++i) {
        ENSURE(!B2_IS_NULL(bodies[i]));
        count += 1;
    }
    for (int step = 0; step <= STEPS; ++step) {
        if (same_state(&first, bodies, count, path, step) != 0) {
            return 1;
        }
        b2World_Step(first.id, TIME_STEP, SUB_STEPS);
        b2World_Step(second.id, TIME_STEP, SUB_STEPS);
    }
    free_v3(&first);
    free_v3(&second);
    b2s_scene_free(reloaded);
    return 0;
}

static int every_scene_file_round_trips_bit_for_bit(void) {
    int loaded = 0;
    int failed = for_each_scene(round_trip, NULL, &loaded);
    ENSURE(loaded >= 10);
    return failed;
}

static int every_scene_file_round_trips_bit_for_bit_given_the_scene(void) {
    int loaded = 0;
    int given = 1;
    int failed = for_each_scene(round_trip, &given, &loaded);
    ENSURE(loaded >= 10);
    return failed;
}

#if V3_MINOR >= 2
/* The forms that are v3.2's own round-trip too, with nothing reported and the same shapes
 * and joints read back: two loops of the same points side by side on one body (each closes
 * before the other begins), a 3-vertex loop, a sensor chain, an edge with ghosts, a
 * prismatic joint with a reference angle on a skew axis, a friction joint off the origins
 * and a motor joint (read back as the Motor it was built from). v3.1 splits a 3-vertex
 * loop's edge, makes a sensor chain solid and acts at the body origins for friction. */
static int v32_forms_round_trip(void) {
    b2s_scene* scene = load_text(
        "<World Version='2'><Gravity>0 -10</Gravity><Shapes>"
        "<Shape Type='Loop'><Vertices><Vertex>-5 0</Vertex><Vertex>5 0</Vertex>"
        "<Vertex>5 10</Vertex><Vertex>-5 10</Vertex></Vertices></Shape>"
        "<Shape Type='Loop'><Vertices><Vertex>0 -3</Vertex><Vertex>4 0</Vertex>"
        "<Vertex>-4 0</Vertex></Vertices></Shape>"
        "<Shape Type='Chain'><Vertices><Vertex>-3 5</Vertex><Vertex>0 4</Vertex>"
        "<Vertex>3 5</Vertex></Vertices><PrevVertex>-4 6</PrevVertex><NextVertex>4 6"
        "</NextVertex><HasPrevVertex>true</HasPrevVertex><HasNextVertex>true</HasNextVertex>"
        "</Shape>"
        "<Shape Type='Edge'><Vertex1>-2 2</Vertex1><Vertex2>2 2</Vertex2><Vertex0>-3 2"
        "</Vertex0><Vertex3>3 2</Vertex3><HasVertex0>true</HasVertex0><HasVertex3>true"
        "</HasVertex3></Shape>"
        "<Shape Type='Circle'><Radius>0.25</Radius><Position>0 0</Position></Shape></Shapes>"
        "<Fixtures><Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape></Fixture>"
        "<Fixture><Shape>2</Shape><IsSensor>true</IsSensor></Fixture>"
        "<Fixture><Shape>3</Shape></Fixture>"
        "<Fixture><Shape>4</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
        "<Body Type='Static'><Fixtures><ID>0</ID><ID>0</ID><ID>1</ID><ID>2</ID><ID>3</ID>"
        "</Fixtures></Body>"
        "<Body Type='Dynamic'><Position>1 8</Position><Fixtures><ID>4</ID></Fixtures></Body>"
        "<Body Type='Dynamic'><Position>-1 8</Position><Angle>0.4</Angle><Fixtures><ID>4</ID>"
        "</Fixtures></Body>"
        "<Body Type='Dynamic'><Position>2 6</Position><Fixtures><ID>4</ID></Fixtures></Body>"
        "<Body Type='Dynamic'><Position>-2 6</Position><Fixtures><ID>4</ID></Fixtures></Body>"
        "</Bodies><Joints>"
        "<Joint Type='Prismatic'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>1 8"
        "</LocalAnchorA><LocalAxisA>2 1</LocalAxisA><ReferenceAngle>0.3</ReferenceAngle>"
        "<EnableLimit>true</EnableLimit><LowerTranslation>-1</LowerTranslation>"
        "<UpperTranslation>1</UpperTranslation></Joint>"
        "<Joint Type='Friction'><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>-1 8"
        "</LocalAnchorA><LocalAnchorB>0.1 0.1</LocalAnchorB><MaxForce>2</MaxForce>"
        "<MaxTorque>1</MaxTorque></Joint>"
        "<Joint Type='Motor'><BodyA>0</BodyA><BodyB>3</BodyB><LinearOffset>2 6.5"
        "</LinearOffset><AngularOffset>0.7</AngularOffset><MaxForce>30</MaxForce>"
        "<MaxTorque>5</MaxTorque><CorrectionFactor>0.37</CorrectionFactor></Joint>"
        "<Joint Type='Revolute'><BodyA>0</BodyA><BodyB>4</BodyB><LocalAnchorA>-2 7"
        "</LocalAnchorA><LocalAnchorB>0 1</LocalAnchorB><ReferenceAngle>-2.5</ReferenceAngle>"
        "</Joint></Joints></World>");
    ENSURE(scene != NULL);
    ENSURE_EQ(round_trip("inline v3.2 forms", scene, NULL), 0);
    /* and what came back is what went in */
    v3_world world = build_v3(scene);
    v3_reports reports;
    b2s_scene* reloaded = captured_and_reloaded(&world, &reports);
    ENSURE(reloaded != NULL);
    const struct b2s_scene_view* view = b2s_scene_get_view(reloaded);
    ENSURE_EQ(view->bodies[0].fixtures.count, 5);
    uint32_t kinds[5], counts[5];
    for (uint32_t k = 0; k < 5; ++k) {
        uint32_t fixture = view->fixture_ids[view->bodies[0].fixtures.first + k];
        const b2s_shape* shape = &view->shapes[view->fixtures[fixture].shape];
        kinds[k] = shape->kind;
        counts[k] = shape->vertices.count;
    }
    ENSURE(kinds[0] == B2S_SHAPE_KIND_CHAIN && counts[0] == 4);
    ENSURE(kinds[1] == B2S_SHAPE_KIND_CHAIN && counts[1] == 4);
    ENSURE(kinds[2] == B2S_SHAPE_KIND_CHAIN && counts[2] == 3);
    ENSURE(kinds[3] == B2S_SHAPE_KIND_CHAIN && counts[3] == 3);
    ENSURE(kinds[4] == B2S_SHAPE_KIND_EDGE && counts[4] == 2);
    ENSURE(view->fixtures[view->fixture_ids[view->bodies[0].fixtures.first + 3]].is_sensor);
    ENSURE_EQ(view->joint_count, 4);
    ENSURE_EQ(view->joints[0].kind, B2S_JOINT_KIND_PRISMATIC);
    ENSURE_NEAR(view->joints[0].reference_angle, 0.3, 1e-6);
    ENSURE_EQ(view->joints[1].kind, B2S_JOINT_KIND_FRICTION);
    ENSURE_FLOAT(view->joints[1].local_anchor_b.x, 0.1f);
    ENSURE_EQ(view->joints[2].kind, B2S_JOINT_KIND_MOTOR);
    ENSURE_FLOAT(view->joints[2].correction_factor, 0.37f);
    ENSURE_FLOAT(view->joints[2].angular_offset, 0.7f);
    ENSURE_FLOAT(view->joints[3].reference_angle, -2.5f);
    V3_ADAPTER(reports_free)(&reports);
    b2s_scene_free(reloaded);
    free_v3(&world);
    b2s_scene_free(scene);
    return 0;
}
#endif

/* ---- what a host's own world holds that the format cannot */

static b2s_scene* capture(b2WorldId world, const b2BodyId* bodies, uint32_t count,
                          v3_reports* reports) {
    b2s_scene* scene = NULL;
    b2s_error error;
    b2s_code code = V3_ADAPTER(capture_world)(world, bodies, count, &scene, reports, &error);
    if (code != B2S_CODE_OK) {
        fprintf(stderr, "capture failed: %s\n", error.message);
    }
    return scene;
}

static int what_the_format_cannot_hold_is_reported(void) {
    b2WorldDef world_def = b2DefaultWorldDef();
    b2WorldId world = b2CreateWorld(&world_def);
    b2BodyDef body_def = b2DefaultBodyDef();
    body_def.type = b2_dynamicBody;
    b2BodyId bodies[3];
    for (int i = 0; i < 3; ++i) {
        body_def.position = v3_pos((b2Vec2){(float)i * 3.0f, 0.0f});
        bodies[i] = b2CreateBody(world, &body_def);
    }
    b2ShapeDef shape_def = b2DefaultShapeDef();
    b2Capsule capsule = {{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f};
    b2CreateCapsuleShape(bodies[0], &shape_def, &capsule);
    b2Circle circle = {{0.0f, 0.0f}, 0.5f};
    /* the bit just above the format's (the width of b2s_filter's fields) */
    const unsigned bits = 8u * (unsigned)sizeof(((b2s_filter*)0)->category_bits);
    shape_def.filter.categoryBits = UINT64_C(1) << bits;
    b2CreateCircleShape(bodies[1], &shape_def, &circle);
    shape_def.filter = b2DefaultFilter(); /* mask UINT64_MAX: "all", held exactly */
    b2CreateCircleShape(bodies[2], &shape_def, &circle);

    v3_joint_without_form(world, bodies[0], bodies[1]); /* a mouse joint in v3.1 */
    b2FilterJointDef filter = b2DefaultFilterJointDef();
    V3_JOINT_BASE(filter).bodyIdA = bodies[1];
    V3_JOINT_BASE(filter).bodyIdB = bodies[2];
    b2CreateFilterJoint(world, &filter);
    b2RevoluteJointDef hinge = b2DefaultRevoluteJointDef();
    V3_JOINT_BASE(hinge).bodyIdA = bodies[0];
    V3_JOINT_BASE(hinge).bodyIdB = bodies[2];
    b2CreateRevoluteJoint(world, &hinge);
    b2WeldJointDef weld = b2DefaultWeldJointDef();
    V3_JOINT_BASE(weld).bodyIdA = bodies[1];
    V3_JOINT_BASE(weld).bodyIdB = bodies[2];
    b2CreateWeldJoint(world, &weld);

    /* Only bodies 1 and 2 are named: the hinge reaches body 0, which is not. */
    v3_reports reports;
    b2s_scene* scene = capture(world, bodies + 1, 2, &reports);
    ENSURE(scene != NULL);
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    ENSURE_EQ(view->body_count, 2);
    ENSURE_EQ(view->fixture_count, 2);
    ENSURE_EQ(view->fixtures[0].filter.category_bits, 0); /* its low bits */
    ENSURE_EQ((uint64_t)view->fixtures[1].filter.mask_bits, UINT64_MAX >> (64u - bits));
    ENSURE_EQ(view->joint_count, 1); /* the weld */
    ENSURE_EQ(view->joints[0].kind, B2S_JOINT_KIND_WELD);
    ENSURE_EQ(count_reports(&reports, B2S_CODE_LOSSY_CAPTURE, "fixture", 0), 1);
    /* the filter bits, the joints to body 0 (the one without a form, the hinge) and the
     * filter joint */
    ENSURE_EQ(count_reports(&reports, B2S_CODE_LOSSY_CAPTURE, NULL, 0), 4);
    V3_ADAPTER(reports_free)(&reports);
    b2s_scene_free(scene);

    /* All three: the capsule, the joint without a form and the filter joint are not
     * written. */
    scene = capture(world, bodies, 3, &reports);
    ENSURE(scene != NULL);
    view = b2s_scene_get_view(scene);
    ENSURE_EQ(view->body_count, 3);
    ENSURE_EQ(view->fixture_count, 2);
    ENSURE_EQ(view->bodies[0].fixtures.count, 0);
    ENSURE_EQ(view->joint_count, 2); /* the hinge and the weld, in creation order */
    ENSURE_EQ(view->joints[0].kind, B2S_JOINT_KIND_REVOLUTE);
    ENSURE_EQ(view->joints[1].kind, B2S_JOINT_KIND_WELD);
    ENSURE_EQ(count_reports(&reports, B2S_CODE_LOSSY_CAPTURE, "shape", 0), 1);
    ENSURE_EQ(count_reports(&reports, B2S_CODE_LOSSY_CAPTURE, "joint", 0), 2);
    ENSURE_EQ(reports.count, 4); /* and the category bits */
    V3_ADAPTER(reports_free)(&reports);
    b2s_scene_free(scene);
    b2DestroyWorld(world);
    return 0;
}

static int capture_refuses_bodies_it_cannot_name(void) {
    b2WorldDef world_def = b2DefaultWorldDef();
    b2WorldId world = b2CreateWorld(&world_def);
    b2WorldId other = b2CreateWorld(&world_def);
    b2BodyDef body_def = b2DefaultBodyDef();
    b2BodyId bodies[2] = {b2CreateBody(world, &body_def), b2CreateBody(other, &body_def)};
    b2s_scene* scene = (b2s_scene*)1;
    v3_reports reports;
    b2s_error error;
    ENSURE_EQ(V3_ADAPTER(capture_world)(world, bodies, 2, &scene, &reports, &error),
              B2S_CODE_INVALID_ARGUMENT);
    ENSURE(scene == NULL);
    ENSURE_EQ(error.code, B2S_CODE_INVALID_ARGUMENT);
    ENSURE(strstr(error.message, "body 1") != NULL);
    b2BodyId twice[2] = {bodies[0], bodies[0]};
    ENSURE_EQ(V3_ADAPTER(capture_world)(world, twice, 2, &scene, &reports, &error),
              B2S_CODE_INVALID_ARGUMENT);
    ENSURE_EQ(V3_ADAPTER(capture_world)(world, NULL, 1, &scene, &reports, &error),
              B2S_CODE_NULL_ARGUMENT);
    b2DestroyWorld(other);
    b2DestroyWorld(world);
    return 0;
}

/* The message of a capture of `bodies` refused as an invalid argument, or "" when it is not. */
static const char* refusal(b2WorldId world, const b2BodyId* bodies, uint32_t count,
                           b2s_error* error) {
    b2s_scene* scene = NULL;
    v3_reports reports;
    if (V3_ADAPTER(capture_world)(world, bodies, count, &scene, &reports, error) !=
        B2S_CODE_INVALID_ARGUMENT) {
        V3_ADAPTER(reports_free)(&reports);
        b2s_scene_free(scene);
        return "";
    }
    return error->message;
}

/* Of several bodies named twice or not live, the host hears of the first a pass in its own
 * order meets, paired with the first index that named the same body. */
static int capture_names_the_first_body_it_refuses(void) {
    b2WorldDef world_def = b2DefaultWorldDef();
    b2WorldId world = b2CreateWorld(&world_def);
    b2BodyDef body_def = b2DefaultBodyDef();
    b2BodyId a = b2CreateBody(world, &body_def), b = b2CreateBody(world, &body_def);
    b2BodyId c = b2CreateBody(world, &body_def), gone = b2CreateBody(world, &body_def);
    b2DestroyBody(gone);
    b2s_error error;
    const b2BodyId crossed[4] = {a, b, b, a};
    ENSURE_STR(refusal(world, crossed, 4, &error), "bodies 1 and 2 are the same body");
    const b2BodyId thrice[5] = {c, a, c, b, c};
    ENSURE_STR(refusal(world, thrice, 5, &error), "bodies 0 and 2 are the same body");
    const b2BodyId late[5] = {c, a, b, a, c};
    ENSURE_STR(refusal(world, late, 5, &error), "bodies 1 and 3 are the same body");
    const b2BodyId dead_first[4] = {a, gone, b, a};
    ENSURE_STR(refusal(world, dead_first, 4, &error), "body 1 is not a live body of this world");
    const b2BodyId twice_first[4] = {a, b, a, gone};
    ENSURE_STR(refusal(world, twice_first, 4, &error), "bodies 0 and 2 are the same body");
    b2DestroyWorld(world);
    return 0;
}

/* A dynamic body given MassData keeps it through the round trip; a rotated body keeps its
 * rotation exactly. */
static int mass_data_and_rotation_survive_capture(void) {
    b2s_scene* scene = load_text(
        "<World Version=\"1\"><Gravity>0 -10</Gravity>"
        "<Shapes><Shape Type=\"Polygon\"><Vertices><Vertex>-1 -0.5</Vertex><Vertex>1 -0.5</Vertex>"
        "<Vertex>1 0.5</Vertex><Vertex>-1 0.5</Vertex></Vertices></Shape></Shapes>"
        "<Fixtures><Fixture><Shape>0</Shape><Density>2</Density></Fixture></Fixtures>"
        "<Bodies><Body Type=\"Dynamic\"><Angle>2.5</Angle><Position>1 2</Position>"
        "<MassData><Mass>7</Mass><Center>0.25 0.125</Center><Inertia>9</Inertia></MassData>"
        "<Fixtures><ID>0</ID></Fixtures></Body></Bodies><Joints/></World>");
    ENSURE(scene != NULL);
    v3_world world = build_v3(scene);
    v3_reports reports;
    b2s_scene* reloaded = captured_and_reloaded(&world, &reports);
    ENSURE(reloaded != NULL);
    ENSURE_EQ(reports.count, 0);
    const struct b2s_scene_view* view = b2s_scene_get_view(reloaded);
    ENSURE_EQ(view->body_count, 1);
    const b2s_body* body = &view->bodies[0];
    ENSURE_FLOAT(body->angle, 2.5f);
    ENSURE(body->mass_data.mass_given && body->mass_data.center_given &&
           body->mass_data.inertia_given);
    ENSURE_FLOAT(body->mass_data.mass, 7.0f);
    ENSURE_FLOAT(body->mass_data.center.x, 0.25f);
    ENSURE_FLOAT(body->mass_data.center.y, 0.125f);
    ENSURE_FLOAT(body->mass_data.inertia, 9.0f);
    V3_ADAPTER(reports_free)(&reports);
    b2s_scene_free(reloaded);
    free_v3(&world);
    b2s_scene_free(scene);
    return 0;
}

/* The showcase saved after 10 s: the solver turns bodies to rotations no float angle gives
 * exactly (a dozen of them), and that is said once, on the world, with how many and how
 * far, so that a real loss (a capsule the host added) stands out rather than drowning among
 * one report a body. */
static int turned_bodies_are_reported_once_a_capture(void) {
    char path[1024];
    snprintf(path, sizeof path, "%s/examples/scenes/showcase.xml", BOX2SCENE_SOURCE_DIR);
    b2s_scene* scene = load_path(path);
    ENSURE(scene != NULL);
    v3_world world = build_v3(scene);
    step_v3(&world, 600);
    b2ShapeDef def = b2DefaultShapeDef();
    b2Capsule capsule = {{-0.1f, 0.0f}, {0.1f, 0.0f}, 0.05f};
    b2CreateCapsuleShape(world.built->bodies[5], &def, &capsule);
    v3_reports reports;
    b2s_scene* reloaded = captured_and_reloaded(&world, &reports);
    ENSURE(reloaded != NULL);
    print_reports(&reports);
    ENSURE_EQ(reports.count, 2);
    ENSURE_EQ(count_reports(&reports, B2S_CODE_LOSSY_CAPTURE, NULL, 0), 2);
    ENSURE_EQ(reports_on(&reports, "shape"), 1); /* the capsule */
    ENSURE_EQ(count_reports(&reports, B2S_CODE_LOSSY_CAPTURE, "world", 0), 1);
    const v3_report* turned = &reports.items[0];
    if (strcmp(turned->object, "world") != 0) {
        turned = &reports.items[1];
    }
    ENSURE(strstr(turned->message, "of the bodies") != NULL);
    unsigned count = 0;
    ENSURE(sscanf(strstr(turned->message, "turns bodies: ") + 14, "%u", &count) == 1);
    ENSURE(count >= 10);
    V3_ADAPTER(reports_free)(&reports);
    b2s_scene_free(reloaded);
    free_v3(&world);
    b2s_scene_free(scene);
    return 0;
}

/* Given what the build made and the scene, a capture keeps the level with no host code:
 * every body, fixture, shape and joint comes back with the Name and UserData the file gave
 * it, a body's whole Name (v3.1 keeps 31 bytes of it), a fixture two bodies share as the one
 * fixture, and joint names where the joints are, though v3 has no pulley (skipped). */
static int built_level_keeps_its_names_and_user_data(void) {
    b2s_scene* scene = load_text(
        "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>"
        "<Shape Type=\"Polygon\"><Name>Plank</Name><Vertices><Vertex>-0.5 -0.1</Vertex>"
        "<Vertex>0.5 -0.1</Vertex><Vertex>0.5 0.1</Vertex><Vertex>-0.5 0.1</Vertex></Vertices>"
        "</Shape>"
        "<Shape Type=\"Chain\"><Name>Hills</Name><Vertices><Vertex>-5 0</Vertex>"
        "<Vertex>0 1</Vertex><Vertex>5 0</Vertex></Vertices><PrevVertex>-6 0</PrevVertex>"
        "<HasPrevVertex>true</HasPrevVertex><NextVertex>6 0</NextVertex>"
        "<HasNextVertex>true</HasNextVertex></Shape></Shapes>"
        "<Fixtures><Fixture><Name>Track</Name><Shape>1</Shape>"
        "<UserData><Color>green</Color></UserData></Fixture>"
        "<Fixture><Name>Wood</Name><Shape>0</Shape><Density>1</Density><UserData><Type>"
        "System.String</Type><Value><string>oak &amp; pine</string></Value></UserData>"
        "</Fixture></Fixtures><Bodies>"
        "<Body Type=\"Static\"><Name>Ground</Name><Fixtures><ID>0</ID></Fixtures></Body>"
        "<Body Type=\"Dynamic\"><Name>TheLeftPlankOfTheRopeBridgeOverTheRiver</Name>"
        "<Position>-1 3</Position><UserData><Type>System.Int32</Type><Value><int>7</int>"
        "</Value></UserData><Fixtures><ID>1</ID></Fixtures></Body>"
        "<Body Type=\"Dynamic\"><Position>1 3</Position><Fixtures><ID>1</ID></Fixtures></Body>"
        "</Bodies><Joints>"
        "<Joint Type=\"Pulley\"><Name>Lift</Name><BodyA>1</BodyA><BodyB>2</BodyB>"
        "<GroundAnchorA>-1 6</GroundAnchorA><GroundAnchorB>1 6</GroundAnchorB>"
        "<LocalAnchorA>0 0</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB>"
        "<LengthA>3</LengthA><LengthB>3</LengthB><Ratio>1</Ratio></Joint>"
        "<Joint Type=\"Revolute\"><Name>Hinge</Name><BodyA>1</BodyA><BodyB>2</BodyB>"
        "<LocalAnchorA>1 0</LocalAnchorA><LocalAnchorB>-1 0</LocalAnchorB>"
        "<UserData>squeaks</UserData></Joint>"
        "</Joints></World>");
    ENSURE(scene != NULL);
    v3_world world = build_v3(scene);
    ENSURE(B2_IS_NULL(world.built->joints[0])); /* v3 has no pulley */
    b2s_scene* captured = NULL;
    v3_reports reports;
    b2s_error error;
    ENSURE_EQ(V3_ADAPTER(capture_built)(world.id, world.built, scene, &captured, &reports,
                                        &error),
              B2S_CODE_OK);
    print_reports(&reports);
    ENSURE_EQ(reports.count, 0);
    char* text = NULL;
    size_t size = 0;
    ENSURE_EQ(b2s_write_memory(captured, NULL, &text, &size, &error), B2S_CODE_OK);
    b2s_scene* reloaded = load_text(text);
    b2s_text_free(text);
    ENSURE(reloaded != NULL);
    const b2s_scene_view* view = b2s_scene_get_view(reloaded);
    ENSURE_EQ(view->body_count, 3);
    ENSURE_STR(view->bodies[0].name, "Ground");
    ENSURE_STR(view->bodies[1].name, "TheLeftPlankOfTheRopeBridgeOverTheRiver");
    ENSURE_STR(view->user_data[view->bodies[1].user_data].value, "7");
    ENSURE(view->bodies[2].name == NULL && view->bodies[2].user_data == B2S_NONE);
    uint32_t track = view->fixture_ids[view->bodies[0].fixtures.first];
    ENSURE_STR(view->fixtures[track].name, "Track");
    ENSURE_STR(view->user_data[view->fixtures[track].user_data].raw, "<Color>green</Color>");
    ENSURE_STR(view->shapes[view->fixtures[track].shape].name, "Hills");
    for (uint32_t b = 1; b <= 2; ++b) {
        const b2s_fixture* wood = &view->fixtures[view->fixture_ids[view->bodies[b].fixtures.first]];
        ENSURE_STR(wood->name, "Wood");
        ENSURE_STR(view->user_data[wood->user_data].value, "oak & pine");
        ENSURE_STR(view->shapes[wood->shape].name, "Plank");
    }
    ENSURE_EQ(view->joint_count, 2); /* the pulley, written back as the file has it */
    ENSURE_EQ(view->joints[0].kind, B2S_JOINT_KIND_PULLEY);
    ENSURE_STR(view->joints[0].name, "Lift");
    ENSURE_FLOAT(view->joints[0].length_a, 3.0f);
    ENSURE_EQ(view->joints[0].body_a, 1);
    ENSURE_STR(view->joints[1].name, "Hinge");
    ENSURE_STR(view->user_data[view->joints[1].user_data].raw, "squeaks");
    V3_ADAPTER(reports_free)(&reports);
    b2s_scene_free(reloaded);
    b2s_scene_free(captured);
    free_v3(&world);
    b2s_scene_free(scene);
    return 0;
}

/* A built result is the scene's or nothing: one of another scene is refused by code. */
static int capture_built_refuses_a_result_of_another_scene(void) {
    b2s_scene* scene = load_text("<World Version=\"2\"><Bodies><Body Type=\"Static\"/>"
                                 "<Body Type=\"Static\"/></Bodies></World>");
    b2s_scene* other = load_text("<World Version=\"2\"><Bodies><Body Type=\"Static\"/>"
                                 "</Bodies></World>");
    ENSURE(scene != NULL && other != NULL);
    v3_world world = build_v3(scene);
    b2s_scene* captured = NULL;
    v3_reports reports;
    b2s_error error;
    ENSURE_EQ(V3_ADAPTER(capture_built)(world.id, world.built, other, &captured, &reports,
                                        &error),
              B2S_CODE_INVALID_ARGUMENT);
    ENSURE(captured == NULL && reports.count == 0);
    ENSURE_EQ(V3_ADAPTER(capture_built)(world.id, NULL, scene, &captured, &reports, &error),
              B2S_CODE_NULL_ARGUMENT);
    free_v3(&world);
    b2s_scene_free(other);
    b2s_scene_free(scene);
    return 0;
}

/* The showcase's pulley and gear, which v3 cannot hold, are written back as the file has
 * them, so every joint keeps its index in the save: CarRearSuspension stays joint 21 (it was
 * joint 19 of a save of the world alone), and the gear still couples its two axles. */
static int showcase_save_keeps_every_joint_at_its_index(void) {
    char path[1024];
    snprintf(path, sizeof path, "%s/examples/scenes/showcase.xml", BOX2SCENE_SOURCE_DIR);
    b2s_scene* scene = load_path(path);
    ENSURE(scene != NULL);
    v3_world world = build_v3(scene);
    v3_reports reports;
    b2s_scene* reloaded = captured_and_reloaded_from(&world, scene, &reports);
    ENSURE(reloaded != NULL);
    print_reports(&reports);
    ENSURE_EQ(reports.count, 0);
    const b2s_scene_view* level = b2s_scene_get_view(scene);
    const b2s_scene_view* saved = b2s_scene_get_view(reloaded);
    ENSURE_EQ(saved->joint_count, level->joint_count);
    for (uint32_t j = 0; j < level->joint_count; ++j) {
        ENSURE_STR(saved->joints[j].name, level->joints[j].name);
        ENSURE_EQ(saved->joints[j].kind, level->joints[j].kind);
    }
    ENSURE_EQ(b2s_scene_find_joint(reloaded, "CarRearSuspension"), 21);
    uint32_t gear = b2s_scene_find_joint(reloaded, "GearMesh");
    ENSURE(gear != B2S_NONE);
    ENSURE_EQ(saved->joints[gear].joint_a, level->joints[gear].joint_a);
    ENSURE_EQ(saved->joints[gear].joint_b, level->joints[gear].joint_b);
    V3_ADAPTER(reports_free)(&reports);
    b2s_scene_free(reloaded);
    free_v3(&world);
    b2s_scene_free(scene);
    return 0;
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(every_scene_file_round_trips_bit_for_bit);
    failed += RUN_TEST(every_scene_file_round_trips_bit_for_bit_given_the_scene);
#if V3_MINOR >= 2
    failed += RUN_TEST(v32_forms_round_trip);
#endif
    failed += RUN_TEST(what_the_format_cannot_hold_is_reported);
    failed += RUN_TEST(capture_refuses_bodies_it_cannot_name);
    failed += RUN_TEST(capture_names_the_first_body_it_refuses);
    failed += RUN_TEST(mass_data_and_rotation_survive_capture);
    failed += RUN_TEST(turned_bodies_are_reported_once_a_capture);
    failed += RUN_TEST(built_level_keeps_its_names_and_user_data);
    failed += RUN_TEST(capture_built_refuses_a_result_of_another_scene);
    failed += RUN_TEST(showcase_save_keeps_every_joint_at_its_index);
    return failed;
}
