// The walk both peers make over the tree their parser built (bench/pugi_loader.cpp,
// bench/rapidxml_loader.cpp): one pass in document order that fills box2scene's own records
// (box2scene.h, for the types only) with the same defaults and the same semantics, element
// names looked up in a hash table (peer_names.hpp), numbers read with std::from_chars
// (peer_values.hpp), and box2scene's checks where they are cheap. Written once, over a
// parser's nodes as `Dom` presents them, so that the two peers differ only in their parser.
//
// What it reads: Versions 1 and 2 with circle and polygon shapes, every Box2D joint kind,
// names (elements, and the Name attribute of shapes): all that bench/generate writes,
// in every spelling. Where box2scene would warn (an unknown element, say), the walk fails
// instead, so that a file outside its scope can never load differently unnoticed.
//
// The checks it makes, as errors, are box2scene's: a DOCTYPE, the root, the version, every
// value's syntax and range (floats finite in f32, IDs, 32-bit bits and 16-bit group
// indices, booleans, vectors), negative values, missing and repeated containers and
// mandatory elements, radii, vertex counts, degenerate polygons (Box2D's hull), every ID
// against its container, gears against their joints, joints on one body, limits upside
// down, zero axes, pulley ratios. It skips: every warning (a repeated scalar element loads
// with the last one winning, as in box2scene, silently; polygons not convex and
// counter-clockwise; dynamic bodies without density); line and column of errors (it gives
// byte offsets); the load limits. What each parser checks of the XML itself, and skips,
// its loader's header says.
//
// `Dom` gives, for its `Node` and `Attribute` handles (null ones false in a condition):
//   static Node first_child(Node), next_sibling(Node)
//   static bool is_element(Node), is_text(Node) (character data), is_cdata(Node),
//               is_doctype(Node)
//   static const char* name(Node)                    an element's name, zero-terminated
//   static std::string_view value(Node)              a text or CDATA node's text, decoded,
//                                                    text trimmed, zero-terminated in place
//   static Attribute first_attribute(Node), next_attribute(Attribute)
//   static std::string_view attribute_name(Attribute), attribute_value(Attribute)
//                                                    decoded, zero-terminated in place
//   ptrdiff_t offset(Node) const                     where the node is in the text
#pragma once

#include <box2scene.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "peer_geometry.hpp"
#include "peer_names.hpp"
#include "peer_scene.hpp"
#include "peer_values.hpp"

namespace bench::peer {

/// Why the file does not load, at a byte offset of the text (-1 when no node is at fault).
struct LoadError {
    std::string message;
    ptrdiff_t offset;
};

/// `message`, said where: "byte N: message" (just the message when `offset` is -1).
inline std::string at_byte(ptrdiff_t offset, const std::string& message) {
    return (offset >= 0 ? "byte " + std::to_string(offset) + ": " : "") + message;
}

template <typename Dom>
class Walker {
public:
    using Node = typename Dom::Node;
    using Attribute = typename Dom::Attribute;

    Walker(const Dom& dom, PeerScene& scene) : dom_(dom), scene_(scene) {}

    /// The scene of `document`, the parser's root, which holds the file's top-level nodes.
    void document(Node document) {
        Node root{};
        for (Node child = Dom::first_child(document); child; child = Dom::next_sibling(child)) {
            if (Dom::is_doctype(child)) {
                fail(child, "a <!DOCTYPE> is not allowed in a scene file");
            }
            if (!Dom::is_element(child)) {
                fail(child, "text outside the root element");
            }
            if (root) {
                fail(child, "a second root element " + tag(child));
            }
            root = child;
        }
        if (!root) {
            fail("the file has no root element; expected <World>");
        }
        if (element_name(Dom::name(root)) != Name::world) {
            fail(root, "the root element is " + tag(root) + ", not <World>");
        }
        world(root);
        std::string problem = reference_problem(scene_);
        if (!problem.empty()) {
            fail(std::move(problem));
        }
    }

private:
    [[noreturn]] void fail(Node node, std::string message) const {
        throw LoadError{std::move(message), node ? dom_.offset(node) : -1};
    }

    [[noreturn]] static void fail(std::string message) { throw LoadError{std::move(message), -1}; }

    static std::string tag(Node node) { return std::string("<") + Dom::name(node) + ">"; }

    /// How an error names a node that is not text: its tag, or the DOCTYPE.
    static std::string markup(Node node) {
        return Dom::is_doctype(node) ? std::string("<!DOCTYPE>") : tag(node);
    }

    [[noreturn]] void unexpected(Node parent, Node child) const {
        fail(child, tag(child) + " does not belong in " + tag(parent) +
                        " (or the peer does not read it)");
    }

    [[noreturn]] void unknown_attribute(Node node, Attribute attribute) const {
        fail(node, "unknown attribute " + std::string(Dom::attribute_name(attribute)) + " on " +
                       tag(node));
    }

