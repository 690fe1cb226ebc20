/*
 * The implementation of box2scene/box2d3.h, compiled where the host defines
 * B2S_BOX2D3_IMPLEMENTATION (C only). Names starting with b2s3_ are private to it.
 */
#ifndef BOX2SCENE_BOX2D3_IMPL_H
#define BOX2SCENE_BOX2D3_IMPL_H

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* v3 asserts that a revolute limit lies within +-0.99 pi, and clamps a reference angle to
 * +-pi (B2_PI). */
#define B2S3_PI 3.14159265359f
#include "box2d3/reports.c"

static bool b2s3_is_zero(b2s_vec2 v) {
    return v.x == 0.0f && v.y == 0.0f;
}


#include "box2d3/world.c"
#include "box2d3/shapes.c"

#include "box2d3/bodies.c"
#include "box2d3/joints.c"

/* ---- capture */

/* A body the host named and the index it gave it. */
typedef struct b2s3_named {
    b2BodyId id;
    uint32_t index;
} b2s3_named;

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
} b2s3_capture;

/* Bodies in an order of their own (negative, zero or positive): zero for the same body. */
static int b2s3_body_order(b2BodyId a, b2BodyId b) {
    if (a.index1 != b.index1) {
        return a.index1 < b.index1 ? -1 : 1;
    }
    if (a.world0 != b.world0) {
        return a.world0 < b.world0 ? -1 : 1;
    }
    return (a.generation > b.generation) - (a.generation < b.generation);
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

/* One component of the velocity the build gives a body's origin, so that v3's
 * b2Body_ApplyMassFromShapes, adding w x (the centre of mass's shift), gives `target`. */
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

static bool b2s3_wide_bits(uint64_t bits) {
    return (bits >> 32) != 0;
}

/* A v3 filter in the format's 32 bits: a mask with every higher bit set is "all". */
static b2s_filter b2s3_filter_of(b2s3_capture* c, b2Filter f, uint32_t fixture) {
    b2s_filter out;
    uint64_t high_mask = f.maskBits >> 32;
    bool exact = !b2s3_wide_bits(f.categoryBits) &&
                 (high_mask == 0 || high_mask == (UINT64_MAX >> 32)) && f.groupIndex >= INT16_MIN &&
                 f.groupIndex <= INT16_MAX;
    out.category_bits = (uint32_t)(f.categoryBits & 0xFFFFFFFFu);
    out.mask_bits = (uint32_t)(f.maskBits & 0xFFFFFFFFu);
    out.group_index = (int16_t)(f.groupIndex < INT16_MIN   ? INT16_MIN
                                : f.groupIndex > INT16_MAX ? INT16_MAX
                                                           : f.groupIndex);
    if (!exact) {
        B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "fixture", fixture, NULL,
                            "its filter (category 0x%llx, mask 0x%llx, group %d) has bits "
                            "above the format's 32 or a group beyond 16 bits; the low 32 bits "
                            "were written",
                            (unsigned long long)f.categoryBits, (unsigned long long)f.maskBits,
                            f.groupIndex);
    }
    return out;
}

/* One shape and the fixture that carries it; `material` and `density` from the v3 shape. */
static bool b2s3_add_fixture(b2s3_capture* c, const b2s_shape* shape, const b2s_vec2* vertices,
                             uint32_t count, b2ShapeId from, float density, float friction,
                             float restitution, bool is_sensor, uint32_t* out_fixture) {
    uint32_t shape_index = 0;
    if (!b2s3_builder_ok(c, b2s_builder_add_shape(c->builder, shape, vertices, count,
                                                  &shape_index, c->error))) {
        return false;
    }
    c->shape_count += 1;
    b2s_fixture fixture;
    b2s_fixture_default(&fixture);
    fixture.shape = shape_index;
    fixture.density = density;
    fixture.friction = friction;
    fixture.restitution = restitution;
    fixture.is_sensor = is_sensor;
    fixture.filter = b2s3_filter_of(c, b2Shape_GetFilter(from), c->fixture_count);
    if (!b2s3_builder_ok(c, b2s_builder_add_fixture(c->builder, &fixture, out_fixture,
                                                    c->error))) {
        return false;
    }
    c->fixture_count += 1;
    return true;
}

