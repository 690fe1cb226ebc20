/*
 * box2scene/box2d32.h: builds a Box2D v3.2 world (b2WorldId) from a loaded box2scene scene,
 * and captures bodies of a live v3.2 world back into a scene: the functions, ids and reports
 * of box2scene/box2d3.h (Box2D v3.1), named b2s_box2d32_*. Its own code is C99 and its
 * declarations are usable from C++; Box2D v3.2's headers, which it includes, need C11.
 * Needs <box2d/box2d.h> (Box2D v3.2, single precision) and <box2scene.h>.
 *
 * Which v3.2: built and tested against upstream commit 56edae79 (June 2026, the sources of
 * boxdd-sys 0.6.0), the API it calls checked against main 617d32ab (August 2026). The tagged
 * 3.2.0 release (October 2026) changed the chain API, which the adapter does not call, and is
 * not available here to build: it is untested.
 *
 * The implementation is compiled where the host defines B2S_BOX2D32_IMPLEMENTATION, in
 * exactly one C file, before including this header (CMake's box2scene::box2d32 target does
 * that for you). It compiles as C, against the host's own Box2D v3.2.
 *
 *     b2s_scene* scene = NULL;
 *     if (b2s_load_file("level.xml", NULL, &scene, NULL) == B2S_CODE_OK) {
 *         b2WorldDef def = b2s_box2d32_world_def(scene, (b2Vec2){0.0f, -10.0f});
 *         b2WorldId world = b2CreateWorld(&def);
 *         b2s_box2d32_built* built = b2s_box2d32_build_world(scene, world);
 *         // built->reports says what Box2D v3.2 could not represent.
 *         b2s_box2d32_built_free(built);
 *         b2s_scene_free(scene);  // the world does not need the scene any more
 *     }
 *
 * The adapter never prints, never aborts and never hands Box2D a value that trips one of its
 * assertions or turns into NaN: what it cannot create it skips and reports. Call it outside
 * b2World_Step. docs/box2d.md shows its use and tables the mapping.
 */
#ifndef BOX2SCENE_BOX2D32_H
#define BOX2SCENE_BOX2D32_H

/* Box2D 2.4's <box2d/box2d.h> is C++ behind the guard BOX2D_H (v3's has none): defined here, it
 * reads as empty, so that the check below, not 2.4's C++, says what is wrong. */
#ifndef BOX2D_H
#define BOX2D_H
#define B2S_BOX2D32_HID_BOX2D_24
#endif
#include <box2d/box2d.h>
#ifdef B2S_BOX2D32_HID_BOX2D_24
#undef BOX2D_H
#undef B2S_BOX2D32_HID_BOX2D_24
#endif

/* The <box2d/base.h> of v3.1 and of v3.2 define B2_HASH_INIT; only v3.2's defines B2_NULL_INDEX. */
#if !defined(B2_NULL_INDEX)
#error "box2scene/box2d32.h needs Box2D 3.2, and <box2d/box2d.h> is another version (box2scene/box2d3.h is for 3.1, box2scene/box2d.hpp for 2.4)"
#else

#include <box2scene.h>

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Something of the scene that Box2D v3.2 could not represent, or only approximately. */
typedef struct b2s_box2d32_report {
    /** B2S_CODE_SKIPPED_JOINT, B2S_CODE_LOSSY_SHAPE, B2S_CODE_BEYOND_BOX2D_RANGE, ... */
    b2s_code code;
    /** "shape", "fixture", "body", "joint" or "world" (static storage). */
    const char* object;
    /** Building: the object's index in the scene's array of that kind. Capturing: the index
     *  it has in the captured scene, or its place among the world's objects of that kind
     *  when it was not written. */
    uint32_t index;
    /** The object's Name, or NULL. */
    const char* name;
    /** What happened, for a level designer. */
    const char* message;
} b2s_box2d32_report;

/** A list of reports, owned by what holds it. */
typedef struct b2s_box2d32_reports {
    b2s_box2d32_report* items;
    uint32_t count;
} b2s_box2d32_reports;

