use super::*;
use crate::Xorshift;

/// The offsets of the marks of `text`, read whole through an index.
fn marked(text: &str) -> Vec<(usize, usize, bool)> {
    indexed(text.as_bytes(), 0, text.len()).iter().map(|m| (m.at, m.end, m.stops)).collect()
}

/// A `<` in a comment, CDATA, a processing instruction or a quoted value begins no mark of
/// its own; a tag ends at its first `>` outside quoted values.
#[test]
fn only_markup_is_marked() {
    let text = "<?pi <a> ?><World><!-- <a> --><Bodies a='<b>' b=\"/>\"><![CDATA[<c>]]>\
                <Body c=\"/\"/></Bodies></World>";
    let at = |piece: &str| text.find(piece).unwrap();
    let end = |piece: &str| at(piece) + piece.len() - 1;
    let expected = ["<?pi <a> ?>", "<World>", "<!-- <a> -->", "<Bodies a='<b>' b=\"/>\">"]
        .into_iter()
        .chain(["<![CDATA[<c>]]>", "<Body c=\"/\"/>", "</Bodies>", "</World>"])
        .map(|piece| (at(piece), end(piece), false))
        .collect::<Vec<_>>();
    assert_eq!(marked(text), expected);
}

/// Markup XML does not have stops the scan: the reader stops there.
#[test]
fn markup_that_cannot_be_read_stops_the_scan() {
    for text in ["<W><B><!DOCTYPE W><I/></B></W>", "<W><B><!-- a -- b --><I/></B></W>"] {
        let marks = marked(text);
        assert_eq!(marks.len(), 3, "{text}");
        assert!(marks[2].2, "{text}");
    }
}

/// Cut anywhere, over as many windows as it takes, a text gives the marks it gives whole.
/// Tags longer than a block and blocks full of tags are read as well as short ones.
#[test]
fn windows_give_what_the_whole_text_gives() {
    let long = format!("<Body Note=\"{}\" x='>'/>", "> < ".repeat(40));
    let text = format!(
        "<?pi ?>\n<World a=\"1/\"><Bodies><Body/><Body x='>'>\r\n<!-- - -->\
         </Body><!-- a - b --><![CDATA[ ]] ]]]> ]]><Body\n/>{long}{}</Bodies><Joints><Joint/>\
         </Joints></World>",
        "<Body/>".repeat(30)
    );
    let expected = indexed(text.as_bytes(), 0, text.len());
    assert_eq!(expected.len(), 10 + 30 + 6);
    for window in [1, 2, 3, 5, 7, 63, 64, 65, 100] {
        assert_eq!(indexed(text.as_bytes(), 0, window), expected, "windows of {window}");
    }
}

/// Appends up to `most` of `pieces` to `text`, at random: mostly tags that open and close
/// (the first two pieces), so that blocks of plain tags are common, and text (the sixth to
/// the eighth); now and then any of the first `others`.
fn random_pieces(
    random: &mut Xorshift,
    text: &mut Vec<u8>,
    pieces: &[&[u8]],
    most: usize,
    others: usize,
) {
    for _ in 0..random.below(most) {
        let piece = match random.below(10) {
            0..3 => 0,
            3..6 => 1,
            6..8 => 5 + random.below(3),
            _ => random.below(others),
        };
        text.extend_from_slice(pieces[piece]);
    }
}

/// The marks of `text` by the scan's rules, followed a byte at a time: every tag and end tag
/// to its `>` past quoted values, processing instructions to `?>`, CDATA to `]]>`, comments
/// to `-->` (or to a `--` before anything else, where the scan stops, as at a DOCTYPE and
/// at `<!` XML does not have); none for markup the text cuts.
fn marks_one_by_one(text: &[u8]) -> Vec<Mark> {
    let (mut i, mut marks) = (0, vec![]);
    let find = |from: usize, delimiter: &[u8]| {
        memchr::memmem::find(&text[from.min(text.len())..], delimiter).map(|at| from + at)
    };
    while let Some(at) = text[i..].iter().position(|&b| b == b'<') {
        let lt = i + at;
        let rest = &text[lt..];
        let (end, stops) = if rest.starts_with(b"<?") {
            (find(lt + 2, b"?>").map(|q| q + 1), false)
        } else if rest.starts_with(b"<![CDATA[") {
            (find(lt + 9, b"]]>").map(|e| e + 2), false)
        } else if rest.starts_with(b"<!--") {
            match find(lt + 4, b"--") {
                Some(d) if text.get(d + 2) == Some(&b'>') => (Some(d + 2), false),
                Some(d) if d + 2 < text.len() => (Some(d), true),
                _ => (None, false),
            }
        } else if rest.starts_with(b"<!") {
            // Too short to tell is cut; anything else stops.
            let cut = b"<!--".starts_with(rest) || b"<![CDATA[".starts_with(rest);
            (if cut { None } else { Some(lt) }, !cut)
        } else if rest.len() < 2 {
            (None, false)
        } else {
            let mut end = lt + 1;
            loop {
                match text[end..].iter().position(|b| b"\"'>".contains(b)) {
                    Some(q) if text[end + q] == b'>' => break (Some(end + q), false),
                    Some(q) => match text[end + q + 1..].iter().position(|&b| b == text[end + q]) {
                        Some(close) => end = end + q + 1 + close + 1,
                        None => break (None, false),
                    },
                    None => break (None, false),
                }
            }
        };
        let Some(end) = end else { break };
        marks.push(Mark { at: lt, end, stops });
        if stops {
            break;
        }
        i = end + 1;
    }
    marks
}