/* The points of a chain: open, [ghost, points..., ghost], or a loop. */
static bool b2s3_capture_chain(b2s3_capture* c, b2ChainId chain, b2ShapeId first,
                               uint32_t* out_fixture) {
    int count = b2Chain_GetSegmentCount(chain);
    b2ShapeId* segments = (b2ShapeId*)malloc((size_t)(count > 0 ? count : 1) * sizeof(b2ShapeId));
    b2s_vec2* points = (b2s_vec2*)malloc(((size_t)count + 3) * sizeof(b2s_vec2));
    if (segments == NULL || points == NULL) {
        free(segments);
        free(points);
        c->list.out_of_memory = true;
        return false;
    }
    count = b2Chain_GetSegments(chain, segments, count);
    b2ChainSegment head = b2Shape_GetChainSegment(segments[0]);
    b2ChainSegment tail = b2Shape_GetChainSegment(segments[count - 1]);
    bool loop = b2s3_same_point(tail.segment.point2, head.segment.point1) &&
                b2s3_same_point(tail.ghost2, head.segment.point2) &&
                b2s3_same_point(head.ghost1, tail.segment.point1);
    b2s_shape shape;
    b2s_shape_default(B2S_SHAPE_KIND_CHAIN, &shape);
    uint32_t n = 0;
    for (int i = 0; i < count; ++i) {
        points[n++] = b2s3_to_b2s(b2Shape_GetChainSegment(segments[i]).segment.point1);
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
    b2SurfaceMaterial material = b2Shape_GetSurfaceMaterial(first);
    bool made = b2s3_add_fixture(c, &shape, points, n, first, 0.0f, material.friction,
                                 material.restitution, false, out_fixture);
    free(segments);
    free(points);
    return made;
}

/* The format's shape for one v3 shape, or false when it has none (reported). */
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
                                "a rounded polygon (radius %.9g m): written without its "
                                "rounding",
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
    b2SurfaceMaterial material = b2Shape_GetSurfaceMaterial(id);
    return b2s3_add_fixture(c, &shape, vertices, count, id, b2Shape_GetDensity(id),
                            material.friction, material.restitution, b2Shape_IsSensor(id),
                            out_fixture);
}

static int b2s3_by_index(const void* a, const void* b) {
    int32_t x = ((const b2ShapeId*)a)->index1, y = ((const b2ShapeId*)b)->index1;
    return (x > y) - (x < y);
}

/* A chain among a body's shapes, and whether its fixture has been made. */
typedef struct b2s3_chain_seen {
    b2ChainId id;
    bool captured;
} b2s3_chain_seen;

static int b2s3_chain_order(const void* a, const void* b) {
    b2ChainId x = ((const b2s3_chain_seen*)a)->id, y = ((const b2s3_chain_seen*)b)->id;
    if (x.index1 != y.index1) {
        return x.index1 < y.index1 ? -1 : 1;
    }
    return (x.generation > y.generation) - (x.generation < y.generation);
}

/* The fixtures of one body, in the order its shapes were created (a chain where its first
 * segment stands), with the masses their densities give. */
