use super::*;
use crate::error::{Code, Position};
use crate::place::Spot;
use crate::scan::Scanner;
use crate::scene::{Body, Fixture, Joint, Scene, Shape, Str};

/// What a read on one thread, or on two with the pieces and the helper's first piece of
/// `split`, gives: the arena (the scene's dump, its records as C sees them but for their
/// string pointers, the warnings, the origins) or the problem.
fn outcome(bytes: &[u8], options: &LoadOptions, split: Option<(Vec<Boundary>, usize)>) -> String {
    let threads = if split.is_some() { 2 } else { 1 };
    let options = &LoadOptions { threads, ..*options };
    match Source::memory(bytes, options) {
        Ok(source) => shown(super::super::read_split(source, options, false, split).0),
        Err(e) => format!("{e:?}"),
    }
}

fn shown(read: Result<Arena, super::super::Stopped>) -> String {
    match read {
        Ok(mut arena) => {
            let warnings = format!("warnings: {:?}\n", arena.findings.take_warnings());
            let origins = format!("version {}, {:?}\n", arena.version, arena.origins);
            let scene = arena.scene.freeze();
            crate::dump::to_json(&scene) + &records(&scene) + &warnings + &origins
        }
        Err(stopped) => format!("{:?}", stopped.errors),
    }
}

/// Every field of every record but the names, whose pointers differ from load to load
/// (the dump has their text): pool ranges and user data indices as they are; and the
/// text kept for the writer, by object and place.
fn records(scene: &Scene) -> String {
    let name = Str::NULL;
    let mut records = String::new();
    for s in scene.shapes() {
        records += &format!("{:?}\n", Shape { name, ..*s });
    }
    for f in scene.fixtures() {
        records += &format!("{:?}\n", Fixture { name, ..*f });
    }
    for b in scene.bodies() {
        records += &format!("{:?}\n", Body { name, ..*b });
    }
    for j in scene.joints() {
        records += &format!("{:?}\n", Joint { name, ..*j });
    }
    for k in &scene.beyond.pieces {
        records += &format!("kept {:?} {:?} {:?}\n", k.object, k.place, scene.beyond.text(k));
    }
    records
}

/// Panics, naming `what` and the first line that differs, unless `got` is `expected`
/// (the whole of either may be megabytes).
#[track_caller]
fn assert_same(got: &str, expected: &str, what: std::fmt::Arguments) {
    if got == expected {
        return;
    }
    let (mut got, mut expected) = (got.lines(), expected.lines());
    for line in 1.. {
        let (g, e) = (got.next(), expected.next());
        if g != e {
            panic!("{what}: line {line} is {g:?}, not {e:?}");
        }
    }
}

/// Where a piece is worth trying: every `<`.
fn tags(bytes: &[u8]) -> impl Iterator<Item = usize> + '_ {
    memchr::memchr_iter(b'<', bytes)
}

/// Where pieces may begin: every item the scan finds in a container.
fn container_items(bytes: &[u8]) -> Vec<Boundary> {
    let text = Pieces::Memory { text: std::str::from_utf8(bytes).unwrap_or_default(), bom: false };
    let mut scanner = Scanner::new();
    scanner.scan(bytes, 0);
    let mut parent = None;
    scanner
        .take_items()
        .into_iter()
        .filter_map(|item| in_container(&text, item, &mut parent, &mut Vec::new()))
        .collect()
}

#[test]
fn pieces_begin_at_the_first_item_from_every_step_on() {
    let body = "<Body Type=\"Static\"><Fixtures /></Body>\n";
    for (bodies, pieces) in [(100, 2), (30_000, 4), (1_000_000, MAX_PIECES)] {
        let text = format!("<World Version=\"1\"><Bodies>{}</Bodies></World>", body.repeat(bodies));
        let found =
            boundaries(&Pieces::Memory { text: &text, bom: false }, || true, &mut Vec::new());
        assert_eq!(found.len(), pieces - 1, "{bodies} bodies");
        let step = text.len() / pieces;
        for (k, &(at, container)) in (1..).zip(&found) {
            assert_eq!(container, Container::Bodies);
            assert!(text[at..].starts_with("<Body "), "{}", &text[at..at + 10]);
            assert!(at >= step * k && at - step * k <= body.len(), "piece {k} at {at}");
        }
    }
    assert_eq!(
        boundaries(
            &Pieces::Memory { text: "<World><Bodies></Bodies></World>", bom: false },
            || true,
            &mut Vec::new()
        ),
        []
    );
}

