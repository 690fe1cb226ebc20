/*
 * Capture: bodies of a live world that the host names, with their shapes and the joints
 * between them, back into a scene that builds into a world evolving bit for bit like it.
 * Derived values are inverted exactly: the float whose forward computation in the build
 * gives the bits the world holds. What the version holds differently (a body's centre, a
 * chain, a joint's frames, the motor joint) it reads back through its hooks (v31.h, v32.h).
 */

/* A body the host named and the index it gave it. */
typedef struct b2s3_named {
    b2BodyId id;
    uint32_t index;
} b2s3_named;

/* A joint the build made and the scene joint it came from. */
typedef struct b2s3_level_joint {
    b2JointId id;
    uint32_t record;
} b2s3_level_joint;

/* What a capture of a built world labels its objects from: the scene, what the build made
 * of it, the scene body of each captured body, and the built joints sorted by id (a joint's
 * record is then a binary search, as a body's index is). */
typedef struct b2s3_level {
    const b2s3_built_t* built;
    const b2s_scene_view* view;
    const uint32_t* body_records;
    b2s3_level_joint* joints;
    uint32_t joint_count;
    /* per scene body, its captured index; per scene joint, the index it was written at
     * (B2S_NONE until then); the next scene joint a capture may write as the file had it */
    uint32_t* captured_bodies;
    uint32_t* written_joints;
    uint32_t next_record;
} b2s3_level;

typedef struct b2s3_capture {
    b2WorldId world;
    const b2BodyId* bodies;
    uint32_t body_count;
    /* the named bodies sorted by id, so that finding a joint's bodies among them is a binary
     * search rather than a pass over all of them for every joint end */
    const b2s3_named* named;
    b2s_builder* builder;
    b2s3_list list;
    b2s_error* error;
    b2s_code failure; /* the first builder error, or B2S_CODE_OK */
    uint32_t shape_count, fixture_count, joint_count;
    /* bodies whose rotation no float angle gives exactly: how many, the first, and the
     * largest turn between a rotation and the angle written, said once a capture */
    uint32_t turned_count, first_turned;
    double largest_turn;
    b2s3_level* level;         /* NULL but for a capture of a built world */
    uint32_t level_body;       /* the scene body of the body being captured */
} b2s3_capture;

/* Ids of one kind in an order of their own (negative, zero or positive): zero for the same
 * object. */
#define B2S3_ID_ORDER(a, b)                                                                  \
    ((a).index1 != (b).index1     ? ((a).index1 < (b).index1 ? -1 : 1)                     \
     : (a).world0 != (b).world0   ? ((a).world0 < (b).world0 ? -1 : 1)                     \
                                  : ((a).generation > (b).generation) -                     \
                                        ((a).generation < (b).generation))

static int b2s3_body_order(b2BodyId a, b2BodyId b) {
    return B2S3_ID_ORDER(a, b);
}

static bool b2s3_same_body(b2BodyId a, b2BodyId b) {
    return b2s3_body_order(a, b) == 0;
}

static int b2s3_named_by_body(const void* a, const void* b) {
    return b2s3_body_order(((const b2s3_named*)a)->id, ((const b2s3_named*)b)->id);
}

/* By body, one body's entries by the host's index: the first two of a body named more than
 * once are the pair a pass in the host's order meets first. */
static int b2s3_named_order(const void* a, const void* b) {
    int order = b2s3_named_by_body(a, b);
    uint32_t x = ((const b2s3_named*)a)->index, y = ((const b2s3_named*)b)->index;
    return order != 0 ? order : (x > y) - (x < y);
}

/* The index the host gave `body`, or B2S_NONE. */
static uint32_t b2s3_captured_index(const b2s3_capture* c, b2BodyId body) {
    b2s3_named key = {body, 0};
    const b2s3_named* found = (const b2s3_named*)bsearch(&key, c->named, c->body_count,
                                                         sizeof(b2s3_named), b2s3_named_by_body);
    return found != NULL ? found->index : B2S_NONE;
}

static bool b2s3_builder_ok(b2s3_capture* c, b2s_code code) {
    if (code != B2S_CODE_OK && c->failure == B2S_CODE_OK) {
        c->failure = code;
    }
    return code == B2S_CODE_OK;
}

/* ---- exact inverses */

/* `x` moved by `steps` representable floats. */
static float b2s3_ulps_away(float x, int steps) {
    float toward = steps < 0 ? -FLT_MAX : FLT_MAX;
    for (int i = 0; i < abs(steps); ++i) {
        x = nextafterf(x, toward);
    }
    return x;
}

/* The float nearest `guess` (within 16 ulps) for which `gives` holds: an inverse computed in
 * floats is a few ulps off the value whose forward computation gives the bits wanted. False,
 * with `guess` in `*out`, when none does. */
static bool b2s3_search_ulps(float guess, bool (*gives)(float x, const float* wanted),
                             const float* wanted, float* out) {
    for (int k = 0; k <= 16; ++k) {
        for (int sign = -1; sign <= 1; sign += 2) {
            float x = b2s3_ulps_away(guess, sign * k);
            if (gives(x, wanted)) {
                *out = x;
                return true;
            }
        }
    }
    *out = guess;
    return false;
}

/* wanted: cosine and sine, as the build makes a rotation of an angle. */
static bool b2s3_rotation_of(float angle, const float* wanted) {
    return cosf(angle) == wanted[0] && sinf(angle) == wanted[1];
}

/* An angle whose cosf and sinf are the rotation's. */
static bool b2s3_angle_of(b2Rot q, float* angle) {
    float wanted[2] = {q.c, q.s};
    return b2s3_search_ulps(atan2f(q.s, q.c), b2s3_rotation_of, wanted, angle);
}

/* wanted: a result and what the build subtracts from x to get it. */
static bool b2s3_less_gives(float x, const float* wanted) {
    return x - wanted[1] == wanted[0];
}

