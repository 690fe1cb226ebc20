use super::values::plain_attributes;
use super::{Attr, Name, Source, Tag, Tokenizer};
use crate::options::LoadOptions;

fn read(attrs: &[Attr]) -> Vec<(String, String, usize)> {
    attrs.iter().map(|a| (a.key.to_string(), a.value.to_string(), a.at)).collect()
}

#[test]
fn find3_finds_the_first_of_three_bytes() {
    for len in 0..80 {
        for at in 0..=len {
            for (b, c) in [(b'<', b'&'), (b'&', b'<'), (b'\r', b'\r'), (0xBC, b'<')] {
                // `b` at `at` (unless past the end), `c` later, other bytes around them.
                let mut hay: Vec<u8> = (0..len).map(|i| b"a \n\xE2<&\r"[i % 3]).collect();
                if at < len {
                    hay[at] = b;
                }
                hay.push(c);
                let expected = hay.iter().position(|&x| matches!(x, b'<' | b'&' | b'\r'));
                assert_eq!(super::find3(&hay, b'<', b'&', b'\r'), expected, "{hay:?}");
            }
        }
    }
}

/// The lowest flag of `first_equal` is the first byte equal to the one looked for, and
/// there is none when no byte is, whatever the bytes after it: in particular those a
/// borrow goes through (one above it, 0x80, 0x81, 0xFF...).
#[test]
fn first_equal_flags_the_first_equal_byte_first() {
    let mut state = 0x2545_F491_4F6C_DD1Du64;
    for b in [0u8, 1, b'\r', b'&', b'<', b'>', 0x7F, 0x80, 0x81, 0xFE, 0xFF] {
        let near = [
            b,
            b ^ 1,
            b ^ 0x80,
            b ^ 0x81,
            b ^ 0x7F,
            b ^ 0xFF,
            b.wrapping_add(1),
            b.wrapping_sub(1),
            0,
            0xFF,
        ];
        for _ in 0..100_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let bytes: [u8; 8] = std::array::from_fn(|i| near[(state >> (6 * i)) as usize % 10]);
            let expected = bytes.iter().position(|&x| x == b);
            let mask = super::bytes::first_equal(u64::from_le_bytes(bytes), b);
            let found = (mask != 0).then(|| (mask.trailing_zeros() / 8) as usize);
            assert_eq!(found, expected, "{bytes:02x?} looking for {b:#04x}");
        }
    }
}

/// The white space of the text at hand is skipped and trimmed as XML white space is, in
/// text without the control characters the source stops before.
#[test]
fn space_len_and_trimmed_span_agree_with_xml_white_space() {
    let pieces: [&[u8]; 9] = [b" ", b"\t", b"\n", b"\r", b"a", b"<", b"\xC3\xA9", b"!", b"\x7F"];
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    for len in 0..40 {
        for _ in 0..500 {
            let mut text = Vec::new();
            for _ in 0..len {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                // Mostly white space, so that runs of it cross the eight-byte words.
                let pick = (state % 16) as usize;
                text.extend_from_slice(pieces[if pick < 8 { pick % 4 } else { pick - 7 }]);
            }
            assert_eq!(super::space_len(&text), crate::text::leading_space(&text), "{text:?}");
            assert_eq!(
                super::bytes::trimmed_span(&text),
                crate::text::trimmed_span(&text),
                "{text:?}"
            );
        }
    }
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
                seen.push(format!("{:?} at {}: {}", e.code, e.at, e.message));
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
                            let tag = Tag {
                                name: Name::new("Shape"),
                                content: Some(content.as_str().into()),
                                at: 7,
                                empty: false,
                            };
                            let body = tag.content.as_deref().unwrap();
                            let xml = parser.xml_attributes(&tag, body);
                            if let Some(plain) = plain_attributes(body, 5, 7) {
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
