use super::{Name, key};

/// Case-insensitive ASCII equality, the rule for element names (spec section 2).
fn same(a: &[u8], b: &[u8]) -> bool {
    a.eq_ignore_ascii_case(b)
}

#[test]
fn a_key_matches_exactly_the_names_equal_to_it_in_any_case() {
    let known = ["vertex1", "localanchora", "collideconnected", "id", "x"];
    let mut names: Vec<Vec<u8>> = Vec::new();
    for k in known {
        names.push(k.as_bytes().to_vec());
        names.push(k.to_ascii_uppercase().into_bytes());
    }
    // Every byte in every place of a few names, and one byte more or less.
    for base in [&b"Vertex1"[..], b"LocalAnchorA", b"ID", b"CollideConnected"] {
        for i in 0..base.len() {
            for b in 0x21..=u8::MAX {
                let mut name = base.to_vec();
                name[i] = b;
                names.push(name);
            }
        }
        names.push(base[..base.len() - 1].to_vec());
        names.push([base, b"1"].concat());
    }
    for name in &names {
        let Ok(text) = std::str::from_utf8(name) else { continue };
        let name = Name::new(text);
        for k in known {
            assert_eq!(name.key() == key(k), same(text.as_bytes(), k.as_bytes()), "{text:?} {k}");
        }
    }
}

#[test]
fn names_with_control_characters_or_over_16_bytes_match_no_key() {
    assert_eq!(Name::new("Vertex\u{11}").key(), 0);
    assert_eq!(Name::new("Vertex\u{11}").as_str(), "Vertex\u{11}");
    let long = "CollideConnectedX";
    assert_eq!(Name::new(long).key(), 0);
    assert_eq!(Name::new(long).as_str(), long);
}

#[test]
fn a_name_ends_only_at_its_own_end_tag() {
    for name in ["A", "Vertex", "CollideConnected", "CollideConnectedX", "名前"] {
        let n = Name::new(name);
        assert_eq!(n.len(), name.len());
        assert_eq!(n.as_str(), name);
        let name = name.as_bytes();
        // Short and long text after the name, since a short name reads 16 bytes at once.
        for tail in [&b""[..], b"                 "] {
            let ends = |text: &[&[u8]]| n.ends(&[text, &[tail]].concat().concat());
            assert!(ends(&[name, b">"]));
            assert!(!ends(&[name, b" >"]));
            assert!(!ends(&[name, b"x>"]));
            assert!(
                !ends(&[&name.to_ascii_lowercase(), b">"]) || name == name.to_ascii_lowercase()
            );
            assert!(!ends(&[&name[..name.len() - 1], b">"]));
            assert!(!ends(&[name]));
        }
    }
    assert!(!Name::new("Vertex").ends(b"vertex>                 "));
}

/// The end tag read as one number is the end tag read byte by byte, for names around
/// the length where the number no longer holds it, before text of every length.
#[test]
fn end_tag_len_agrees_with_reading_the_end_tag() {
    let names = ["A", "Vertex", "Restitution", "LocalAnchorA", "ReferenceAngle", "MotorSpeeds"];
    let names =
        names.iter().chain(&["CollideConnected", "CollideConnectedX", "名前", "abcdefghijklm"]);
    for name in names {
        let n = Name::new(name);
        let bytes = name.as_bytes();
        let mut texts: Vec<Vec<u8>> = Vec::new();
        let end_tag = [b"</", bytes, b">"].concat();
        for cut in 0..=end_tag.len() {
            texts.push(end_tag[..cut].to_vec());
            for i in 0..cut {
                for b in [b'>', b' ', b'a', b'A', 0x80, bytes[i % bytes.len()] ^ 0x20] {
                    let mut changed = end_tag[..cut].to_vec();
                    changed[i] = b;
                    texts.push(changed);
                }
            }
        }
        for tail in [&b""[..], b"x", b"  \n    <Next>", b"                  "] {
            for text in &texts {
                let text = [text, tail].concat();
                let expected = match &text[..] {
                    [b'<', b'/', after @ ..] if n.ends(after) => Some(3 + n.len()),
                    _ => None,
                };
                let expected_bytes = text.starts_with(&end_tag).then_some(end_tag.len());
                assert_eq!(expected, expected_bytes, "{name} {text:?}");
                assert_eq!(n.end_tag_len(&text), expected, "{name} {text:?}");
            }
        }
    }
}
