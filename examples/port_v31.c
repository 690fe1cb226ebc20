/*
 * A port's own builder: a Box2D v3.1 world made from box2scene's plan with nothing but
 * <box2scene.h> and Box2D v3.1's own calls (no adapter header), as docs/ports.md describes.
 * The plan has done every conversion and check; this file only copies fields into defs, in
 * the plan's order. `port_v31 [SCENE] [STEPS]` builds the scene (the bundled showcase by
 * default), steps it and prints the reports and every body's pose. c_tests/box2d3_port_test.c
 * compiles this file without its main (PORT_V31_NO_MAIN) and checks the world against the
 * v3.1 adapter's, bit for bit.
 */
#include <box2d/box2d.h>
#include <box2scene.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct port_world {
    b2WorldId world;
    b2BodyId* bodies;   /* indexed like the scene's bodies; null ids where the plan made none */
    b2JointId* joints;  /* indexed like the plan's joints */
    uint32_t body_count, joint_count, report_count;
} port_world;

static b2Vec2 vec(b2s_vec2 v) {
    return (b2Vec2){v.x, v.y};
}

static void make_shape(const b2s_plan_view* plan, const b2s_plan_shape* s, b2BodyId body) {
    b2ShapeDef def = b2DefaultShapeDef();
    def.density = s->density;
    def.material.friction = s->friction;
    def.material.restitution = s->restitution;
    def.filter.categoryBits = s->filter.category_bits;
    def.filter.maskBits = s->filter.mask_bits;
    def.filter.groupIndex = s->filter.group_index;
    def.isSensor = s->is_sensor;
    def.enableSensorEvents = true; /* 2.x's sensors saw every shape */
    def.updateBodyMass = false;    /* one mass update, after every shape: the plan predicts that */
    const b2s_vec2* p = plan->points + s->points.first;
    int n = (int)s->points.count;
    if (s->kind == B2S_PLAN_SHAPE_KIND_CIRCLE) {
        b2Circle circle = {vec(s->center), s->radius};
        b2CreateCircleShape(body, &def, &circle);
    } else if (s->kind == B2S_PLAN_SHAPE_KIND_POLYGON) {
        b2Hull hull = {.count = n}; /* already b2ComputeHull's points */
        for (int i = 0; i < n; ++i) hull.points[i] = vec(p[i]);
        b2Polygon polygon = b2MakePolygon(&hull, 0.0f);
        b2CreatePolygonShape(body, &def, &polygon);
    } else if (s->kind == B2S_PLAN_SHAPE_KIND_SEGMENT) {
        b2Segment segment = {vec(p[0]), vec(p[1])};
        b2CreateSegmentShape(body, &def, &segment);
    } else { /* a chain ([ghost, vertices..., ghost]) or a loop: v3.1's b2ChainDef */
        b2Vec2* points = malloc((size_t)n * sizeof *points);
        if (points == NULL) return;
        for (int i = 0; i < n; ++i) points[i] = vec(p[i]);
        b2ChainDef chain = b2DefaultChainDef();
        chain.points = points;
        chain.count = n;
        chain.isLoop = s->kind == B2S_PLAN_SHAPE_KIND_LOOP;
        chain.materials = &def.material;
        chain.materialCount = 1;
        chain.filter = def.filter;
        chain.enableSensorEvents = def.enableSensorEvents;
        b2CreateChain(body, &chain);
        free(points);
    }
}

static b2BodyId make_body(const b2s_plan_view* plan, const b2s_plan_body* b, b2WorldId world) {
    b2BodyDef def = b2DefaultBodyDef();
    def.type = (b2BodyType)b->kind;
    def.position = vec(b->position);
    def.rotation = (b2Rot){b->rotation.c, b->rotation.s};
    def.linearVelocity = vec(b->linear_velocity);
    def.angularVelocity = b->angular_velocity;
    def.linearDamping = b->linear_damping;
    def.angularDamping = b->angular_damping;
    def.gravityScale = b->gravity_scale;
    def.enableSleep = b->allow_sleep;
    def.isAwake = b->awake;
    def.fixedRotation = b->fixed_rotation;
    def.isBullet = b->bullet;
    def.isEnabled = b->enabled;
    def.name = b->name;
    b2BodyId id = b2CreateBody(world, &def);
    for (uint32_t i = 0; i < b->shapes.count; ++i) {
        make_shape(plan, &plan->shapes[b->shapes.first + i], id);
    }
    if (b->apply_mass_from_shapes) b2Body_ApplyMassFromShapes(id);
    if (b->set_mass) {
        b2Body_SetMassData(id, (b2MassData){b->mass.mass, vec(b->mass.center), b->mass.inertia});
    }
    if (b->set_velocity) b2Body_SetLinearVelocity(id, vec(b->velocity_after_mass));
    return id;
}