/* wanted: a result and what the build adds to x to get it. */
static bool b2s3_plus_gives(float x, const float* wanted) {
    return x + wanted[1] == wanted[0];
}

/* The inertia about the body origin that the build turns back into `central`:
 * origin - mass * |center|^2 == central. */
static float b2s3_origin_inertia(float central, float mass, b2Vec2 center) {
    float wanted[2] = {central, mass * b2Dot(center, center)};
    float origin;
    b2s3_search_ulps(central + wanted[1], b2s3_less_gives, wanted, &origin);
    return origin;
}

/* One component of the velocity the build gives a body's origin, so that adding w x (the
 * centre of mass's offset), as v3 and the build do, gives `target`. */
static float b2s3_before_shift(float target, float shift) {
    float wanted[2] = {target, shift};
    float before;
    b2s3_search_ulps(target - shift, b2s3_plus_gives, wanted, &before);
    return before;
}

/* The linear velocity the file gives a dynamic body is its origin's; v3 reports its centre
 * of mass's, w x (R local_center) away. */
static b2s_vec2 b2s3_origin_velocity(b2Transform transform, b2Vec2 local_center, float w,
                                     b2s_vec2 velocity) {
    b2Vec2 center = b2TransformPoint(transform, local_center);
    b2Vec2 shift = b2CrossSV(w, b2Sub(center, transform.p));
    b2s_vec2 out = {b2s3_before_shift(velocity.x, shift.x), b2s3_before_shift(velocity.y, shift.y)};
    return out;
}

/* ---- the level's labels */

/* The scene's UserData `index` added to the capture, or B2S_NONE. */
static uint32_t b2s3_level_user_data(b2s3_capture* c, uint32_t index) {
    const b2s_scene_view* view = c->level->view;
    if (index == B2S_NONE || index >= view->user_data_count) {
        return B2S_NONE;
    }
    uint32_t added = B2S_NONE;
    return b2s3_builder_ok(c, b2s_builder_add_user_data(c->builder, &view->user_data[index],
                                                        &added, c->error))
               ? added
               : B2S_NONE;
}

/* The scene fixture the shape `from` of the body being captured was built for, or NULL. */
static const b2s_fixture* b2s3_level_fixture(const b2s3_capture* c, b2ShapeId from) {
    const b2s_scene_view* view = c->level->view;
    b2s_range slots = view->bodies[c->level_body].fixtures;
    for (uint32_t slot = slots.first; slot < slots.first + slots.count; ++slot) {
        if (b2s3_slot_holds(c->level->built, slot, from) &&
            view->fixture_ids[slot] < view->fixture_count) {
            return &view->fixtures[view->fixture_ids[slot]];
        }
    }
    return NULL;
}

static int b2s3_level_joint_order(const void* a, const void* b) {
    b2JointId x = ((const b2s3_level_joint*)a)->id, y = ((const b2s3_level_joint*)b)->id;
    return B2S3_ID_ORDER(x, y);
}

/* ---- fixtures */

/* The filter in the scene's own widths (its fields' sizes say them): a mask with every
 * higher bit set is "all". */
#define B2S3_FILTER_BITS (8u * (unsigned)sizeof(((b2s_filter*)0)->category_bits))
#define B2S3_GROUP_BITS (8u * (unsigned)sizeof(((b2s_filter*)0)->group_index))

static b2s_filter b2s3_filter_of(b2s3_capture* c, b2Filter f, uint32_t fixture) {
    b2s_filter out;
    uint64_t low = B2S3_FILTER_BITS >= 64u ? UINT64_MAX : (UINT64_C(1) << B2S3_FILTER_BITS) - 1u;
    int64_t group_max = (INT64_C(1) << (B2S3_GROUP_BITS - 1u)) - 1;
    int64_t group_min = -group_max - 1;
    uint64_t high_mask = f.maskBits & ~low;
    bool exact = (f.categoryBits & ~low) == 0 && (high_mask == 0 || high_mask == ~low) &&
                 f.groupIndex >= group_min && f.groupIndex <= group_max;
    int64_t group = f.groupIndex < group_min   ? group_min
                    : f.groupIndex > group_max ? group_max
                                               : f.groupIndex;
    out.category_bits = (f.categoryBits & low);
    out.mask_bits = (f.maskBits & low);
    out.group_index = group;
    if (!exact) {
        B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "fixture", fixture, NULL,
                    "its filter (category 0x%llx, mask 0x%llx, group %d) has bits above the "
                    "format's %u or a group beyond %u bits; the low %u bits were written",
                    (unsigned long long)f.categoryBits, (unsigned long long)f.maskBits,
                    f.groupIndex, B2S3_FILTER_BITS, B2S3_GROUP_BITS, B2S3_FILTER_BITS);
    }
    return out;
}

/* One shape and the fixture that carries it; the material and density from the v3 shape. */
static bool b2s3_add_fixture(b2s3_capture* c, const b2s_shape* shape, const b2s_vec2* vertices,
                             uint32_t count, b2ShapeId from, float density,
                             uint32_t* out_fixture) {
    const b2s_fixture* record = c->level != NULL ? b2s3_level_fixture(c, from) : NULL;
    b2s_shape named = *shape;
    if (record != NULL && record->shape < c->level->view->shape_count) {
        named.name = c->level->view->shapes[record->shape].name;
    }
    uint32_t shape_index = 0;
    if (!b2s3_builder_ok(c, b2s_builder_add_shape(c->builder, &named, vertices, count,
                                                  &shape_index, c->error))) {
        return false;
    }
    c->shape_count += 1;
    b2SurfaceMaterial material = b2Shape_GetSurfaceMaterial(from);
    b2s_fixture fixture;
    b2s_fixture_default(&fixture);
    fixture.shape = shape_index;
    fixture.density = density;
    fixture.friction = material.friction;
    fixture.restitution = material.restitution;
    fixture.is_sensor = b2Shape_IsSensor(from);
    fixture.filter = b2s3_filter_of(c, b2Shape_GetFilter(from), c->fixture_count);
    if (record != NULL) {
        fixture.name = record->name;
        fixture.user_data = b2s3_level_user_data(c, record->user_data);
    }
    if (!b2s3_builder_ok(c, b2s_builder_add_fixture(c->builder, &fixture, out_fixture,
                                                    c->error))) {
        return false;
    }
    c->fixture_count += 1;
    return true;
}

