// Nothing Box2D cannot take: a scene that loads builds, through the adapter, a world whose
// bodies stay finite for 600 steps, and nothing aborts on one of Box2D's assertions. The
// scenes are every file of the project, and generated levels with every shape and joint
// kind whose fields are drawn from ordinary ranges and, one in 40, from extremes (the
// largest floats, subnormals, negative zero, the edges of the adapter's working range).
//
// Every one of them must stay finite. Box2D's solver can diverge on an assembly whatever
// its values (a light body carrying a heavy one far out on a prismatic joint, a kinematic
// body crushing a chain of joints: "the solver can't handle this setup",
// erincatto/box2d#984), so each generated level is written twice in one pass, with its
// extremes and with the ordinary values they replaced. A level that diverges fails the
// test either way; its ordinary twin tells which fix it needs: a tighter working range in
// the adapter (the twin stays finite), or a generator that stops writing an assembly
// Box2D cannot hold (the twin diverges too).
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "test_macros.h"
#include "test_scenes.hpp"
#include "test_worlds.hpp"

static const int kSteps = 600;
static const int kGeneratedScenes = 2000; // that load; more are generated

// ---- stepping a built world

/// Whether every created body's position, angle and velocities are finite.
static bool bodies_finite(const box2scene::Built& built) {
    for (const b2Body* body : built.bodies) {
        if (body == nullptr) {
            continue;
        }
        b2Vec2 p = body->GetPosition(), v = body->GetLinearVelocity();
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(body->GetAngle()) ||
            !std::isfinite(v.x) || !std::isfinite(v.y) ||
            !std::isfinite(body->GetAngularVelocity())) {
            return false;
        }
    }
    return true;
}

/// What the sweeps saw, for the summary line.
struct Tally {
    int files = 0;
    int generated = 0;
    int loaded = 0;
    int beyond_range = 0;
    int skipped_dependent = 0;
};

static Tally tally;

static void count_reports(const box2scene::Built& built) {
    for (const box2scene::Report& report : built.reports) {
        tally.beyond_range += report.code == B2S_CODE_BEYOND_BOX2D_RANGE;
        tally.skipped_dependent += report.code == B2S_CODE_SKIPPED_DEPENDENT;
    }
}

/// Steps the world `steps` times: the step after which a body stopped being finite (0: as
/// built), or -1 when none did.
static int first_step_not_finite(World& world, int steps = kSteps) {
    for (int step = 0; step <= steps; ++step) {
        if (!bodies_finite(world.built)) {
            return step;
        }
        if (step < steps) {
            step_once(world.world);
        }
    }
    return -1;
}

// ---- generated levels

/// splitmix64: small, and the same sequence on every platform.
class Random {
public:
    explicit Random(uint64_t seed) : state_(seed) {}

    uint64_t next() {
        uint64_t z = (state_ += 0x9E3779B97F4A7C15u);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
        return z ^ (z >> 31);
    }
    uint32_t below(uint32_t n) { return static_cast<uint32_t>(next() % n); }
    bool chance(double p) { return static_cast<double>(next() >> 11) * 0x1p-53 < p; }
    float uniform(float low, float high) {
        double unit = static_cast<double>(next() >> 40) * 0x1p-24;
        return low + (high - low) * static_cast<float>(unit);
    }

private:
    uint64_t state_;
};

/// Floats a level never holds, and the edges of the adapter's working range.
static const float kExtremes[] = {
    FLT_MAX, -FLT_MAX, 1e38f,   -1e30f, 1e20f,    1e10f,     1e6f, -1e6f,  1.0001e5f, 1e5f, -1e5f,
    1e4f,    -1e3f,    FLT_MIN, 1e-40f, 1.4e-45f, -1.4e-45f, 0.0f, -0.0f, 1e-20f,    1e-7f};
static const uint32_t kExtremeCount = sizeof kExtremes / sizeof kExtremes[0];

/// A value of the level with its extremes, and of its ordinary twin.
struct Pair {
    float extreme, plain;
};

/// Text of both levels.
struct Twin {
    std::string extreme, plain;

    Twin& operator+=(const Twin& more) {
        extreme += more.extreme;
        plain += more.plain;
        return *this;
    }
    Twin& operator+=(const std::string& both) { return *this += Twin{both, both}; }
};

static std::string text(float v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(v));
    return buffer;
}