/// The scan goes on only while its pieces are wanted (the calling thread, done with its
/// reading, waits for the helper): it looks at the next window only when asked.
#[test]
fn the_scan_stops_when_its_pieces_are_no_longer_wanted() {
    let body = "<Body Type=\"Static\"><Fixtures /></Body>\n";
    let text = format!("<World Version=\"1\"><Bodies>{}</Bodies></World>", body.repeat(100_000));
    let text = Pieces::Memory { text: &text, bom: false };
    assert_eq!(boundaries(&text, || false, &mut Vec::new()), []);
    // Wanted for two windows: asked a third time, and no piece found, the first lying
    // past them.
    let asked = std::cell::Cell::new(0);
    let found = boundaries(
        &text,
        || {
            asked.set(asked.get() + 1);
            asked.get() <= 2
        },
        &mut Vec::new(),
    );
    assert_eq!(asked.get(), 3);
    assert_eq!(found, []);
    assert_eq!(boundaries(&text, || true, &mut Vec::new()).len(), 14);
}

/// Only an item is where a piece begins: not a body in a comment, in CDATA, in a quoted
/// value or in UserData, nor one in an element that is not a container; nor one right after
/// a comment, CDATA or a processing instruction, which a reading cannot stop before.
#[test]
fn pieces_begin_only_at_items() {
    // Each piece of text, and whether a piece may begin at it.
    let items = [
        ("<!-- </Body><Body> -->", false),
        ("<![CDATA[ </Body><Body> ]]>", false),
        ("<Body Type=\"Static\" Note=\"</Body><Body>\"/>", false),
        ("<Body><UserData><Body/><Body/></UserData></Body>", true),
        ("\n  <?pi?>\n  ", false),
        ("<Body/>", false),
        ("<Body/>", true),
    ];
    let mut text = String::from("<World Version=\"1\"><Wind>");
    text += &"<Body/>".repeat(60_000);
    text += "</Wind><Bodies>";
    let mut starts = Vec::new();
    while text.len() < 4 * PIECE_BYTES {
        for (item, starts_a_piece) in items {
            if starts_a_piece {
                starts.push(text.len());
            }
            text += item;
        }
    }
    text += "</Bodies></World>";
    let found = boundaries(&Pieces::Memory { text: &text, bom: false }, || true, &mut Vec::new());
    assert_eq!(found.len(), 3);
    for &(at, container) in &found {
        assert_eq!(container, Container::Bodies);
        assert!(starts.binary_search(&at).is_ok(), "a piece at {at}: {}", &text[at..at + 20]);
    }
}

/// One piece from every tag, assuming each container: what the helper reads is taken
/// where the assumption holds and dropped elsewhere, and the result never changes.
#[test]
fn every_piece_of_every_scene_file_loads_as_one_thread_reads_it() {
    let options = LoadOptions::default();
    for (name, bytes) in crate::scene_files() {
        let expected = outcome(&bytes, &options, None);
        for at in tags(&bytes) {
            for container in Container::ALL {
                let split = outcome(&bytes, &options, Some((vec![(at, container)], 0)));
                assert_same(
                    &split,
                    &expected,
                    format_args!("{name}: a piece from {at} in {container:?}"),
                );
            }
        }
    }
}

/// Pieces at every item, the helper taking them from each on; and three pieces with
/// any tag between two items, so that the middle one may be unusable.
#[test]
fn many_pieces_of_every_scene_file_load_as_one_thread_reads_them() {
    let options = LoadOptions::default();
    for (name, bytes) in crate::scene_files() {
        let expected = outcome(&bytes, &options, None);
        let items = container_items(&bytes);
        for first in 0..=items.len() {
            let got = outcome(&bytes, &options, Some((items.clone(), first)));
            assert_same(
                &got,
                &expected,
                format_args!("{name}: pieces at every item, the helper's from {first}"),
            );
        }
        let (Some(&first), Some(&last)) = (items.first(), items.last()) else { continue };
        for at in tags(&bytes).filter(|&at| first.0 < at && at < last.0) {
            for container in Container::ALL {
                for helped in 0..3 {
                    let split = (vec![first, (at, container), last], helped);
                    let got = outcome(&bytes, &options, Some(split));
                    assert_same(
                        &got,
                        &expected,
                        format_args!(
                            "{name}: pieces at {first:?}, {at} in {container:?}, {last:?}"
                        ),
                    );
                }
            }
        }
    }
}

