// simulate: load a Box2Scene file, build a Box2D world from it, run it, and show what happened.
//
//     simulate [SCENE] [--steps N] [--svg OUT.svg]
//
// SCENE defaults to the bundled showcase, N to 300 steps of 1/60 s, OUT.svg to simulate.svg in
// the build folder beside the program (build/examples/).
// Prints the load's warnings, what Box2D could not represent, and a table of every body's
// start and end position; the SVG, drawn by the library (b2s_draw_svg), shows the start
// (faint), the end (solid), the joints and each moving body's path, with a key.

#include <box2scene/box2d.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

constexpr float kTimeStep = 1.0f / 60.0f;
constexpr int kVelocityIterations = 8;
constexpr int kPositionIterations = 3;
// Every 5th step is enough for a smooth trajectory and keeps the SVG small.
constexpr int kTrajectorySampleSteps = 5;
// The scene decides gravity; a file without <Gravity> gets Earth's, Y up.
const b2Vec2 kDefaultGravity(0.0f, -10.0f);

struct Options {
    std::string scene_path = BOX2SCENE_EXAMPLE_SCENE;
    int steps = 300;
    std::string svg_path = BOX2SCENE_EXAMPLE_SVG;
    bool help = false;
};

using ScenePtr = std::unique_ptr<b2s_scene, decltype(&b2s_scene_free)>;

// Where each body is at one instant, indexed like the scene's bodies: not finite where the
// adapter created no body, which the drawing leaves out. The angle is b2Body::GetAngle, which
// is not wrapped, so whole turns count when two frames are compared.
using Frame = std::vector<b2s_pose>;

// Each body's origin sampled along the run: sample after sample, one point per body, as
// b2s_draw_svg takes them.
using Samples = std::vector<b2s_vec2>;

constexpr float kNotCreated = std::numeric_limits<float>::quiet_NaN();

void print_usage(std::FILE* to) {
    std::fprintf(to, "usage: simulate [SCENE] [--steps N] [--svg OUT.svg]\n");
}

std::optional<int> parse_step_count(const char* text) {
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || value < 0 || value > 1000000) return std::nullopt;
    return static_cast<int>(value);
}

std::optional<Options> parse_options(int argc, char** argv) {
    Options options;
    bool scene_given = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool has_value = i + 1 < argc;
        if (arg == "--help" || arg == "-h") {
            options.help = true;
        } else if (arg == "--steps" && has_value) {
            const std::optional<int> steps = parse_step_count(argv[++i]);
            if (!steps) {
                std::fprintf(stderr, "simulate: --steps wants a whole number from 0 to 1000000\n");
                return std::nullopt;
            }
            options.steps = *steps;
        } else if (arg == "--svg" && has_value) {
            options.svg_path = argv[++i];
        } else if (arg.rfind("--", 0) != 0 && !scene_given) {
            options.scene_path = arg;
            scene_given = true;
        } else {
            print_usage(stderr);
            return std::nullopt;
        }
    }
    return options;
}

ScenePtr load_scene(const std::string& path) {
    b2s_scene* scene = nullptr;
    b2s_error error{};
    if (b2s_load_file(path.c_str(), nullptr, &scene, &error) != B2S_CODE_OK) {
        std::fprintf(stderr, "%s:%u:%u: error[%s]: %s\n", path.c_str(), error.line, error.column,
                     b2s_code_name(error.code), error.message);
    }
    return ScenePtr(scene, b2s_scene_free);
}

void print_warnings(const std::string& path, const b2s_scene_view& view) {
    for (uint32_t i = 0; i < view.diagnostic_count; ++i) {
        const b2s_diagnostic& warning = view.diagnostics[i];
        std::fprintf(stderr, "%s:%u:%u: warning[%s]: %s\n", path.c_str(), warning.line,
                     warning.column, b2s_code_name(warning.code), warning.message);
    }
}

void print_reports(const std::vector<box2scene::Report>& reports) {
    for (const box2scene::Report& report : reports) {
        const std::string name = report.name.empty() ? "" : " \"" + report.name + "\"";
        std::fprintf(stderr, "box2d: not represented[%s]: %s %u%s: %s\n",
                     b2s_code_name(report.code), report.object, report.index, name.c_str(),
                     report.message.c_str());
    }
}

void print_gravity(const b2s_scene_view& view, b2Vec2 gravity) {
    std::printf("gravity (%g, %g) m/s^2, %s\n", gravity.x, gravity.y,
                view.gravity_given ? "from the scene" : "the default: the scene gives none");
}

Frame capture_frame(const box2scene::Built& built) {
    Frame frame;
    for (const b2Body* body : built.bodies) {
        if (body == nullptr) {
            frame.push_back({{kNotCreated, kNotCreated}, kNotCreated});
        } else {
            frame.push_back({{body->GetPosition().x, body->GetPosition().y}, body->GetAngle()});
        }
    }
    return frame;
}

void sample_positions(const std::vector<b2Body*>& bodies, Samples& samples) {
    for (const b2Body* body : bodies) {
        samples.push_back(body != nullptr ? b2s_vec2{body->GetPosition().x, body->GetPosition().y}
                                          : b2s_vec2{kNotCreated, kNotCreated});
    }
}