/** What b2s_box2d32_build_world created. Every id is owned by the world. */
typedef struct b2s_box2d32_built {
    /** Indexed like the scene's bodies; b2_nullBodyId where not created. */
    b2BodyId* bodies;
    uint32_t body_count;
    /** Indexed like the scene's fixture ID pool (b2s_scene_view::fixture_ids): the v3.2 shape
     *  of each (body, fixture) pair, since a scene fixture may serve many bodies. A chain (and
     *  an edge with ghost vertices) becomes one chain segment shape per edge: `shapes` holds
     *  the first and `segments[slot]` the range of all of them in `segment_pool`. Null
     *  where not created. */
    b2ShapeId* shapes;
    b2s_range* segments;
    uint32_t fixture_count;
    b2ShapeId* segment_pool;
    uint32_t segment_pool_count;
    /** Indexed like the scene's joints; b2_nullJointId where skipped. */
    b2JointId* joints;
    uint32_t joint_count;
    /** What could not be represented, in the order it was met. */
    b2s_box2d32_reports reports;
} b2s_box2d32_built;

/** The values the adapter passes to Box2D are bounded by the library's working range for
 *  its version, b2s_engine_working_range(B2S_ENGINE_BOX2D32) (box2scene.h): an object with a value beyond
 *  them is not created (B2S_CODE_BEYOND_BOX2D_RANGE) and neither is what depends on it.
 *  docs/working-range.md gives each bound and the measurement that set it. */

/** The scene's gravity when the file gives one within the range's max_acceleration, else
 *  `fallback` (the format has no default gravity: the host decides). NULL gives fallback. */
b2Vec2 b2s_box2d32_scene_gravity(const b2s_scene* scene, b2Vec2 fallback);

/** b2DefaultWorldDef() with the scene's gravity (b2s_box2d32_scene_gravity) and a maximum
 *  linear speed of the range's world_max_linear_speed. The host may change anything else
 *  before b2CreateWorld. */
b2WorldDef b2s_box2d32_world_def(const b2s_scene* scene, b2Vec2 fallback_gravity);

/** Adds the scene's bodies, shapes and joints to `world`. Returns what it created and its
 *  reports (free it with b2s_box2d32_built_free); NULL only when memory runs out. A NULL
 *  scene adds nothing. The library plans the build (b2s_plan_make, for the world's gravity
 *  and maximum linear speed): the adapter copies the plan's reports and creates what it
 *  says, converting and checking nothing of its own. */
b2s_box2d32_built* b2s_box2d32_build_world(const b2s_scene* scene, b2WorldId world);

/** b2s_box2d32_build_world with the whole scene moved by `placement` (a rotation about the
 *  world origin, then a translation), so that one scene can be built into a world several
 *  times, as a level piece or a prefab: every body's position, rotation and linear velocity
 *  is moved; joint anchors, which are local to their bodies, and everything else are not.
 *  The placement's rotation must be normalised. A body's Angle gives its rotation times the
 *  placement's, so a capture of a placed body reads its angle back to within an ulp or two
 *  (reported). b2Transform_identity builds the scene as b2s_box2d32_build_world does. */
b2s_box2d32_built* b2s_box2d32_build_world_at(const b2s_scene* scene, b2WorldId world,
                                              b2Transform placement);

/** Frees a result of b2s_box2d32_build_world (not the world's objects). NULL is ignored. */
void b2s_box2d32_built_free(b2s_box2d32_built* built);

/** A new scene holding `bodies` of `world` (v3.2 cannot list a world's bodies: the host
 *  names them), in that order, each with its shapes (in creation order, consecutive chain
 *  segments regrouped into the chain or edge they came from) and the joints between them (in
 *  creation order): what b2s_box2d32_build_world gives back, so that a world built from a
 *  scene, captured, written, loaded and built again evolves bit for bit like the first. As
 *  b2s_box2d3_capture_world: what the scene cannot hold is reported in `reports` (free them
 *  with b2s_box2d32_reports_free), the world is not changed, B2S_CODE_INVALID_ARGUMENT names
 *  the first body that is not a live body of `world` or that was named before. */
