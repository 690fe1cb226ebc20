/*
 * box2scene/box2d.hpp: builds a Box2D 2.4 b2World from a loaded box2scene scene, and
 * captures a live b2World back into a scene.
 * Header-only C++17; needs <box2d/box2d.h> (Box2D 2.4.x) and <box2scene.h>.
 *
 *     b2s_scene* scene = nullptr;
 *     if (b2s_load_file("level.xml", nullptr, &scene, nullptr) == B2S_CODE_OK) {
 *         b2World world(box2scene::scene_gravity(scene, b2Vec2(0.0f, -10.0f)));
 *         box2scene::Built built = box2scene::build_world(scene, world);
 *         // built.reports says what Box2D 2.4 could not represent.
 *         b2s_scene_free(scene);  // the world does not need the scene any more
 *     }
 *
 *     std::vector<box2scene::Report> reports;  // what the file cannot hold exactly
 *     b2s_scene* saved = box2scene::capture_world(world, reports);
 *     b2s_write_file(saved, "saved.xml", nullptr, nullptr);
 *     b2s_scene_free(saved);
 *
 * docs/format.md tables the mapping ("Onto Box2D 2.4.1"). The library makes it: a build
 * asks it for the scene's plan for Box2D 2.4 (b2s_plan_make), which holds every body,
 * fixture and joint as Box2D's defs want them and the reports, and carries the plan out
 * through Box2D's own calls. The adapter never prints, never aborts and throws nothing for
 * bad data: what it cannot create it skips and reports. Debian's Box2D keeps its
 * assertions on, so the plan checks what they check (bodies it follows, joint kinds, a
 * negative damping, a MassData that leaves no positive inertia about the centre of mass, a
 * prismatic limit's order, a gear's bodies), whether or not the loader in use already
 * refuses it: a report is better than an abort. Values past box2scene::working_range(),
 * where Box2D would compute inf or NaN, are reported and their objects not created.
 * Call it outside b2World::Step (Box2D refuses to add objects to a locked world).
 */
#ifndef BOX2SCENE_BOX2D_HPP
#define BOX2SCENE_BOX2D_HPP

#include <box2d/box2d.h>
#include <box2scene.h>

#include <cstdint>
#include <string>
#include <vector>

