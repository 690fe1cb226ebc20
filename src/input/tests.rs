use super::{CHUNK, Shared, Source};
use crate::error::{Code, Spot};
use crate::options::LoadOptions;

/// A file that grows past the input limit while it is read stops the text after the
/// last chunk read within the limit.
#[test]
fn a_file_that_grows_past_the_limit_stops_the_text() {
    let path = std::env::temp_dir().join(format!("box2scene-grows-{}.xml", std::process::id()));
    std::fs::write(&path, "a".repeat(CHUNK + 100)).unwrap();
    let options = LoadOptions { max_input_bytes: 3 * CHUNK as u64, ..LoadOptions::default() };
    let mut source = Source::path(&path, &options).unwrap();
    let mut file = std::fs::OpenOptions::new().append(true).open(&path).unwrap();
    std::io::Write::write_all(&mut file, "b".repeat(3 * CHUNK).as_bytes()).unwrap();
    while source.more(source.end()) {}
    std::fs::remove_file(&path).unwrap();
    // Three chunks were read within the limit; the fourth passed it.
    let stop = source.stop().expect("the limit stops the text");
    assert_eq!((stop.code, stop.at), (Code::LimitExceeded, Spot::offset(3 * CHUNK)));
    assert_eq!(source.end(), 3 * CHUNK);
}

/// A text in memory is checked a chunk at a time as it is read (the longer the text
/// kept, the more at once): the text at hand stops before the first character XML does
/// not allow, or the first byte that is not UTF-8, whichever comes first, and only
/// once it is reached; a piece is a text only when it is checked all through.
#[test]
fn a_text_in_memory_is_checked_as_it_is_read() {
    let text = "a".repeat(5 * CHUNK);
    let options = LoadOptions::default();
    let read_keeping = |bytes: &[u8], all: bool| {
        let mut source = Source::memory(bytes, &options).unwrap();
        assert_eq!(source.end(), CHUNK.min(bytes.len()));
        let mut ends = vec![source.end()];
        while source.more(if all { 0 } else { source.end() }) {
            ends.push(source.end());
        }
        let stop = source.stop().map(|s| (s.code, s.at));
        (ends, stop)
    };
    let read = |bytes: &[u8]| read_keeping(bytes, false);
    assert_eq!(read(text.as_bytes()), ((1..=5).map(|k| k * CHUNK).collect(), None));
    let doubling = vec![CHUNK, 2 * CHUNK, 4 * CHUNK, 5 * CHUNK];
    assert_eq!(read_keeping(text.as_bytes(), true), (doubling, None));
    let mut bytes = text.clone().into_bytes();
    bytes[4 * CHUNK + 9] = 0x01;
    let ends = vec![CHUNK, 2 * CHUNK, 3 * CHUNK, 4 * CHUNK, 4 * CHUNK + 9];
    assert_eq!(read(&bytes), (ends, Some((Code::MalformedXml, Spot::offset(4 * CHUNK + 9)))));
    bytes[4 * CHUNK + 10] = 0xFF;
    assert_eq!(read(&bytes).1, Some((Code::MalformedXml, Spot::offset(4 * CHUNK + 9))));
    bytes[3 * CHUNK] = 0xFF;
    assert_eq!(read(&bytes).1, Some((Code::InvalidUtf8, Spot::offset(3 * CHUNK))));
    bytes[3 * CHUNK] = 0;
    assert_eq!(read(&bytes).1, Some((Code::NulByte, Spot::offset(3 * CHUNK))));

    let mut bytes = text.into_bytes();
    bytes[2 * CHUNK] = 0x0B;
    let source = Source::memory(&bytes, &options).unwrap();
    let pieces = source.shared().expect("a text in memory is shared");
    assert!(pieces.source(CHUNK, 2 * CHUNK).is_some());
    assert!(pieces.source(2 * CHUNK, 3 * CHUNK).is_none());
    assert!(pieces.source(2 * CHUNK + 1, 3 * CHUNK).is_some());
}

/// The second thread reads the file the first one opened, even when another file has
/// been renamed over its path since (as editors save).
#[cfg(unix)]
#[test]
fn pieces_of_a_file_come_from_the_file_opened_not_its_path() {
    let dir = std::env::temp_dir();
    let (path, other) = (
        dir.join(format!("box2scene-pieces-{}.xml", std::process::id())),
        dir.join(format!("box2scene-pieces-{}-new.xml", std::process::id())),
    );
    let text = |c: &str| format!("<World>{}</World>", c.repeat(200_000));
    std::fs::write(&path, text("a")).unwrap();
    std::fs::write(&other, text("b")).unwrap();
    let options = LoadOptions::default();
    let source = Source::path(&path, &options).unwrap();
    std::fs::rename(&other, &path).unwrap();
    let Some(pieces @ Shared::File { .. }) = source.shared() else {
        panic!("a UTF-8 file being read is shared")
    };
    assert_eq!(pieces.len(), text("a").len());
    assert_eq!(pieces.bytes(150_000, 150_004, &mut Vec::new()).unwrap(), b"aaaa");
    let piece = pieces.source(100_000, 100_010).unwrap();
    assert_eq!(piece.slice(100_000, 100_010), "aaaaaaaaaa");
    std::fs::remove_file(&path).unwrap();
}

/// A piece of a file is read through a window, as a whole file is: its reader never holds
/// the whole piece (a 64th of a large file), and what the window lets it see, a chunk at a
/// time, is the piece's text, from its start to its end, each byte at its offset in the
/// whole, and no further.
#[cfg(unix)]
#[test]
fn a_piece_of_a_file_is_read_through_a_window() {
    let path = std::env::temp_dir().join(format!("box2scene-window-{}.xml", std::process::id()));
    let text: String = (0..12 * CHUNK).map(|i| char::from(b'a' + (i % 26) as u8)).collect();
    std::fs::write(&path, format!("\u{FEFF}{text}")).unwrap();
    let options = LoadOptions::default();
    let source = Source::path(&path, &options).unwrap();
    let shared = source.shared().expect("a UTF-8 file being read is shared");
    std::fs::remove_file(&path).unwrap();
    let (from, to) = (CHUNK + 7, 11 * CHUNK - 3);
    let mut piece = shared.source(from, to).unwrap();
    let mut read = String::new();
    loop {
        assert!(piece.text().len() <= 2 * CHUNK, "{} bytes at hand", piece.text().len());
        read.push_str(piece.slice(piece.base().max(from + read.len()), piece.end()));
        if !piece.more(piece.end()) {
            break;
        }
    }
    assert_eq!(read, text[from..to]);
    assert!(piece.stop().is_none() && piece.ends_early());
}
