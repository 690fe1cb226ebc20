/*
 * Every scene file of the project and the editor's corpus, built into real Box2D v3 (its
 * assertions on): each body, shape and joint v3 can represent is created, the rest is
 * reported, the world stays finite over 600 steps; and every body's mass, centre and
 * inertia equal what a body built by hand with v3's own API gets (for a MassData override:
 * the file's values moved to v3's convention, inertia about the centre of mass). Compiled
 * once per v3 adapter (V3_SUPPORT names its support header) as box2d3_scenes_test and
 * box2d32_scenes_test.
 */
#include V3_SUPPORT

static bool created_shape(const v3_built* built, uint32_t slot) {
    return !B2_IS_NULL(built->shapes[slot]) || v3_chain_segments(built, slot, NULL, 0) > 0;
}

/* Whether a report names `object` `index`, with one of the codes that mean "not created". */
static bool reported_missing(const v3_reports* reports, const char* object, uint32_t index) {
    static const b2s_code not_created[] = {
        B2S_CODE_SKIPPED_JOINT,      B2S_CODE_SKIPPED_DEPENDENT,  B2S_CODE_BEYOND_BOX2D_RANGE,
        B2S_CODE_JOINT_SELF_REFERENCE, B2S_CODE_DEGENERATE_POLYGON, B2S_CODE_DEGENERATE_EDGE,
        B2S_CODE_DEGENERATE_CHAIN};
    for (size_t i = 0; i < sizeof not_created / sizeof not_created[0]; ++i) {
        if (count_reports(reports, not_created[i], object, index) > 0) {
            return true;
        }
    }
    return false;
}

/* Steps of a project scene file, and of a generated level (whose thousands of bodies joined
 * at random make their crashes within the first steps, and take a second a hundred steps). */
#define SCENE_STEPS 600
#define LEVEL_STEPS 120

/* `context`: NULL for SCENE_STEPS, or the steps. */
static int build_and_step(const char* path, const b2s_scene* scene, void* context) {
    int steps = context != NULL ? *(const int*)context : SCENE_STEPS;
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    v3_world world = build_v3(scene);
    ENSURE(world.built != NULL);
    const v3_built* built = world.built;
    ENSURE_EQ(built->body_count, view->body_count);
    ENSURE_EQ(built->fixture_count, view->fixture_id_count);
    ENSURE_EQ(built->joint_count, view->joint_count);
    /* Nothing is missing without a report. */
    for (uint32_t i = 0; i < view->body_count; ++i) {
        if (B2_IS_NULL(built->bodies[i]) && !reported_missing(&built->reports, "body", i)) {
            fprintf(stderr, "%s: body %u missing without a report\n", path, (unsigned)i);
            return 1;
        }
        const b2s_body* body = &view->bodies[i];
        for (uint32_t k = 0; k < body->fixtures.count; ++k) {
            uint32_t slot = body->fixtures.first + k;
            uint32_t fixture = view->fixture_ids[slot];
            if (!created_shape(built, slot) &&
                !reported_missing(&built->reports, "fixture", fixture)) {
                fprintf(stderr, "%s: fixture %u of body %u missing without a report\n", path,
                        (unsigned)fixture, (unsigned)i);
                return 1;
            }
        }
    }
    for (uint32_t i = 0; i < view->joint_count; ++i) {
        if (B2_IS_NULL(built->joints[i]) && !reported_missing(&built->reports, "joint", i)) {
            fprintf(stderr, "%s: joint %u missing without a report\n", path, (unsigned)i);
            print_reports(&built->reports);
            return 1;
        }
    }
    step_v3(&world, steps);
    ENSURE(bodies_finite(&world));
    free_v3(&world);
    return 0;
}

/* ---- mass: the adapter's body against one built by hand with v3's plain API */

