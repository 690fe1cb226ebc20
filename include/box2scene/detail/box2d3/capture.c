/*
 * Capture: the bodies a host gives (or those a build made) read through the engine's
 * getters into the library's held records, in the plan's terms, which b2s_capture_make
 * turns into a scene and the reports of what the format cannot hold. Nothing is converted
 * here: every inverse, form, label and report is the library's, which knows each version.
 * What the reader does is the engine's side: which shapes and joints are the bodies',
 * in creation order, a chain's segments together, and the ids of the bodies, fixture slots
 * and joints a build made as the scene's indices (lookup.c's hooks).
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

/* A shape the build made and the fixture slot it was made for. */
typedef struct b2s3_level_shape {
    b2ShapeId id;
    uint32_t slot;
} b2s3_level_shape;

/* What a capture of a built world reads the scene's indices from: what the build made,
 * the scene, the scene body of each captured body, and the built shapes and joints sorted
 * by id. */
typedef struct b2s3_level {
    const b2s3_built_t* built;
    const b2s_scene_view* view;
    const uint32_t* body_records;
    b2s3_level_shape* shapes;
    uint32_t shape_count;
    b2s3_level_joint* joints;
    uint32_t joint_count;
} b2s3_level;

/* The held records as they are read, each array with room for all it may hold. */
typedef struct b2s3_reader {
    const b2s3_named* named; /* the host's bodies sorted by id, for a joint's bodies */
    uint32_t body_count;
    const b2s3_level* level; /* NULL but for a capture of a built world */
    b2s_held_body* bodies;
    b2s_held_shape* shapes;
    b2s_vec2* points;
    b2s_held_joint* joints;
    uint32_t* skipped;
    uint32_t shape_count, point_count, joint_count, skipped_count;
    b2ShapeId* ids; /* one body's shapes, then one chain's segments */
} b2s3_reader;

/* A loose chain segment's chain (v3.2 builds them): the library regroups the ones that
 * continue one another. */
#define B2S3_LOOSE_SEGMENTS (B2S_NONE - 1u)

/* Ids of one kind in an order of their own (negative, zero or positive): zero for the same
 * object. */
#define B2S3_ID_ORDER(a, b)                                                                  \
    ((a).index1 != (b).index1     ? ((a).index1 < (b).index1 ? -1 : 1)                     \
     : (a).world0 != (b).world0   ? ((a).world0 < (b).world0 ? -1 : 1)                     \
                                  : ((a).generation > (b).generation) -                     \
                                        ((a).generation < (b).generation))

static int b2s3_named_by_body(const void* a, const void* b) {
    return B2S3_ID_ORDER(((const b2s3_named*)a)->id, ((const b2s3_named*)b)->id);
}

/* By body, one body's entries by the host's index: the first two of a body named more than
 * once are the pair a pass in the host's order meets first. */
static int b2s3_named_order(const void* a, const void* b) {
    int order = b2s3_named_by_body(a, b);
    uint32_t x = ((const b2s3_named*)a)->index, y = ((const b2s3_named*)b)->index;
    return order != 0 ? order : (x > y) - (x < y);
}

static int b2s3_level_joint_order(const void* a, const void* b) {
    b2JointId x = ((const b2s3_level_joint*)a)->id, y = ((const b2s3_level_joint*)b)->id;
    return B2S3_ID_ORDER(x, y);
}

static int b2s3_level_shape_order(const void* a, const void* b) {
    b2ShapeId x = ((const b2s3_level_shape*)a)->id, y = ((const b2s3_level_shape*)b)->id;
    return B2S3_ID_ORDER(x, y);
}

static int b2s3_shape_by_index(const void* a, const void* b) {
    int32_t x = ((const b2ShapeId*)a)->index1, y = ((const b2ShapeId*)b)->index1;
    return (x > y) - (x < y);
}

static int b2s3_joint_by_index(const void* a, const void* b) {
    int32_t x = ((const b2JointId*)a)->index1, y = ((const b2JointId*)b)->index1;
    return (x > y) - (x < y);
}