static Twin text(Pair v) {
    return Twin{text(v.extreme), text(v.plain)};
}

static Twin text(Pair x, Pair y) {
    return Twin{text(x.extreme) + " " + text(y.extreme), text(x.plain) + " " + text(y.plain)};
}

enum JointKind : uint32_t {
    kRevolute, kPrismatic, kDistance, kPulley, kLine, kWeld, kFriction, kWheel, kRope, kMotor,
    kJointKinds, // a gear couples two joints made before it
};
static const char* const kJointTypes[] = {"Revolute", "Prismatic", "Distance", "Pulley",
                                          "Line",     "Weld",      "Friction", "Wheel",
                                          "Rope",     "Motor"};

/// Whether each body of `draft` (a level without joints) yields to a joint: it is created,
/// dynamic and has mass. A joint network holding two bodies that do not yield contradicts
/// itself as soon as one moves.
static std::vector<bool> yielding_bodies(const std::string& draft) {
    std::vector<bool> yielding;
    b2s_scene* scene = nullptr;
    if (b2s_load_memory(reinterpret_cast<const uint8_t*>(draft.data()), draft.size(), nullptr,
                        &scene, nullptr) != B2S_CODE_OK) {
        return yielding;
    }
    World world{ScenePtr(scene)};
    for (const b2Body* body : world.built.bodies) {
        yielding.push_back(body != nullptr && body->GetType() == b2_dynamicBody &&
                           body->GetMass() > 0.0f);
    }
    return yielding;
}

/// Where a generated body starts, in one of the twins: what its joints derive from.
struct Pose {
    b2Transform at;
    float angle; // as written, unwrapped: Box2D's joint angles are differences of these
};

/// Writes a level and its ordinary twin. Joints are made as an editor makes them: each
/// body that yields hangs from at most one earlier body, anchored at a shared world point,
/// with the reference angle of the poses, so that every joint starts satisfied and none
/// contradicts another (Box2D diverges on those, whatever their values).
class LevelWriter {
public:
    explicit LevelWriter(Random& random) : random_(random) {}

    Twin level() {
        xml_ = Twin{};
        poses_.clear();
        xml_ += "<World Version=\"2\">";
        if (random_.chance(0.7)) {
            element("Gravity", vec(-20.0f, 20.0f));
        }
        uint32_t shapes = 1 + random_.below(4), fixtures = 1 + random_.below(4);
        uint32_t bodies = 1 + random_.below(5);
        xml_ += "<Shapes>";
        for (uint32_t i = 0; i < shapes; ++i) {
            shape();
        }
        xml_ += "</Shapes><Fixtures>";
        for (uint32_t i = 0; i < fixtures; ++i) {
            fixture(shapes);
        }
        xml_ += "</Fixtures><Bodies>";
        for (uint32_t i = 0; i < bodies; ++i) {
            body(fixtures);
        }
        xml_ += "</Bodies>";
        // Both twins get the same joints, laid out by the ordinary one.
        std::vector<bool> yielding = yielding_bodies(xml_.plain + "<Joints /></World>");
        xml_ += "<Joints>";
        if (yielding.size() == bodies) {
            joints(yielding);
        }
        xml_ += "</Joints></World>";
        return xml_;
    }

private:
    /// `ordinary` in the twin; in the level, 1 time in 40 an extreme (a level has some 60
    /// values). `beyond` draws only extremes beyond the working range: for what places a
    /// joint, where one within it would start the joint far from satisfied.
    Pair extreme_or(Pair ordinary, bool beyond = false) {
        if (!random_.chance(1.0 / 40.0)) {
            return ordinary;
        }
        float v = kExtremes[random_.below(kExtremeCount)];
        while (beyond && !(std::fabs(v) > box2scene::working_range().max_length)) {
            v = kExtremes[random_.below(kExtremeCount)];
        }
        return Pair{v, ordinary.plain};
    }
    Pair value(float low, float high) {
        float v = random_.uniform(low, high);
        return extreme_or(Pair{v, v});
    }