/* Every v3.1 joint def has its bodies and collideConnected. */
#define CONNECT(def, port, j)                                                                  \
    ((def).bodyIdA = (port)->bodies[(j)->body_a], (def).bodyIdB = (port)->bodies[(j)->body_b], \
     (def).collideConnected = (j)->collide_connected)

static b2JointId make_joint(const port_world* port, const b2s_plan_joint* j) {
    switch (j->kind) {
    case B2S_PLAN_JOINT_KIND_REVOLUTE: {
        b2RevoluteJointDef def = b2DefaultRevoluteJointDef();
        CONNECT(def, port, j);
        def.localAnchorA = vec(j->anchor_a);
        def.localAnchorB = vec(j->anchor_b);
        def.referenceAngle = j->reference_angle;
        def.enableLimit = j->enable_limit;
        def.lowerAngle = j->lower;
        def.upperAngle = j->upper;
        def.enableMotor = j->enable_motor;
        def.motorSpeed = j->motor_speed;
        def.maxMotorTorque = j->max_motor;
        return b2CreateRevoluteJoint(port->world, &def);
    }
    case B2S_PLAN_JOINT_KIND_PRISMATIC: {
        b2PrismaticJointDef def = b2DefaultPrismaticJointDef();
        CONNECT(def, port, j);
        def.localAnchorA = vec(j->anchor_a);
        def.localAnchorB = vec(j->anchor_b);
        def.localAxisA = vec(j->axis);
        def.referenceAngle = j->reference_angle;
        def.enableLimit = j->enable_limit;
        def.lowerTranslation = j->lower;
        def.upperTranslation = j->upper;
        def.enableMotor = j->enable_motor;
        def.motorSpeed = j->motor_speed;
        def.maxMotorForce = j->max_motor;
        return b2CreatePrismaticJoint(port->world, &def);
    }
    case B2S_PLAN_JOINT_KIND_DISTANCE: { /* a rod, a spring, or a rope (its limit on) */
        b2DistanceJointDef def = b2DefaultDistanceJointDef();
        CONNECT(def, port, j);
        def.localAnchorA = vec(j->anchor_a);
        def.localAnchorB = vec(j->anchor_b);
        def.length = j->length;
        def.enableSpring = j->enable_spring;
        def.hertz = j->hertz;
        def.dampingRatio = j->damping_ratio;
        if (j->enable_limit) { /* else v3.1's own defaults stand */
            def.enableLimit = true;
            def.minLength = j->min_length;
            def.maxLength = j->max_length;
        }
        return b2CreateDistanceJoint(port->world, &def);
    }
    case B2S_PLAN_JOINT_KIND_WHEEL: { /* a wheel, or a line joint: no spring */
        b2WheelJointDef def = b2DefaultWheelJointDef();
        CONNECT(def, port, j);
        def.localAnchorA = vec(j->anchor_a);
        def.localAnchorB = vec(j->anchor_b);
        def.localAxisA = vec(j->axis);
        def.enableSpring = j->enable_spring;
        if (j->enable_spring) { /* else v3.1's own defaults stand */
            def.hertz = j->hertz;
            def.dampingRatio = j->damping_ratio;
        }
        def.enableLimit = j->enable_limit;
        def.lowerTranslation = j->lower;
        def.upperTranslation = j->upper;
        def.enableMotor = j->enable_motor;
        def.motorSpeed = j->motor_speed;
        def.maxMotorTorque = j->max_motor;
        return b2CreateWheelJoint(port->world, &def);
    }
    case B2S_PLAN_JOINT_KIND_WELD: {
        b2WeldJointDef def = b2DefaultWeldJointDef();
        CONNECT(def, port, j);
        def.localAnchorA = vec(j->anchor_a);
        def.localAnchorB = vec(j->anchor_b);
        def.referenceAngle = j->reference_angle;
        def.linearHertz = 0.0f;
        def.angularHertz = j->hertz;
        def.angularDampingRatio = j->damping_ratio;
        return b2CreateWeldJoint(port->world, &def);
    }
    case B2S_PLAN_JOINT_KIND_FRICTION: /* v3.1's motor joint; a friction one has no offsets */
    case B2S_PLAN_JOINT_KIND_MOTOR: {
        b2MotorJointDef def = b2DefaultMotorJointDef();
        CONNECT(def, port, j);
        def.linearOffset = vec(j->linear_offset);
        def.angularOffset = j->angular_offset;
        def.maxForce = j->max_force;
        def.maxTorque = j->max_torque;
        def.correctionFactor = j->correction_factor;
        return b2CreateMotorJoint(port->world, &def);
    }
    default: return b2_nullJointId; /* the v3.1 plan holds no other kind */
    }
}