/* Whether chain segment `next` continues `cur` as the build makes consecutive edges. */
static bool b2s3_continues(b2ChainSegment cur, b2ChainSegment next) {
    return b2s3_same_point(next.ghost1, cur.segment.point1) &&
           b2s3_same_point(next.segment.point1, cur.segment.point2) &&
           b2s3_same_point(next.segment.point2, cur.ghost2);
}

/* The chain (or edge with ghost vertices) that `count` chain segments make, in their order:
 * a loop when the last continues into the first, else open with its ghosts; its material
 * and filter are those of `from`. */
static bool b2s3_capture_chain(b2s3_capture* c, const b2ShapeId* shapes, int count,
                               b2ShapeId from, uint32_t* out_fixture) {
    b2s_vec2* points = (b2s_vec2*)malloc(((size_t)count + 1) * sizeof(b2s_vec2));
    if (points == NULL) {
        c->list.out_of_memory = true;
        return false;
    }
    b2ChainSegment head = b2Shape_GetChainSegment(shapes[0]);
    b2ChainSegment tail = b2Shape_GetChainSegment(shapes[count - 1]);
    bool loop = count >= 3 && b2s3_continues(tail, head);
    b2s_shape shape;
    b2s_shape_default(count == 1 ? B2S3_LONE_SEGMENT_KIND : B2S_SHAPE_KIND_CHAIN, &shape);
    uint32_t n = 0;
    for (int i = 0; i < count; ++i) {
        points[n++] = b2s3_to_b2s(b2Shape_GetChainSegment(shapes[i]).segment.point1);
    }
    if (loop) {
        shape.is_loop = true;
    } else {
        points[n++] = b2s3_to_b2s(tail.segment.point2);
        shape.has_prev_vertex = true;
        shape.prev_vertex = b2s3_to_b2s(head.ghost1);
        shape.has_next_vertex = true;
        shape.next_vertex = b2s3_to_b2s(tail.ghost2);
    }
    bool made = b2s3_add_fixture(c, &shape, points, n, from, 0.0f, out_fixture);
    free(points);
    return made;
}

/* The format's shape for one v3 shape other than a chain segment, or false when it has
 * none (reported). */
static bool b2s3_capture_shape(b2s3_capture* c, b2ShapeId id, uint32_t* out_fixture) {
    b2s_shape shape;
    b2s_vec2 vertices[B2_MAX_POLYGON_VERTICES];
    uint32_t count = 0;
    switch (b2Shape_GetType(id)) {
    case b2_circleShape: {
        b2Circle circle = b2Shape_GetCircle(id);
        b2s_shape_default(B2S_SHAPE_KIND_CIRCLE, &shape);
        shape.radius = circle.radius;
        shape.position = b2s3_to_b2s(circle.center);
        break;
    }
    case b2_polygonShape: {
        b2Polygon polygon = b2Shape_GetPolygon(id);
        b2s_shape_default(B2S_SHAPE_KIND_POLYGON, &shape);
        for (int i = 0; i < polygon.count; ++i) {
            vertices[count++] = b2s3_to_b2s(polygon.vertices[i]);
        }
        if (polygon.radius > 0.0f) {
            B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "shape", c->shape_count, NULL,
                        "a rounded polygon (radius %.9g m): written without its rounding",
                        (double)polygon.radius);
        }
        break;
    }
    case b2_segmentShape: {
        b2Segment segment = b2Shape_GetSegment(id);
        b2s_shape_default(B2S_SHAPE_KIND_EDGE, &shape);
        vertices[count++] = b2s3_to_b2s(segment.point1);
        vertices[count++] = b2s3_to_b2s(segment.point2);
        break;
    }
    default:
        B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "shape", c->shape_count, NULL,
                    "a capsule has no Box2Scene form; not written");
        return false;
    }
    return b2s3_add_fixture(c, &shape, vertices, count, id, b2Shape_GetDensity(id), out_fixture);
}

static int b2s3_by_index(const void* a, const void* b) {
    int32_t x = ((const b2ShapeId*)a)->index1, y = ((const b2ShapeId*)b)->index1;
    return (x > y) - (x < y);
}

/* The fixtures of one body, in the order its shapes were created (a chain where its first
 * segment stands, its segments as the version groups them), with the mass their densities
 * give. */