    Twin scalar(float low, float high) { return text(value(low, high)); }
    Twin vec(float low, float high) { return text(value(low, high), value(low, high)); }
    Twin boolean(double p) { return Twin{} += random_.chance(p) ? "true" : "false"; }
    Twin integer(uint32_t v) { return Twin{} += std::to_string(v); }
    /// What places a joint (an anchor, a reference angle, a length): `at[0]` in the level,
    /// `at[1]` in the twin.
    Twin placing(const b2Vec2 (&at)[2]) {
        return text(extreme_or(Pair{at[0].x, at[1].x}, true),
                    extreme_or(Pair{at[0].y, at[1].y}, true));
    }
    Twin placing(const float (&at)[2]) { return text(extreme_or(Pair{at[0], at[1]}, true)); }

    void element(const char* name, const Twin& content) {
        xml_ += std::string("<") + name + ">";
        xml_ += content;
        xml_ += std::string("</") + name + ">";
    }

    void vertices(const std::vector<Twin>& points) {
        xml_ += "<Vertices>";
        for (const Twin& p : points) {
            element("Vertex", p);
        }
        xml_ += "</Vertices>";
    }

    /// A point of a convex polygon or a chain around `centre`, `turn` of the way round.
    Twin around(Pair cx, Pair cy, Pair radius, float turn) {
        float c = std::cos(6.2831853f * turn), s = std::sin(6.2831853f * turn);
        float jx = random_.uniform(-0.01f, 0.01f), jy = random_.uniform(-0.01f, 0.01f);
        Pair x{cx.extreme + radius.extreme * c + jx, cx.plain + radius.plain * c + jx};
        Pair y{cy.extreme + radius.extreme * s + jy, cy.plain + radius.plain * s + jy};
        return text(extreme_or(x), extreme_or(y));
    }

    void shape() {
        switch (random_.below(5)) {
        case 0:
            xml_ += "<Shape Type=\"Circle\">";
            element("Radius", scalar(0.05f, 2.0f));
            element("Position", vec(-1.0f, 1.0f));
            break;
        case 1: polygon(); break;
        case 2:
            xml_ += "<Shape Type=\"Polygon\">"; // Box2D 2.1's SetAsEdge: a segment
            vertices({vec(-3.0f, 0.0f), vec(0.5f, 3.0f)});
            break;
        case 3: edge(); break;
        default: chain(); break;
        }
        xml_ += "</Shape>";
    }

    void polygon() {
        xml_ += "<Shape Type=\"Polygon\">";
        uint32_t count = 3 + random_.below(6);
        Pair radius = value(0.1f, 2.0f), cx = value(-1.0f, 1.0f), cy = value(-1.0f, 1.0f);
        std::vector<Twin> points;
        for (uint32_t i = 0; i < count; ++i) {
            points.push_back(around(cx, cy, radius, static_cast<float>(i) / count));
        }
        vertices(points);
        if (random_.chance(0.3)) {
            element("Centroid", vec(-1.0f, 1.0f));
        }
    }

    void edge() {
        xml_ += "<Shape Type=\"Edge\">";
        element("Vertex1", vec(-5.0f, 0.0f));
        element("Vertex2", vec(0.5f, 5.0f));
        element("Vertex0", vec(-6.0f, 0.0f));
        element("HasVertex0", boolean(0.5));
        element("Vertex3", vec(0.0f, 6.0f));
        element("HasVertex3", boolean(0.5));
    }

    void chain() {
        bool loop = random_.chance(0.4);
        xml_ += loop ? "<Shape Type=\"Loop\">" : "<Shape Type=\"Chain\">";
        uint32_t count = (loop ? 3 : 2) + random_.below(5);
        Pair radius = value(1.0f, 8.0f);
        std::vector<Twin> points;
        for (uint32_t i = 0; i < count; ++i) {
            // Clockwise, so a loop keeps things inside (Box2D 2.4 chains are one-sided).
            points.push_back(around({0, 0}, {0, 0}, radius, -static_cast<float>(i) / count));
        }
        vertices(points);
        if (!loop) {
            element("PrevVertex", vec(-9.0f, 9.0f));
            element("HasPrevVertex", boolean(0.5));
            element("NextVertex", vec(-9.0f, 9.0f));
            element("HasNextVertex", boolean(0.5));
        }
    }

    void fixture(uint32_t shapes) {
        xml_ += "<Fixture>";
        element("Shape", integer(random_.below(shapes)));
        element("Density", random_.chance(0.2) ? Twin{"0", "0"} : scalar(0.1f, 5.0f));
        element("Friction", scalar(0.0f, 1.0f));
        element("Restitution", scalar(0.0f, 1.0f));
        element("IsSensor", boolean(0.1));
        xml_ += "</Fixture>";
    }

