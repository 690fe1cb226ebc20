/*
 * The world: its def, and one build from start to end. The library plans the build
 * (b2s_plan_make: every body, shape and joint as this version's defs take them, placed and
 * checked, and the reports); the build copies the reports and creates what the plan says,
 * in its order: each body with its shapes and mass, then the joints.
 */

/* ---- the world def */

b2Vec2 B2S3_API(scene_gravity)(const b2s_scene* scene, b2Vec2 fallback) {
    b2s_vec2 gravity = b2s_plan_world_gravity(scene, B2S3_ENGINE_VERSION, b2s3_to_b2s(fallback));
    return b2s3_to_b2(gravity);
}

b2WorldDef B2S3_API(world_def)(const b2s_scene* scene, b2Vec2 fallback_gravity) {
    b2WorldDef def = b2DefaultWorldDef();
    def.gravity = B2S3_API(scene_gravity)(scene, fallback_gravity);
    def.maximumLinearSpeed = b2s3_range()->world_max_linear_speed;
    return def;
}

/* ---- one build */

typedef struct b2s3_builder {
    const b2s_plan_view* plan;
    b2WorldId world;
    b2s3_built_t* built;
    b2s3_list list;
    uint32_t chain_capacity; /* of the version's store of chain shapes, where it grows */
    b2Vec2* points;          /* room for the longest chain's points */
    uint32_t point_capacity;
} b2s3_builder;

static void b2s3_make_body(b2s3_builder* b, const b2s_plan_body* body);
static void b2s3_make_joint(b2s3_builder* b, const b2s_plan_joint* joint);

/* Every array of the result, zeroed (null ids), or false when memory runs out. */
static bool b2s3_allocate(b2s3_built_t* built, const struct b2s_scene_view* view) {
    built->body_count = view->body_count;
    built->fixture_count = view->fixture_id_count;
    built->joint_count = view->joint_count;
    built->bodies = (b2BodyId*)calloc(view->body_count + 1, sizeof(b2BodyId));
    built->shapes = (b2ShapeId*)calloc(view->fixture_id_count + 1, sizeof(b2ShapeId));
    built->joints = (b2JointId*)calloc(view->joint_count + 1, sizeof(b2JointId));
    return built->bodies != NULL && built->shapes != NULL && built->joints != NULL &&
           b2s3_allocate_chains(built, view->fixture_id_count);
}

void B2S3_API(built_free)(b2s3_built_t* built) {
    if (built == NULL) {
        return;
    }
    free(built->bodies);
    free(built->shapes);
    b2s3_free_chains(built);
    free(built->joints);
    B2S3_API(reports_free)(&built->reports);
    free(built);
}

/* The plan of the scene for this version, built into `world` at `placement`; NULL when
 * the library cannot make it (out of memory). */
static b2s_plan* b2s3_plan(const b2s_scene* scene, b2WorldId world, b2Transform placement) {
    b2s_plan_options options;
    memset(&options, 0, sizeof options);
    options.engine = B2S3_ENGINE_VERSION;
    options.placement.p = b2s3_to_b2s(placement.p);
    options.placement.q.c = placement.q.c;
    options.placement.q.s = placement.q.s;
    options.gravity = b2s3_to_b2s(b2World_GetGravity(world));
    options.max_linear_speed = b2World_GetMaximumLinearSpeed(world);
    options.name_bytes = B2S3_NAME_BYTES;
    b2s_plan* plan = NULL;
    b2s_plan_make(scene, &options, &plan, NULL);
    return plan;
}

/* Carries out the plan: its reports, then its bodies and joints (joints last: they need
 * every body). */
static void b2s3_carry_out(b2s3_builder* b) {
    const b2s_plan_view* plan = b->plan;
    for (uint32_t i = 0; i < plan->report_count && !b->list.out_of_memory; ++i) {
        const b2s_plan_report* r = &plan->reports[i];
        b2s3_add_report(&b->list, (b2s_code)r->code, r->object, r->index, r->name, r->message);
    }
    for (uint32_t i = 0; i < plan->body_count && !b->list.out_of_memory; ++i) {
        b2s3_make_body(b, &plan->bodies[i]);
    }
    for (uint32_t i = 0; i < plan->joint_count && !b->list.out_of_memory; ++i) {
        b2s3_make_joint(b, &plan->joints[i]);
    }
}

b2s3_built_t* B2S3_API(build_world_at)(const b2s_scene* scene, b2WorldId world,
                                       b2Transform placement) {
    b2s3_built_t* built = (b2s3_built_t*)calloc(1, sizeof(b2s3_built_t));
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    if (built == NULL || view == NULL) {
        return built;
    }
    b2s_plan* plan = b2s3_plan(scene, world, placement);
    b2s3_builder b;
    memset(&b, 0, sizeof b);
    b.plan = b2s_plan_get_view(plan);
    b.world = world;
    b.built = built;
    b.list.reports = &built->reports;
    bool ok = plan != NULL && b2s3_allocate(built, view);
    if (ok) {
        b2s3_carry_out(&b);
    }
    free(b.points);
    b2s_plan_free(plan);
    if (!ok || b.list.out_of_memory) {
        B2S3_API(built_free)(built);
        return NULL;
    }
    return built;
}

b2s3_built_t* B2S3_API(build_world)(const b2s_scene* scene, b2WorldId world) {
    return B2S3_API(build_world_at)(scene, world, b2Transform_identity);
}
