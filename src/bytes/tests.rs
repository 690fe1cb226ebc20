use super::*;

/// Every character that XML forbids, at every offset of texts of what it allows (plain
/// lines; tabs and carriage returns; characters past ASCII; those from U+F000 on next
/// to U+FFFE), is found where a character-by-character look finds it.
#[test]
fn first_non_char_finds_what_a_character_by_character_look_finds() {
    let kinds: [&[&str]; 4] = [
        &["a\n", "  <b>", "12 "],
        &["\t", "\r\n", "x"],
        &["é€", "日本", "\u{10000}", " "],
        &["\u{EFFF}", "\u{F000}\u{FFFD}", "\u{FEFF}", "\n"],
    ];
    let forbidden = ["\0", "\u{1}", "\u{8}", "\u{B}", "\u{C}", "\u{1F}", "\u{FFFE}", "\u{FFFF}"];
    let by_char = |text: &str| {
        let non_char = |c| matches!(c, '\0'..='\u{8}' | '\u{B}' | '\u{C}' | '\u{E}'..='\u{1F}' | '\u{FFFE}' | '\u{FFFF}');
        text.char_indices().find(|&(_, c)| non_char(c)).map(|(at, _)| at)
    };
    for pieces in kinds {
        let clean: String = (0..100).map(|i| pieces[i % pieces.len()]).collect();
        assert_eq!(first_non_char(clean.as_bytes()), None);
        for at in (0..=clean.len()).filter(|&at| clean.is_char_boundary(at)) {
            for bad in forbidden {
                let text = format!("{}{bad}{}", &clean[..at], &clean[at..]);
                assert_eq!(by_char(&text), Some(at));
                assert_eq!(first_non_char(text.as_bytes()), Some(at), "{bad:?} at {at}");
            }
        }
    }
}

#[test]
fn xml_space_len_stops_at_the_first_other_byte() {
    let spaces = b" \t\n\r";
    for len in 0..20 {
        for b in 0..=u8::MAX {
            // `len` white space bytes of every kind, `b`, then more white space.
            let mut bytes: Vec<u8> = (0..len).map(|i| spaces[i % 4]).collect();
            bytes.push(b);
            bytes.extend(spaces);
            let expected = match spaces.contains(&b) {
                true => bytes.len(),
                false => len,
            };
            assert_eq!(xml_space_len(&bytes), expected, "{bytes:?}");
            assert_eq!(xml_space_len(&bytes[..len]), len);
        }
    }
}

/// The lowest flag of `first_equal` is the first byte equal to the one looked for, and
/// there is none when no byte is, whatever the bytes after it: in particular those a
/// borrow goes through (one above it, 0x80, 0x81, 0xFF...).
#[test]
fn first_equal_flags_the_first_equal_byte_first() {
    let mut random = crate::Xorshift(0x2545_F491_4F6C_DD1D);
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
            let state = random.next();
            let bytes: [u8; 8] = std::array::from_fn(|i| near[(state >> (6 * i)) as usize % 10]);
            let expected = bytes.iter().position(|&x| x == b);
            let mask = first_equal(u64::from_le_bytes(bytes), b);
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
    let mut random = crate::Xorshift(0x9E37_79B9_7F4A_7C15);
    for len in 0..40 {
        for _ in 0..500 {
            let mut text = Vec::new();
            for _ in 0..len {
                // Mostly white space, so that runs of it cross the eight-byte words.
                let pick = random.below(16);
                text.extend_from_slice(pieces[if pick < 8 { pick % 4 } else { pick - 7 }]);
            }
            assert_eq!(space_len(&text), xml_space_len(&text), "{text:?}");
            assert_eq!(trimmed_span(&text), xml_trimmed_span(&text), "{text:?}");
        }
    }
}