    void body(uint32_t fixtures) {
        static const char* const kinds[] = {"Static", "Dynamic", "Dynamic", "Kinematic"};
        xml_ += std::string("<Body Type=\"") + kinds[random_.below(4)] + "\">";
        Pair x = value(-5.0f, 5.0f), y = value(-5.0f, 5.0f), a = value(-3.2f, 3.2f);
        poses_.push_back({Pose{b2Transform(b2Vec2(x.extreme, y.extreme), b2Rot(a.extreme)),
                               a.extreme},
                          Pose{b2Transform(b2Vec2(x.plain, y.plain), b2Rot(a.plain)), a.plain}});
        element("Position", text(x, y));
        element("Angle", text(a));
        element("LinearVelocity", vec(-10.0f, 10.0f));
        element("AngularVelocity", scalar(-5.0f, 5.0f));
        element("LinearDamping", scalar(0.0f, 1.0f));
        element("AngularDamping", scalar(0.0f, 1.0f));
        element("GravityScale", scalar(-1.0f, 2.0f));
        element("FixedRotation", boolean(0.1));
        element("Bullet", boolean(0.2));
        element("AllowSleep", boolean(0.8));
        element("Awake", boolean(0.9));
        if (random_.chance(0.2)) {
            mass_data();
        }
        xml_ += "<Fixtures>";
        for (uint32_t i = random_.below(4); i > 0; --i) {
            element("ID", integer(random_.below(fixtures)));
        }
        xml_ += "</Fixtures></Body>";
    }

    void mass_data() {
        xml_ += "<MassData>";
        if (random_.chance(0.7)) {
            element("Mass", scalar(0.1f, 10.0f));
        }
        if (random_.chance(0.5)) {
            element("Center", vec(-0.5f, 0.5f));
        }
        if (random_.chance(0.5)) {
            element("Inertia", scalar(1.0f, 20.0f));
        }
        xml_ += "</MassData>";
    }

    /// Each body that yields may hang from one earlier body, so the joints make trees, each
    /// with at most one body that does not yield: its root, or the world a pulley hangs
    /// from.
    void joints(const std::vector<bool>& yielding) {
        std::vector<uint32_t> root(poses_.size());
        std::vector<bool> held(poses_.size()); // by root: the tree has a body that does not yield
        std::vector<uint32_t> made;            // each joint's body B
        std::vector<uint32_t> gear_inputs;     // revolute and prismatic joints
        for (uint32_t b = 0; b < poses_.size(); ++b) {
            root[b] = b;
            held[b] = !yielding[b];
            if (b == 0 || !yielding[b] || random_.chance(0.3)) {
                continue;
            }
            uint32_t a = random_.below(b);
            uint32_t kind = random_.below(kJointKinds);
            if (kind == kPulley && held[root[a]]) {
                kind = kRevolute;
            }
            if (kind == kRevolute || kind == kPrismatic) {
                gear_inputs.push_back(static_cast<uint32_t>(made.size()));
            }
            joint(kind, a, b);
            made.push_back(b);
            root[b] = root[a];
            held[root[a]] = held[root[a]] || kind == kPulley;
        }
        if (gear_inputs.size() < 2 || !random_.chance(0.5)) {
            return;
        }
        // A gear ties its joints' trees together: only one of them may be held.
        uint32_t first = gear_inputs[0], second = gear_inputs[1];
        uint32_t tree_a = root[made[first]], tree_b = root[made[second]];
        if (tree_a == tree_b || !held[tree_a] || !held[tree_b]) {
            xml_ += "<Joint Type=\"Gear\">";
            element("BodyA", integer(made[first]));
            element("BodyB", integer(made[second]));
            element("JointA", integer(first));
            element("JointB", integer(second));
            element("Ratio", scalar(-3.0f, 3.0f));
            xml_ += "</Joint>";
        }
    }