/// A change anywhere (a warning, an error, a repeated container, a limit) gives the
/// load of one thread, however the text is cut.
#[test]
fn changed_files_load_as_one_thread_reads_them() {
    let mut random = crate::Xorshift(0x2545_f491_4f6c_dd1d);
    let mut next = move |below: usize| random.below(below);
    let strict = LoadOptions { strict: true, ..LoadOptions::default() };
    for (name, bytes) in crate::scene_files() {
        let items = container_items(&bytes);
        for _ in 0..200 {
            let mut changed = bytes.clone();
            let at = next(changed.len());
            changed[at] = b"<>/\"x 1&-"[next(9)];
            for options in [LoadOptions::default(), strict] {
                let expected = outcome(&changed, &options, None);
                let mut splits: Vec<_> = items.iter().map(|&item| (vec![item], 0)).collect();
                splits.extend([0, items.len() / 2].map(|first| (items.clone(), first)));
                for split in splits {
                    let got = outcome(&changed, &options, Some(split.clone()));
                    assert_same(
                        &got,
                        &expected,
                        format_args!("{name}, byte {at} changed, pieces {split:?}"),
                    );
                }
            }
        }
    }
}

/// A reading stops before an item only where a reading that goes on from there reads
/// what it would have read: directly in the container assumed, with nothing read
/// waiting. Elsewhere it reads on to the next end, past the last to the end of the
/// text; from memory and from a path (whose text at hand is a window) alike.
#[test]
fn a_reading_ends_before_an_item_only_where_another_can_go_on() {
    let bodies = [
        // An item after its twin inside UserData, which is kept verbatim.
        "<Body Type=\"Static\"><UserData><Body/>\n<Body/></UserData></Body>\n",
        // After a comment, which goes before the item.
        "<!-- c --><Body Type=\"Static\"/>\n",
        // Assumed in another container.
        "<Body Type=\"Static\"/>\n",
        "<Body Type=\"Static\"/>\n",
        "<Body Type=\"Static\"/>\n",
    ];
    // A prolog longer than a window, so that a path's ends lie past its first one.
    let text = format!(
        "<!--{}-->\n<World Version=\"1\"><Shapes /><Fixtures /><Bodies>{}</Bodies><Joints /></World>",
        " ".repeat(100_000),
        bodies.concat()
    );
    let at: Vec<usize> = text.match_indices("<Body Type").map(|(at, _)| at).collect();
    let inner = text.find("<Body/>\n<Body/>").unwrap() + "<Body/>\n".len();
    let name = |container: Container| Name::new(container.name());
    let ends = vec![
        (inner, name(Container::Bodies)),
        (at[1], name(Container::Bodies)),
        (at[2], name(Container::Shapes)),
        (at[3], name(Container::Bodies)),
        (at[4], name(Container::Bodies)),
    ];
    let options = LoadOptions::default();
    let file = std::env::temp_dir().join(format!("box2scene-ends-{}.xml", std::process::id()));
    std::fs::write(&file, &text).unwrap();
    for from_path in [false, true] {
        let source = match from_path {
            false => Source::memory(text.as_bytes(), &options).unwrap(),
            true => Source::path(&file, &options).unwrap(),
        };
        let mut reader = Reader::new(Tokenizer::new(source, &options), false);
        reader.tok.end_before(ends.clone());
        let mut seen = Seen::default();
        let mut read = reader.document(&mut seen);
        let mut stops = Vec::new();
        while matches!(read, Err(Halt::PieceEnd)) {
            let end = reader.tok.pass_end();
            stops.push((end, reader.tok.position(), reader.arena.scene.bodies.len()));
            let (root, tag) = reader.tok.open_item().unwrap();
            read = reader.document_from_item((&root, &tag), Container::Bodies, &mut seen);
        }
        assert!(read.is_ok(), "from a path: {from_path}");
        assert_eq!(stops, [(3, at[3], 3), (4, at[4], 4)], "from a path: {from_path}");
        assert_eq!(reader.arena.scene.bodies.len(), 5);
        // Each item after an end was read once.
        assert_eq!(reader.tok.elements(), 1 + 4 + 1 + 2 + 5);
    }
    std::fs::remove_file(&file).unwrap();
}

