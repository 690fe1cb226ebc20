// simulate: load a Box2Scene file, build a Box2D world from it, run it, and show what happened.
//
//     simulate [SCENE] [--steps N] [--svg OUT.svg]
//
// SCENE defaults to the bundled showcase, N to 300 steps of 1/60 s, OUT.svg to simulate.svg in
// the build folder beside the program (build/examples/).
// Prints the load's warnings, what Box2D could not represent, and a table of every body's
// start and end position; the SVG shows the start (faint), the end (solid), the joints and
// each moving body's trajectory.

#include <box2scene/box2d.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
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

// Where a body is at one instant. The angle is b2Body::GetAngle, which is not wrapped, so
// whole turns count when two poses are compared.
struct Pose {
    b2Transform transform;
    float angle = 0.0f;
};

// The state worth drawing at one instant: each body's pose (indexed like the scene's bodies;
// unused where the adapter created no body) and each created joint as a polyline through
// its anchors.
struct Frame {
    std::vector<Pose> bodies;
    std::vector<std::vector<b2Vec2>> joints;
};

// For each body (indexed like the scene's bodies), its origin sampled along the run.
using Trajectories = std::vector<std::vector<b2Vec2>>;

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

// A pulley is drawn over its two ground anchors; every other joint straight between its
// body anchors (revolute and weld anchors coincide, which shows as a dot).
std::vector<b2Vec2> joint_polyline(const b2Joint& joint) {
    if (joint.GetType() == e_pulleyJoint) {
        const auto& pulley = static_cast<const b2PulleyJoint&>(joint);
        return {pulley.GetAnchorA(), pulley.GetGroundAnchorA(), pulley.GetGroundAnchorB(),
                pulley.GetAnchorB()};
    }
    return {joint.GetAnchorA(), joint.GetAnchorB()};
}

Frame capture_frame(const box2scene::Built& built) {
    Frame frame;
    for (const b2Body* body : built.bodies) {
        frame.bodies.push_back(body != nullptr ? Pose{body->GetTransform(), body->GetAngle()}
                                               : Pose{});
    }
    for (const b2Joint* joint : built.joints) {
        if (joint != nullptr) frame.joints.push_back(joint_polyline(*joint));
    }
    return frame;
}

void sample_positions(const std::vector<b2Body*>& bodies, Trajectories& paths) {
    for (size_t i = 0; i < bodies.size(); ++i) {
        if (bodies[i] != nullptr) paths[i].push_back(bodies[i]->GetPosition());
    }
}

Trajectories run(b2World& world, const std::vector<b2Body*>& bodies, int steps) {
    Trajectories paths(bodies.size());
    sample_positions(bodies, paths);
    for (int step = 1; step <= steps; ++step) {
        world.Step(kTimeStep, kVelocityIterations, kPositionIterations);
        if (step % kTrajectorySampleSteps == 0 || step == steps) sample_positions(bodies, paths);
    }
    return paths;
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

bool finite_pose(const Pose& pose) {
    return std::isfinite(pose.transform.p.x) && std::isfinite(pose.transform.p.y) &&
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
        const Pose& from = start.bodies[i];
        const Pose& to = end.bodies[i];
        if (!finite_pose(to)) {
            std::printf("(%7.2f, %7.2f)  not finite: Box2D lost this body\n", from.transform.p.x,
                        from.transform.p.y);
            non_finite += 1;
            continue;
        }
        std::printf("(%7.2f, %7.2f)  (%7.2f, %7.2f)  %12.2f\n", from.transform.p.x,
                    from.transform.p.y, to.transform.p.x, to.transform.p.y, to.angle - from.angle);
    }
    return non_finite;
}

std::string escape_xml(const std::string& text) {
    std::string escaped;
    for (const char c : text) {
        switch (c) {
        case '&': escaped += "&amp;"; break;
        case '<': escaped += "&lt;"; break;
        case '>': escaped += "&gt;"; break;
        case '"': escaped += "&quot;"; break;
        default: escaped += c;
        }
    }
    return escaped;
}

// An SVG drawing in world coordinates (metres, Y up). Points are flipped to SVG's Y down as
// they are written, and the view box is fitted to everything drawn.
class Svg {
public:
    // SVG's Y axis points down. 0 - y rather than -y, so that y = 0 prints "0", not "-0".
    static float flipped(float y) { return 0.0f - y; }

    void open_group(const std::string& css_class, const std::string& title = "") {
        body_ << "<g class=\"" << css_class << "\">";
        if (!title.empty()) body_ << "<title>" << escape_xml(title) << "</title>";
        body_ << '\n';
    }

    void close_group() { body_ << "</g>\n"; }

    void circle(b2Vec2 centre, float radius) {
        include({centre.x - radius, centre.y - radius});
        include({centre.x + radius, centre.y + radius});
        body_ << "<circle cx=\"" << centre.x << "\" cy=\"" << flipped(centre.y) << "\" r=\""
              << radius << "\"/>\n";
    }

    void polygon(const std::vector<b2Vec2>& points) { shape("polygon", points); }

    void polyline(const std::vector<b2Vec2>& points) { shape("polyline", points); }

    std::string document(const std::string& style) const {
        const float margin = 1.0f;
        const float x = lower_.x - margin;
        const float y = flipped(upper_.y) - margin;
        const float width = upper_.x - lower_.x + 2 * margin;
        const float height = upper_.y - lower_.y + 2 * margin;
        const float pixels_per_metre = 20.0f;
        std::ostringstream out;
        out << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << x << ' ' << y << ' '
            << width << ' ' << height << "\" width=\"" << width * pixels_per_metre << "\" height=\""
            << height * pixels_per_metre << "\">\n"
            << "<style>" << style << "</style>\n"
            << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << width << "\" height=\""
            << height << "\" fill=\"white\"/>\n"
            << body_.str() << "</svg>\n";
        return out.str();
    }

private:
    void shape(const char* element, const std::vector<b2Vec2>& points) {
        body_ << '<' << element << " points=\"";
        for (const b2Vec2& point : points) {
            include(point);
            body_ << point.x << ',' << flipped(point.y) << ' ';
        }
        body_ << "\"/>\n";
    }