    /// A joint between bodies a and b, satisfied in their poses in each twin.
    void joint(uint32_t kind, uint32_t a, uint32_t b) {
        b2Vec2 near(random_.uniform(-1.0f, 1.0f), random_.uniform(-1.0f, 1.0f));
        b2Vec2 apart(random_.uniform(1.0f, 3.0f), random_.uniform(-1.0f, 1.0f));
        float rise_a = random_.uniform(1.0f, 3.0f), rise_b = random_.uniform(1.0f, 3.0f);
        float slack = random_.uniform(1.0f, 1.5f);
        bool spaced = kind == kDistance || kind == kPulley || kind == kRope;
        // Per twin: the world points and lengths the joint is made from.
        b2Vec2 local_a[2], local_b[2], ground_a[2], ground_b[2], offset[2];
        float relative[2], span[2], length_a[2], length_b[2];
        for (int t = 0; t < 2; ++t) {
            const Pose& pa = poses_[a][t];
            const Pose& pb = poses_[b][t];
            b2Vec2 shared = pb.at.p + near;
            b2Vec2 other = spaced ? shared + apart : shared;
            local_a[t] = b2MulT(pa.at, shared);
            local_b[t] = b2MulT(pb.at, other);
            ground_a[t] = shared + b2Vec2(0.0f, rise_a);
            ground_b[t] = other + b2Vec2(0.0f, rise_b);
            offset[t] = b2MulT(pa.at, pb.at.p);
            relative[t] = pb.angle - pa.angle;
            span[t] = b2Distance(shared, other) * (kind == kRope ? slack : 1.0f);
            length_a[t] = rise_a;
            length_b[t] = rise_b;
        }
        xml_ += std::string("<Joint Type=\"") + kJointTypes[kind] + "\">";
        element("BodyA", integer(a));
        element("BodyB", integer(b));
        element("CollideConnected", boolean(0.3));
        if (kind != kMotor) {
            element("LocalAnchorA", placing(local_a));
            element("LocalAnchorB", placing(local_b));
        }
        if (kind == kRevolute || kind == kPrismatic || kind == kWeld) {
            element("ReferenceAngle", placing(relative));
        }
        if (kind == kPrismatic || kind == kLine || kind == kWheel) {
            element("LocalAxisA", vec(-1.0f, 1.0f));
        }
        if (kind == kRevolute || kind == kPrismatic || kind == kLine) {
            element(kind == kRevolute ? "LowerAngle" : "LowerTranslation", scalar(-2.0f, 0.0f));
            element(kind == kRevolute ? "UpperAngle" : "UpperTranslation", scalar(0.0f, 2.0f));
            element("EnableLimit", boolean(0.5));
        }
        if (kind == kRevolute || kind == kPrismatic || kind == kLine || kind == kWheel) {
            element("EnableMotor", boolean(0.5));
            element("MotorSpeed", scalar(-5.0f, 5.0f));
            bool linear = kind == kPrismatic || kind == kLine;
            element(linear ? "MaxMotorForce" : "MaxMotorTorque", scalar(0.0f, 100.0f));
        }
        if (kind == kDistance || kind == kWeld || kind == kWheel) {
            element("FrequencyHz", scalar(0.0f, 10.0f));
            element("DampingRatio", scalar(0.0f, 1.0f));
        }
        if (kind == kDistance) {
            element("Length", placing(span));
        }
        if (kind == kRope) {
            element("MaxLength", placing(span));
        }
        if (kind == kPulley) {
            element("GroundAnchorA", placing(ground_a));
            element("GroundAnchorB", placing(ground_b));
            element("LengthA", placing(length_a));
            element("LengthB", placing(length_b));
            element("Ratio", scalar(0.2f, 3.0f));
        }
        if (kind == kFriction || kind == kMotor) {
            element("MaxForce", scalar(0.0f, 100.0f));
            element("MaxTorque", scalar(0.0f, 100.0f));
        }
        if (kind == kMotor) {
            element("LinearOffset", placing(offset));
            element("AngularOffset", placing(relative));
            element("CorrectionFactor", scalar(0.0f, 1.0f));
        }
        xml_ += "</Joint>";
    }

    Random& random_;
    Twin xml_;
    std::vector<std::vector<Pose>> poses_; // by body: in the level, in the twin
};

// ---- the sweeps

/// Steps of a generated level: its thousands of bodies joined at random, overlapping, make
/// their crashes at the first steps, and take most of a second each in Box2D 2.4.
static const int kLevelSteps = 10;

/// The scene at `path` built and stepped `steps` times: 0 when every body stays finite.
static int scene_stays_finite(const char* path, ScenePtr scene, int steps = kSteps) {
    ENSURE(scene != nullptr);
    ++tally.files;
    World world(std::move(scene));
    count_reports(world.built);
    int broken = first_step_not_finite(world, steps);
    if (broken >= 0) {
        std::fprintf(stderr, "%s: a body is not finite after step %d\n", path, broken);
    }
    ENSURE_EQ(broken, -1);
    return 0;
}