#[test]
fn what_the_helper_must_not_decide_is_left_to_the_calling_thread() {
    let bodies = "<Body Type=\"Static\"><Fixtures /></Body>\n".repeat(4);
    let scene = |before: &str, after: &str| {
        format!(
            "<World Version=\"1\">{before}<Shapes /><Fixtures /><Bodies>{bodies}</Bodies>{after}</World>"
        )
    };
    let cases = [
        ("gravity on both sides", scene("<Gravity>0 -10</Gravity>", "<Gravity>0 -9</Gravity>")),
        ("gravity after the split", scene("", "<Gravity>0 -9</Gravity><Joints />")),
        ("a container read twice", scene("<Joints />", "<Joints />")),
        ("a missing container", scene("", "")),
        ("an unknown element", scene("", "<Joints /><Wind />")),
        ("text after the world", scene("", "<Joints />") + "x"),
        ("a twin in a comment", scene("<!-- </Body> <Body> -->", "<Joints />")),
    ];
    for (case, text) in cases {
        let bytes = text.as_bytes();
        let count = bytes.iter().filter(|&&b| b == b'<').count() as u64;
        let items = container_items(bytes);
        for max_elements in [count, count / 2, 3] {
            let options = LoadOptions { max_elements, ..LoadOptions::default() };
            let expected = outcome(bytes, &options, None);
            for at in tags(bytes) {
                let got = outcome(bytes, &options, Some((vec![(at, Container::Bodies)], 0)));
                assert_same(
                    &got,
                    &expected,
                    format_args!("{case}, max {max_elements}, a piece from {at}"),
                );
            }
            for first in 0..=items.len() {
                let got = outcome(bytes, &options, Some((items.clone(), first)));
                assert_same(
                    &got,
                    &expected,
                    format_args!("{case}, max {max_elements}, helped from {first}"),
                );
            }
        }
    }
}

/// A scene of more than [`MIN_BYTES`], cut where [`boundaries`] cuts it, loads on two
/// threads as on one however the two meet: the helper is given each piece from the
/// start, or left to the timing. Its circles and bodies without fixtures have empty
/// ranges, which stay `{0, 0}` in every piece.
#[test]
fn a_large_scene_loads_on_two_threads_as_on_one() {
    let n = 6_000;
    let mut text = String::from("<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>");
    for i in 0..n {
        text += &if i % 3 == 0 {
            format!(
                "<Shape Type=\"Polygon\"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>0 1.{i}</Vertex></Vertices></Shape>\n"
            )
        } else {
            format!(
                "<Shape Type=\"Circle\"><Radius>1.{i}</Radius><Position>0 0</Position></Shape>\n"
            )
        };
    }
    text += "</Shapes><Fixtures>";
    for i in 0..n {
        text += &format!("<Fixture><Shape>{i}</Shape><Density>{i}.5</Density></Fixture>\n");
    }
    text += "</Fixtures><Bodies>";
    for i in 0..n {
        text += &format!(
            "<Body Type=\"Dynamic\"><Position>{i} 1</Position><Fixtures>{}</Fixtures></Body>\n",
            if i % 7 == 0 { String::new() } else { format!("<ID>{i}</ID>") }
        );
    }
    text += "</Bodies><Joints>";
    for i in 1..n {
        text += &format!(
            "<Joint Type=\"Distance\"><BodyA>{}</BodyA><BodyB>{i}</BodyB><Length>2</Length></Joint>\n",
            i - 1
        );
    }
    text += "</Joints></World>";
    let bytes = text.as_bytes();
    assert!(bytes.len() >= MIN_BYTES, "{} bytes", bytes.len());
    let pieces = boundaries(&Pieces::Memory { text: &text, bom: false }, || true, &mut Vec::new());
    assert_eq!(pieces.len(), bytes.len() / PIECE_BYTES - 1);
    let containers: Vec<_> = pieces.iter().map(|&(_, c)| c).collect();
    for container in Container::ALL {
        assert!(containers.contains(&container), "no piece begins in {container:?}");
    }
    let options = LoadOptions::default();
    let expected = outcome(bytes, &options, None);
    assert!(expected.contains("warnings: []"), "{}", &expected[expected.len() - 500..]);
    for helped in 0..=pieces.len() {
        let got = outcome(bytes, &options, Some((pieces.clone(), helped)));
        assert_same(&got, &expected, format_args!("the helper's from piece {helped}"));
    }
    for _ in 0..20 {
        let source = Source::memory(bytes, &options).unwrap();
        let got = shown(super::super::read(source, &options, false).0);
        assert_same(&got, &expected, format_args!("as the two threads met"));
    }
    // A character XML does not allow, in a comment in each piece: whoever reads it
    // stops there, the helper included, which leaves the piece to the calling thread.
    for (k, &(at, _)) in pieces.iter().enumerate() {
        let mut bad = text.clone();
        bad.insert_str(at + text[at..].find('\n').unwrap(), "<!-- \u{1} -->");
        let expected = outcome(bad.as_bytes(), &options, None);
        assert!(expected.contains("U+0001"), "{}", &expected[..200]);
        for helped in [0, k, k + 1] {
            let got = outcome(bad.as_bytes(), &options, Some((pieces.clone(), helped)));
            assert_same(&got, &expected, format_args!("piece {k} bad, helped from {helped}"));
        }
    }
}