/* The held index of `body`, or B2S_NONE for a body the host did not give. */
static uint32_t b2s3_held_index(const b2s3_reader* r, b2BodyId body) {
    b2s3_named key = {body, 0};
    const b2s3_named* found = (const b2s3_named*)bsearch(&key, r->named, r->body_count,
                                                         sizeof(b2s3_named), b2s3_named_by_body);
    return found != NULL ? found->index : B2S_NONE;
}

/* ---- shapes */

/* The fixture slot that `shape` was built for, or B2S_NONE. */
static uint32_t b2s3_slot_of(const b2s3_level* level, b2ShapeId shape) {
    if (level == NULL) {
        return B2S_NONE;
    }
    b2s3_level_shape key = {shape, 0};
    const b2s3_level_shape* found = (const b2s3_level_shape*)bsearch(
        &key, level->shapes, level->shape_count, sizeof key, b2s3_level_shape_order);
    return found != NULL ? found->slot : B2S_NONE;
}

static b2s_held_shape* b2s3_add_shape(b2s3_reader* r, b2ShapeId id, uint32_t kind,
                                      uint32_t slot) {
    b2s_held_shape* held = &r->shapes[r->shape_count++];
    memset(held, 0, sizeof *held);
    b2SurfaceMaterial material = b2Shape_GetSurfaceMaterial(id);
    b2Filter filter = b2Shape_GetFilter(id);
    held->shape.slot = slot;
    held->shape.kind = kind;
    held->shape.points.first = r->point_count;
    held->shape.density = b2Shape_GetDensity(id);
    held->shape.friction = material.friction;
    held->shape.restitution = material.restitution;
    held->shape.is_sensor = b2Shape_IsSensor(id);
    held->category_bits = filter.categoryBits;
    held->mask_bits = filter.maskBits;
    held->group_index = filter.groupIndex;
    held->restitution_threshold = NAN;
    held->chain = B2S_NONE;
    return held;
}

static void b2s3_add_point(b2s3_reader* r, b2s_held_shape* held, b2Vec2 p) {
    r->points[r->point_count++] = b2s3_to_b2s(p);
    held->shape.points.count += 1;
}

static void b2s3_add_segment(b2s3_reader* r, b2ShapeId id, uint32_t chain, uint32_t slot) {
    b2ChainSegment s = b2Shape_GetChainSegment(id);
    b2s_held_shape* held = b2s3_add_shape(r, id, B2S_PLAN_SHAPE_KIND_SEGMENT, slot);
    held->chain = chain;
    b2Vec2 points[4] = {s.ghost1, s.segment.point1, s.segment.point2, s.ghost2};
    for (int i = 0; i < 4; ++i) {
        b2s3_add_point(r, held, points[i]);
    }
}

/* A chain object's segments in its order, where its first segment stands among the
 * body's shapes (the others are skipped where they stand). */
static void b2s3_read_chain(b2s3_reader* r, b2ChainId chain, b2ShapeId id, uint32_t slot,
                            b2ShapeId* segments, int capacity) {
    b2ShapeId first;
    if (b2Chain_GetSegments(chain, &first, 1) != 1 || B2S3_ID_ORDER(first, id) != 0) {
        return;
    }
    int count = b2Chain_GetSegments(chain, segments, capacity);
    for (int i = 0; i < count; ++i) {
        b2s3_add_segment(r, segments[i], (uint32_t)chain.index1, slot);
    }
}

/* One shape other than a chain segment. */
static void b2s3_read_shape(b2s3_reader* r, b2ShapeId id, uint32_t slot) {
    switch (b2Shape_GetType(id)) {
    case b2_circleShape: {
        b2Circle circle = b2Shape_GetCircle(id);
        b2s_held_shape* held = b2s3_add_shape(r, id, B2S_PLAN_SHAPE_KIND_CIRCLE, slot);
        held->shape.center = b2s3_to_b2s(circle.center);
        held->shape.radius = circle.radius;
        break;
    }
    case b2_polygonShape: {
        b2Polygon polygon = b2Shape_GetPolygon(id);
        b2s_held_shape* held = b2s3_add_shape(r, id, B2S_PLAN_SHAPE_KIND_POLYGON, slot);
        held->shape.radius = polygon.radius;
        for (int i = 0; i < polygon.count; ++i) {
            b2s3_add_point(r, held, polygon.vertices[i]);
        }
        break;
    }
    case b2_segmentShape: {
        b2Segment segment = b2Shape_GetSegment(id);
        b2s_held_shape* held = b2s3_add_shape(r, id, B2S_PLAN_SHAPE_KIND_SEGMENT, slot);
        b2s3_add_point(r, held, segment.point1);
        b2s3_add_point(r, held, segment.point2);
        break;
    }
    default: b2s3_add_shape(r, id, B2S_PLAN_SHAPE_KIND_CIRCLE, slot)->other = "a capsule"; break;
    }
}