/// Every byte value, at every place in a block, is flagged in its own mask and in no other.
#[test]
fn block_masks_flag_each_byte_asked_for() {
    let sets = [b'<', b'"', b'\'', 0x80, 0xFF];
    for shift in 0..=255u8 {
        let block: [u8; BLOCK] =
            std::array::from_fn(|i| (i as u8).wrapping_mul(7).wrapping_add(shift));
        let expected = sets
            .map(|set| (0..BLOCK).filter(|&i| block[i] == set).fold(0u64, |mask, i| mask | 1 << i));
        assert_eq!(block_masks(&block, sets), expected, "shift {shift}");
    }
}

/// A text is plain when no byte of it is `&` or a carriage return, wherever one falls in it,
/// in the words read eight at a time or in the bytes after them.
#[test]
fn plain_text_has_no_reference_or_carriage_return() {
    for len in 0..40 {
        let text = vec![b'1'; len];
        assert!(is_plain(&text), "{len}");
        for at in 0..len {
            for special in [b'&', b'\r'] {
                let mut text = text.clone();
                text[at] = special;
                assert!(!is_plain(&text), "{len}, {at}");
            }
            // Bytes near them, which the word-at-a-time test must not take for them.
            let mut near = text.clone();
            near[at] = [b'%', b'\'', b'\n', 0x0C, 0xA6, 0x8D][at % 6];
            assert!(is_plain(&near), "{len}, {at}");
        }
    }
}

/// The end of a short name is the first byte of sixteen that ends a name or that no name
/// holds, wherever it is and whichever byte it is, as a look at one byte at a time finds it.
#[test]
fn short_name_len_finds_the_first_byte_that_ends_a_name() {
    let ends = |b: u8| ENDS_NAME[usize::from(b)] || (b'!'..=b'&').contains(&b);
    for b in 0..=255u8 {
        for at in 0..16 {
            let mut head = *b"VeryLongElementN";
            head[at] = b;
            let expected = head.iter().position(|&b| ends(b));
            assert_eq!(short_name_len(&head), expected, "{b:#04x} at {at}");
        }
    }
    assert_eq!(short_name_len(b"\xC3\xA9t\xC3\xA9 x=\"1\">    "), Some(5));
    assert_eq!(short_name_len(b"Angle>0.5</Angle"), Some(5));
    assert_eq!(short_name_len(b"Pair/><Pair/><Pa"), Some(4));
}

/// A value and the text after it, of every length up to past 32 bytes, mostly white space
/// with references, carriage returns and characters past ASCII among it: the plain value's
/// span in one pass is what the check for references and the trimming give apart.
#[test]
fn plain_trimmed_agrees_with_is_plain_and_trimmed_span() {
    let pieces: [&[u8]; 9] = [b" ", b"\t", b"\n", b"\r", b"a", b"&", b"\xC3\xA9", b"<", b"1"];
    let mut random = crate::Xorshift(0x2545_F491_4F6C_DD1D);
    for len in 0..40 {
        for _ in 0..2_000 {
            let mut text = Vec::new();
            while text.len() < len + random.below(20) {
                let pick = random.below(24);
                text.extend_from_slice(
                    pieces[if pick < 9 { pick } else { [0, 2, 4, 8][pick % 4] }],
                );
            }
            let len = len.min(text.len());
            let value = &text[..len];
            let apart = is_plain(value).then(|| trimmed_span(value));
            assert_eq!(plain_trimmed(&text, len), apart, "{text:?} {len}");
        }
    }
}

/// Texts of every length up to past 32 bytes with a `<` or none, anywhere: the first is
/// where a look at one byte at a time finds it.
#[test]
fn first_lt_finds_the_first_lt() {
    let pieces: [&[u8]; 5] = [b" ", b"a", b"<", b"\xC3\xA9", b">"];
    let mut random = crate::Xorshift(0x9E37_79B9_7F4A_7C15);
    for len in 0..40 {
        for _ in 0..500 {
            let mut text = Vec::new();
            while text.len() < len {
                // Mostly spaces and letters, now and then anything.
                let kinds = if random.below(4) == 0 { pieces.len() } else { 2 };
                text.extend_from_slice(pieces[random.below(kinds)]);
            }
            let expected = text.iter().position(|&b| b == b'<');
            assert_eq!(first_lt(&text), expected, "{text:?}");
        }
    }
}