namespace box2scene {

/// Something of the scene that Box2D 2.4 could not represent, or only approximately.
struct Report {
    b2s_code code;       ///< B2S_CODE_LOSSY_LINE_MOTOR, B2S_CODE_SKIPPED_JOINT, ...
    const char* object;  ///< "shape", "fixture", "body", "joint" or "world" (static storage)
    /// build_world: the object's index in the scene's array of that kind; capture_world: its
    /// place among the world's objects of that kind in creation order (a fixture's and its
    /// shape's: counted over the bodies in creation order).
    uint32_t index;
    std::string name;    ///< the object's Name, empty when it has none
    std::string message; ///< what happened, for a level designer
};

/// What build_world created. Every pointer is owned by the b2World.
struct Built {
    /// Indexed like the scene's bodies; nullptr where not created.
    std::vector<b2Body*> bodies;
    /// Indexed like the scene's fixture ID pool (b2s_scene_view::fixture_ids): one b2Fixture
    /// per (body, fixture) pair, since a scene fixture may serve many bodies; nullptr where
    /// not created. A body's fixtures are the slots its b2s_body::fixtures range names.
    std::vector<b2Fixture*> fixtures;
    /// Indexed like the scene's joints; nullptr where skipped.
    std::vector<b2Joint*> joints;
    /// What could not be represented, in the order it was met.
    std::vector<Report> reports;
};

/// The scene's gravity when the file gives one within working_range().max_acceleration, else
/// `fallback` (the format has no default gravity: the host decides; build_world reports a
/// gravity beyond the range). A NULL scene gives `fallback`.
inline b2Vec2 scene_gravity(const b2s_scene* scene, b2Vec2 fallback);

/// Adds the scene's bodies, fixtures and joints to `world`, in time linear in their number
/// (each body's mass is computed once, after all its fixtures). A NULL scene adds nothing.
inline Built build_world(const b2s_scene* scene, b2World& world);

/// build_world with the whole scene moved by `placement` (a rotation about the world origin,
/// then a translation), so that one scene can be built into a world several times, as a
/// level piece or a prefab: every body's position and linear velocity is moved and its angle
/// turned by the placement's, and a pulley's ground anchors (world points) are moved; joint
/// anchors, local to their bodies, and everything else are not. The placement's rotation
/// must be normalised; one that is not, or a translation not finite or beyond
/// working_range().max_length, builds nothing and is reported (B2S_CODE_INVALID_ARGUMENT, on the
/// world). The identity builds the scene as build_world does.
inline Built build_world_at(const b2s_scene* scene, b2World& world, const b2Transform& placement);

/// The values build_world passes to Box2D 2.4: the library's measured table for it
/// (b2s_working_range, docs/working-range.md gives each bound's measurement). The format,
/// and the loader, accept any finite float; Box2D does not: near FLT_MAX its solver computes
/// inf and NaN, or trips an assertion (Debian's Box2D keeps them). An object with a value
/// beyond these bounds is not created: build_world reports it (B2S_CODE_BEYOND_BOX2D_RANGE,
/// naming the field and the value) and what depends on it (B2S_CODE_SKIPPED_DEPENDENT).
inline const b2s_working_range& working_range() {
    return *b2s_engine_working_range(B2S_ENGINE_BOX2D24);
}

// ---- capture: a live b2World back into a scene, so that a host can save its level

/// The code of a capture report for a value the format cannot hold exactly, written as near
/// as it can (the message says what changed): the library's B2S_CODE_LOSSY_CAPTURE, which
/// b2s_code_name calls "lossy-capture".
inline constexpr b2s_code lossy_capture_code = B2S_CODE_LOSSY_CAPTURE;

/// A Name and UserData that capture_world gives one object; an empty string gives none.
struct Label {
    std::string name;
    /// UserData as XML content, written verbatim; it wins over type_name and value.
    std::string user_data_raw;
    /// UserData in the editor's form: a type name (`System.String`) and its value.
    std::string user_data_type;
    std::string user_data_value;
};

/// Names and UserData for what capture_world writes, usually found from each object's
/// Box2D user data. Override what you need; the rest stays unnamed. Objects that Box2D
/// holds once per fixture (its shape, its material) are shared in the scene only when
/// their labels agree.
class Namer {
public:
    virtual ~Namer() = default;
    virtual Label body(b2Body&) const { return {}; }
    virtual Label fixture(b2Fixture&) const { return {}; }
    virtual Label joint(b2Joint&) const { return {}; }
    /// Shapes have a Name and no UserData.
    virtual std::string shape(b2Fixture&) const { return {}; }
};

/// A new scene holding `world`: its gravity, bodies in their current state, fixtures and
/// shapes (equal ones shared, as the editor wrote them) and joints, in creation order, so
/// that build_world recreates them in that order and the rebuilt world evolves bit for bit
/// like this one. Derived values are inverted exactly: MassData is written only where it
/// differs from what the fixtures give, spring stiffness and damping become the
/// FrequencyHz and DampingRatio that give back the same bits, a polygon keeps its centroid.
/// Appends to `reports` what the scene does not hold (a mouse joint, a gear on it: not
/// written) or holds only approximately (lossy_capture_code). The caller owns the scene
/// (b2s_scene_free); nullptr only if the library fails to finish it (reported).
///
/// Exactness needs the world to be the scene build_world would make: each body created
/// with its fixtures before the next, gears after every other joint, nothing destroyed
/// (Box2D recycles broad-phase proxies). A world captured in motion keeps each body's
/// state exactly, but not what Box2D carries from step to step (contacts, warm-starting
/// impulses, sleep timers), so it evolves alike, not bit for bit. The world's switches
/// (SetAllowSleeping, SetWarmStarting, ...) are the host's, not the scene's.
/// The world is not changed; it is not const because Box2D 2.4 declares GetUserData,
/// GetBodyA and GetJoint1 non-const. Call it outside b2World::Step.
inline b2s_scene* capture_world(b2World& world, std::vector<Report>& reports,
                                const Namer* namer = nullptr);

/// capture_world of a world that build_world made from `scene` (`built` is what it gave,
/// and the scene is still loaded), which keeps the level with no host code: every body,
/// fixture, shape and joint built from a record is written with the record's Name and
/// UserData (the Namer's label wins where it gives one; it labels the host's own objects),
/// joints in the scene's order: one build_world skipped (beyond the working range, or
/// depending on one that is) is written back as the file has it, so that every joint keeps
/// its index; a gear that the file puts before its joints comes right after them, as the
/// format wants. Nothing the build made may have been destroyed since: Box2D reuses its
/// memory for what the host creates next, which would then be taken for the level's.
/// Where the engine still holds exactly what the build set from a record, the record's own
/// values are written back rather than ones inverted from the engine's: a spring's
/// FrequencyHz and DampingRatio, which Box2D 2.4 holds as a stiffness and damping computed
/// from them and the bodies, come back as the level gave them, and the world built again
/// from the capture moves like this one to the bit. Everything else is as for
/// capture_world.
inline b2s_scene* capture_world(b2World& world, const Built& built, const b2s_scene* scene,
                                std::vector<Report>& reports, const Namer* namer = nullptr);

// ---- lookups: the engine object built from a named record of the scene, and back. Each
// takes time linear in the records of its kind.

/// The b2Body built from the scene's first body named `name` (b2s_scene_find_body), or
/// nullptr when the scene has none of that name or it was not created. `built` is what
/// build_world made of `scene` (a result of another scene, with other counts, finds
/// nothing); a NULL scene or name finds nothing.
inline b2Body* find_body(const Built& built, const b2s_scene* scene, const char* name);

/// The b2Fixture built from the scene's first fixture named `name`, on the first body that
/// has that fixture (its first entry in the fixture ID pool), or nullptr.
inline b2Fixture* find_fixture(const Built& built, const b2s_scene* scene, const char* name);

/// The b2Joint built from the scene's first joint named `name`, or nullptr (also when it
/// was skipped).
inline b2Joint* find_joint(const Built& built, const b2s_scene* scene, const char* name);

/// The scene body `body` was built from: its index in the scene's bodies (and in
/// built.bodies), or B2S_NONE when `built` does not hold it (a body the host made itself).
inline uint32_t body_index(const Built& built, const b2Body* body);

/// The entry of the fixture ID pool (b2s_scene_view::fixture_ids, and built.fixtures) that
/// `fixture` was built for: the pool's value there is the scene fixture, and the body whose
/// fixtures range holds the entry is its body. B2S_NONE when `built` does not hold it.
inline uint32_t fixture_slot(const Built& built, const b2Fixture* fixture);

/// The scene joint `joint` was built from: its index in the scene's joints, or B2S_NONE.
inline uint32_t joint_index(const Built& built, const b2Joint* joint);

/// Owns a scene: b2s_scene_free when it goes out of scope or is given another. Movable, not
/// copyable (a scene is freed once).
///
///     box2scene::Scene scene;
///     if (b2s_load_file("level.xml", nullptr, scene.out(), nullptr) == B2S_CODE_OK) { ... }
class Scene {
public:
    Scene() noexcept = default;
    /// Takes ownership of `scene` (nullptr is fine).
    explicit Scene(b2s_scene* scene) noexcept : scene_(scene) {}
    Scene(Scene&& other) noexcept : scene_(other.release()) {}
    Scene& operator=(Scene&& other) noexcept {
        reset(other.release());
        return *this;
    }
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;
    ~Scene() { b2s_scene_free(scene_); }

