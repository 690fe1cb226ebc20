#include "rapidxml_loader.hpp"

#include <rapidxml/rapidxml.hpp>

#include <cstring>
#include <memory>
#include <string_view>
#include <utility>

#include "file_bytes.hpp"
#include "peer_walk.hpp"

namespace bench {
namespace {

/// parse_default on the loader's own copy of the text, rather than parse_non_destructive:
/// rapidxml reads up to a NUL, so a text in memory is copied either way, and once the copy
/// is the loader's, parsing it in place costs nothing more and gives what the scene needs,
/// every name a zero-terminated string with its entities decoded. Non-destructive parsing
/// would leave both to the loader: a copy of every name and an entity decoder of its own.
/// To the defaults it adds: text trimmed, as the format trims values; no element values
/// (the walk reads the text nodes, as it does pugixml's); end tags matched against their
/// start tags, one comparison of a name each, or a file box2scene and pugixml refuse as
/// malformed would load; and DOCTYPE nodes, only to be refused.
constexpr int kParseFlags = rapidxml::parse_default | rapidxml::parse_trim_whitespace |
                            rapidxml::parse_no_element_values |
                            rapidxml::parse_validate_closing_tags |
                            rapidxml::parse_doctype_node;

/// rapidxml's tree as the walk reads it (bench/peer_walk.hpp). Parsed in place with string
/// terminators, every name and value is a zero-terminated piece of the text.
struct RapidxmlDom {
    using Node = const rapidxml::xml_node<>*;
    using Attribute = const rapidxml::xml_attribute<>*;

    const char* text; // where the parsed text begins, for offsets

    static Node first_child(Node node) { return node->first_node(); }
    static Node next_sibling(Node node) { return node->next_sibling(); }
    static bool is_element(Node node) { return node->type() == rapidxml::node_element; }
    static bool is_text(Node node) { return node->type() == rapidxml::node_data; }
    static bool is_cdata(Node node) { return node->type() == rapidxml::node_cdata; }
    static bool is_doctype(Node node) { return node->type() == rapidxml::node_doctype; }
    static const char* name(Node node) { return node->name(); }
    static std::string_view value(Node node) { return {node->value(), node->value_size()}; }
    static Attribute first_attribute(Node node) { return node->first_attribute(); }
    static Attribute next_attribute(Attribute a) { return a->next_attribute(); }
    static std::string_view attribute_name(Attribute a) { return {a->name(), a->name_size()}; }
    static std::string_view attribute_value(Attribute a) {
        return {a->value(), a->value_size()};
    }
    /// An element's name, or another node's value: where it begins.
    ptrdiff_t offset(Node node) const {
        return (is_element(node) ? node->name() : node->value()) - text;
    }
};

/// Parses `text`, `size` bytes and a NUL, which the scene keeps, and walks it.
bool load_terminated(std::unique_ptr<char[]> text, PeerScene& scene, std::string& error) {
    scene = PeerScene{};
    scene.text = std::move(text);
    // The tree is only walked: freed on return, while the names stay in the text.
    rapidxml::xml_document<> document;
    try {
        document.parse<kParseFlags>(scene.text.get());
    } catch (const rapidxml::parse_error& e) {
        error = peer::at_byte(e.where<char>() - scene.text.get(),
                              std::string("malformed XML: ") + e.what());
        return false;
    }
    return peer::walk(RapidxmlDom{scene.text.get()}, &document, scene, error);
}

} // namespace

bool rapidxml_load(const char* text, size_t size, PeerScene& scene, std::string& error) {
    // new char[n] leaves the bytes uninitialised: the pages are touched once, by the copy.
    std::unique_ptr<char[]> copy(new char[size + 1]);
    std::memcpy(copy.get(), text, size);
    copy[size] = '\0';
    return load_terminated(std::move(copy), scene, error);
}

bool rapidxml_load_file(const char* path, PeerScene& scene, std::string& error) {
    size_t size = 0;
    std::unique_ptr<char[]> text = read_file(path, size);
    if (!text) {
        error = std::string("cannot read ") + path;
        return false;
    }
    return load_terminated(std::move(text), scene, error);
}

} // namespace bench
