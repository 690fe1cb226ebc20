use super::values::{plain_attributes, plain_tag_end};
use super::{Attr, Name, Source, Tag, Tokenizer};
use crate::options::LoadOptions;

fn read(attrs: &[Attr]) -> Vec<(String, String, usize)> {
    attrs.iter().map(|a| (a.key.to_string(), a.value.to_string(), a.at)).collect()
}

/// What a reader sees of the children of the first element of `xml`, read with `child`
/// (`usual`) or node by node: each child's name, offset, emptiness and attributes, and
/// where the tokenizer stands after it; then the end, or the error that stops the
/// reading.
fn children(xml: &str, usual: bool, limits: &LoadOptions) -> Vec<String> {
    let mut seen = Vec::new();
    let source = Source::memory(xml.as_bytes(), limits).unwrap();
    let mut tok = Tokenizer::new(source, limits);
    let parent = match tok.next_node() {
        Ok(super::Node::Open(parent)) => parent,
        _ => return seen,
    };
    let mut slot = Tag::slot();
    loop {
        let next = match (usual, parent.empty) {
            (true, _) => tok.child(&parent, &mut slot).map(|more| more.then_some(&slot)),
            (false, true) => Ok(None),
            (false, false) => match tok.other_child(&parent) {
                Ok(Some(tag)) => {
                    slot = tag;
                    Ok(Some(&slot))
                }
                Ok(None) => Ok(None),
                Err(e) => Err(e),
            },
        };
        match next {
            Ok(Some(tag)) => {
                let attrs = tok.attributes(tag).map(|a| read(&a)).map_err(|e| e.at);
                seen.push(format!("{} {} {} {attrs:?}", tag.name(), tag.at, tag.empty));
                let (pos, skipped) = (tok.position(), tok.skip(tag).map_err(|e| e.at));
                seen.push(format!("at {pos}, skipped {skipped:?} to {}", tok.position()));
                if skipped.is_err() {
                    return seen;
                }
            }
            Ok(None) => {
                seen.push(format!("end at {}", tok.position()));
                return seen;
            }
            Err(e) => {
                seen.push(format!("{:?} at {:?}: {}", e.code, e.at, e.message));
                return seen;
            }
        }
    }
}

/// Reading children the usual way gives what reading them node by node gives, on every
/// mix of the usual and unusual markup, including the limits' errors.
#[test]
fn child_reads_what_the_nodes_give() {
    let pieces = [
        "<A>1</A>",
        "<Bb/>",
        "<Cc x='1'>2</Cc>",
        "<VeryLongElementName>3</VeryLongElementName>",
        "\n  ",
        "<!-- c -->",
        "text",
        "<D><E>4</E></D>",
        "<F",
        "</Other>",
        "<?pi x?>",
        "<![CDATA[ ]]>",
    ];
    let mut limits = LoadOptions::default();
    let defaults = limits;
    let mut tried = 0;
    for first in 0..pieces.len() {
        for second in 0..pieces.len() {
            for third in [0, 1, 4, 5] {
                let inner = [pieces[first], pieces[third], pieces[second]].concat();
                for xml in [format!("<Root>{inner}</Root>"), format!("<Root>{inner}")] {
                    for (elements, depth) in [(u64::MAX, u32::MAX), (3, u32::MAX), (99, 2)] {
                        limits.max_elements = elements.min(defaults.max_elements);
                        limits.max_depth = depth.min(defaults.max_depth);
                        let by_nodes = children(&xml, false, &limits);
                        assert_eq!(children(&xml, true, &limits), by_nodes, "{xml}");
                        tried += 1;
                    }
                }
            }
        }
    }
    assert!(tried > 1000);
}

/// The plain reading of attributes gives what quick-xml gives, or leaves the tag to it.
#[test]
fn plain_attributes_agree_with_quick_xml() {
    let options = LoadOptions::default();
    let parser = Tokenizer::new(Source::memory(b"", &options).unwrap(), &options);
    let keys = ["Type", "type", "a:b", "x-y.z", "_k", "é", "1a", "a b", ""];
    let values = ["Polygon", "", "a&amp;b", "a<b", "tab\there", "line\nbreak", "it's", "x\"y"];
    let spaces = [" ", "\t", "\r\n", "", "  "];
    let mut tried = 0;
    for key in keys {
        for value in values {
            for space in spaces {
                for quote in ['"', '\''] {
                    for equals in ["=", " = ", "= "] {
                        let first = format!("{space}{key}{equals}{quote}{value}{quote}");
                        for rest in ["", " ", " Other='1'", " Type=\"2\"", "Id=\"3\"", " k"] {
                            let content = format!("Shape{first}{rest}");
                            let end = 8 + content.len();
                            let tag = Tag { name: Name::new("Shape"), end, at: 7, empty: false };
                            let xml = parser.xml_attributes(&tag, &content);
                            if let Some(plain) = plain_attributes(&content, 5, 7) {
                                let xml = xml.unwrap_or_else(|e| panic!("{content:?}: {e:?}"));
                                assert_eq!(read(&plain), read(&xml), "{content:?}");
                                tried += 1;
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(tried > 200, "only {tried} contents were plain");
}

/// Start tags made at random of names, white space, attributes with either quote, `>`,
/// `/` and quotes where they belong or not, whole or cut short: where the reader finds the
/// end of one with plain attributes is where the scan stage marks it, and any it cannot
/// tell is left to the scan.
#[test]
fn a_plain_tag_ends_where_the_scan_marks_it() {
    let pieces = [
        "Body",
        "a\"b",
        " ",
        "\t",
        "\n",
        "Type=\"Dynamic\"",
        "k='v>w'",
        "x=\"it's\"",
        "y='a\"b'",
        "=",
        "\"",
        "'",
        ">",
        "/",
        "/>",
        "<",
        "&amp;",
        "é",
    ];
    let mut random = crate::Xorshift(0x5851_F42D_4C95_7F2D);
    let mut plain = 0;
    for _ in 0..20_000 {
        let mut text = String::from("<");
        for _ in 0..1 + random.below(8) {
            text.push_str(pieces[random.below(pieces.len())]);
        }
        if random.below(2) == 0 {
            text.push('>');
        }
        let marked = crate::scan::Index::new(0).next(0, text.as_bytes(), 0).map(|m| m.end);
        if let Some(end) = plain_tag_end(text.as_bytes()) {
            assert_eq!(Some(end), marked, "{text:?}");
            plain += 1;
        }
    }
    assert!(plain > 1_000, "only {plain} tags were plain");
}