    static bool is_attribute(Attribute attribute, const char* lower) {
        return is_word(Dom::attribute_name(attribute), lower);
    }

    // ---- the world and its containers

    void world(Node node) {
        read_version(node);
        bool shapes = false, fixtures = false, bodies = false, joints = false;
        each_child(node, [&](Node child, Name name) {
            switch (name) {
            case Name::gravity:
                scene_.gravity = vector(child);
                scene_.gravity_given = true;
                break;
            case Name::shapes: items(child, shapes, Name::shape, &Walker::shape); break;
            case Name::fixtures: items(child, fixtures, Name::fixture, &Walker::fixture); break;
            case Name::bodies: items(child, bodies, Name::body, &Walker::body); break;
            case Name::joints: items(child, joints, Name::joint, &Walker::joint); break;
            default: unexpected(node, child);
            }
        });
    }

    void read_version(Node node) {
        std::string_view version;
        for (Attribute a = Dom::first_attribute(node); a; a = Dom::next_attribute(a)) {
            if (!is_attribute(a, "version")) {
                unknown_attribute(node, a);
            }
            version = trim(Dom::attribute_value(a));
        }
        if (version != "1" && version != "2") {
            fail(node, "the peer reads Versions 1 and 2, not \"" + std::string(version) + "\"");
        }
        scene_.version = static_cast<uint32_t>(version[0] - '0');
    }

    /// Each child of a container, which must be an `item` element. A container comes once:
    /// twice, the indices of its items would be ambiguous.
    void items(Node container, bool& seen, Name item, void (Walker::*read)(Node)) {
        if (seen) {
            fail(container, tag(container) + " appears twice in <World>");
        }
        seen = true;
        each_child(container, [&](Node child, Name name) {
            if (name != item) {
                unexpected(container, child);
            }
            (this->*read)(child);
        });
    }

    // ---- objects

    void shape(Node node) {
        Attribute name_attribute{}; // some writers name shapes by an attribute
        std::string_view type = type_of(node, &name_attribute);
        bool circle = is_word(type, "circle");
        if (!circle && !is_word(type, "polygon")) {
            fail(node, "the peer reads Circle and Polygon shapes only");
        }
        b2s_shape shape = shape_default(circle ? B2S_SHAPE_KIND_CIRCLE : B2S_SHAPE_KIND_POLYGON);
        if (name_attribute) {
            shape.name = attribute_string(name_attribute);
        }
        bool radius = false, position = false, vertices = false;
        each_child(node, [&](Node child, Name name) {
            if (name == Name::name) {
                shape.name = string(child);
            } else if (circle && name == Name::radius) {
                shape.radius = real(child);
                radius = true;
            } else if (circle && name == Name::position) {
                shape.position = vector(child);
                position = true;
            } else if (!circle && name == Name::vertices) {
                if (vertices) {
                    fail(child, "<Vertices> appears twice in a shape");
                }
                shape.vertices = polygon_vertices(child);
                vertices = true;
            } else if (!circle && name == Name::centroid) {
                shape.centroid = vector(child);
                shape.centroid_given = true;
            } else {
                unexpected(node, child);
            }
        });
        if (circle && (!radius || !position)) {
            fail(node, "a Circle needs a <Radius> and a <Position>");
        }
        if (circle && !(shape.radius > 0)) {
            fail(node, "a circle's <Radius> must be greater than 0");
        }
        if (!circle) {
            check_polygon(node, shape, vertices);
        }
        scene_.shapes.push_back(shape);
    }

    b2s_range polygon_vertices(Node node) {
        uint32_t first = static_cast<uint32_t>(scene_.vertices.size());
        each_child(node, [&](Node child, Name name) {
            if (name != Name::vertex) {
                unexpected(node, child);
            }
            if (scene_.vertices.size() - first == 8) {
                fail(child, "a polygon has at most 8 vertices");
            }
            scene_.vertices.push_back(vector(child));
        });
        return b2s_range{first, static_cast<uint32_t>(scene_.vertices.size()) - first};
    }

    void check_polygon(Node node, const b2s_shape& shape, bool has_vertices) {
        if (!has_vertices) {
            fail(node, "a Polygon needs <Vertices>");
        }
        if (shape.vertices.count < 2) {
            fail(node, "a polygon needs 2 to 8 vertices");
        }
        const b2s_vec2* vertices = &scene_.vertices[shape.vertices.first];
        if (const char* why = degenerate_polygon(vertices, shape.vertices.count)) {
            fail(node, why);
        }
    }