Samples run(b2World& world, const std::vector<b2Body*>& bodies, int steps) {
    Samples samples;
    sample_positions(bodies, samples);
    for (int step = 1; step <= steps; ++step) {
        world.Step(kTimeStep, kVelocityIterations, kPositionIterations);
        if (step % kTrajectorySampleSteps == 0 || step == steps) sample_positions(bodies, samples);
    }
    return samples;
}

const char* body_kind_name(uint32_t kind) {
    switch (kind) {
    case B2S_BODY_KIND_STATIC: return "static";
    case B2S_BODY_KIND_KINEMATIC: return "kinematic";
    case B2S_BODY_KIND_DYNAMIC: return "dynamic";
    default: return "unknown";
    }
}

std::string body_name(const b2s_body& body) { return body.name ? body.name : "-"; }

bool finite_pose(const b2s_pose& pose) {
    return std::isfinite(pose.position.x) && std::isfinite(pose.position.y) &&
           std::isfinite(pose.angle);
}

/// Prints where each body started and ended; returns how many ended non-finite.
int print_table(const b2s_scene_view& view, const box2scene::Built& built, const Frame& start,
                const Frame& end) {
    int non_finite = 0;
    size_t name_width = 4;
    for (uint32_t i = 0; i < view.body_count; ++i) {
        name_width = std::max(name_width, body_name(view.bodies[i]).size());
    }
    const int width = static_cast<int>(name_width);
    std::printf("%5s  %-*s  %-9s  %-18s  %-18s  %s\n", "index", width, "name", "type", "start (m)",
                "end (m)", "turned (rad)");
    for (uint32_t i = 0; i < view.body_count; ++i) {
        const b2s_body& body = view.bodies[i];
        std::printf("%5u  %-*s  %-9s  ", i, width, body_name(body).c_str(),
                    body_kind_name(body.kind));
        if (built.bodies[i] == nullptr) {
            std::printf("not created\n");
            continue;
        }
        const b2s_pose& from = start[i];
        const b2s_pose& to = end[i];
        if (!finite_pose(to)) {
            std::printf("(%7.2f, %7.2f)  not finite: Box2D lost this body\n", from.position.x,
                        from.position.y);
            non_finite += 1;
            continue;
        }
        std::printf("(%7.2f, %7.2f)  (%7.2f, %7.2f)  %12.2f\n", from.position.x,
                    from.position.y, to.position.x, to.position.y, to.angle - from.angle);
    }
    return non_finite;
}

// The picture the library draws: the start faint, the end solid, the paths between; empty
// (and said why) when it cannot.
std::string draw(const b2s_scene* scene, const box2scene::Built& built, const Options& options,
                 const Frame& start, const Frame& end, const Samples& samples) {
    const std::string file = std::filesystem::path(options.scene_path).filename().string();
    const std::string title =
        file + ": " + std::to_string(options.steps) + " steps of 1/60 s in Box2D 2.4";
    b2s_picture picture = b2s_picture_default();
    picture.title = title.c_str();
    picture.start = start.data();
    picture.end = end.data();
    picture.trajectories = samples.data();
    picture.trajectory_samples = start.empty() ? 0 : samples.size() / start.size();
    // The joints the adapter created (it skips those Box2D cannot hold).
    const std::unique_ptr<bool[]> created(new bool[built.joints.size() + 1]);
    for (size_t i = 0; i < built.joints.size(); ++i) created[i] = built.joints[i] != nullptr;
    picture.joints_created = created.get();
    char* svg = nullptr;
    size_t size = 0;
    b2s_error error{};
    if (b2s_draw_svg(scene, &picture, &svg, &size, &error) != B2S_CODE_OK) {
        std::fprintf(stderr, "simulate: cannot draw the scene: %s\n", error.message);
        return {};
    }
    std::string document(svg, size);
    b2s_text_free(svg);
    return document;
}

bool write_file(const std::string& path, const std::string& content) {
    std::ofstream out(path, std::ios::binary);
    out << content;
    out.close();
    if (!out) {
        std::fprintf(stderr, "simulate: cannot write %s\n", path.c_str());
        return false;
    }
    return true;
}

} // namespace

int main(int argc, char** argv) {
    const std::optional<Options> options = parse_options(argc, argv);
    if (!options) return 2;
    if (options->help) {
        print_usage(stdout);
        return 0;
    }

    const ScenePtr scene = load_scene(options->scene_path);
    if (!scene) return 1;
    const b2s_scene_view& view = *b2s_scene_get_view(scene.get());
    print_warnings(options->scene_path, view);

    const b2Vec2 gravity = box2scene::scene_gravity(scene.get(), kDefaultGravity);
    print_gravity(view, gravity);
    b2World world(gravity);
    const box2scene::Built built = box2scene::build_world(scene.get(), world);
    print_reports(built.reports);

    const Frame start = capture_frame(built);
    const Samples samples = run(world, built.bodies, options->steps);
    const Frame end = capture_frame(built);

    std::printf("%d steps of %.4f s\n", options->steps, kTimeStep);
    if (int lost = print_table(view, built, start, end); lost > 0) {
        std::fprintf(stderr,
                     "simulate: %d bod%s ended with a non-finite position or angle: Box2D could "
                     "not hold this scene; no drawing written\n",
                     lost, lost == 1 ? "y" : "ies");
        return 1;
    }
    const std::string svg = draw(scene.get(), built, *options, start, end, samples);
    if (svg.empty() || !write_file(options->svg_path, svg)) return 1;
    std::printf("wrote %s\n", options->svg_path.c_str());
    return 0;
}