/* A body's shapes, in the order they were created (a chain's segments together). */
static void b2s3_read_shapes(b2s3_reader* r, b2BodyId body) {
    int capacity = b2Body_GetShapeCount(body);
    b2ShapeId* segments = r->ids + capacity;
    int count = b2Body_GetShapes(body, r->ids, capacity);
    qsort(r->ids, (size_t)count, sizeof(b2ShapeId), b2s3_shape_by_index);
    for (int i = 0; i < count; ++i) {
        b2ShapeId id = r->ids[i];
        uint32_t slot = b2s3_slot_of(r->level, id);
        if (b2Shape_GetType(id) != b2_chainSegmentShape) {
            b2s3_read_shape(r, id, slot);
            continue;
        }
        b2ChainId chain = b2Shape_GetParentChain(id);
        if (B2_IS_NULL(chain)) {
            b2s3_add_segment(r, id, B2S3_LOOSE_SEGMENTS, slot);
        } else {
            b2s3_read_chain(r, chain, id, slot, segments, capacity);
        }
    }
}

/* ---- bodies */

static void b2s3_read_body(b2s3_reader* r, b2BodyId id, uint32_t index) {
    b2s_held_body* held = &r->bodies[index];
    memset(held, 0, sizeof *held);
    b2s_plan_body* body = &held->body;
    uint32_t record = r->level != NULL ? r->level->body_records[index] : B2S_NONE;
    body->body = record;
    body->kind = (uint32_t)b2Body_GetType(id);
    body->position = b2s3_to_b2s(b2s3_body_position(id));
    b2Rot q = b2Body_GetRotation(id);
    body->rotation.c = q.c;
    body->rotation.s = q.s;
    body->linear_velocity = b2s3_to_b2s(b2Body_GetLinearVelocity(id));
    body->angular_velocity = b2Body_GetAngularVelocity(id);
    body->linear_damping = b2Body_GetLinearDamping(id);
    body->angular_damping = b2Body_GetAngularDamping(id);
    body->gravity_scale = b2Body_GetGravityScale(id);
    b2MassData mass = b2Body_GetMassData(id);
    body->mass.mass = mass.mass;
    body->mass.center = b2s3_to_b2s(mass.center);
    body->mass.inertia = mass.rotationalInertia;
    body->allow_sleep = b2Body_IsSleepEnabled(id);
    body->awake = b2Body_IsAwake(id);
    body->fixed_rotation = b2s3_rotation_locked(id);
    body->bullet = b2Body_IsBullet(id);
    body->enabled = b2Body_IsEnabled(id);
    const char* name = b2Body_GetName(id);
    held->label.name = name != NULL && name[0] != '\0' ? name : NULL;
    body->shapes.first = r->shape_count;
    b2s3_read_shapes(r, id);
    body->shapes.count = r->shape_count - body->shapes.first;
}

/* ---- joints */

/* The scene joint a build made `id` from, or B2S_NONE. */
static uint32_t b2s3_joint_record(const b2s3_level* level, b2JointId id) {
    if (level == NULL) {
        return B2S_NONE;
    }
    b2s3_level_joint key = {id, 0};
    const b2s3_level_joint* found = (const b2s3_level_joint*)bsearch(
        &key, level->joints, level->joint_count, sizeof key, b2s3_level_joint_order);
    return found != NULL ? found->record : B2S_NONE;
}