    void fixture(Node node) {
        if (Attribute attribute = Dom::first_attribute(node)) {
            unknown_attribute(node, attribute);
        }
        b2s_fixture fixture = fixture_default();
        bool has_shape = false;
        each_child(node, [&](Node child, Name name) {
            switch (name) {
            case Name::shape:
                fixture.shape = id(child);
                has_shape = true;
                break;
            case Name::name: fixture.name = string(child); break;
            case Name::density: fixture.density = non_negative(child); break;
            case Name::friction: fixture.friction = non_negative(child); break;
            case Name::restitution: fixture.restitution = non_negative(child); break;
            case Name::is_sensor: fixture.is_sensor = boolean(child); break;
            case Name::filter_data: filter(child, fixture.filter); break;
            default: unexpected(node, child);
            }
        });
        if (!has_shape) {
            fail(node, "<Fixture> has no <Shape>: a fixture with no shape is malformed");
        }
        scene_.fixtures.push_back(fixture);
    }

    void filter(Node node, b2s_filter& filter) {
        each_child(node, [&](Node child, Name name) {
            switch (name) {
            case Name::category_bits: filter.category_bits = convert(child, to_bits); break;
            case Name::mask_bits: filter.mask_bits = convert(child, to_bits); break;
            case Name::group_index: filter.group_index = convert(child, to_int16); break;
            default: unexpected(node, child);
            }
        });
    }

    void body(Node node) {
        b2s_body body = body_default(body_kind(node));
        bool has_fixtures = false;
        each_child(node, [&](Node child, Name name) {
            switch (name) {
            case Name::name: body.name = string(child); break;
            case Name::active: body.active = boolean(child); break;
            case Name::allow_sleep: body.allow_sleep = boolean(child); break;
            case Name::awake: body.awake = boolean(child); break;
            case Name::bullet: body.bullet = boolean(child); break;
            case Name::fixed_rotation: body.fixed_rotation = boolean(child); break;
            case Name::angle: body.angle = real(child); break;
            case Name::angular_damping: body.angular_damping = real(child); break;
            case Name::angular_velocity: body.angular_velocity = real(child); break;
            case Name::linear_damping: body.linear_damping = real(child); break;
            case Name::linear_velocity: body.linear_velocity = vector(child); break;
            case Name::position: body.position = vector(child); break;
            case Name::inertia_scale: body.inertia_scale = real(child); break;
            case Name::gravity_scale: body.gravity_scale = real(child); break;
            case Name::mass_data: mass_data(child, body.mass_data); break;
            case Name::fixtures:
                if (has_fixtures) {
                    fail(child, "<Fixtures> appears twice in a body");
                }
                body.fixtures = fixture_ids(child);
                has_fixtures = true;
                break;
            default: unexpected(node, child);
            }
        });
        scene_.bodies.push_back(body);
    }

    uint32_t body_kind(Node node) const {
        std::string_view type = type_of(node);
        if (is_word(type, "static")) {
            return B2S_BODY_KIND_STATIC;
        }
        if (is_word(type, "kinematic")) {
            return B2S_BODY_KIND_KINEMATIC;
        }
        if (is_word(type, "dynamic")) {
            return B2S_BODY_KIND_DYNAMIC;
        }
        fail(node, "unknown body Type \"" + std::string(type) + "\"");
    }

    void mass_data(Node node, b2s_mass_data& mass) {
        each_child(node, [&](Node child, Name name) {
            switch (name) {
            case Name::mass:
                mass.mass = non_negative(child);
                mass.mass_given = true;
                break;
            case Name::center:
                mass.center = vector(child);
                mass.center_given = true;
                break;
            case Name::inertia:
                mass.inertia = non_negative(child);
                mass.inertia_given = true;
                break;
            default: unexpected(node, child);
            }
        });
    }

    b2s_range fixture_ids(Node node) {
        uint32_t first = static_cast<uint32_t>(scene_.fixture_ids.size());
        each_child(node, [&](Node child, Name name) {
            if (name != Name::id) {
                unexpected(node, child);
            }
            scene_.fixture_ids.push_back(id(child));
        });
        uint32_t count = static_cast<uint32_t>(scene_.fixture_ids.size()) - first;
        return count == 0 ? b2s_range{0, 0} : b2s_range{first, count};
    }

    void joint(Node node) {
        uint32_t kind = 0;
        std::string_view type = type_of(node);
        if (!joint_kind(type, kind)) {
            fail(node, "the peer reads Box2D's joint types only, not \"" + std::string(type) +
                           "\"");
        }
        b2s_joint joint = joint_default(kind);
        each_child(node, [&](Node child, Name name) {
            switch (name) {
            case Name::name: joint.name = string(child); return;
            case Name::body_a: joint.body_a = id(child); return;
            case Name::body_b: joint.body_b = id(child); return;
            case Name::collide_connected: joint.collide_connected = boolean(child); return;
            case Name::joint_a:
            case Name::joint_b:
                if (kind != B2S_JOINT_KIND_GEAR) {
                    unexpected(node, child);
                }
                (name == Name::joint_a ? joint.joint_a : joint.joint_b) = id(child);
                return;
            default: set_joint_field(node, child, name, kind, joint);
            }
        });
        if (const char* why = joint_problem(joint)) {
            fail(node, why);
        }
        scene_.joints.push_back(joint);
    }