static bool b2s3_capture_fixtures(b2s3_capture* c, b2BodyId body, uint32_t** fixtures,
                                  uint32_t* count, b2MassData* computed) {
    int capacity = b2Body_GetShapeCount(body);
    size_t room = (size_t)(capacity > 0 ? capacity : 1);
    b2ShapeId* shapes = (b2ShapeId*)malloc(room * sizeof(b2ShapeId));
    b2MassData* masses = (b2MassData*)malloc(room * sizeof(b2MassData));
    float* densities = (float*)malloc(room * sizeof(float));
    *fixtures = (uint32_t*)malloc(room * sizeof(uint32_t));
    *count = 0;
    bool ok = shapes != NULL && masses != NULL && densities != NULL && *fixtures != NULL;
    if (!ok) {
        c->list.out_of_memory = true;
    }
    int shape_count = ok ? b2Body_GetShapes(body, shapes, capacity) : 0;
    qsort(shapes, (size_t)shape_count, sizeof(b2ShapeId), b2s3_by_index);
    b2s3_chains chains;
    if (!b2s3_chains_of(&chains, shapes, shape_count)) {
        c->list.out_of_memory = true;
        ok = false;
    }
    size_t massive = 0;
    for (int i = 0; i < shape_count && ok; ++i) {
        b2ShapeId id = shapes[i];
        uint32_t fixture = 0;
        bool made;
        if (b2Shape_GetType(id) == b2_chainSegmentShape) {
            const b2ShapeId* segments = NULL;
            int run = b2s3_chain_at(&chains, shapes, i, shape_count, &segments);
            if (run == 0) {
                continue; /* its chain's fixture is made */
            }
            made = b2s3_capture_chain(c, segments, run, id, &fixture);
        } else {
            made = b2s3_capture_shape(c, id, &fixture);
            if (made) {
                densities[massive] = b2Shape_GetDensity(id);
                masses[massive] = b2s3_shape_mass(id);
                massive += 1;
            }
        }
        if (!made) {
            ok = c->failure == B2S_CODE_OK && !c->list.out_of_memory;
            continue;
        }
        (*fixtures)[(*count)++] = fixture;
    }
    bool kept = true;
    *computed = b2s3_mass_from_shapes(masses, densities, massive, b2s3_rotation_locked(body),
                                      &kept);
    computed->mass = b2s3_positive(computed->mass);
    b2s3_chains_free(&chains);
    free(shapes);
    free(masses);
    free(densities);
    return ok;
}

/* Notes that body `index`'s rotation `q` was written as `angle`, the nearest: the solver
 * turns nearly every body it moves to such a rotation, so one report a capture says it. */
static void b2s3_note_turned(b2s3_capture* c, uint32_t index, b2Rot q, float angle) {
    double turn = fabs(atan2((double)q.s * cos((double)angle) - (double)q.c * sin((double)angle),
                             (double)q.c * cos((double)angle) + (double)q.s * sin((double)angle)));
    if (c->turned_count == 0) {
        c->first_turned = index;
    }
    c->turned_count += 1;
    c->largest_turn = turn > c->largest_turn ? turn : c->largest_turn;
}

static void b2s3_report_turned(b2s3_capture* c) {
    if (c->turned_count == 0) {
        return;
    }
    B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "world", 0, NULL,
                "rotations no angle gives exactly, as the solver turns bodies: %u of the "
                "bodies (the first body %u) were written at the nearest angle, at most %.3g "
                "rad from the rotation",
                (unsigned)c->turned_count, (unsigned)c->first_turned, c->largest_turn);
}

static bool b2s3_same_mass(b2MassData a, b2MassData b) {
    return a.mass == b.mass && a.center.x == b.center.x && a.center.y == b.center.y &&
           a.rotationalInertia == b.rotationalInertia;
}

static bool b2s3_capture_body(b2s3_capture* c, uint32_t index) {
    b2BodyId id = c->bodies[index];
    if (c->level != NULL) {
        c->level_body = c->level->body_records[index];
    }
    uint32_t* fixtures = NULL;
    uint32_t fixture_count = 0;
    b2MassData computed;
    if (!b2s3_capture_fixtures(c, id, &fixtures, &fixture_count, &computed)) {
        free(fixtures);
        return false;
    }
    b2BodyType type = b2Body_GetType(id);
    b2s_body body;
    b2s_body_default((uint32_t)type, &body);
    body.position = b2s3_to_b2s(b2s3_body_position(id));
    if (!b2s3_angle_of(b2Body_GetRotation(id), &body.angle)) {
        b2s3_note_turned(c, index, b2Body_GetRotation(id), body.angle);
    }
    body.linear_velocity = b2s3_to_b2s(b2Body_GetLinearVelocity(id));
    if (type == b2_dynamicBody) {
        body.linear_velocity = b2s3_origin_velocity(b2Body_GetTransform(id),
                                                    b2s3_local_center(id),
                                                    b2Body_GetAngularVelocity(id),
                                                    body.linear_velocity);
    }
    body.angular_velocity = b2Body_GetAngularVelocity(id);
    body.linear_damping = b2Body_GetLinearDamping(id);
    body.angular_damping = b2Body_GetAngularDamping(id);
    body.gravity_scale = b2Body_GetGravityScale(id);
    body.allow_sleep = b2Body_IsSleepEnabled(id);
    body.awake = b2Body_IsAwake(id);
    body.bullet = b2Body_IsBullet(id);
    body.fixed_rotation = b2s3_rotation_locked(id);
    body.active = b2Body_IsEnabled(id);
    const char* name = b2Body_GetName(id);
    body.name = name != NULL && name[0] != '\0' ? name : NULL;
    if (c->level != NULL) { /* the level's Name, whole: v3 keeps only its first bytes */
        const b2s_body* record = &c->level->view->bodies[c->level_body];
        body.name = record->name;
        body.user_data = b2s3_level_user_data(c, record->user_data);
    }
    if (type == b2_dynamicBody) {
        b2MassData actual = b2Body_GetMassData(id);
        if (!b2s3_same_mass(actual, computed)) {
            body.mass_data.mass_given = true;
            body.mass_data.mass = actual.mass;
            body.mass_data.center_given = true;
            body.mass_data.center = b2s3_to_b2s(actual.center);
            body.mass_data.inertia_given = true;
            body.mass_data.inertia =
                b2s3_origin_inertia(actual.rotationalInertia, actual.mass, actual.center);
        }
    }
    uint32_t added = 0;
    bool ok = b2s3_builder_ok(c, b2s_builder_add_body(c->builder, &body, fixtures, fixture_count,
                                                      &added, c->error));
    free(fixtures);
    return ok;
}

/* ---- joints */

static int b2s3_joint_by_index(const void* a, const void* b) {
    int32_t x = ((const b2JointId*)a)->index1, y = ((const b2JointId*)b)->index1;
    return (x > y) - (x < y);
}

static void b2s3_capture_lossy(b2s3_capture* c, const char* what) {
    B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "joint", c->joint_count, NULL,
                "%s has no Box2Scene form; written without it", what);
}