/// The marks of a text read through an [`Index`] from `start`, the text at hand growing by
/// `window` bytes whenever the index has no mark left in it.
fn indexed(text: &[u8], start: usize, window: usize) -> Vec<Mark> {
    let mut index = Index::new(start);
    let (mut marks, mut end) = (vec![], (start + window).min(text.len()));
    loop {
        let at = marks.last().map_or(start, |mark: &Mark| mark.at + 1);
        match index.next(at, &text[..end], 0) {
            Some(mark) => {
                marks.push(mark);
                index.take();
            }
            None if end == text.len() => return marks,
            None => end = (end + window).min(text.len()),
        }
    }
}

/// Asks an index over `text`, whose marks are `expected`, for the mark at the start of each
/// of them in turn, passing some at random as the reader passes the markup it reads itself,
/// the text at hand growing by `window` bytes whenever the index has no mark in it: each
/// mark asked for and the one given.
fn asked_past(
    text: &[u8],
    expected: &[Mark],
    window: usize,
    random: &mut Xorshift,
) -> Vec<(Mark, Option<Mark>)> {
    let mut index = Index::new(0);
    let (mut given, mut end, mut k) = (vec![], window.min(text.len()), random.below(3));
    while let Some(&wanted) = expected.get(k) {
        // The reader has read up to the markup it asks for: that much is at hand.
        while end < wanted.at {
            end = (end + window).min(text.len());
        }
        match index.next(wanted.at, &text[..end], 0) {
            Some(mark) => {
                given.push((wanted, Some(mark)));
                index.take();
                k += 1 + random.below(3);
            }
            None if end == text.len() => {
                given.push((wanted, None));
                break;
            }
            None => end = (end + window).min(text.len()),
        }
    }
    given
}

/// Texts made at random of tags, text and markup, broken or not: the marks the reader walks,
/// through an index over the whole text and over windows of it, are those a byte-at-a-time
/// reading finds.
#[test]
fn the_index_marks_what_a_byte_at_a_time_reading_finds() {
    let pieces: [&[u8]; 20] = [
        b"<a>",
        b"</a>",
        b"<b/>",
        b"<c x='1>'>",
        b"<d y=\"/>'\"/>",
        b" text ",
        b"\n    ",
        b"1.5 2",
        b">",
        b"</>",
        b"<>",
        b"<!-- c -->",
        b"<?p ?>",
        b"<![CDATA[<x>]]>",
        b"<<",
        b"</a y='>'>",
        b"<e\n/>",
        b"&amp;",
        b"<!-- a -- b -->",
        b"<!DOCTYPE a>",
    ];
    let mut random = Xorshift(0x9e37_79b9_7f4a_7c15);
    let long = format!("<Long a=\"{}\">", "x>".repeat(CHUNK));
    for round in 0..2000 {
        let mut text = b"<W><C>".to_vec();
        if round % 100 == 0 {
            text.extend_from_slice(long.as_bytes());
        }
        // The last two pieces stop the scan: in a text now and then.
        let stopping = if round % 4 == 0 { 0 } else { 2 };
        random_pieces(&mut random, &mut text, &pieces, 300, pieces.len() - stopping);
        let expected = marks_one_by_one(&text);
        for window in [text.len().max(1), 1, 13, 64, 100, 4096] {
            assert_eq!(
                indexed(&text, 0, window),
                expected,
                "round {round}, windows of {window}: {}",
                String::from_utf8_lossy(&text)
            );
        }
        // The reader reads the usual markup itself and asks for the marks of the rest.
        for window in [text.len().max(1), 13, 64] {
            for (wanted, given) in asked_past(&text, &expected, window, &mut random) {
                assert_eq!(
                    given,
                    Some(wanted),
                    "round {round}, windows of {window}: {}",
                    String::from_utf8_lossy(&text)
                );
            }
        }
        // An index that starts at an item, as a piece's reader does, marks what follows.
        if let Some(item) = expected.iter().skip(3).find(|m| text[m.at + 1].is_ascii_alphabetic()) {
            let from = expected.iter().position(|m| m == item).unwrap();
            assert_eq!(
                indexed(&text, item.at, 64),
                expected[from..],
                "round {round}, from {}",
                item.at
            );
        }
    }
}