    void set_joint_field(Node node, Node child, Name name, uint32_t kind, b2s_joint& joint) {
        const JointField& field = joint_field(name);
        if (!has_field(field, kind)) {
            unexpected(node, child);
        }
        if (field.vector != nullptr) {
            joint.*field.vector = vector(child);
        } else if (field.real != nullptr) {
            joint.*field.real = field.non_negative ? non_negative(child) : real(child);
        } else {
            joint.*field.flag = boolean(child);
        }
    }

    // ---- children, attributes and values

    /// Calls `each(child, name)` for every child element of `node`; text where only
    /// elements belong is an error.
    template <typename Each>
    void each_child(Node node, Each each) const {
        for (Node child = Dom::first_child(node); child; child = Dom::next_sibling(child)) {
            if (!Dom::is_element(child)) {
                fail(child, "text inside " + tag(node) + ", which holds only elements");
            }
            each(child, element_name(Dom::name(child)));
        }
    }

    /// The trimmed `Type` attribute. Any other attribute is an error, but a `Name` when
    /// `name` is given to receive it.
    std::string_view type_of(Node node, Attribute* name = nullptr) const {
        std::string_view type;
        bool found = false;
        for (Attribute a = Dom::first_attribute(node); a; a = Dom::next_attribute(a)) {
            if (is_attribute(a, "type")) {
                type = trim(Dom::attribute_value(a));
                found = true;
            } else if (name != nullptr && is_attribute(a, "name")) {
                *name = a;
            } else {
                unknown_attribute(node, a);
            }
        }
        if (!found) {
            fail(node, tag(node) + " has no Type attribute");
        }
        return type;
    }

    /// The text of a value element: the parser's one text node, already trimmed in place;
    /// else its pieces (text and CDATA) joined and trimmed.
    std::string_view text(Node element) {
        Node first = Dom::first_child(element);
        if (!first) {
            return {};
        }
        if (!Dom::next_sibling(first) && Dom::is_text(first)) {
            return Dom::value(first);
        }
        scratch_.clear();
        for (Node piece = first; piece; piece = Dom::next_sibling(piece)) {
            if (!Dom::is_text(piece) && !Dom::is_cdata(piece)) {
                fail(piece, tag(element) + " holds a value, not markup such as " + markup(piece));
            }
            scratch_ += Dom::value(piece);
        }
        return trim(scratch_);
    }

    /// A string for the scene: in place when it is one piece of the text.
    const char* string(Node element) {
        Node first = Dom::first_child(element);
        if (first && !Dom::next_sibling(first) && Dom::is_text(first)) {
            return Dom::value(first).data();
        }
        std::string_view joined = text(element);
        return joined.empty() ? "" : owned(joined);
    }

    /// An attribute's trimmed value: in place when nothing was trimmed off its end, where
    /// the parser wrote a NUL.
    const char* attribute_string(Attribute attribute) {
        std::string_view trimmed = trim(Dom::attribute_value(attribute));
        return trimmed.data()[trimmed.size()] == '\0' ? trimmed.data() : owned(trimmed);
    }

    const char* owned(std::string_view text) {
        return scene_.joined_names.emplace_back(text).c_str();
    }

    template <typename Value>
    Value convert(Node element, Value (*to_value)(std::string_view)) {
        try {
            return to_value(text(element));
        } catch (const ValueError& e) {
            fail(element, tag(element) + ": " + e.what());
        }
    }

    float real(Node element) { return convert(element, to_float); }

    /// A float that must not be negative (-0 passes, as in box2scene).
    float non_negative(Node element) {
        float value = real(element);
        if (value < 0) {
            fail(element, tag(element) + " cannot be negative");
        }
        return value;
    }

    b2s_vec2 vector(Node element) { return convert(element, to_vector2); }
    bool boolean(Node element) { return convert(element, to_bool); }
    uint32_t id(Node element) { return convert(element, to_id); }

    const Dom& dom_;
    PeerScene& scene_;
    std::string scratch_; // the joined pieces of a value element
};

/// Walks `document`, the root of what `dom`'s parser built, into `scene`; false with why in
/// `error` when the file breaks a rule.
template <typename Dom>
bool walk(const Dom& dom, typename Dom::Node document, PeerScene& scene, std::string& error) {
    try {
        Walker<Dom>(dom, scene).document(document);
    } catch (const LoadError& e) {
        error = at_byte(e.offset, e.message);
        return false;
    }
    return true;
}

} // namespace bench::peer