static bool same_mass(b2MassData a, b2MassData b) {
    return memcmp(&a.mass, &b.mass, sizeof(float)) == 0 &&
           memcmp(&a.center, &b.center, sizeof(b2Vec2)) == 0 &&
           memcmp(&a.rotationalInertia, &b.rotationalInertia, sizeof(float)) == 0;
}

/* Adds fixture `index`'s shape to `body` the plain way (v3 updates the mass each time). */
static void add_by_hand(const struct b2s_scene_view* view, uint32_t index, b2BodyId body) {
    const b2s_fixture* fixture = &view->fixtures[index];
    const b2s_shape* shape = &view->shapes[fixture->shape];
    b2ShapeDef def = b2DefaultShapeDef();
    def.density = fixture->density;
    const b2s_vec2* v = view->vertices + shape->vertices.first;
    if (shape->kind == B2S_SHAPE_KIND_CIRCLE) {
        b2Circle circle = {{shape->position.x, shape->position.y}, shape->radius};
        b2CreateCircleShape(body, &def, &circle);
    } else if (shape->kind == B2S_SHAPE_KIND_POLYGON && shape->vertices.count > 2) {
        b2Vec2 points[B2_MAX_POLYGON_VERTICES];
        for (uint32_t i = 0; i < shape->vertices.count; ++i) {
            points[i] = (b2Vec2){v[i].x, v[i].y};
        }
        b2Hull hull = b2ComputeHull(points, (int)shape->vertices.count);
        b2Polygon polygon = b2MakePolygon(&hull, 0.0f);
        b2CreatePolygonShape(body, &def, &polygon);
    }
    /* segments and chains have no mass */
}

static float one_kg_for_none(float mass) {
    return mass > 0.0f ? mass : 1.0f;
}

/* What the format asks of a dynamic body's mass, in v3's convention, as Box2D 2.x's
 * SetMassData makes it: the shapes' mass, with MassData written over it (inertia about the
 * origin in the file, about the centre in v3; none when it is not positive), a mass of 0
 * counted as 1 kg, and no inertia under a fixed rotation. */
static b2MassData expected_mass(b2MassData shapes, const b2s_body* body) {
    b2MassData m = shapes;
    m.mass = one_kg_for_none(shapes.mass);
    const b2s_mass_data* given = &body->mass_data;
    if (given->mass_given || given->center_given || given->inertia_given) {
        float origin = shapes.rotationalInertia +
                       shapes.mass * b2Dot(shapes.center, shapes.center);
        if (given->mass_given) {
            m.mass = one_kg_for_none(given->mass);
        }
        if (given->center_given) {
            m.center = (b2Vec2){given->center.x, given->center.y};
        }
        if (given->inertia_given) {
            origin = given->inertia;
        }
        m.rotationalInertia = origin > 0.0f ? origin - m.mass * b2Dot(m.center, m.center) : 0.0f;
    }
    if (body->fixed_rotation) {
        m.rotationalInertia = 0.0f;
    }
    return m;
}

/* How many dynamic bodies were compared, and how many of them have a MassData mass. */
typedef struct mass_tally {
    int compared, overridden;
} mass_tally;