/// The helper's pieces are used where the assumptions hold: given a text with one more
/// body at the end than the calling thread's, that thread ends with it.
#[test]
fn the_calling_thread_takes_what_the_helper_read() {
    let scene = |bodies: usize| {
        let body = "<Body Type=\"Dynamic\"><Fixtures /></Body>";
        format!(
            "<World Version=\"1\"><Shapes /><Fixtures /><Bodies>{}</Bodies><Joints /></World>",
            body.repeat(bodies)
        )
    };
    let (mine, theirs) = (scene(3), scene(4));
    let starts: Vec<_> = mine.match_indices("<Body ").map(|(at, _)| at).collect();
    let options = LoadOptions::default();
    let file = std::env::temp_dir().join(format!("box2scene-ahead-{}.xml", std::process::id()));
    std::fs::write(&file, &theirs).unwrap();
    for in_file in [false, true] {
        for first in 0..2 {
            let source = Source::memory(mine.as_bytes(), &options).unwrap();
            let mut reader = Reader::new(Tokenizer::new(source, &options), false);
            let second = match in_file {
                false => Pieces::Memory { text: &theirs, bom: false },
                true => {
                    let file = std::fs::File::open(&file).unwrap();
                    Pieces::File { file, bom: 0, len: theirs.len() }
                }
            };
            let pieces = vec![(starts[1], Container::Bodies), (starts[2], Container::Bodies)];
            std::thread::scope(|scope| {
                let helper = start(scope, second, &options, Some((pieces, first)));
                read(&mut reader, helper).unwrap();
            });
            let what = format!("helped from piece {first}, from a file: {in_file}");
            assert_eq!(reader.arena.scene.bodies.len(), 4, "{what}");
            assert_eq!(reader.tok.elements(), 4 + 4 * 2 + 1, "{what}");
            // A piece read from a file is placed as it is read (the text is one line).
            let last = theirs.rfind("<Body ").unwrap();
            let last = match in_file {
                false => Spot::offset(last),
                true => Spot::placed(Position {
                    line: 1,
                    column: last as u32 + 1,
                    byte_offset: last as u64,
                }),
            };
            assert_eq!(reader.arena.origins.bodies.iter().last(), Some(last), "{what}");
        }
    }
    std::fs::remove_file(&file).unwrap();
}

