// A second peer box2scene is measured against (bench/run): a Box2Scene loader written the
// way a careful C++ programmer would on rapidxml. rapidxml reads a zero-terminated text and
// parses it in place; the walk of bench/peer_walk.hpp then fills box2scene's own records
// with the same defaults, the same semantics and box2scene's checks where they are cheap,
// exactly as it does for the pugixml peer (bench/pugi_loader.hpp).
//
// Of the XML itself, rapidxml refuses what it cannot parse (an unclosed element, a missing
// quote, a character reference without its `;`) and, as asked, an end tag that does not
// match its start tag; the walk refuses a DOCTYPE. It skips, to stay a plain rapidxml
// loader: the rest of XML's well-formedness (a `<` in an attribute value, an unknown entity,
// kept as written, characters a name may not hold, ...); UTF-8 validation and UTF-16 input;
// the NUL-byte check (rapidxml ends the text at the first NUL); duplicate attributes
// (rapidxml keeps both); XML's end-of-line and attribute white-space normalisation (a name
// with a CR LF in it keeps both bytes); and white space that rapidxml drops around a comment
// or CDATA section that splits a value.
// Not supported (an error): what the pugixml peer does not support.
//
// Like the pugixml peer's, the scene keeps the whole input text (here a copy of it, one
// byte longer), where its names point.
#pragma once

#include <cstddef>
#include <string>

#include "peer_scene.hpp"

namespace bench {

/// Copies the `size` bytes of `text` (UTF-8) with a NUL after them, as rapidxml reads, then
/// parses the copy in place and fills `scene`. On failure returns false and says why, with
/// a byte offset, in `error`.
bool rapidxml_load(const char* text, size_t size, PeerScene& scene, std::string& error);

/// Reads the file at `path` into memory, with the NUL after it, and loads it as
/// rapidxml_load does (without the copy).
bool rapidxml_load_file(const char* path, PeerScene& scene, std::string& error);

} // namespace bench