static bool b2s3_capture_fixtures(b2s3_capture* c, b2BodyId body, uint32_t** fixtures,
                                  uint32_t* count, b2MassData* computed) {
    int capacity = b2Body_GetShapeCount(body);
    b2ShapeId* shapes = (b2ShapeId*)malloc((size_t)(capacity > 0 ? capacity : 1) * sizeof(b2ShapeId));
    b2s3_chain_seen* chains =
        (b2s3_chain_seen*)malloc((size_t)(capacity > 0 ? capacity : 1) * sizeof(b2s3_chain_seen));
    b2MassData* masses = (b2MassData*)malloc((size_t)(capacity > 0 ? capacity : 1) * sizeof(b2MassData));
    float* densities = (float*)malloc((size_t)(capacity > 0 ? capacity : 1) * sizeof(float));
    *fixtures = (uint32_t*)malloc((size_t)(capacity > 0 ? capacity : 1) * sizeof(uint32_t));
    *count = 0;
    bool ok = shapes != NULL && chains != NULL && masses != NULL && densities != NULL &&
              *fixtures != NULL;
    if (!ok) {
        c->list.out_of_memory = true;
    }
    int shape_count = ok ? b2Body_GetShapes(body, shapes, capacity) : 0;
    qsort(shapes, (size_t)shape_count, sizeof(b2ShapeId), b2s3_by_index);
    /* the body's chains, each once and sorted, so that a segment finds its chain's entry by
     * a binary search however many chains the body holds */
    size_t chain_count = 0;
    for (int i = 0; i < shape_count; ++i) {
        if (b2Shape_GetType(shapes[i]) == b2_chainSegmentShape) {
            chains[chain_count].id = b2Shape_GetParentChain(shapes[i]);
            chains[chain_count].captured = false;
            chain_count += 1;
        }
    }
    qsort(chains, chain_count, sizeof(b2s3_chain_seen), b2s3_chain_order);
    size_t distinct = 0;
    for (size_t k = 0; k < chain_count; ++k) {
        if (distinct == 0 || b2s3_chain_order(&chains[distinct - 1], &chains[k]) != 0) {
            chains[distinct++] = chains[k];
        }
    }
    size_t massive = 0;
    for (int i = 0; i < shape_count && ok; ++i) {
        b2ShapeId id = shapes[i];
        uint32_t fixture = 0;
        if (b2Shape_GetType(id) == b2_chainSegmentShape) {
            b2s3_chain_seen key = {b2Shape_GetParentChain(id), false};
            b2s3_chain_seen* chain = (b2s3_chain_seen*)bsearch(
                &key, chains, distinct, sizeof(b2s3_chain_seen), b2s3_chain_order);
            if (chain->captured) {
                continue;
            }
            chain->captured = true;
            if (!b2s3_capture_chain(c, chain->id, id, &fixture)) {
                ok = c->failure == B2S_CODE_OK && !c->list.out_of_memory;
                continue;
            }
        } else if (!b2s3_capture_shape(c, id, &fixture)) {
            ok = c->failure == B2S_CODE_OK && !c->list.out_of_memory;
            continue;
        } else {
            densities[massive] = b2Shape_GetDensity(id);
            masses[massive] = b2Shape_GetMassData(id);
            massive += 1;
        }
        (*fixtures)[(*count)++] = fixture;
    }
    bool kept = true;
    *computed = b2s3_mass_from_shapes(masses, densities, massive, b2Body_IsFixedRotation(body),
                                      &kept);
    free(shapes);
    free(chains);
    free(masses);
    free(densities);
    return ok;
}

static bool b2s3_same_mass(b2MassData a, b2MassData b) {
    return a.mass == b.mass && a.center.x == b.center.x && a.center.y == b.center.y &&
           a.rotationalInertia == b.rotationalInertia;
}