/* A motor joint as the Friction or Motor joint the build makes of it (the version's
 * b2s3_motor_of); one of another form is read as the nearest Motor and reported. */
static void b2s3_motor_joint_of(b2s3_capture* c, b2JointId id, b2s_joint* joint,
                                uint32_t* kind) {
    const char* loss = b2s3_motor_of(id, joint);
    *kind = joint->kind;
    if (loss != NULL) {
        B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "joint", c->joint_count, NULL, "%s", loss);
    }
}

/* Reports that a joint of `what` kind has no Box2Scene form; false. */
static bool b2s3_unwritten_joint(b2s3_capture* c, const char* what) {
    B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "joint", c->joint_count, NULL,
                "%s has no Box2Scene form; not written", what);
    return false;
}

/* The joint kind the build makes a v3 joint of, or false when it has no Box2Scene form
 * (reported). A motor joint is read whole here. Kinds are compared by name: their numbers
 * moved between the 3.2 sources. */
static bool b2s3_joint_kind(b2s3_capture* c, b2JointId id, b2s_joint* joint, uint32_t* kind) {
    switch (b2Joint_GetType(id)) {
    case b2_revoluteJoint: *kind = B2S_JOINT_KIND_REVOLUTE; break;
    case b2_prismaticJoint: *kind = B2S_JOINT_KIND_PRISMATIC; break;
    case b2_weldJoint: *kind = B2S_JOINT_KIND_WELD; break;
    case b2_distanceJoint:
        *kind = b2DistanceJoint_IsSpringEnabled(id) && b2DistanceJoint_GetSpringHertz(id) == 0.0f
                    ? B2S_JOINT_KIND_ROPE
                    : B2S_JOINT_KIND_DISTANCE;
        break;
    case b2_wheelJoint:
        *kind = b2WheelJoint_IsSpringEnabled(id) ? B2S_JOINT_KIND_WHEEL : B2S_JOINT_KIND_LINE;
        break;
    case b2_motorJoint: b2s3_motor_joint_of(c, id, joint, kind); return true;
    case b2_filterJoint: return b2s3_unwritten_joint(c, "a filter joint");
#if B2S3_HAS_MOUSE_JOINT
    case b2_mouseJoint: return b2s3_unwritten_joint(c, "a mouse joint");
#endif
    default: return b2s3_unwritten_joint(c, "a joint of a kind this adapter does not know");
    }
    b2s_joint_default(*kind, joint);
    return true;
}

/* The format's joint for one v3 joint, or false when it has none (reported). */
static bool b2s3_joint_of(b2s3_capture* c, b2JointId id, b2s_joint* joint) {
    uint32_t kind = 0;
    if (!b2s3_joint_kind(c, id, joint, &kind)) {
        return false;
    }
    if (kind == B2S_JOINT_KIND_FRICTION || kind == B2S_JOINT_KIND_MOTOR) {
        return true;
    }
    char losses[2][B2S3_LOSS_SIZE];
    int lost = b2s3_frames_of(id, joint, losses);
    for (int i = 0; i < lost; ++i) {
        B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "joint", c->joint_count, NULL, "%s", losses[i]);
    }
    switch (kind) {
    case B2S_JOINT_KIND_REVOLUTE:
        joint->enable_limit = b2RevoluteJoint_IsLimitEnabled(id);
        joint->lower_limit = b2RevoluteJoint_GetLowerLimit(id);
        joint->upper_limit = b2RevoluteJoint_GetUpperLimit(id);
        joint->enable_motor = b2RevoluteJoint_IsMotorEnabled(id);
        joint->motor_speed = b2RevoluteJoint_GetMotorSpeed(id);
        joint->max_motor_torque = b2RevoluteJoint_GetMaxMotorTorque(id);
        if (b2RevoluteJoint_IsSpringEnabled(id)) {
            b2s3_capture_lossy(c, "a revolute joint's spring");
        }
        break;
    case B2S_JOINT_KIND_PRISMATIC:
        joint->enable_limit = b2PrismaticJoint_IsLimitEnabled(id);
        joint->lower_limit = b2PrismaticJoint_GetLowerLimit(id);
        joint->upper_limit = b2PrismaticJoint_GetUpperLimit(id);
        joint->enable_motor = b2PrismaticJoint_IsMotorEnabled(id);
        joint->motor_speed = b2PrismaticJoint_GetMotorSpeed(id);
        joint->max_motor_force = b2PrismaticJoint_GetMaxMotorForce(id);
        if (b2PrismaticJoint_IsSpringEnabled(id)) {
            b2s3_capture_lossy(c, "a prismatic joint's spring");
        }
        break;
    case B2S_JOINT_KIND_DISTANCE:
        joint->length = b2DistanceJoint_GetLength(id);
        if (b2DistanceJoint_IsSpringEnabled(id)) {
            joint->frequency_hz = b2DistanceJoint_GetSpringHertz(id);
            joint->damping_ratio = b2DistanceJoint_GetSpringDampingRatio(id);
        }
        if (b2DistanceJoint_IsLimitEnabled(id)) {
            b2s3_capture_lossy(c, "a distance joint's length range");
        }
        if (b2DistanceJoint_IsMotorEnabled(id)) {
            b2s3_capture_lossy(c, "a distance joint's motor");
        }
        break;
    case B2S_JOINT_KIND_ROPE:
        joint->max_length = b2DistanceJoint_GetMaxLength(id);
        if (!b2DistanceJoint_IsLimitEnabled(id)) {
            b2s3_capture_lossy(c, "a slack distance joint without its length limit");
        }
        if (b2DistanceJoint_IsMotorEnabled(id)) {
            b2s3_capture_lossy(c, "a distance joint's motor");
        }
        break;
    case B2S_JOINT_KIND_WHEEL:
        joint->frequency_hz = b2WheelJoint_GetSpringHertz(id);
        joint->damping_ratio = b2WheelJoint_GetSpringDampingRatio(id);
        joint->enable_motor = b2WheelJoint_IsMotorEnabled(id);
        joint->motor_speed = b2WheelJoint_GetMotorSpeed(id);
        joint->max_motor_torque = b2WheelJoint_GetMaxMotorTorque(id);
        if (b2WheelJoint_IsLimitEnabled(id)) {
            b2s3_capture_lossy(c, "a wheel joint's limit beside its spring");
        }
        break;
    case B2S_JOINT_KIND_LINE:
        joint->enable_limit = b2WheelJoint_IsLimitEnabled(id);
        joint->lower_limit = b2WheelJoint_GetLowerLimit(id);
        joint->upper_limit = b2WheelJoint_GetUpperLimit(id);
        if (b2WheelJoint_IsMotorEnabled(id)) {
            b2s3_capture_lossy(c, "a springless wheel joint's rotation motor");
        }
        break;
    case B2S_JOINT_KIND_WELD:
        joint->frequency_hz = b2WeldJoint_GetAngularHertz(id);
        joint->damping_ratio = b2WeldJoint_GetAngularDampingRatio(id);
        if (b2WeldJoint_GetLinearHertz(id) != 0.0f) {
            b2s3_capture_lossy(c, "a weld joint's linear spring");
        }
        break;
    default: break;
    }
    return true;
}

