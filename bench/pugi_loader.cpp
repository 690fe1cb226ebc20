#include "pugi_loader.hpp"

#include <pugixml.hpp>

#include <array>
#include <string_view>
#include <utility>

#include "file_bytes.hpp"
#include "peer_geometry.hpp"
#include "peer_names.hpp"
#include "peer_values.hpp"

namespace bench {
namespace {

using peer::Name;
using pugi::xml_node;

/// In place; entities, CDATA, end-of-line and attribute white space as XML requires; text
/// trimmed, as the format trims values; a DOCTYPE parsed only to be refused.
constexpr unsigned kParseOptions =
    pugi::parse_default | pugi::parse_trim_pcdata | pugi::parse_doctype;

/// Why the file does not load, at a byte offset of the text (-1 when no node is at fault).
struct LoadError {
    std::string message;
    ptrdiff_t offset;
};

[[noreturn]] void fail(xml_node node, std::string message) {
    throw LoadError{std::move(message), node ? node.offset_debug() : -1};
}

[[noreturn]] void fail(std::string message) { throw LoadError{std::move(message), -1}; }

std::string tag(xml_node node) { return std::string("<") + node.name() + ">"; }

[[noreturn]] void unexpected(xml_node parent, xml_node child) {
    fail(child, tag(child) + " does not belong in " + tag(parent) +
                    " (or the peer does not read it)");
}

using peer::is_word;

bool is_attribute(pugi::xml_attribute attribute, const char* lower) {
    return is_word(attribute.name(), lower);
}

constexpr uint32_t bit(uint32_t kind) { return 1u << kind; }

// ---- box2scene's defaults (src/scene.rs), per object and kind

b2s_shape shape_default(uint32_t kind) {
    b2s_shape shape{};
    shape.kind = kind;
    return shape;
}

b2s_fixture fixture_default() {
    b2s_fixture fixture{};
    fixture.shape = B2S_NONE;
    fixture.friction = 0.2f;
    fixture.filter = b2s_filter{0x0001, 0xFFFF, 0};
    fixture.user_data = B2S_NONE;
    return fixture;
}

b2s_body body_default(uint32_t kind) {
    b2s_body body{};
    body.kind = kind;
    body.gravity_scale = 1.0f;
    body.inertia_scale = 1.0f;
    body.user_data = B2S_NONE;
    body.active = body.allow_sleep = body.awake = true;
    return body;
}

b2s_joint joint_default(uint32_t kind) {
    b2s_joint joint{};
    joint.kind = kind;
    joint.body_a = joint.body_b = joint.user_data = joint.joint_a = joint.joint_b = B2S_NONE;
    switch (kind) {
    case B2S_JOINT_KIND_PRISMATIC:
    case B2S_JOINT_KIND_LINE:
        joint.local_axis_a = b2s_vec2{1, 0};
        break;
    case B2S_JOINT_KIND_DISTANCE:
        joint.length = 1;
        break;
    case B2S_JOINT_KIND_PULLEY:
        joint.ground_anchor_a = b2s_vec2{-1, 1};
        joint.ground_anchor_b = b2s_vec2{1, 1};
        joint.local_anchor_a = b2s_vec2{-1, 0};
        joint.local_anchor_b = b2s_vec2{1, 0};
        joint.ratio = 1;
        break;
    case B2S_JOINT_KIND_GEAR:
        joint.ratio = 1;
        break;
    case B2S_JOINT_KIND_WHEEL:
        joint.local_axis_a = b2s_vec2{1, 0};
        joint.frequency_hz = 2;
        joint.damping_ratio = 0.7f;
        break;
    case B2S_JOINT_KIND_ROPE:
        joint.local_anchor_a = b2s_vec2{-1, 0};
        joint.local_anchor_b = b2s_vec2{1, 0};
        break;
    case B2S_JOINT_KIND_MOTOR:
        joint.max_force = 1;
        joint.max_torque = 1;
        joint.correction_factor = 0.3f;
        break;
    default:
        break;
    }
    return joint;
}

// ---- the joint elements: which kinds have each, and where it goes (src/parse/joint.rs)

struct JointField {
    uint32_t kinds = 0; // bit(kind) for each joint kind that has the element
    b2s_vec2 b2s_joint::*vector = nullptr;
    float b2s_joint::*real = nullptr;
    bool b2s_joint::*flag = nullptr;
    bool non_negative = false;
};

using JointFields = std::array<JointField, static_cast<size_t>(Name::count)>;

constexpr uint32_t kRevolute = bit(B2S_JOINT_KIND_REVOLUTE),
                   kPrismatic = bit(B2S_JOINT_KIND_PRISMATIC),
                   kDistance = bit(B2S_JOINT_KIND_DISTANCE), kPulley = bit(B2S_JOINT_KIND_PULLEY),
                   kLine = bit(B2S_JOINT_KIND_LINE), kWeld = bit(B2S_JOINT_KIND_WELD),
                   kFriction = bit(B2S_JOINT_KIND_FRICTION), kGear = bit(B2S_JOINT_KIND_GEAR),
                   kWheel = bit(B2S_JOINT_KIND_WHEEL), kRope = bit(B2S_JOINT_KIND_ROPE),
                   kMotor = bit(B2S_JOINT_KIND_MOTOR);
constexpr uint32_t kAnchored =
    kRevolute | kPrismatic | kDistance | kPulley | kLine | kWeld | kFriction | kWheel | kRope;

/// A Line joint's FrequencyHz, DampingRatio and MaxMotorTorque make it Farseer's wheel
/// joint, which box2scene converts with a warning: not the peer's business.
JointFields make_joint_fields() {
    JointFields fields{};
    auto at = [&](Name name) -> JointField& { return fields[static_cast<size_t>(name)]; };
    auto vector = [&](Name name, uint32_t kinds, b2s_vec2 b2s_joint::*member) {
        at(name).kinds = kinds;
        at(name).vector = member;
    };
    auto real = [&](Name name, uint32_t kinds, float b2s_joint::*member, bool non_negative) {
        at(name).kinds = kinds;
        at(name).real = member;
        at(name).non_negative = non_negative;
    };
    auto flag = [&](Name name, uint32_t kinds, bool b2s_joint::*member) {
        at(name).kinds = kinds;
        at(name).flag = member;
    };
    const uint32_t motorised = kRevolute | kPrismatic | kLine | kWheel;
    vector(Name::local_anchor_a, kAnchored, &b2s_joint::local_anchor_a);
    vector(Name::local_anchor_b, kAnchored, &b2s_joint::local_anchor_b);
    vector(Name::local_axis_a, kPrismatic | kLine | kWheel, &b2s_joint::local_axis_a);
    real(Name::reference_angle, kRevolute | kPrismatic | kWeld, &b2s_joint::reference_angle,
         false);
    flag(Name::enable_limit, kRevolute | kPrismatic | kLine, &b2s_joint::enable_limit);
    real(Name::lower_angle, kRevolute, &b2s_joint::lower_limit, false);
    real(Name::upper_angle, kRevolute, &b2s_joint::upper_limit, false);
    real(Name::lower_translation, kPrismatic | kLine, &b2s_joint::lower_limit, false);
    real(Name::upper_translation, kPrismatic | kLine, &b2s_joint::upper_limit, false);
    flag(Name::enable_motor, motorised, &b2s_joint::enable_motor);
    real(Name::motor_speed, motorised, &b2s_joint::motor_speed, false);
    real(Name::max_motor_torque, kRevolute | kWheel, &b2s_joint::max_motor_torque, true);
    real(Name::max_motor_force, kPrismatic | kLine, &b2s_joint::max_motor_force, true);
    real(Name::length, kDistance, &b2s_joint::length, true);
    real(Name::frequency_hz, kDistance | kWeld | kWheel, &b2s_joint::frequency_hz, true);
    real(Name::damping_ratio, kDistance | kWeld | kWheel, &b2s_joint::damping_ratio, true);
    vector(Name::ground_anchor_a, kPulley, &b2s_joint::ground_anchor_a);
    vector(Name::ground_anchor_b, kPulley, &b2s_joint::ground_anchor_b);
    real(Name::length_a, kPulley, &b2s_joint::length_a, false);
    real(Name::length_b, kPulley, &b2s_joint::length_b, false);
    real(Name::max_length_a, kPulley, &b2s_joint::max_length_a, false);
    real(Name::max_length_b, kPulley, &b2s_joint::max_length_b, false);
    real(Name::ratio, kPulley | kGear, &b2s_joint::ratio, false);
    real(Name::max_force, kFriction | kMotor, &b2s_joint::max_force, true);
    real(Name::max_torque, kFriction | kMotor, &b2s_joint::max_torque, true);
    real(Name::max_length, kRope, &b2s_joint::max_length, true);
    vector(Name::linear_offset, kMotor, &b2s_joint::linear_offset);
    real(Name::angular_offset, kMotor, &b2s_joint::angular_offset, false);
    real(Name::correction_factor, kMotor, &b2s_joint::correction_factor, false);
    return fields;
}

const JointFields kJointFields = make_joint_fields();

/// The joint kinds by their `Type`, lower case, in b2s_joint_kind order.
constexpr const char* kJointTypes[] = {"revolute", "prismatic", "distance", "pulley",
                                       "line",     "weld",      "friction", "gear",
                                       "wheel",    "rope",      "motor"};

/// One walk over pugixml's tree, in document order, into the scene's arrays.
class Walker {
public:
    explicit Walker(PugiScene& scene) : scene_(scene) {}