/* What each kind holds beyond its frames and its motor joint's (the version's hooks). */
static void b2s3_read_kind(b2JointId id, b2s_held_joint* held) {
    b2s_plan_joint* j = &held->joint;
    switch (b2Joint_GetType(id)) {
    case b2_revoluteJoint:
        j->kind = B2S_PLAN_JOINT_KIND_REVOLUTE;
        j->enable_limit = b2RevoluteJoint_IsLimitEnabled(id);
        j->lower = b2RevoluteJoint_GetLowerLimit(id);
        j->upper = b2RevoluteJoint_GetUpperLimit(id);
        j->enable_motor = b2RevoluteJoint_IsMotorEnabled(id);
        j->motor_speed = b2RevoluteJoint_GetMotorSpeed(id);
        j->max_motor = b2RevoluteJoint_GetMaxMotorTorque(id);
        j->enable_spring = b2RevoluteJoint_IsSpringEnabled(id);
        break;
    case b2_prismaticJoint:
        j->kind = B2S_PLAN_JOINT_KIND_PRISMATIC;
        j->enable_limit = b2PrismaticJoint_IsLimitEnabled(id);
        j->lower = b2PrismaticJoint_GetLowerLimit(id);
        j->upper = b2PrismaticJoint_GetUpperLimit(id);
        j->enable_motor = b2PrismaticJoint_IsMotorEnabled(id);
        j->motor_speed = b2PrismaticJoint_GetMotorSpeed(id);
        j->max_motor = b2PrismaticJoint_GetMaxMotorForce(id);
        j->enable_spring = b2PrismaticJoint_IsSpringEnabled(id);
        break;
    case b2_distanceJoint:
        j->kind = B2S_PLAN_JOINT_KIND_DISTANCE;
        j->length = b2DistanceJoint_GetLength(id);
        j->enable_spring = b2DistanceJoint_IsSpringEnabled(id);
        j->hertz = b2DistanceJoint_GetSpringHertz(id);
        j->damping_ratio = b2DistanceJoint_GetSpringDampingRatio(id);
        j->enable_limit = b2DistanceJoint_IsLimitEnabled(id);
        j->min_length = b2DistanceJoint_GetMinLength(id);
        j->max_length = b2DistanceJoint_GetMaxLength(id);
        j->enable_motor = b2DistanceJoint_IsMotorEnabled(id);
        break;
    case b2_wheelJoint:
        j->kind = B2S_PLAN_JOINT_KIND_WHEEL;
        j->enable_spring = b2WheelJoint_IsSpringEnabled(id);
        j->hertz = b2WheelJoint_GetSpringHertz(id);
        j->damping_ratio = b2WheelJoint_GetSpringDampingRatio(id);
        j->enable_motor = b2WheelJoint_IsMotorEnabled(id);
        j->motor_speed = b2WheelJoint_GetMotorSpeed(id);
        j->max_motor = b2WheelJoint_GetMaxMotorTorque(id);
        j->enable_limit = b2WheelJoint_IsLimitEnabled(id);
        j->lower = b2WheelJoint_GetLowerLimit(id);
        j->upper = b2WheelJoint_GetUpperLimit(id);
        break;
    case b2_weldJoint:
        j->kind = B2S_PLAN_JOINT_KIND_WELD;
        j->hertz = b2WeldJoint_GetAngularHertz(id);
        j->damping_ratio = b2WeldJoint_GetAngularDampingRatio(id);
        held->linear_hertz = b2WeldJoint_GetLinearHertz(id);
        held->linear_damping_ratio = b2WeldJoint_GetLinearDampingRatio(id);
        break;
    case b2_motorJoint:
        j->kind = B2S_PLAN_JOINT_KIND_MOTOR;
        b2s3_read_motor(id, held);
        break;
    case b2_filterJoint: held->other = "a filter joint"; break;
    default: held->other = b2s3_joint_without_form(id); break;
    }
}

static void b2s3_read_joint(b2s3_reader* r, b2JointId id) {
    b2s_held_joint* held = &r->joints[r->joint_count++];
    memset(held, 0, sizeof *held);
    b2s_plan_joint* j = &held->joint;
    j->joint = b2s3_joint_record(r->level, id);
    j->body_a = b2s3_held_index(r, b2Joint_GetBodyA(id));
    j->body_b = b2s3_held_index(r, b2Joint_GetBodyB(id));
    j->joint_a = B2S_NONE;
    j->joint_b = B2S_NONE;
    j->collide_connected = b2Joint_GetCollideConnected(id);
    b2s3_read_kind(id, held);
    if (held->other == NULL) {
        b2s3_read_frames(id, j);
    }
}