/* ---- joints the build skipped, written back as the file had them */

/* Where a joint stands in a capture of a built world: at its scene joint, the host's after
 * every scene joint, in creation order. */
static uint64_t b2s3_joint_place(const b2s3_capture* c, b2JointId id) {
    b2s3_level_joint key = {id, 0};
    const b2s3_level_joint* found = (const b2s3_level_joint*)bsearch(
        &key, c->level->joints, c->level->joint_count, sizeof key, b2s3_level_joint_order);
    return found != NULL ? (uint64_t)found->record
                         : (uint64_t)c->level->view->joint_count + (uint64_t)(uint32_t)id.index1;
}

/* The scene joint `j`, which the build skipped (the engine cannot hold it), written as the
 * file has it between the captured bodies, so that the joints after it keep their indices;
 * reported and not written when a body or joint it names was not written. */
static bool b2s3_write_skipped(b2s3_capture* c, uint32_t j) {
    const b2s3_level* level = c->level;
    b2s_joint joint = level->view->joints[j];
    if (joint.kind == B2S_JOINT_KIND_UNSUPPORTED) {
        B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "joint", c->joint_count, joint.name,
                    "scene joint %u, a Farseer-only joint, has no Box2Scene form to write; not "
                    "written",
                    (unsigned)j);
        return true;
    }
    uint32_t body_count = level->view->body_count, joint_count = level->view->joint_count;
    joint.body_a = joint.body_a < body_count ? level->captured_bodies[joint.body_a] : B2S_NONE;
    joint.body_b = joint.body_b < body_count ? level->captured_bodies[joint.body_b] : B2S_NONE;
    uint32_t refers[2] = {joint.joint_a, joint.joint_b};
    uint32_t* written[2] = {&joint.joint_a, &joint.joint_b};
    bool resolved = joint.body_a != B2S_NONE && joint.body_b != B2S_NONE;
    for (int k = 0; k < 2; ++k) {
        if (refers[k] != B2S_NONE) {
            *written[k] = refers[k] < joint_count ? level->written_joints[refers[k]] : B2S_NONE;
            resolved = resolved && *written[k] != B2S_NONE;
        }
    }
    if (!resolved) {
        B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "joint", c->joint_count, joint.name,
                    "scene joint %u, which " B2S3_ENGINE " cannot hold, joins a body or joint "
                    "not written before it (a gear is written after its joints); not written",
                    (unsigned)j);
        return true;
    }
    joint.user_data = b2s3_level_user_data(c, level->view->joints[j].user_data);
    uint32_t added = 0;
    if (!b2s3_builder_ok(c, b2s_builder_add_joint(c->builder, &joint, &added, c->error))) {
        return false;
    }
    level->written_joints[j] = c->joint_count++;
    return true;
}

/* Writes the joints the build skipped among the scene joints before `limit`. */
static bool b2s3_write_skipped_before(b2s3_capture* c, uint32_t limit) {
    b2s3_level* level = c->level;
    bool ok = true;
    for (; level->next_record < limit && ok; ++level->next_record) {
        if (B2_IS_NULL(level->built->joints[level->next_record])) {
            ok = b2s3_write_skipped(c, level->next_record);
        }
    }
    return ok;
}

/* A joint and where it stands in a capture of a built world. */
typedef struct b2s3_placed_joint {
    uint64_t place;
    b2JointId id;
} b2s3_placed_joint;

static int b2s3_by_place(const void* a, const void* b) {
    uint64_t x = ((const b2s3_placed_joint*)a)->place, y = ((const b2s3_placed_joint*)b)->place;
    return (x > y) - (x < y);
}

/* `joints` in the order a capture of a built world writes them (b2s3_joint_place). */
static bool b2s3_order_joints(b2s3_capture* c, b2JointId* joints, size_t count) {
    b2s3_placed_joint* placed =
        (b2s3_placed_joint*)malloc((count > 0 ? count : 1) * sizeof(b2s3_placed_joint));
    if (placed == NULL) {
        c->list.out_of_memory = true;
        return false;
    }
    for (size_t i = 0; i < count; ++i) {
        placed[i].place = b2s3_joint_place(c, joints[i]);
        placed[i].id = joints[i];
    }
    qsort(placed, count, sizeof(b2s3_placed_joint), b2s3_by_place);
    for (size_t i = 0; i < count; ++i) {
        joints[i] = placed[i].id;
    }
    free(placed);
    return true;
}

/* Every joint whose two bodies are captured, once, in creation order (in a capture of a
 * built world, in the scene's order, with the joints the build skipped). */