/* The world, its bodies with their shapes, then its joints; the plan's reports printed.
 * False when the plan cannot be made (out of memory). */
static bool port_build(const b2s_scene* scene, port_world* port) {
    b2WorldDef def = b2DefaultWorldDef();
    def.gravity = vec(b2s_plan_world_gravity(scene, B2S_ENGINE_BOX2D31, (b2s_vec2){0.0f, -10.0f}));
    def.maximumLinearSpeed = b2s_engine_working_range(B2S_ENGINE_BOX2D31)->world_max_linear_speed;
    port->world = b2CreateWorld(&def);
    b2s_plan_options options = {.engine = B2S_ENGINE_BOX2D31};
    options.placement.q.c = 1.0f; /* placed where the file says */
    options.gravity = (b2s_vec2){def.gravity.x, def.gravity.y};
    options.max_linear_speed = def.maximumLinearSpeed;
    b2s_plan* made = NULL;
    b2s_error error;
    if (b2s_plan_make(scene, &options, &made, &error) != B2S_CODE_OK) {
        fprintf(stderr, "no plan: %s\n", error.message);
        return false;
    }
    const b2s_plan_view* plan = b2s_plan_get_view(made);
    for (uint32_t i = 0; i < plan->report_count; ++i) {
        const b2s_plan_report* r = &plan->reports[i];
        printf("%s %s %u: %s\n", b2s_code_name((b2s_code)r->code), r->object, r->index,
               r->message);
    }
    port->body_count = b2s_scene_get_view(scene)->body_count;
    port->joint_count = plan->joint_count;
    port->report_count = plan->report_count;
    port->bodies = calloc(port->body_count + 1, sizeof *port->bodies);
    port->joints = calloc(port->joint_count + 1, sizeof *port->joints);
    bool ok = port->bodies != NULL && port->joints != NULL;
    for (uint32_t i = 0; ok && i < plan->body_count; ++i) {
        port->bodies[plan->bodies[i].body] = make_body(plan, &plan->bodies[i], port->world);
    }
    for (uint32_t i = 0; ok && i < plan->joint_count; ++i) {
        port->joints[i] = make_joint(port, &plan->joints[i]);
    }
    b2s_plan_free(made);
    return ok;
}

static void port_free(port_world* port) {
    b2DestroyWorld(port->world);
    free(port->bodies);
    free(port->joints);
}

#ifndef PORT_V31_NO_MAIN
int main(int argc, char** argv) {
    const char* path = argc > 1 ? argv[1] : BOX2SCENE_EXAMPLE_SCENE;
    int steps = argc > 2 ? atoi(argv[2]) : 60;
    b2s_scene* scene = NULL;
    b2s_error error;
    if (b2s_load_file(path, NULL, &scene, &error) != B2S_CODE_OK) {
        fprintf(stderr, "%s:%u:%u: %s\n", path, error.line, error.column, error.message);
        return 1;
    }
    port_world port = {0};
    bool built = port_build(scene, &port);
    b2s_scene_free(scene); /* the world does not refer to the scene */
    for (int i = 0; built && i < steps; ++i) b2World_Step(port.world, 1.0f / 60.0f, 4);
    for (uint32_t i = 0; built && i < port.body_count; ++i) {
        if (B2_IS_NULL(port.bodies[i])) continue;
        b2Vec2 p = b2Body_GetPosition(port.bodies[i]);
        printf("body %u: (%.4f, %.4f) %.4f rad\n", i, p.x, p.y,
               b2Rot_GetAngle(b2Body_GetRotation(port.bodies[i])));
    }
    port_free(&port);
    return built ? 0 : 1;
}
#endif
