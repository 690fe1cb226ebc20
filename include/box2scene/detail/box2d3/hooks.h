/*
 * The hooks of one Box2D v3 version: every name the adapter's sources (world.c, shapes.c,
 * bodies.c, joints.c, capture.c, lookup.c) take from the version's own header (v31.h for
 * v3.1, v32.h for v3.2), the one place where two v3 versions differ. A header for another
 * v3 version defines each of them, and nothing else the adapter reads. adapter.c includes
 * this file after the version's header: the compiler then holds each definition to the
 * declaration here, and a hook left out is an error (a macro) or a warning that the tests'
 * -Werror makes one (a function declared static and never defined).
 *
 * What each hook is for, in the order a build and a capture meet them:
 *   names       B2S3_API(name) the public name of `name` (b2s_box2d3_name, b2s_box2d32_name);
 *               B2S3_ENGINE_VERSION the plan's engine (B2S_ENGINE_BOX2D31, ...); B2S3_ENGINE
 *               the engine as reports name it; b2s3_report_t, b2s3_reports_t and
 *               b2s3_built_t the public report, reports and built types
 *   bodies      B2S3_NAME_BYTES the body name bytes the build keeps (0: the working
 *               range's); how a def takes a pose and a fixed rotation; how a body gives back
 *               its origin and fixed rotation
 *   chains      the built result's store of chains (allocate, free) and one chain made of a
 *               plan's points with a shape def's material
 *   joints      B2S3_JOINT_BASE(def) the fields every joint def has; the frames of each
 *               kind from a plan joint (anchors, axis, reference angle or local frames); the
 *               motor joint and the friction joint's stand-in from a plan joint
 *   capture     a joint's frames and motor joint read as the engine holds them (the library
 *               inverts them), what a joint of a kind without a form is; the shape a fixture
 *               slot holds, and every shape it holds (a chain's segments)
 */
#ifndef BOX2SCENE_BOX2D3_HOOKS_H
#define BOX2SCENE_BOX2D3_HOOKS_H

#if !defined(B2S3_API) || !defined(B2S3_ENGINE_VERSION) || !defined(B2S3_ENGINE) ||          \
    !defined(B2S3_NAME_BYTES)
#error "a Box2D v3 version header defines B2S3_API, B2S3_ENGINE_VERSION, B2S3_ENGINE and B2S3_NAME_BYTES"
#endif
#if !defined(B2S3_JOINT_BASE) || !defined(B2S3_ANCHOR_FRAMES) ||                               \
    !defined(B2S3_REVOLUTE_FRAMES) || !defined(B2S3_WELD_FRAMES) ||                             \
    !defined(B2S3_PRISMATIC_FRAMES) || !defined(B2S3_AXIS_FRAMES)
#error "a Box2D v3 version header defines B2S3_JOINT_BASE and the frames of each joint kind"
#endif

/* ---- bodies */

static void b2s3_set_pose(b2BodyDef* def, b2Vec2 position, b2Rot rotation);
static b2Vec2 b2s3_body_position(b2BodyId body);
static void b2s3_lock_rotation(b2BodyDef* def, bool fixed);
static bool b2s3_rotation_locked(b2BodyId body);

/* ---- chains */

static bool b2s3_allocate_chains(b2s3_built_t* built, uint32_t slots);
static void b2s3_free_chains(b2s3_built_t* built);
static bool b2s3_create_chain(b2s3_built_t* built, uint32_t* capacity, uint32_t slot,
                              b2BodyId body, const b2ShapeDef* shape, const b2Vec2* points, int n,
                              bool loop);

/* ---- joints */

static void b2s3_motor_def(b2MotorJointDef* def, const b2s_plan_joint* joint);
static void b2s3_friction_def(b2MotorJointDef* def, const b2s_plan_joint* joint);

/* ---- capture */

static void b2s3_read_frames(b2JointId id, b2s_plan_joint* joint);
static void b2s3_read_motor(b2JointId id, b2s_held_joint* held);
static const char* b2s3_joint_without_form(b2JointId id);
static b2ShapeId b2s3_slot_shape(const b2s3_built_t* built, uint32_t slot);
static bool b2s3_slot_holds(const b2s3_built_t* built, uint32_t slot, b2ShapeId shape);
static int b2s3_slot_shapes(const b2s3_built_t* built, uint32_t slot, b2ShapeId* out,
                            int capacity);

#endif /* BOX2SCENE_BOX2D3_HOOKS_H */