static bool b2s3_capture_body(b2s3_capture* c, uint32_t index) {
    b2BodyId id = c->bodies[index];
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
    body.position = b2s3_to_b2s(b2Body_GetPosition(id));
    if (!b2s3_angle_of(b2Body_GetRotation(id), &body.angle)) {
        B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "body", index, b2Body_GetName(id),
                            "no angle has exactly its rotation's cosine and sine; the nearest, "
                            "%.9g rad, was written",
                            (double)body.angle);
    }
    body.linear_velocity = b2s3_to_b2s(b2Body_GetLinearVelocity(id));
    if (type == b2_dynamicBody) {
        body.linear_velocity = b2s3_origin_velocity(b2Body_GetTransform(id),
                                                    b2Body_GetLocalCenterOfMass(id),
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
    body.fixed_rotation = b2Body_IsFixedRotation(id);
    body.active = b2Body_IsEnabled(id);
    const char* name = b2Body_GetName(id);
    body.name = name != NULL && name[0] != '\0' ? name : NULL;
    if (type == b2_dynamicBody) {
        b2MassData actual = b2Body_GetMassData(id);
        computed.mass = b2s3_positive(computed.mass);
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

static int b2s3_joint_by_index(const void* a, const void* b) {
    int32_t x = ((const b2JointId*)a)->index1, y = ((const b2JointId*)b)->index1;
    return (x > y) - (x < y);
}

static void b2s3_capture_lossy(b2s3_capture* c, const char* what) {
    B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "joint", c->joint_count, NULL,
                        "%s has no Box2Scene form; written without it", what);
}

/* The format's joint for one v3 joint, or false when it has none (reported). */
static bool b2s3_joint_of(b2s3_capture* c, b2JointId id, b2s_joint* joint) {
    b2JointType type = b2Joint_GetType(id);
    uint32_t kind;
    switch (type) {
    case b2_revoluteJoint: kind = B2S_JOINT_KIND_REVOLUTE; break;
    case b2_prismaticJoint: kind = B2S_JOINT_KIND_PRISMATIC; break;
    case b2_weldJoint: kind = B2S_JOINT_KIND_WELD; break;
    case b2_motorJoint:
        kind = b2MotorJoint_GetCorrectionFactor(id) == 0.0f &&
                       b2s3_same_point(b2MotorJoint_GetLinearOffset(id), b2Vec2_zero) &&
                       b2MotorJoint_GetAngularOffset(id) == 0.0f
                   ? B2S_JOINT_KIND_FRICTION
                   : B2S_JOINT_KIND_MOTOR;
        break;
    case b2_distanceJoint:
        kind = b2DistanceJoint_IsSpringEnabled(id) && b2DistanceJoint_GetSpringHertz(id) == 0.0f
                   ? B2S_JOINT_KIND_ROPE
                   : B2S_JOINT_KIND_DISTANCE;
        break;
    case b2_wheelJoint:
        kind = b2WheelJoint_IsSpringEnabled(id) ? B2S_JOINT_KIND_WHEEL : B2S_JOINT_KIND_LINE;
        break;
    default:
        B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "joint", c->joint_count, NULL,
                            "a %s joint has no Box2Scene form; not written",
                            type == b2_mouseJoint ? "mouse" : "filter");
        return false;
    }
    b2s_joint_default(kind, joint);
    if (kind != B2S_JOINT_KIND_FRICTION && kind != B2S_JOINT_KIND_MOTOR) {
        joint->local_anchor_a = b2s3_to_b2s(b2Joint_GetLocalAnchorA(id));
        joint->local_anchor_b = b2s3_to_b2s(b2Joint_GetLocalAnchorB(id));
    }
    switch (kind) {
    case B2S_JOINT_KIND_REVOLUTE:
        joint->reference_angle = b2Joint_GetReferenceAngle(id);
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
        joint->local_axis_a = b2s3_to_b2s(b2Joint_GetLocalAxisA(id));
        joint->reference_angle = b2Joint_GetReferenceAngle(id);
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
        joint->local_axis_a = b2s3_to_b2s(b2Joint_GetLocalAxisA(id));
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
        joint->local_axis_a = b2s3_to_b2s(b2Joint_GetLocalAxisA(id));
        joint->enable_limit = b2WheelJoint_IsLimitEnabled(id);
        joint->lower_limit = b2WheelJoint_GetLowerLimit(id);
        joint->upper_limit = b2WheelJoint_GetUpperLimit(id);
        if (b2WheelJoint_IsMotorEnabled(id)) {
            b2s3_capture_lossy(c, "a springless wheel joint's rotation motor");
        }
        break;
    case B2S_JOINT_KIND_WELD:
        joint->reference_angle = b2Joint_GetReferenceAngle(id);
        joint->frequency_hz = b2WeldJoint_GetAngularHertz(id);
        joint->damping_ratio = b2WeldJoint_GetAngularDampingRatio(id);
        if (b2WeldJoint_GetLinearHertz(id) != 0.0f) {
            b2s3_capture_lossy(c, "a weld joint's linear spring");
        }
        break;
    case B2S_JOINT_KIND_FRICTION:
    case B2S_JOINT_KIND_MOTOR:
        joint->linear_offset = b2s3_to_b2s(b2MotorJoint_GetLinearOffset(id));
        joint->angular_offset = b2MotorJoint_GetAngularOffset(id);
        joint->max_force = b2MotorJoint_GetMaxForce(id);
        joint->max_torque = b2MotorJoint_GetMaxTorque(id);
        joint->correction_factor = b2MotorJoint_GetCorrectionFactor(id);
        break;
    }
    return true;
}

/* Every joint whose two bodies are captured, once, in creation order. */
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
    bool ok = true;
    for (size_t i = 0; i < count && ok; ++i) {
        b2JointId id = joints[i];
        uint32_t a = b2s3_captured_index(c, b2Joint_GetBodyA(id));
        uint32_t bb = b2s3_captured_index(c, b2Joint_GetBodyB(id));
        if (a == B2S_NONE || bb == B2S_NONE) {
            B2S3_REPORT(c, B2S_CODE_LOSSY_CAPTURE, "joint", c->joint_count, NULL,
                                "it connects body %u to a body the host did not name; not "
                                "written",
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
        uint32_t added = 0;
        ok = b2s3_builder_ok(c, b2s_builder_add_joint(c->builder, &joint, &added, c->error));
        c->joint_count += ok ? 1 : 0;
    }
    free(joints);
    return ok;
}

static b2s_code b2s3_capture_error(b2s_error* error, b2s_code code, const char* message) {
    if (error != NULL) {
        memset(error, 0, sizeof *error);
        error->code = code;
        snprintf(error->message, sizeof error->message, "%s", message);
    }
    return code;
}

b2s_code b2s_box2d3_capture_world(b2WorldId world, const b2BodyId* bodies, uint32_t body_count,
                                  b2s_scene** out_scene, b2s_box2d3_reports* reports,
                                  b2s_error* error) {
    if (out_scene == NULL || reports == NULL || (bodies == NULL && body_count > 0)) {
        return b2s3_capture_error(error, B2S_CODE_NULL_ARGUMENT,
                                  "b2s_box2d3_capture_world needs out_scene, reports and, "
                                  "for a body count above 0, bodies");
    }
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
    b2s3_named* named =
        (b2s3_named*)malloc((size_t)(live > 0 ? live : 1) * sizeof(b2s3_named));
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
    b2Vec2 gravity = b2World_GetGravity(world);
    b2s_vec2 scene_gravity = b2s3_to_b2s(gravity);
    bool ok = b2s3_builder_ok(&c, b2s_builder_set_gravity(c.builder, &scene_gravity, error));
    for (uint32_t i = 0; i < body_count && ok; ++i) {
        ok = b2s3_capture_body(&c, i);
    }
    ok = ok && b2s3_capture_joints(&c);
    free(named);
    if (c.list.out_of_memory) {
        b2s_builder_free(c.builder);
        b2s_box2d3_reports_free(reports);
        return b2s3_capture_error(error, B2S_CODE_INTERNAL, "out of memory");
    }
    if (!ok) {
        b2s_builder_free(c.builder);
        return c.failure != B2S_CODE_OK ? c.failure : B2S_CODE_INTERNAL;
    }
    return b2s_builder_finish(c.builder, out_scene, error);
}

#endif /* BOX2SCENE_BOX2D3_IMPL_H */