    b2s_scene* get() const noexcept { return scene_; }
    explicit operator bool() const noexcept { return scene_ != nullptr; }
    /// Frees the scene held and takes `scene`.
    void reset(b2s_scene* scene = nullptr) noexcept {
        b2s_scene* old = scene_;
        scene_ = scene;
        b2s_scene_free(old);
    }
    /// Gives the scene up without freeing it: the caller owns it.
    b2s_scene* release() noexcept {
        b2s_scene* scene = scene_;
        scene_ = nullptr;
        return scene;
    }
    /// Frees the scene held and gives where a loader stores the next (b2s_load_file's
    /// `out_scene`).
    b2s_scene** out() noexcept {
        reset();
        return &scene_;
    }

private:
    b2s_scene* scene_ = nullptr;
};

} // namespace box2scene

// The definitions, cut by concept as the v3 adapter's sources are (detail/box2d3/): what the
// build and the capture share, the world (the build, carrying out the library's plan), its
// shapes, bodies and joints, the capture, the lookups.
#include "detail/box2d/reports.hpp"
#include "detail/box2d/world.hpp"
#include "detail/box2d/shapes.hpp"
#include "detail/box2d/bodies.hpp"
#include "detail/box2d/joints.hpp"
#include "detail/box2d/capture.hpp"
#include "detail/box2d/lookup.hpp"

#endif // BOX2SCENE_BOX2D_HPP