/* Every joint of the captured bodies once (from its body A when that is captured, else
 * from B), in creation order; `ids` has room for them all. */
static void b2s3_read_joints(b2s3_reader* r, const b2BodyId* bodies, b2JointId* ids) {
    size_t count = 0;
    for (uint32_t i = 0; i < r->body_count; ++i) {
        int found = b2Body_GetJoints(bodies[i], ids + count, b2Body_GetJointCount(bodies[i]));
        size_t kept = count;
        for (int k = 0; k < found; ++k) {
            b2JointId id = ids[count + (size_t)k];
            uint32_t a = b2s3_held_index(r, b2Joint_GetBodyA(id));
            if (a == i || (a == B2S_NONE && b2s3_held_index(r, b2Joint_GetBodyB(id)) == i)) {
                ids[kept++] = id;
            }
        }
        count = kept;
    }
    qsort(ids, count, sizeof(b2JointId), b2s3_joint_by_index);
    for (size_t i = 0; i < count; ++i) {
        b2s3_read_joint(r, ids[i]);
    }
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

/* The first of the host's bodies that is not live, or named twice: an error, else OK. */
static b2s_code b2s3_check_bodies(b2WorldId world, const b2BodyId* bodies, uint32_t count,
                                  b2s3_named* named, b2s_error* error) {
    uint32_t live = 0;
    while (live < count && b2Body_IsValid(bodies[live]) &&
           bodies[live].world0 == world.index1 - 1) {
        named[live].id = bodies[live];
        named[live].index = live;
        live += 1;
    }
    /* Sorted, a body named twice stands beside itself. The host hears of whichever comes
     * first in its order, a body not live or a body named twice. */
    qsort(named, live, sizeof(b2s3_named), b2s3_named_order);
    uint32_t first = B2S_NONE, twice = live;
    for (uint32_t i = 1; i < live; ++i) {
        if (b2s3_named_by_body(&named[i - 1], &named[i]) == 0 && named[i].index < twice) {
            first = named[i - 1].index;
            twice = named[i].index;
        }
    }
    char message[96];
    if (twice < live) {
        snprintf(message, sizeof message, "bodies %u and %u are the same body",
                 (unsigned)first, (unsigned)twice);
        return b2s3_capture_error(error, B2S_CODE_INVALID_ARGUMENT, message);
    }
    if (live < count) {
        snprintf(message, sizeof message, "body %u is not a live body of this world",
                 (unsigned)live);
        return b2s3_capture_error(error, B2S_CODE_INVALID_ARGUMENT, message);
    }
    return B2S_CODE_OK;
}

/* The library's scene of the held records, its reports copied into `reports`. */
static b2s_code b2s3_make(b2WorldId world, b2s3_reader* r, const b2s_scene* scene,
                          b2s_scene** out_scene, b2s3_reports_t* reports, b2s_error* error) {
    b2s_held_world held;
    memset(&held, 0, sizeof held);
    held.engine = B2S3_ENGINE_VERSION;
    held.gravity = b2s3_to_b2s(b2World_GetGravity(world));
    held.bodies = r->bodies;
    held.shapes = r->shapes;
    held.points = r->points;
    held.joints = r->joints;
    held.skipped_joints = r->skipped;
    held.body_count = r->body_count;
    held.shape_count = r->shape_count;
    held.point_count = r->point_count;
    held.joint_count = r->joint_count;
    held.skipped_count = r->skipped_count;
    b2s_capture* capture = NULL;
    b2s_code code = b2s_capture_make(&held, scene, &capture, error);
    if (code != B2S_CODE_OK) {
        return code;
    }
    const b2s_capture_view* view = b2s_capture_get_view(capture);
    b2s3_list list = {reports, 0, false};
    for (uint32_t i = 0; i < view->report_count && !list.out_of_memory; ++i) {
        const b2s_plan_report* report = &view->reports[i];
        b2s3_add_report(&list, (b2s_code)report->code, report->object, report->index,
                        report->name, report->message);
    }
    *out_scene = list.out_of_memory ? NULL : b2s_capture_take_scene(capture);
    b2s_capture_free(capture);
    if (list.out_of_memory) {
        B2S3_API(reports_free)(reports);
        return b2s3_capture_error(error, B2S_CODE_INTERNAL, "out of memory");
    }
    return B2S_CODE_OK;
}

/* The capture of `bodies`, their scene indices read from `level` when it is not NULL. */
static b2s_code b2s3_capture_run(b2WorldId world, const b2BodyId* bodies, uint32_t body_count,
                                 const b2s3_level* level, const b2s_scene* scene,
                                 b2s_scene** out_scene, b2s3_reports_t* reports,
                                 b2s_error* error) {
    *out_scene = NULL;
    reports->items = NULL;
    reports->count = 0;
    if (!b2World_IsValid(world)) {
        return b2s3_capture_error(error, B2S_CODE_INVALID_ARGUMENT, "the world is not valid");
    }
    b2s3_reader r;
    memset(&r, 0, sizeof r);
    b2s3_named* named = (b2s3_named*)malloc((body_count + 1u) * sizeof(b2s3_named));
    if (named == NULL) {
        return b2s3_capture_error(error, B2S_CODE_INTERNAL, "out of memory");
    }
    b2s_code code = b2s3_check_bodies(world, bodies, body_count, named, error);
    size_t shapes = 0, joints = 0, widest = 0;
    for (uint32_t i = 0; i < body_count && code == B2S_CODE_OK; ++i) {
        size_t count = (size_t)b2Body_GetShapeCount(bodies[i]);
        shapes += count;
        widest = count > widest ? count : widest;
        joints += (size_t)b2Body_GetJointCount(bodies[i]);
    }
    size_t skipped = level != NULL ? level->built->joint_count : 0u;
    r.named = named;
    r.body_count = body_count;
    r.level = level;
    r.bodies = (b2s_held_body*)malloc((body_count + 1u) * sizeof(b2s_held_body));
    r.shapes = (b2s_held_shape*)malloc((shapes + 1u) * sizeof(b2s_held_shape));
    r.points = (b2s_vec2*)malloc((shapes * B2_MAX_POLYGON_VERTICES + 1u) * sizeof(b2s_vec2));
    r.joints = (b2s_held_joint*)malloc((joints + 1u) * sizeof(b2s_held_joint));
    r.skipped = (uint32_t*)malloc((skipped + 1u) * sizeof(uint32_t));
    r.ids = (b2ShapeId*)malloc((2u * widest + 1u) * sizeof(b2ShapeId));
    b2JointId* joint_ids = (b2JointId*)malloc((joints + 1u) * sizeof(b2JointId));
    if (code == B2S_CODE_OK && (r.bodies == NULL || r.shapes == NULL || r.points == NULL ||
                                r.joints == NULL || r.skipped == NULL || r.ids == NULL ||
                                joint_ids == NULL)) {
        code = b2s3_capture_error(error, B2S_CODE_INTERNAL, "out of memory");
    }
    if (code == B2S_CODE_OK) {
        for (uint32_t i = 0; i < body_count; ++i) {
            b2s3_read_body(&r, bodies[i], i);
        }
        b2s3_read_joints(&r, bodies, joint_ids);
        for (uint32_t j = 0; j < skipped; ++j) {
            if (B2_IS_NULL(level->built->joints[j])) {
                r.skipped[r.skipped_count++] = j;
            }
        }
        code = b2s3_make(world, &r, scene, out_scene, reports, error);
    }
    free(joint_ids);
    free(r.ids);
    free(r.skipped);
    free(r.joints);
    free(r.points);
    free(r.shapes);
    free(r.bodies);
    free(named);
    return code;
}

b2s_code B2S3_API(capture_world)(b2WorldId world, const b2BodyId* bodies, uint32_t body_count,
                                 b2s_scene** out_scene, b2s3_reports_t* reports,
                                 b2s_error* error) {
    if (out_scene == NULL || reports == NULL || (bodies == NULL && body_count > 0)) {
        return b2s3_capture_error(error, B2S_CODE_NULL_ARGUMENT,
                                  B2S3_NAME_OF(B2S3_API(capture_world)) " needs out_scene, "
                                  "reports and, for a body count above 0, bodies");
    }
    return b2s3_capture_run(world, bodies, body_count, NULL, NULL, out_scene, reports, error);
}

/* The bodies the build made that are still live, in the scene's order, with their scene
 * bodies, and the joints it made sorted by id. */
static void b2s3_level_of(const b2s3_built_t* built, b2s3_level* level, b2BodyId* bodies,
                          uint32_t* records, uint32_t* count) {
    *count = 0;
    for (uint32_t i = 0; i < built->body_count; ++i) {
        if (B2_IS_NON_NULL(built->bodies[i]) && b2Body_IsValid(built->bodies[i])) {
            bodies[*count] = built->bodies[i];
            records[(*count)++] = i;
        }
    }
    level->body_records = records;
    level->joint_count = 0;
    for (uint32_t j = 0; j < built->joint_count; ++j) {
        if (B2_IS_NON_NULL(built->joints[j])) {
            level->joints[level->joint_count].id = built->joints[j];
            level->joints[level->joint_count++].record = j;
        }
    }
    qsort(level->joints, level->joint_count, sizeof(b2s3_level_joint), b2s3_level_joint_order);
}

/* Every shape the build made with its fixture slot (a chain's segments each), sorted by id,
 * so that a shape's slot is a binary search and not a pass over its body's slots; false
 * when memory runs out. */
static bool b2s3_level_shapes(const b2s3_built_t* built, b2s3_level* level) {
    size_t total = 0;
    int widest = 0;
    for (uint32_t slot = 0; slot < built->fixture_count; ++slot) {
        int count = b2s3_slot_shapes(built, slot, NULL, 0);
        total += (size_t)count;
        widest = count > widest ? count : widest;
    }
    level->shapes = (b2s3_level_shape*)malloc((total + 1u) * sizeof(b2s3_level_shape));
    b2ShapeId* ids = (b2ShapeId*)malloc(((size_t)widest + 1u) * sizeof(b2ShapeId));
    if (level->shapes == NULL || ids == NULL) {
        free(ids);
        return false;
    }
    level->shape_count = 0;
    for (uint32_t slot = 0; slot < built->fixture_count; ++slot) {
        int count = b2s3_slot_shapes(built, slot, ids, widest);
        for (int k = 0; k < count; ++k) {
            b2s3_level_shape entry = {ids[k], slot};
            level->shapes[level->shape_count++] = entry;
        }
    }
    free(ids);
    qsort(level->shapes, level->shape_count, sizeof(b2s3_level_shape), b2s3_level_shape_order);
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
    *out_scene = NULL;
    reports->items = NULL;
    reports->count = 0;
    if (built->body_count != view->body_count || built->fixture_count != view->fixture_id_count ||
        built->joint_count != view->joint_count) {
        return b2s3_capture_error(error, B2S_CODE_INVALID_ARGUMENT,
                                  "built is not what building this scene gave");
    }
    b2BodyId* bodies = (b2BodyId*)malloc((built->body_count + 1u) * sizeof(b2BodyId));
    uint32_t* records = (uint32_t*)malloc((built->body_count + 1u) * sizeof(uint32_t));
    b2s3_level level = {built, view, NULL, NULL, 0, NULL, 0};
    level.joints =
        (b2s3_level_joint*)malloc((built->joint_count + 1u) * sizeof(b2s3_level_joint));
    b2s_code code;
    if (bodies == NULL || records == NULL || level.joints == NULL ||
        !b2s3_level_shapes(built, &level)) {
        code = b2s3_capture_error(error, B2S_CODE_INTERNAL, "out of memory");
    } else {
        uint32_t count = 0;
        b2s3_level_of(built, &level, bodies, records, &count);
        code = b2s3_capture_run(world, bodies, count, &level, scene, out_scene, reports, error);
    }
    free(level.shapes);
    free(level.joints);
    free(records);
    free(bodies);
    return code;
}