static bool b2s3_capture_joints(b2s3_capture* c) {
    size_t total = 0;
    for (uint32_t i = 0; i < c->body_count; ++i) {
        total += (size_t)b2Body_GetJointCount(c->bodies[i]);
    }
    b2JointId* joints = (b2JointId*)malloc((total > 0 ? total : 1) * sizeof(b2JointId));
    if (joints == NULL) {
        c->list.out_of_memory = true;
        return false;
    }
    size_t count = 0;
    for (uint32_t i = 0; i < c->body_count; ++i) {
        int capacity = b2Body_GetJointCount(c->bodies[i]);
        int found = b2Body_GetJoints(c->bodies[i], joints + count, capacity);
        size_t kept = count;
        for (int k = 0; k < found; ++k) {
            b2JointId id = joints[count + (size_t)k];
            /* each joint once: from its body A when that is captured, else from B */
            uint32_t a = b2s3_captured_index(c, b2Joint_GetBodyA(id));
            if (a == i || (a == B2S_NONE && b2s3_same_body(b2Joint_GetBodyB(id), c->bodies[i]))) {
                joints[kept++] = id;
            }
        }
        count = kept;
    }
    qsort(joints, count, sizeof(b2JointId), b2s3_joint_by_index);
    bool ok = c->level == NULL || b2s3_order_joints(c, joints, count);
    for (size_t i = 0; i < count && ok; ++i) {
        b2JointId id = joints[i];
        uint32_t record = B2S_NONE;
        if (c->level != NULL) {
            uint64_t place = b2s3_joint_place(c, id);
            uint32_t scene_joints = c->level->view->joint_count;
            record = place < scene_joints ? (uint32_t)place : B2S_NONE;
            ok = b2s3_write_skipped_before(c, record != B2S_NONE ? record : scene_joints);
            c->level->next_record += record != B2S_NONE ? 1u : 0u;
            if (!ok) {
                break;
            }
        }
        uint32_t a = b2s3_captured_index(c, b2Joint_GetBodyA(id));
        uint32_t bb = b2s3_captured_index(c, b2Joint_GetBodyB(id));
        if (a == B2S_NONE || bb == B2S_NONE) {
            B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "joint", c->joint_count, NULL,
                        "it connects body %u to a body the host did not name; not written",
                        (unsigned)(a == B2S_NONE ? bb : a));
            continue;
        }
        b2s_joint joint;
        if (!b2s3_joint_of(c, id, &joint)) {
            continue;
        }
        joint.body_a = a;
        joint.body_b = bb;
        joint.collide_connected = b2Joint_GetCollideConnected(id);
        if (record != B2S_NONE) {
            const b2s_joint* level_joint = &c->level->view->joints[record];
            joint.name = level_joint->name;
            joint.user_data = b2s3_level_user_data(c, level_joint->user_data);
        }
        uint32_t added = 0;
        ok = b2s3_builder_ok(c, b2s_builder_add_joint(c->builder, &joint, &added, c->error));
        if (ok && record != B2S_NONE) {
            c->level->written_joints[record] = c->joint_count;
        }
        c->joint_count += ok ? 1 : 0;
    }
    if (ok && c->level != NULL) {
        ok = b2s3_write_skipped_before(c, c->level->view->joint_count);
    }
    free(joints);
    return ok;
}

/* ---- the capture */

/* A public name as text. */
#define B2S3_NAME_OF(name) B2S3_TEXT(name)
#define B2S3_TEXT(name) #name

static b2s_code b2s3_capture_error(b2s_error* error, b2s_code code, const char* message) {
    if (error != NULL) {
        memset(error, 0, sizeof *error);
        error->code = code;
        snprintf(error->message, sizeof error->message, "%s", message);
    }
    return code;
}

/* The capture of `bodies`, labelled from `level` when it is not NULL. */
static b2s_code b2s3_capture_run(b2WorldId world, const b2BodyId* bodies, uint32_t body_count,
                                 b2s3_level* level, b2s_scene** out_scene,
                                 b2s3_reports_t* reports, b2s_error* error) {
    *out_scene = NULL;
    reports->items = NULL;
    reports->count = 0;
    if (!b2World_IsValid(world)) {
        return b2s3_capture_error(error, B2S_CODE_INVALID_ARGUMENT, "the world is not valid");
    }
    uint32_t live = 0;
    while (live < body_count && b2Body_IsValid(bodies[live]) &&
           bodies[live].world0 == world.index1 - 1) {
        live += 1;
    }
    /* Sorted, a body named twice stands beside itself. The host hears of whichever comes
     * first in its order, a body not live or a body named twice, so only the bodies before
     * the first not live are looked at. */
    b2s3_named* named = (b2s3_named*)malloc((size_t)(live > 0 ? live : 1) * sizeof(b2s3_named));
    if (named == NULL) {
        return b2s3_capture_error(error, B2S_CODE_INTERNAL, "out of memory");
    }
    for (uint32_t i = 0; i < live; ++i) {
        named[i].id = bodies[i];
        named[i].index = i;
    }
    qsort(named, live, sizeof(b2s3_named), b2s3_named_order);
    uint32_t first = B2S_NONE, twice = live;
    for (uint32_t i = 1; i < live; ++i) {
        if (b2s3_same_body(named[i - 1].id, named[i].id) && named[i].index < twice) {
            first = named[i - 1].index;
            twice = named[i].index;
        }
    }
    if (twice < live) {
        free(named);
        char message[96];
        snprintf(message, sizeof message, "bodies %u and %u are the same body",
                 (unsigned)first, (unsigned)twice);
        return b2s3_capture_error(error, B2S_CODE_INVALID_ARGUMENT, message);
    }
    if (live < body_count) {
        free(named);
        char message[96];
        snprintf(message, sizeof message, "body %u is not a live body of this world",
                 (unsigned)live);
        return b2s3_capture_error(error, B2S_CODE_INVALID_ARGUMENT, message);
    }
    b2s3_capture c;
    memset(&c, 0, sizeof c);
    c.world = world;
    c.bodies = bodies;
    c.body_count = body_count;
    c.named = named;
    c.builder = b2s_builder_new();
    c.list.reports = reports;
    c.error = error;
    c.level = level;
    b2s_vec2 scene_gravity = b2s3_to_b2s(b2World_GetGravity(world));
    bool ok = b2s3_builder_ok(&c, b2s_builder_set_gravity(c.builder, &scene_gravity, error));
    for (uint32_t i = 0; i < body_count && ok; ++i) {
        ok = b2s3_capture_body(&c, i);
    }
    b2s3_report_turned(&c);
    ok = ok && b2s3_capture_joints(&c);
    free(named);
    if (c.list.out_of_memory) {
        b2s_builder_free(c.builder);
        B2S3_API(reports_free)(reports);
        return b2s3_capture_error(error, B2S_CODE_INTERNAL, "out of memory");
    }
    if (!ok) {
        b2s_builder_free(c.builder);
        return c.failure != B2S_CODE_OK ? c.failure : B2S_CODE_INTERNAL;
    }
    return b2s_builder_finish(c.builder, out_scene, error);
}