/// Pieces with warnings are taken, their warnings kept as one thread keeps them: given
/// a text whose last bodies carry an unknown element, the calling thread ends with the
/// helper's warnings; and a scene with more warnings than a scene keeps gives the same
/// warnings, the count of the rest included, however the pieces fall.
#[test]
fn pieces_with_warnings_are_taken_and_kept_in_order() {
    let scene = |odd: &str| {
        let body = "<Body Type=\"Static\"><Fixtures /></Body>";
        format!(
            "<World Version=\"1\"><Shapes /><Fixtures /><Bodies>{body}{body}{}</Bodies><Joints /></World>",
            format!("<Body Type=\"Static\">{odd}<Fixtures /></Body>").repeat(2)
        )
    };
    let (mine, theirs) = (scene(""), scene("<Wind/>"));
    let starts: Vec<_> = mine.match_indices("<Body ").map(|(at, _)| at).collect();
    let options = LoadOptions::default();
    let source = Source::memory(mine.as_bytes(), &options).unwrap();
    let mut reader = Reader::new(Tokenizer::new(source, &options), false);
    // One piece: the helper's text matches the caller's up to its start.
    let pieces = vec![(starts[2], Container::Bodies)];
    std::thread::scope(|scope| {
        let theirs = Pieces::Memory { text: &theirs, bom: false };
        let helper = start(scope, theirs, &options, Some((pieces, 0)));
        read(&mut reader, helper).unwrap();
    });
    let warnings = reader.arena.findings.take_warnings();
    let wind: Vec<_> = theirs.match_indices("<Wind/>").map(|(at, _)| at).collect();
    let found: Vec<_> = warnings.iter().map(|w| (w.code, w.at)).collect();
    assert_eq!(found, wind.iter().map(|&at| (Code::UnknownElement, at)).collect::<Vec<_>>());

    let body = |i: usize| {
        let odd = if i % 3 == 0 { "<Wind/>" } else { "" };
        format!("<Body Type=\"Static\">{odd}<Position>{i} 0</Position></Body>\n")
    };
    for bodies in [600, 2_400, 20_000] {
        let text = format!(
            "<World Version=\"1\"><Shapes /><Fixtures /><Bodies>{}</Bodies><Joints /></World>",
            (0..bodies).map(body).collect::<String>()
        );
        let bytes = text.as_bytes();
        let expected = outcome(bytes, &options, None);
        let items = container_items(bytes);
        let pieces: Vec<_> = (1..8).map(|k| items[k * items.len() / 8]).collect();
        for first in 0..=pieces.len() {
            let got = outcome(bytes, &options, Some((pieces.clone(), first)));
            assert_same(&got, &expected, format_args!("{bodies} bodies, helped from {first}"));
        }
    }
}

/// Comments between the items, as in the benchmark's scenes: every piece the helper would
/// read, from the boundaries found, reads to where the next begins, so that it can be
/// taken (a piece cut right after a comment could not be, nor any before it).
#[test]
fn every_piece_cut_at_the_found_items_can_be_taken() {
    let body = "<Body Type=\"Static\"><Fixtures /></Body>\n";
    let mut text = String::from("<World Version=\"1\"><Bodies>\n");
    for i in 0..40_000 {
        text += body;
        if i % 7 == 0 {
            text += "<!-- a comment between bodies -->\n";
        }
    }
    text += "</Bodies><Joints>";
    for i in 0..20_000 {
        text += "<!-- joints -->\n<Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>\n";
        if i % 3 == 0 {
            text += "<Joint Type=\"Weld\"><BodyA>1</BodyA><BodyB>0</BodyB></Joint>\n";
        }
    }
    text += "</Joints></World>";
    let pieces = Pieces::Memory { text: &text, bom: false };
    let found = boundaries(&pieces, || true, &mut Vec::new());
    assert!(found.len() >= 8, "{} pieces", found.len());
    assert!(found.iter().any(|&(_, container)| container == Container::Joints));
    let options = LoadOptions::default();
    let mut buffer = Vec::new();
    let (root, version) = root(&pieces, &options, found[0].0, &mut buffer).unwrap();
    for (i, &boundary) in found.iter().enumerate() {
        let end = found.get(i + 1).copied();
        let source = pieces.source(boundary.0, end.map_or(text.len(), |(at, _)| at), &mut buffer);
        let done = source.and_then(|s| read_piece(s, &options, &root, version, boundary, end));
        assert!(
            done.is_some(),
            "piece {i} at {}: {}",
            boundary.0,
            &text[boundary.0 - 40..boundary.0]
        );
    }
}
