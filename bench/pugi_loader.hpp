// A peer box2scene is measured against (bench/run): a Box2Scene loader written the way a
// careful C++ programmer would on pugixml. An in-place DOM parse, then the walk of
// bench/peer_walk.hpp, which fills box2scene's own records with the same defaults, the same
// semantics and box2scene's checks where they are cheap.
//
// Of the XML itself, pugixml refuses what is malformed, and the walk a DOCTYPE. It skips,
// to stay a plain pugixml loader: UTF-8 validation, the NUL-byte check and UTF-16 input;
// duplicate attributes (pugixml keeps both); and white space that pugixml drops around a
// comment or CDATA section that splits a value.
// Not supported (an error): unversioned files, Farseer's spellings and Version 3, edge and
// chain shapes, UserData, Farseer-only joints.
//
// Unlike box2scene's, the scene keeps the whole input text, where its names point.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "peer_scene.hpp"

namespace bench {

/// Parses the `size` bytes of `text` (UTF-8) in place and fills `scene`. On failure returns
/// false and says why, with a byte offset, in `error`.
bool pugi_load(std::unique_ptr<char[]> text, size_t size, PeerScene& scene,
               std::string& error);

/// Reads the file at `path` into memory and loads it as pugi_load does.
bool pugi_load_file(const char* path, PeerScene& scene, std::string& error);

} // namespace bench
