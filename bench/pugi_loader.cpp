#include "pugi_loader.hpp"

#include <pugixml.hpp>

#include <string_view>
#include <utility>

#include "file_bytes.hpp"
#include "peer_walk.hpp"

namespace bench {
namespace {

/// In place; entities, CDATA, end-of-line and attribute white space as XML requires; text
/// trimmed, as the format trims values; a DOCTYPE parsed only to be refused.
constexpr unsigned kParseOptions =
    pugi::parse_default | pugi::parse_trim_pcdata | pugi::parse_doctype;

/// pugixml's tree as the walk reads it (bench/peer_walk.hpp). Parsed in place, every name
/// and value is a zero-terminated piece of the text.
struct PugiDom {
    using Node = pugi::xml_node;
    using Attribute = pugi::xml_attribute;

    static Node first_child(Node node) { return node.first_child(); }
    static Node next_sibling(Node node) { return node.next_sibling(); }
    static bool is_element(Node node) { return node.type() == pugi::node_element; }
    static bool is_text(Node node) { return node.type() == pugi::node_pcdata; }
    static bool is_cdata(Node node) { return node.type() == pugi::node_cdata; }
    static bool is_doctype(Node node) { return node.type() == pugi::node_doctype; }
    static const char* name(Node node) { return node.name(); }
    static std::string_view value(Node node) { return node.value(); }
    static Attribute first_attribute(Node node) { return node.first_attribute(); }
    static Attribute next_attribute(Attribute a) { return a.next_attribute(); }
    static std::string_view attribute_name(Attribute a) { return a.name(); }
    static std::string_view attribute_value(Attribute a) { return a.value(); }
    ptrdiff_t offset(Node node) const { return node.offset_debug(); }
};

} // namespace

bool pugi_load(std::unique_ptr<char[]> text, size_t size, PeerScene& scene,
               std::string& error) {
    scene = PeerScene{};
    scene.text = std::move(text);
    // The tree is only walked: freed on return, while the names stay in the text.
    pugi::xml_document document;
    pugi::xml_parse_result parsed =
        document.load_buffer_inplace(scene.text.get(), size, kParseOptions, pugi::encoding_utf8);
    if (!parsed) {
        error = peer::at_byte(parsed.offset,
                              std::string("malformed XML: ") + parsed.description());
        return false;
    }
    return peer::walk(PugiDom{}, document, scene, error);
}

bool pugi_load_file(const char* path, PeerScene& scene, std::string& error) {
    size_t size = 0;
    std::unique_ptr<char[]> text = read_file(path, size);
    if (!text) {
        error = std::string("cannot read ") + path;
        return false;
    }
    return pugi_load(std::move(text), size, scene, error);
}

} // namespace bench