    void document(const pugi::xml_document& document) {
        xml_node root;
        for (xml_node child = document.first_child(); child; child = child.next_sibling()) {
            if (child.type() == pugi::node_doctype) {
                fail(child, "a <!DOCTYPE> is not allowed in a scene file");
            }
            if (child.type() != pugi::node_element) {
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
        if (peer::element_name(root.name()) != Name::world) {
            fail(root, "the root element is " + tag(root) + ", not <World>");
        }
        world(root);
        check_references();
    }

private:
    // ---- the world and its containers

    void world(xml_node node) {
        read_version(node);
        bool shapes = false, fixtures = false, bodies = false, joints = false;
        each_child(node, [&](xml_node child, Name name) {
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

    void read_version(xml_node node) {
        std::string_view version;
        for (pugi::xml_attribute a = node.first_attribute(); a; a = a.next_attribute()) {
            if (!is_attribute(a, "version")) {
                fail(node, std::string("unknown attribute ") + a.name() + " on <World>");
            }
            version = peer::trim(a.value());
        }
        if (version != "1" && version != "2") {
            fail(node, "the peer reads Versions 1 and 2, not \"" + std::string(version) + "\"");
        }
        scene_.version = static_cast<uint32_t>(version[0] - '0');
    }

    /// Each child of a container, which must be an `item` element. A container comes once:
    /// twice, the indices of its items would be ambiguous.
    void items(xml_node container, bool& seen, Name item, void (Walker::*read)(xml_node)) {
        if (seen) {
            fail(container, tag(container) + " appears twice in <World>");
        }
        seen = true;
        each_child(container, [&](xml_node child, Name name) {
            if (name != item) {
                unexpected(container, child);
            }
            (this->*read)(child);
        });
    }

    // ---- objects

    void shape(xml_node node) {
        pugi::xml_attribute name_attribute; // some writers name shapes by an attribute
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
        each_child(node, [&](xml_node child, Name name) {
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

    b2s_range polygon_vertices(xml_node node) {
        uint32_t first = static_cast<uint32_t>(scene_.vertices.size());
        each_child(node, [&](xml_node child, Name name) {
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

    void check_polygon(xml_node node, const b2s_shape& shape, bool has_vertices) {
        if (!has_vertices) {
            fail(node, "a Polygon needs <Vertices>");
        }
        if (shape.vertices.count < 2) {
            fail(node, "a polygon needs 2 to 8 vertices");
        }
        const b2s_vec2* vertices = &scene_.vertices[shape.vertices.first];
        if (const char* why = peer::degenerate_polygon(vertices, shape.vertices.count)) {
            fail(node, why);
        }
    }

    void fixture(xml_node node) {
        if (node.first_attribute()) {
            fail(node, std::string("unknown attribute ") + node.first_attribute().name() +
                           " on <Fixture>");
        }
        b2s_fixture fixture = fixture_default();
        bool has_shape = false;
        each_child(node, [&](xml_node child, Name name) {
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

    void filter(xml_node node, b2s_filter& filter) {
        each_child(node, [&](xml_node child, Name name) {
            switch (name) {
            case Name::category_bits: filter.category_bits = convert(child, peer::to_bits); break;
            case Name::mask_bits: filter.mask_bits = convert(child, peer::to_bits); break;
            case Name::group_index: filter.group_index = convert(child, peer::to_int16); break;
            default: unexpected(node, child);
            }
        });
    }

    void body(xml_node node) {
        b2s_body body = body_default(body_kind(node));
        bool has_fixtures = false;
        each_child(node, [&](xml_node child, Name name) {
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

    static uint32_t body_kind(xml_node node) {
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

    void mass_data(xml_node node, b2s_mass_data& mass) {
        each_child(node, [&](xml_node child, Name name) {
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

    b2s_range fixture_ids(xml_node node) {
        uint32_t first = static_cast<uint32_t>(scene_.fixture_ids.size());
        each_child(node, [&](xml_node child, Name name) {
            if (name != Name::id) {
                unexpected(node, child);
            }
            scene_.fixture_ids.push_back(id(child));
        });
        uint32_t count = static_cast<uint32_t>(scene_.fixture_ids.size()) - first;
        return count == 0 ? b2s_range{0, 0} : b2s_range{first, count};
    }

    void joint(xml_node node) {
        uint32_t kind = joint_kind(node);
        b2s_joint joint = joint_default(kind);
        each_child(node, [&](xml_node child, Name name) {
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
            default: joint_field(node, child, name, kind, joint);
            }
        });
        check_joint(node, joint);
        scene_.joints.push_back(joint);
    }

    static uint32_t joint_kind(xml_node node) {
        std::string_view type = type_of(node);
        for (uint32_t kind = 0; kind < sizeof kJointTypes / sizeof kJointTypes[0]; ++kind) {
            if (is_word(type, kJointTypes[kind])) {
                return kind;
            }
        }
        fail(node, "the peer reads Box2D's joint types only, not \"" + std::string(type) + "\"");
    }

    void joint_field(xml_node node, xml_node child, Name name, uint32_t kind, b2s_joint& joint) {
        const JointField& field = kJointFields[static_cast<size_t>(name)];
        if ((field.kinds & bit(kind)) == 0) {
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

    /// The rules one joint can break on its own (src/validate.rs).
    static void check_joint(xml_node node, const b2s_joint& joint) {
        if (joint.body_a == B2S_NONE || joint.body_b == B2S_NONE) {
            fail(node, "a joint names both of its bodies (<BodyA>, <BodyB>)");
        }
        if (joint.kind == B2S_JOINT_KIND_GEAR &&
            (joint.joint_a == B2S_NONE || joint.joint_b == B2S_NONE)) {
            fail(node, "a gear joint names the two joints it couples (<JointA>, <JointB>)");
        }
        if (joint.body_a == joint.body_b) {
            fail(node, "the joint connects a body to itself");
        }
        if (joint.enable_limit && joint.lower_limit > joint.upper_limit) {
            fail(node, "a lower limit above the upper one, with the limit enabled");
        }
        bool has_axis = (bit(joint.kind) & (kPrismatic | kLine | kWheel)) != 0;
        if (has_axis && joint.local_axis_a.x == 0 && joint.local_axis_a.y == 0) {
            fail(node, "<LocalAxisA> is (0, 0): a joint axis needs a direction");
        }
        if (joint.kind == B2S_JOINT_KIND_PULLEY && !(joint.ratio > 0)) {
            fail(node, "a pulley's <Ratio> must be greater than 0");
        }
    }

    /// Every ID against its container, and gears against the joints they couple: only
    /// possible once the whole file is read, since containers come in any order.
    void check_references() const {
        const PugiScene& s = scene_;
        for (size_t i = 0; i < s.fixtures.size(); ++i) {
            if (s.fixtures[i].shape >= s.shapes.size()) {
                fail("fixture " + std::to_string(i) + " names a shape the file does not have");
            }
        }
        for (uint32_t id : s.fixture_ids) {
            if (id >= s.fixtures.size()) {
                fail("a body names fixture " + std::to_string(id) +
                     ", which the file does not have");
            }
        }
        for (size_t i = 0; i < s.joints.size(); ++i) {
            const b2s_joint& joint = s.joints[i];
            if (joint.body_a >= s.bodies.size() || joint.body_b >= s.bodies.size()) {
                fail("joint " + std::to_string(i) + " names a body the file does not have");
            }
            if (joint.kind == B2S_JOINT_KIND_GEAR &&
                (!couplable(i, joint.joint_a) || !couplable(i, joint.joint_b))) {
                fail("gear joint " + std::to_string(i) +
                     " does not couple two other revolute or prismatic joints");
            }
        }
    }

    bool couplable(size_t gear, uint32_t target) const {
        return target != gear && target < scene_.joints.size() &&
               (bit(scene_.joints[target].kind) & (kRevolute | kPrismatic)) != 0;
    }

    // ---- children, attributes and values

    /// Calls `each(child, name)` for every child element of `node`; text where only
    /// elements belong is an error.
    template <typename Each>
    static void each_child(xml_node node, Each each) {
        for (xml_node child = node.first_child(); child; child = child.next_sibling()) {
            if (child.type() != pugi::node_element) {
                fail(child, "text inside " + tag(node) + ", which holds only elements");
            }
            each(child, peer::element_name(child.name()));
        }
    }

    /// The trimmed `Type` attribute. Any other attribute is an error, but a `Name` when
    /// `name` is given to receive it.
    static std::string_view type_of(xml_node node, pugi::xml_attribute* name = nullptr) {
        std::string_view type;
        bool found = false;
        for (pugi::xml_attribute a = node.first_attribute(); a; a = a.next_attribute()) {
            if (is_attribute(a, "type")) {
                type = peer::trim(a.value());
                found = true;
            } else if (name != nullptr && is_attribute(a, "name")) {
                *name = a;
            } else {
                fail(node, std::string("unknown attribute ") + a.name() + " on " + tag(node));
            }
        }
        if (!found) {
            fail(node, tag(node) + " has no Type attribute");
        }
        return type;
    }

    /// The text of a value element: pugixml's one text node, already trimmed in place;
    /// else its pieces (text and CDATA) joined and trimmed.
    std::string_view text(xml_node element) {
        xml_node first = element.first_child();
        if (!first) {
            return {};
        }
        if (!first.next_sibling() && first.type() == pugi::node_pcdata) {
            return first.value();
        }
        scratch_.clear();
        for (xml_node piece = first; piece; piece = piece.next_sibling()) {
            if (piece.type() == pugi::node_element) {
                fail(piece, tag(element) + " holds a value, not elements such as " + tag(piece));
            }
            scratch_ += piece.value();
        }
        return peer::trim(scratch_);
    }

    /// A string for the scene: in place when it is one piece of the text.
    const char* string(xml_node element) {
        xml_node first = element.first_child();
        if (first && !first.next_sibling() && first.type() == pugi::node_pcdata) {
            return first.value();
        }
        std::string_view joined = text(element);
        return joined.empty() ? "" : owned(joined);
    }

    /// An attribute's trimmed value: in place when nothing was trimmed off its end, where
    /// pugixml wrote a NUL.
    const char* attribute_string(pugi::xml_attribute attribute) {
        std::string_view trimmed = peer::trim(attribute.value());
        return trimmed.data()[trimmed.size()] == '\0' ? trimmed.data() : owned(trimmed);
    }

    const char* owned(std::string_view text) {
        return scene_.joined_names.emplace_back(text).c_str();
    }

    template <typename Value>
    Value convert(xml_node element, Value (*to_value)(std::string_view)) {
        try {
            return to_value(text(element));
        } catch (const peer::ValueError& e) {
            fail(element, tag(element) + ": " + e.what());
        }
    }

    float real(xml_node element) { return convert(element, peer::to_float); }

    /// A float that must not be negative (-0 passes, as in box2scene).
    float non_negative(xml_node element) {
        float value = real(element);
        if (value < 0) {
            fail(element, tag(element) + " cannot be negative");
        }
        return value;
    }

    b2s_vec2 vector(xml_node element) { return convert(element, peer::to_vector2); }
    bool boolean(xml_node element) { return convert(element, peer::to_bool); }
    uint32_t id(xml_node element) { return convert(element, peer::to_id); }

    PugiScene& scene_;
    std::string scratch_; // the joined pieces of a value element
};

} // namespace

b2s_scene_view PugiScene::view() const {
    b2s_scene_view view{};
    view.shapes = shapes.data();
    view.fixtures = fixtures.data();
    view.bodies = bodies.data();
    view.joints = joints.data();
    view.vertices = vertices.data();
    view.fixture_ids = fixture_ids.data();
    view.shape_count = static_cast<uint32_t>(shapes.size());
    view.fixture_count = static_cast<uint32_t>(fixtures.size());
    view.body_count = static_cast<uint32_t>(bodies.size());
    view.joint_count = static_cast<uint32_t>(joints.size());
    view.vertex_count = static_cast<uint32_t>(vertices.size());
    view.fixture_id_count = static_cast<uint32_t>(fixture_ids.size());
    view.version = version;
    view.gravity = gravity;
    view.gravity_given = gravity_given;
    return view;
}

bool pugi_load(std::unique_ptr<char[]> text, size_t size, PugiScene& scene,
               std::string& error) {
    scene = PugiScene{};
    scene.text = std::move(text);
    // The tree is only walked: freed on return, while the names stay in the text.
    pugi::xml_document document;
    pugi::xml_parse_result parsed =
        document.load_buffer_inplace(scene.text.get(), size, kParseOptions, pugi::encoding_utf8);
    if (!parsed) {
        error = "byte " + std::to_string(parsed.offset) +
                ": malformed XML: " + parsed.description();
        return false;
    }
    try {
        Walker(scene).document(document);
    } catch (const LoadError& e) {
        error = (e.offset >= 0 ? "byte " + std::to_string(e.offset) + ": " : "") + e.message;
        return false;
    }
    return true;
}

bool pugi_load_file(const char* path, PugiScene& scene, std::string& error) {
    size_t size = 0;
    std::unique_ptr<char[]> text = read_file(path, size);
    if (!text) {
        error = std::string("cannot read ") + path;
        return false;
    }
    return pugi_load(std::move(text), size, scene, error);
}

} // namespace bench