    void include(b2Vec2 point) {
        lower_ = empty_ ? point : b2Min(lower_, point);
        upper_ = empty_ ? point : b2Max(upper_, point);
        empty_ = false;
    }

    std::ostringstream body_;
    bool empty_ = true;
    b2Vec2 lower_{0.0f, 0.0f};
    b2Vec2 upper_{0.0f, 0.0f};
};

// Faint start, solid end; colours by body type; joints red, trajectories orange.
constexpr const char* kSvgStyle = "g{stroke-width:0.05;stroke-linejoin:round}"
                                  ".start{opacity:0.25}"
                                  ".static{fill:#c8c8c8;stroke:#606060}"
                                  ".kinematic{fill:#b8e0b0;stroke:#3a7a30}"
                                  ".dynamic{fill:#a8c8f0;stroke:#2a5a9a}"
                                  ".joints{stroke:#d03030;fill:#d03030}"
                                  ".joints polyline{fill:none}"
                                  ".trajectories{stroke:#f08a00;stroke-width:0.04;fill:none}";

std::vector<b2Vec2> transformed(const b2Transform& xf, const b2Vec2* vertices, int count) {
    std::vector<b2Vec2> points;
    for (int i = 0; i < count; ++i) points.push_back(b2Mul(xf, vertices[i]));
    return points;
}

// A circle carries a radius line so that its rotation shows.
void draw_circle(Svg& svg, const b2CircleShape& circle, const b2Transform& xf) {
    const b2Vec2 centre = b2Mul(xf, circle.m_p);
    svg.circle(centre, circle.m_radius);
    svg.polyline({centre, b2Mul(xf, circle.m_p + b2Vec2(circle.m_radius, 0.0f))});
}

void draw_shape(Svg& svg, const b2Shape& shape, const b2Transform& xf) {
    switch (shape.GetType()) {
    case b2Shape::e_circle: draw_circle(svg, static_cast<const b2CircleShape&>(shape), xf); break;
    case b2Shape::e_polygon: {
        const auto& polygon = static_cast<const b2PolygonShape&>(shape);
        svg.polygon(transformed(xf, polygon.m_vertices, polygon.m_count));
        break;
    }
    case b2Shape::e_edge: {
        const auto& edge = static_cast<const b2EdgeShape&>(shape);
        svg.polyline({b2Mul(xf, edge.m_vertex1), b2Mul(xf, edge.m_vertex2)});
        break;
    }
    case b2Shape::e_chain: {
        // A loop's last vertex repeats its first, so this closes it.
        const auto& chain = static_cast<const b2ChainShape&>(shape);
        svg.polyline(transformed(xf, chain.m_vertices, chain.m_count));
        break;
    }
    case b2Shape::e_typeCount: break;
    }
}

void draw_bodies(Svg& svg, const b2s_scene_view& view, const box2scene::Built& built,
                 const Frame& frame) {
    for (size_t i = 0; i < built.bodies.size(); ++i) {
        if (built.bodies[i] == nullptr) continue;
        svg.open_group(body_kind_name(view.bodies[i].kind), body_name(view.bodies[i]));
        for (const b2Fixture* fixture = built.bodies[i]->GetFixtureList(); fixture != nullptr;
             fixture = fixture->GetNext()) {
            draw_shape(svg, *fixture->GetShape(), frame.bodies[i].transform);
        }
        svg.close_group();
    }
}

void draw_joints(Svg& svg, const Frame& frame) {
    const float anchor_radius = 0.08f;
    svg.open_group("joints");
    for (const std::vector<b2Vec2>& joint : frame.joints) {
        svg.polyline(joint);
        svg.circle(joint.front(), anchor_radius);
        svg.circle(joint.back(), anchor_radius);
    }
    svg.close_group();
}

void draw_trajectories(Svg& svg, const b2s_scene_view& view, const Trajectories& paths) {
    svg.open_group("trajectories");
    for (size_t i = 0; i < paths.size(); ++i) {
        if (view.bodies[i].kind != B2S_BODY_KIND_STATIC && !paths[i].empty())
            svg.polyline(paths[i]);
    }
    svg.close_group();
}

std::string render_svg(const b2s_scene_view& view, const box2scene::Built& built,
                       const Frame& start, const Frame& end, const Trajectories& paths) {
    Svg svg;
    svg.open_group("start");
    draw_bodies(svg, view, built, start);
    draw_joints(svg, start);
    svg.close_group();
    draw_trajectories(svg, view, paths);
    svg.open_group("end");
    draw_bodies(svg, view, built, end);
    draw_joints(svg, end);
    svg.close_group();
    return svg.document(kSvgStyle);
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
    const Trajectories paths = run(world, built.bodies, options->steps);
    const Frame end = capture_frame(built);

    std::printf("%d steps of %.4f s\n", options->steps, kTimeStep);
    if (int lost = print_table(view, built, start, end); lost > 0) {
        std::fprintf(stderr,
                     "simulate: %d bod%s ended with a non-finite position or angle: Box2D could "
                     "not hold this scene; no drawing written\n",
                     lost, lost == 1 ? "y" : "ies");
        return 1;
    }
    if (!write_file(options->svg_path, render_svg(view, built, start, end, paths))) return 1;
    std::printf("wrote %s\n", options->svg_path.c_str());
    return 0;
}
