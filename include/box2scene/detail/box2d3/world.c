/*
 * The world: its def, where a build places the scene, and one build from start to end (the
 * shapes, the bodies with their fixtures and mass, then the joints).
 */

/* ---- gravity and the world def */

static bool b2s3_gravity_fits(b2s_vec2 gravity) {
    return fabsf(gravity.x) <= b2s3_range()->max_acceleration &&
           fabsf(gravity.y) <= b2s3_range()->max_acceleration;
}

b2Vec2 B2S3_API(scene_gravity)(const b2s_scene* scene, b2Vec2 fallback) {
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    if (view == NULL || !view->gravity_given || !b2s3_gravity_fits(view->gravity)) {
        return fallback;
    }
    return b2s3_to_b2(view->gravity);
}

b2WorldDef B2S3_API(world_def)(const b2s_scene* scene, b2Vec2 fallback_gravity) {
    b2WorldDef def = b2DefaultWorldDef();
    def.gravity = B2S3_API(scene_gravity)(scene, fallback_gravity);
    def.maximumLinearSpeed = b2s3_range()->world_max_linear_speed;
    return def;
}

/* ---- one build */

/* A shape of the scene as v3 geometry, made once and used by every fixture naming it. */
typedef enum b2s3_geometry_kind {
    B2S3_NONE,    /* not created (reported) */
    B2S3_CIRCLE,
    B2S3_POLYGON,
    B2S3_SEGMENT,
    B2S3_CHAIN,   /* points[0 .. point_count): [ghost, vertices..., ghost], or a loop */
} b2s3_geometry_kind;

typedef struct b2s3_geometry {
    b2s3_geometry_kind kind;
    b2Circle circle;
    b2Polygon polygon;
    b2Segment segment;
    b2Vec2* points;
    int point_count;
    bool is_loop;
} b2s3_geometry;

typedef struct b2s3_builder {
    const struct b2s_scene_view* view;
    b2WorldId world;
    b2Transform placement;
    b2s3_built_t* built;
    b2s3_list list;
    b2s3_geometry* geometries; /* indexed like the scene's shapes */
    b2MassData* masses;        /* each created dynamic body's, inertia about its centre */
    uint32_t chain_capacity;   /* of the version's store of chain shapes, where it grows */
    uint32_t* pulled;          /* per body: 1 + the joint that starts it violated, or 0 */
} b2s3_builder;

static void b2s3_beyond(b2s3_builder* b, const b2s3_check* check, const char* object,
                        uint32_t index, const char* name, const char* owner) {
    B2S3_REPORT(b, B2S_CODE_BEYOND_BOX2D_RANGE, object, index, name, "%s%s; %s not created",
                owner, check->problem, object);
}

static void b2s3_check_gravity(b2s3_builder* b) {
    if (b->view->gravity_given && !b2s3_gravity_fits(b->view->gravity)) {
        B2S3_REPORT(b, B2S_CODE_BEYOND_BOX2D_RANGE, "world", 0, NULL,
                    "Gravity (%.9g, %.9g) lies beyond " B2S3_ENGINE "'s working range (each "
                    "component within +-%g m/s^2); the world def gives the host's fallback "
                    "instead",
                    (double)b->view->gravity.x, (double)b->view->gravity.y,
                    (double)b2s3_range()->max_acceleration);
    }
}

/* A placement v3 can take: finite, its rotation normalised as b2CreateBody asserts. */
static bool b2s3_placement_valid(b2Transform t) {
    float qq = t.q.c * t.q.c + t.q.s * t.q.s;
    return isfinite(t.p.x) && isfinite(t.p.y) && isfinite(t.q.c) && isfinite(t.q.s) &&
           fabsf(qq - 1.0f) < 1e-4f && fabsf(t.p.x) <= b2s3_range()->max_length &&
           fabsf(t.p.y) <= b2s3_range()->max_length;
}

static void b2s3_make_shape(b2s3_builder* b, uint32_t index);
static void b2s3_make_body(b2s3_builder* b, uint32_t index);
static void b2s3_make_joint(b2s3_builder* b, uint32_t index);

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

b2s3_built_t* B2S3_API(build_world_at)(const b2s_scene* scene, b2WorldId world,
                                       b2Transform placement) {
    b2s3_built_t* built = (b2s3_built_t*)calloc(1, sizeof(b2s3_built_t));
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    if (built == NULL || view == NULL) {
        return built;
    }
    b2s3_builder b;
    memset(&b, 0, sizeof b);
    b.view = view;
    b.world = world;
    b.placement = placement;
    b.built = built;
    b.list.reports = &built->reports;
    b.geometries = (b2s3_geometry*)calloc(view->shape_count + 1, sizeof(b2s3_geometry));
    b.masses = (b2MassData*)calloc(view->body_count + 1, sizeof(b2MassData));
    b.pulled = (uint32_t*)calloc(view->body_count + 1, sizeof(uint32_t));
    bool ok = b2s3_allocate(built, view) && b.geometries != NULL && b.masses != NULL &&
              b.pulled != NULL;
    if (ok && !b2s3_placement_valid(placement)) {
        B2S3_REPORT(&b, B2S_CODE_INVALID_ARGUMENT, "world", 0, NULL,
                    "the placement (%.9g, %.9g) turned by (%.9g, %.9g) is not finite, not "
                    "within +-%g m or not a normalised rotation; nothing was built",
                    (double)placement.p.x, (double)placement.p.y, (double)placement.q.c,
                    (double)placement.q.s, (double)b2s3_range()->max_length);
    } else if (ok) {
        b2s3_check_gravity(&b);
        for (uint32_t i = 0; i < view->shape_count && !b.list.out_of_memory; ++i) {
            b2s3_make_shape(&b, i);
        }
        for (uint32_t i = 0; i < view->body_count && !b.list.out_of_memory; ++i) {
            b2s3_make_body(&b, i);
        }
        /* Joints come after every body has its final mass: their checks depend on it. */
        for (uint32_t i = 0; i < view->joint_count && !b.list.out_of_memory; ++i) {
            b2s3_make_joint(&b, i);
        }
    }
    if (b.geometries != NULL) {
        for (uint32_t i = 0; i < view->shape_count; ++i) {
            free(b.geometries[i].points);
        }
    }
    free(b.geometries);
    free(b.masses);
    free(b.pulled);
    if (!ok || b.list.out_of_memory) {
        B2S3_API(built_free)(built);
        return NULL;
    }
    return built;
}

b2s3_built_t* B2S3_API(build_world)(const b2s_scene* scene, b2WorldId world) {
    return B2S3_API(build_world_at)(scene, world, b2Transform_identity);
}
