// The peer box2scene is measured against (bench/run): a Box2Scene loader written the way a
// careful C++ programmer would on pugixml. An in-place DOM parse, then one walk that fills
// box2scene's own records (box2scene.h, for the types only) with the same defaults and the
// same semantics, element names looked up in a hash table, numbers read with
// std::from_chars, and box2scene's checks where they are cheap.
//
// What it reads: Versions 1 and 2 with circle and polygon shapes, every Box2D joint kind,
// names (elements, and the Name attribute of shapes): all that bench/generate writes,
// in every spelling. Where box2scene would warn (an unknown element, say), the peer fails
// instead, so that a file outside its scope can never load differently unnoticed.
//
// The checks it makes, as errors, are box2scene's: malformed XML, a DOCTYPE, the root, the
// version, every value's syntax and range (floats finite in f32, IDs, 16-bit bits and
// group indices, booleans, vectors), negative values, missing and repeated containers and
// mandatory elements, radii, vertex counts, degenerate polygons (Box2D's hull), every ID
// against its container, gears against their joints, joints on one body, limits upside
// down, zero axes, pulley ratios. It skips, to stay a plain pugixml loader: every warning
// (a repeated scalar element loads with the last one winning, as in box2scene, silently;
// polygons not convex and counter-clockwise; dynamic bodies without density); line and
// column of errors (it gives byte offsets); UTF-8 validation, the NUL-byte check and
// UTF-16 input; duplicate attributes (pugixml keeps both); the load limits; and white space
// that pugixml drops around a comment or CDATA section that splits a value.
// Not supported (an error): unversioned files, Farseer's spellings and Version 3, edge and
// chain shapes, UserData, Farseer-only joints.
//
// Unlike box2scene's, the scene keeps the whole input text, where its names point.
#pragma once

#include <box2scene.h>

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace bench {

/// A scene as the peer loads it: box2scene's records, in vectors. Names point into the
/// parsed text (pugixml decodes it in place), which the scene keeps.
struct PugiScene {
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

/// Parses the `size` bytes of `text` (UTF-8) in place and fills `scene`. On failure returns
/// false and says why, with a byte offset, in `error`.
bool pugi_load(std::unique_ptr<char[]> text, size_t size, PugiScene& scene,
               std::string& error);

/// Reads the file at `path` into memory and loads it as pugi_load does.
bool pugi_load_file(const char* path, PugiScene& scene, std::string& error);

} // namespace bench