static int every_project_scene_stays_finite() {
    int failed = 0;
    for (const std::string& relative : project_scene_files()) {
        failed += scene_stays_finite(relative.c_str(), load_project_file(relative.c_str()));
    }
    ENSURE(tally.files >= 10);
    return failed;
}

/// Takes out of `twin` what build_world did not create in `level` (they were built from
/// scenes of the same objects): gears first, as Box2D needs, then joints, fixtures, bodies.
static void take_out_what_level_lacks(World& twin, const box2scene::Built& level) {
    for (int gears = 1; gears >= 0; --gears) {
        for (size_t i = 0; i < level.joints.size(); ++i) {
            b2Joint* joint = twin.built.joints[i];
            if (level.joints[i] == nullptr && joint != nullptr &&
                (joint->GetType() == e_gearJoint) == (gears == 1)) {
                twin.world.DestroyJoint(joint);
            }
        }
    }
    for (size_t i = 0; i < level.fixtures.size(); ++i) {
        b2Fixture* fixture = twin.built.fixtures[i];
        if (level.fixtures[i] == nullptr && fixture != nullptr) {
            fixture->GetBody()->DestroyFixture(fixture);
        }
    }
    for (size_t i = 0; i < level.bodies.size(); ++i) {
        if (level.bodies[i] == nullptr && twin.built.bodies[i] != nullptr) {
            twin.world.DestroyBody(twin.built.bodies[i]);
            twin.built.bodies[i] = nullptr;
        }
    }
}

/// Whether the ordinary twin of a level that diverged, holding the objects the level's
/// world holds, diverges too.
static bool twin_diverges(const std::string& plain, const box2scene::Built& level) {
    ScenePtr scene = load_quietly(plain);
    if (scene == nullptr) {
        return false;
    }
    World twin(std::move(scene));
    take_out_what_level_lacks(twin, level);
    return first_step_not_finite(twin) >= 0;
}

static int generated_levels_stay_finite() {
    Random random(0x5EED2B5Cu);
    LevelWriter writer(random);
    while (tally.loaded < kGeneratedScenes && tally.generated < 10 * kGeneratedScenes) {
        Twin xml = writer.level();
        ++tally.generated;
        ScenePtr scene = load_quietly(xml.extreme);
        if (scene == nullptr) {
            continue;
        }
        ++tally.loaded;
        World world(std::move(scene));
        count_reports(world.built);
        int broken = first_step_not_finite(world);
        if (broken < 0) {
            continue;
        }
        bool assembly = twin_diverges(xml.plain, world.built);
        std::fprintf(stderr, "generated level %d: a body is not finite after step %d; %s:\n%s\n",
                     tally.generated, broken,
                     assembly ? "so it is in its ordinary twin (Box2D cannot hold the assembly)"
                              : "it is finite in its ordinary twin (a value the adapter let "
                                "through is what Box2D could not take)",
                     xml.extreme.c_str());
        return 1;
    }
    ENSURE_EQ(tally.loaded, kGeneratedScenes);
    return 0;
}

/// Each scene file named on the command line (a generated level) built and stepped.
static int files_stay_finite(int count, char** paths) {
    int failed = 0;
    for (int i = 0; i < count; ++i) {
        b2s_scene* scene = nullptr;
        b2s_load_file(paths[i], nullptr, &scene, nullptr);
        failed += scene_stays_finite(paths[i], ScenePtr(scene), kLevelSteps);
    }
    return failed;
}

int main(int argc, char** argv) {
    if (argc > 1) {
        return files_stay_finite(argc - 1, argv + 1);
    }
    auto start = std::chrono::steady_clock::now();
    int failed = 0;
    failed += RUN_TEST(every_project_scene_stays_finite);
    failed += RUN_TEST(generated_levels_stay_finite);
    std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    std::printf("%d files and %d of %d generated levels loaded, built and stepped %d times in "
                "%.1f s; reports: %d beyond-box2d-range, %d skipped-dependent\n",
                tally.files, tally.loaded, tally.generated, kSteps, seconds.count(),
                tally.beyond_range, tally.skipped_dependent);
    return failed;
}