b2s_code b2s_box2d32_capture_world(b2WorldId world, const b2BodyId* bodies, uint32_t body_count,
                                   b2s_scene** out_scene, b2s_box2d32_reports* reports,
                                   b2s_error* error);

/** b2s_box2d32_capture_world of every body `built` holds that is still live, in the scene's
 *  order, for a world built from `scene` (`built` is what building it gave, and the scene is
 *  still loaded): the save keeps the level with no host code, every body, shape, fixture and
 *  joint built from a record written with the record's Name (whole, where v3 keeps only the
 *  first bytes of a body's) and UserData, in the scene's order. A joint the build skipped
 *  (v3 has no pulley or gear) is written back as the file has it between the captured
 *  bodies, so that the joints keep their indices; one that cannot be (a Farseer-only joint,
 *  a gear before its joints) is reported. Joints the host made between those bodies follow,
 *  captured as by b2s_box2d32_capture_world. B2S_CODE_INVALID_ARGUMENT when `built` has other
 *  counts than the scene. */
b2s_code b2s_box2d32_capture_built(b2WorldId world, const b2s_box2d32_built* built,
                                   const b2s_scene* scene, b2s_scene** out_scene,
                                   b2s_box2d32_reports* reports, b2s_error* error);

/** Frees the reports of a capture and sets them empty. NULL is ignored. */
void b2s_box2d32_reports_free(b2s_box2d32_reports* reports);

/* ---- lookups: the engine object built from a named record of the scene, and back. Each
 * takes time linear in the records of its kind. */

/** The body built from the scene's first body named `name` (b2s_scene_find_body), or
 *  b2_nullBodyId when the scene has none of that name or it was not created. `built` is
 *  what building `scene` gave (a result of another scene, with other counts, finds nothing);
 *  NULL arguments give the null id. */
b2BodyId b2s_box2d32_find_body(const b2s_box2d32_built* built, const b2s_scene* scene,
                               const char* name);

/** The shape built from the scene's first fixture named `name`, on the first body that has
 *  that fixture (its first entry in the fixture ID pool): for a chain (one shape per edge),
 *  its first segment. b2_nullShapeId when there is none or it was not created. */
b2ShapeId b2s_box2d32_find_fixture(const b2s_box2d32_built* built, const b2s_scene* scene,
                                   const char* name);

/** The joint built from the scene's first joint named `name`, or b2_nullJointId when there
 *  is none or it was skipped. */
b2JointId b2s_box2d32_find_joint(const b2s_box2d32_built* built, const b2s_scene* scene,
                                 const char* name);

/** The scene body `body` was built from, by `built`: its index in the scene's bodies, or
 *  B2S_NONE when `body` is not a live body `built` holds (one the host made itself). */
uint32_t b2s_box2d32_body_index(const b2s_box2d32_built* built, b2BodyId body);

/** The entry of the fixture ID pool (b2s_scene_view::fixture_ids) that `shape` was built
 *  for, a chain's segments included: the pool's value there is the scene fixture, and the
 *  body whose fixtures range holds the entry is its body. B2S_NONE when `shape` is not a
 *  live shape `built` holds. */
uint32_t b2s_box2d32_shape_slot(const b2s_box2d32_built* built, b2ShapeId shape);

/** The scene joint `joint` was built from: its index in the scene's joints, or B2S_NONE. */
uint32_t b2s_box2d32_joint_index(const b2s_box2d32_built* built, b2JointId joint);

#ifdef __cplusplus
} /* extern "C" */
#endif

#ifdef B2S_BOX2D32_IMPLEMENTATION
#include "detail/box2d3/v32.h"
#include "detail/box2d3/adapter.c"
#endif

#endif /* Box2D 3.2 */

#endif /* BOX2SCENE_BOX2D32_H */
