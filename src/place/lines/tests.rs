use super::*;

/// The position of every offset of `text`, counted from the start one character at a
/// time, as a reference.
fn expected(text: &str, encoding: Encoding) -> Vec<Position> {
    let (mut line, mut column, mut units, mut after_cr) = (1, 1, 0, false);
    let bom = matches!(encoding, Encoding::Utf8 { bom: true });
    let mut positions = vec![Position::default(); text.len() + 1];
    for (offset, c) in text.char_indices().chain([(text.len(), '\0')]) {
        let byte_offset = match encoding {
            Encoding::Utf8 { .. } => offset as u64 + if bom { 3 } else { 0 },
            Encoding::Utf16 { .. } => 2 + 2 * units,
        };
        positions[offset] = Position { line, column, byte_offset };
        units += c.len_utf16() as u64;
        match c {
            '\n' if after_cr => column = 0,
            '\n' | '\r' => (line, column) = (line + 1, 0),
            _ => {}
        }
        column += 1;
        after_cr = c == '\r';
    }
    positions
}

#[test]
fn every_offset_in_every_order_is_placed_as_counted_from_the_start() {
    let texts = [
        "a\nb\r\nc\rd\n\re",
        "\r\n\r\n\n\r\r",
        "é€日本\n😀x\r😀\r\n",
        "",
        "one long line without an end",
    ];
    let encodings = [
        Encoding::Utf8 { bom: false },
        Encoding::Utf8 { bom: true },
        Encoding::Utf16 { big_endian: false },
    ];
    for text in texts {
        for encoding in encodings {
            let expected = expected(text, encoding);
            let offsets: Vec<usize> =
                (0..=text.len()).filter(|&i| text.is_char_boundary(i)).collect();
            // Forward, backward, and every pair.
            let mut lines = Lines::new(encoding, Cursor::start(0));
            for &at in offsets.iter().chain(offsets.iter().rev()) {
                assert_eq!(lines.locate(text, 0, at), expected[at], "{text:?} at {at}");
            }
            for &a in &offsets {
                for &b in &offsets {
                    let mut lines = Lines::new(encoding, Cursor::start(0));
                    lines.locate(text, 0, a);
                    assert_eq!(lines.locate(text, 0, b), expected[b], "{text:?} {a} {b}");
                }
            }
        }
    }
}

/// The counts are the counts byte by byte, for every length around the widths of the
/// vectors they are counted by.
#[test]
fn counts_are_counts_byte_by_byte() {
    let mut random = crate::Xorshift(0x2545_F491_4F6C_DD1D);
    let alphabet = [b'\n', b'\r', b'a', 0x80, 0xBF, 0xC3, 0xF0, b' '];
    for len in 0..4 * 64 + 3 {
        let bytes: Vec<u8> = (0..len).map(|_| alphabet[random.below(8)]).collect();
        let naive = |wanted: u8| bytes.iter().filter(|&&b| b == wanted).count() as u64;
        assert_eq!(feeds_and_returns(&bytes), (naive(b'\n'), naive(b'\r')), "{len}");
        let continuing = bytes.iter().filter(|&&b| b & 0xC0 == 0x80).count() as u64;
        assert_eq!(characters(&bytes), len as u64 - continuing, "{len}");
    }
}

/// Text that goes before the cursor passes it is counted first; offsets after it are
/// placed from what is left.
#[test]
fn released_text_is_counted_before_it_goes() {
    let text = "ab\r\ncd\ne\rf\r\ngh\n";
    let encoding = Encoding::Utf8 { bom: false };
    let expected = expected(text, encoding);
    for keep in 0..text.len() {
        for (at, &position) in expected.iter().enumerate().skip(keep) {
            let mut lines = Lines::new(encoding, Cursor::start(0));
            lines.release(text, 0, keep);
            let rest = &text[keep..];
            assert_eq!(lines.locate(rest, keep, at), position, "keep {keep}, at {at}");
        }
    }
}