static int masses_match_hand_built_bodies(const char* path, const b2s_scene* scene,
                                          void* context) {
    mass_tally* tally = (mass_tally*)context;
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    v3_world world = build_v3(scene);
    b2WorldDef def = b2DefaultWorldDef();
    b2WorldId by_hand = b2CreateWorld(&def);
    for (uint32_t i = 0; i < view->body_count; ++i) {
        const b2s_body* body = &view->bodies[i];
        b2BodyId built = world.built->bodies[i];
        if (B2_IS_NULL(built) || body->kind != B2S_BODY_KIND_DYNAMIC) {
            continue;
        }
        b2BodyDef body_def = b2DefaultBodyDef();
        body_def.type = b2_dynamicBody;
        v3_lock_rotation(&body_def, body->fixed_rotation);
        b2BodyId hand = b2CreateBody(by_hand, &body_def);
        for (uint32_t k = 0; k < body->fixtures.count; ++k) {
            uint32_t slot = body->fixtures.first + k;
            if (created_shape(world.built, slot)) {
                add_by_hand(view, view->fixture_ids[slot], hand);
            }
        }
        b2MassData expected = expected_mass(b2Body_GetMassData(hand), body);
        b2MassData actual = b2Body_GetMassData(built);
        if (!same_mass(actual, expected)) {
            fprintf(stderr,
                    "%s: body %u: mass %.9g centre (%.9g, %.9g) inertia %.9g, expected %.9g "
                    "(%.9g, %.9g) %.9g\n",
                    path, (unsigned)i, (double)actual.mass, (double)actual.center.x,
                    (double)actual.center.y, (double)actual.rotationalInertia,
                    (double)expected.mass, (double)expected.center.x, (double)expected.center.y,
                    (double)expected.rotationalInertia);
            return 1;
        }
        tally->compared += 1;
        tally->overridden += body->mass_data.mass_given;
    }
    b2DestroyWorld(by_hand);
    free_v3(&world);
    return 0;
}

static int every_scene_file_builds_and_stays_finite(void) {
    int loaded = 0;
    int failed = for_each_scene(build_and_step, NULL, &loaded);
    ENSURE(loaded >= 10);
    return failed;
}

static int every_body_has_the_mass_v3_gives_its_shapes(void) {
    mass_tally tally = {0, 0};
    int loaded = 0;
    int failed = for_each_scene(masses_match_hand_built_bodies, &tally, &loaded);
    ENSURE(tally.compared >= 50);
    ENSURE(tally.overridden >= 2);
    return failed;
}

/* The showcase uses every kind the format has: v3 skips exactly its pulley, its gear and
 * what depends on nothing else. */
static int the_showcase_reports_what_v3_lacks(void) {
    char path[1024];
    snprintf(path, sizeof path, "%s/examples/scenes/showcase.xml", BOX2SCENE_SOURCE_DIR);
    b2s_scene* scene = load_path(path);
    ENSURE(scene != NULL);
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    v3_world world = build_v3(scene);
    uint32_t pulleys = 0, gears = 0;
    for (uint32_t i = 0; i < view->joint_count; ++i) {
        uint32_t kind = view->joints[i].kind;
        if (kind == B2S_JOINT_KIND_PULLEY || kind == B2S_JOINT_KIND_GEAR) {
            pulleys += kind == B2S_JOINT_KIND_PULLEY;
            gears += kind == B2S_JOINT_KIND_GEAR;
            ENSURE(B2_IS_NULL(world.built->joints[i]));
            ENSURE_EQ(count_reports(&world.built->reports, B2S_CODE_SKIPPED_JOINT, "joint", i), 1);
        } else {
            ENSURE(!B2_IS_NULL(world.built->joints[i]));
        }
    }
    ENSURE(pulleys >= 1 && gears >= 1);
    ENSURE_EQ(count_reports(&world.built->reports, B2S_CODE_SKIPPED_JOINT, NULL, 0),
              pulleys + gears);
    free_v3(&world);
    b2s_scene_free(scene);
    return 0;
}

/* Each scene file named on the command line (a generated level), built and stepped. */
static int files_build_and_stay_finite(int count, char** paths) {
    int failed = 0;
    int steps = LEVEL_STEPS;
    for (int i = 0; i < count; ++i) {
        b2s_scene* scene = load_path(paths[i]);
        ENSURE(scene != NULL);
        failed += build_and_step(paths[i], scene, &steps);
        b2s_scene_free(scene);
    }
    return failed;
}

int main(int argc, char** argv) {
    if (argc > 1) {
        return files_build_and_stay_finite(argc - 1, argv + 1);
    }
    int failed = 0;
    failed += RUN_TEST(every_scene_file_builds_and_stays_finite);
    failed += RUN_TEST(every_body_has_the_mass_v3_gives_its_shapes);
    failed += RUN_TEST(the_showcase_reports_what_v3_lacks);
    return failed;
}