b2s_code B2S3_API(capture_world)(b2WorldId world, const b2BodyId* bodies, uint32_t body_count,
                                 b2s_scene** out_scene, b2s3_reports_t* reports,
                                 b2s_error* error) {
    if (out_scene == NULL || reports == NULL || (bodies == NULL && body_count > 0)) {
        return b2s3_capture_error(error, B2S_CODE_NULL_ARGUMENT,
                                  B2S3_NAME_OF(B2S3_API(capture_world)) " needs out_scene, "
                                  "reports and, for a body count above 0, bodies");
    }
    return b2s3_capture_run(world, bodies, body_count, NULL, out_scene, reports, error);
}

/* The bodies the build made that are still live, in the scene's order, with their scene
 * bodies, and the joints it made sorted by id; false when memory runs out. */
static bool b2s3_level_of(const b2s3_built_t* built, b2s3_level* level, b2BodyId* bodies,
                          uint32_t* records, uint32_t* count) {
    *count = 0;
    for (uint32_t i = 0; i < built->body_count; ++i) {
        if (B2_IS_NON_NULL(built->bodies[i]) && b2Body_IsValid(built->bodies[i])) {
            bodies[*count] = built->bodies[i];
            records[(*count)++] = i;
        }
    }
    level->body_records = records;
    size_t bodies_room = (size_t)(built->body_count > 0 ? built->body_count : 1);
    level->captured_bodies = (uint32_t*)malloc(bodies_room * sizeof(uint32_t));
    level->written_joints = (uint32_t*)malloc(
        (size_t)(built->joint_count > 0 ? built->joint_count : 1) * sizeof(uint32_t));
    if (level->captured_bodies == NULL || level->written_joints == NULL) {
        return false;
    }
    for (uint32_t i = 0; i < built->body_count; ++i) {
        level->captured_bodies[i] = B2S_NONE;
    }
    for (uint32_t k = 0; k < *count; ++k) {
        level->captured_bodies[records[k]] = k;
    }
    for (uint32_t j = 0; j < built->joint_count; ++j) {
        level->written_joints[j] = B2S_NONE;
    }
    level->joints = (b2s3_level_joint*)malloc(
        (size_t)(built->joint_count > 0 ? built->joint_count : 1) * sizeof(b2s3_level_joint));
    if (level->joints == NULL) {
        return false;
    }
    level->joint_count = 0;
    for (uint32_t j = 0; j < built->joint_count; ++j) {
        if (B2_IS_NON_NULL(built->joints[j])) {
            level->joints[level->joint_count].id = built->joints[j];
            level->joints[level->joint_count++].record = j;
        }
    }
    qsort(level->joints, level->joint_count, sizeof(b2s3_level_joint), b2s3_level_joint_order);
    return true;
}

b2s_code B2S3_API(capture_built)(b2WorldId world, const b2s3_built_t* built,
                                 const b2s_scene* scene, b2s_scene** out_scene,
                                 b2s3_reports_t* reports, b2s_error* error) {
    const b2s_scene_view* view = scene != NULL ? b2s_scene_get_view(scene) : NULL;
    if (built == NULL || view == NULL || out_scene == NULL || reports == NULL) {
        return b2s3_capture_error(error, B2S_CODE_NULL_ARGUMENT,
                                  B2S3_NAME_OF(B2S3_API(capture_built)) " needs built, scene, "
                                  "out_scene and reports");
    }
    if (built->body_count != view->body_count || built->fixture_count != view->fixture_id_count ||
        built->joint_count != view->joint_count) {
        *out_scene = NULL;
        reports->items = NULL;
        reports->count = 0;
        return b2s3_capture_error(error, B2S_CODE_INVALID_ARGUMENT,
                                  "built is not what building this scene gave");
    }
    size_t room = (size_t)(built->body_count > 0 ? built->body_count : 1);
    b2BodyId* bodies = (b2BodyId*)malloc(room * sizeof(b2BodyId));
    uint32_t* records = (uint32_t*)malloc(room * sizeof(uint32_t));
    b2s3_level level = {built, view, NULL, NULL, 0, NULL, NULL, 0};
    uint32_t count = 0;
    b2s_code code;
    if (bodies == NULL || records == NULL ||
        !b2s3_level_of(built, &level, bodies, records, &count)) {
        *out_scene = NULL;
        reports->items = NULL;
        reports->count = 0;
        code = b2s3_capture_error(error, B2S_CODE_INTERNAL, "out of memory");
    } else {
        code = b2s3_capture_run(world, bodies, count, &level, out_scene, reports, error);
    }
    free(level.joints);
    free(level.captured_bodies);
    free(level.written_joints);
    free(records);
    free(bodies);
    return code;
}
