// What the peers (bench/pugi_loader.hpp, bench/rapidxml_loader.hpp) load a scene into, and
// the parts of box2scene's reading that do not depend on the XML parser: every record's
// defaults, which joint kinds have which elements, the rules a joint breaks on its own, and
// every ID against its container.
#pragma once

#include <box2scene.h>

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "peer_names.hpp"

namespace bench {

/// A scene as a peer loads it: box2scene's records, in vectors. Names point into the
/// parsed text (both parsers decode it in place), which the scene keeps.
struct PeerScene {
    uint32_t version = 0;
    b2s_vec2 gravity{0, 0};
    bool gravity_given = false;
    std::vector<b2s_shape> shapes;
    std::vector<b2s_fixture> fixtures;
    std::vector<b2s_body> bodies;
    std::vector<b2s_joint> joints;
    std::vector<b2s_vec2> vertices;
    std::vector<uint32_t> fixture_ids;
    std::unique_ptr<char[]> text;
    /// Names that are not one piece of the text: joined from pieces, or trimmed CDATA.
    std::deque<std::string> joined_names;

    /// The arrays as box2scene presents a scene (no user data, no diagnostics).
    b2s_scene_view view() const;
};

namespace peer {

// ---- box2scene's defaults (src/scene.rs), per object and kind

b2s_shape shape_default(uint32_t kind);
b2s_fixture fixture_default();
b2s_body body_default(uint32_t kind);
b2s_joint joint_default(uint32_t kind);

// ---- the joint elements (src/parse/joint.rs)

/// Where a joint element goes: one of the three members, for the kinds that have it.
struct JointField {
    uint32_t kinds = 0; // 1 << kind for each joint kind that has the element
    b2s_vec2 b2s_joint::*vector = nullptr;
    float b2s_joint::*real = nullptr;
    bool b2s_joint::*flag = nullptr;
    bool non_negative = false;
};

/// The field of the joint element `name`; `kinds` is 0 for names no joint kind has here
/// (BodyA, JointA and the like are read by the walk itself).
const JointField& joint_field(Name name);

/// Whether `kind` (a b2s_joint_kind) has a field `field`.
inline bool has_field(const JointField& field, uint32_t kind) {
    return (field.kinds & (1u << kind)) != 0;
}

/// The joint kind whose `Type` is `type` (any letter case): Box2D's eleven; false for
/// another.
bool joint_kind(std::string_view type, uint32_t& kind);

// ---- the rules (src/validate.rs)

/// Why `joint` breaks a rule on its own (both bodies named and apart, a gear's two joints
/// named, limits the right way up, a direction for its axis, a pulley's ratio above 0), or
/// nullptr when it does not.
const char* joint_problem(const b2s_joint& joint);

/// Why an ID of `scene` names nothing (or a gear couples what it cannot), or "" when every
/// one resolves: only possible once the whole file is read, since containers come in any
/// order.
std::string reference_problem(const PeerScene& scene);

} // namespace peer
} // namespace bench
