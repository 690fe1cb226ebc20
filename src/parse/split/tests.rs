use super::*;
use crate::error::{Code, Position, Spot};
use crate::scene::{Body, Fixture, Joint, Scene, Shape, Str};

/// What a read on one thread, or on two with the pieces and the helper's first piece of
/// `split`, gives: the arena (the scene's dump, its records as C sees them but for their
/// string pointers, the warnings, the origins) or the problem.
fn outcome(bytes: &[u8], options: &LoadOptions, split: Option<(Vec<Boundary>, usize)>) -> String {
    let threads = if split.is_some() { 2 } else { 1 };
    let options = &LoadOptions { threads, ..*options };
    let source = match Source::memory(bytes, options) {
        Ok(source) => source,
        Err(e) => return format!("{e:?}"),
    };
    match (split, source.shared()) {
        (Some(split), Some(text)) => shown(read(source, text, options, Some(split)).0),
        _ => shown(read_whole(source, options, false).0),
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

/// Where pieces may begin: every start tag that names a container's item, in the
/// container it names, wherever it is (every item, and more).
fn container_items(bytes: &[u8]) -> Vec<Boundary> {
    let named = |at: usize| Container::ALL.into_iter().find(|c| names(&bytes[at + 1..], c.item()));
    tags(bytes).filter_map(|at| Some((at, named(at)?))).collect()
}

/// The text `text` in memory, shared.
fn memory(text: &str) -> Shared<'_> {
    Shared::Memory { text, bom: false }
}

#[test]
fn pieces_begin_at_the_first_item_from_every_step_on() {
    let body = "<Body Type=\"Static\"><Fixtures /></Body>\n";
    for (bodies, pieces) in [(100, 2), (30_000, 4), (1_000_000, MAX_PIECES)] {
        let text = format!("<World Version=\"1\"><Bodies>{}</Bodies></World>", body.repeat(bodies));
        let found = boundaries(&memory(&text), &mut Vec::new());
        assert_eq!(found.len(), pieces - 1, "{bodies} bodies");
        let step = text.len() / pieces;
        for (k, &(at, container)) in (1..).zip(&found) {
            assert_eq!(container, Container::Bodies);
            assert!(text[at..].starts_with("<Body "), "{}", &text[at..at + 10]);
            assert!(at >= step * k && at - step * k <= body.len(), "piece {k} at {at}");
        }
    }
    assert_eq!(boundaries(&memory("<World><Bodies></Bodies></World>"), &mut Vec::new()), []);
}

/// A piece begins where an item's start tag follows the end tag of another, a guess the
/// reading settles: a body in a comment, in CDATA, in a quoted value or in UserData, or in
/// an element that is not a container, is looked at like any other, and a piece cut there
/// is not taken; nor one right after a comment, CDATA or a processing instruction, which
/// goes with the item after it. However the pieces fall, the load is one thread's.
#[test]
fn pieces_begin_after_an_item_and_wrong_guesses_are_not_taken() {
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
    let found = boundaries(&memory(&text), &mut Vec::new());
    assert_eq!(found.len(), 3);
    for &(at, container) in &found {
        assert_eq!(container, Container::Bodies);
        assert!(text[..at].trim_end().ends_with("</Body>"), "{}", &text[at - 20..at + 20]);
    }
    let options = LoadOptions::default();
    let expected = outcome(text.as_bytes(), &options, None);
    let inner = text.find("<Body/><Body/></UserData>").unwrap() + "<Body/>".len();
    let comment = text.find("</Body><Body> -->").unwrap() + "</Body>".len();
    let wrong = [(inner, Container::Bodies), (comment, Container::Bodies)];
    for split in [found.clone(), wrong.to_vec(), vec![(starts[8], Container::Bodies)]] {
        for helped in 0..=split.len() {
            let got = outcome(text.as_bytes(), &options, Some((split.clone(), helped)));
            assert_same(&got, &expected, format_args!("pieces at {split:?}, helped from {helped}"));
        }
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

/// A piece is read to its end only where a reading that goes on from there reads what it
/// would have read: directly in a container, with nothing read waiting; and it is taken
/// only where the next piece was read in that container. From memory and from a file
/// (whose pieces are placed as they are read) alike.
#[test]
fn a_piece_ends_before_an_item_only_where_another_can_go_on() {
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
    // A prolog of many lines.
    let text = format!(
        "<!--{}-->\n<World Version=\"1\"><Shapes /><Fixtures /><Bodies>{}</Bodies><Joints /></World>",
        " \n".repeat(1_000),
        bodies.concat()
    );
    let at: Vec<usize> = text.match_indices("<Body Type").map(|(at, _)| at).collect();
    let inner = text.find("<Body/>\n<Body/>").unwrap() + "<Body/>\n".len();
    let options = LoadOptions::default();
    let file = std::env::temp_dir().join(format!("box2scene-ends-{}.xml", std::process::id()));
    std::fs::write(&file, &text).unwrap();
    for from_path in [false, true] {
        let shared = match from_path {
            false => memory(&text),
            true => {
                Shared::File { file: std::fs::File::open(&file).unwrap(), bom: 0, len: text.len() }
            }
        };
        let mut buffer = Vec::new();
        let root = root(&shared, &options, at[0], &mut buffer).unwrap();
        let first = |to: usize| Piece { from: 0, to, container: None };
        let fresh = || Arena::new(false, false);
        let mut read = |piece: &Piece| read_piece(&shared, &options, (&root, piece), fresh(), None);
        let ended: Vec<_> = [inner, at[1], at[2], at[3], at[4]]
            .map(|end| read(&first(end)).map(|(_, ended)| ended.container))
            .into();
        let bodies = Some(Container::Bodies);
        assert_eq!(ended, [None, None, Some(bodies), Some(bodies), Some(bodies)], "{from_path}");
        let cut = |ends: [Boundary; 2]| pieces(&ends, text.len()).unwrap();
        for (assumed, taken) in [(Container::Bodies, true), (Container::Shapes, false)] {
            let pieces = cut([(at[2], assumed), (at[4], Container::Bodies)]);
            let mut done: Vec<_> = pieces.iter().map(&mut read).collect();
            // Each item read once, where every piece is read.
            let elements: Option<u64> =
                done.iter().map(|d| d.as_ref().map(|(_, ended)| ended.elements)).sum();
            assert_eq!(elements, taken.then_some(1 + 4 + 1 + 2 + 5), "{from_path}, {assumed:?}");
            // The first piece the calling thread's, the others the second thread's, as sent.
            let mine = done.remove(0).map(|(arena, ended)| (arena, vec![ended]));
            let theirs =
                (1..pieces.len()).zip(done).map(|(k, d)| d.map(|(a, e)| (k, a, e))).rev().collect();
            let arena = mine.and_then(|mine| merged(mine, theirs, &pieces, &shared, &options));
            assert_eq!(arena.is_some(), taken, "{from_path}, {assumed:?}");
            if let Some(arena) = arena {
                assert_eq!(arena.scene.bodies.len(), 5);
                // The last body begins line 1,007, in a piece that begins on line 1,006.
                let last = match from_path {
                    false => Spot::offset(at[4]),
                    true => {
                        Spot::placed(Position { line: 1007, column: 1, byte_offset: at[4] as u64 })
                    }
                };
                assert_eq!(arena.origins.bodies.iter().last(), Some(last), "{from_path}");
            }
        }
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
    let pieces = boundaries(&memory(&text), &mut Vec::new());
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

/// The second thread's pieces are used where the assumptions hold: given a text with one
/// more body at the end than the one the calling thread would read alone, the load ends
/// with it, its origin placed where it is.
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
            let second = match in_file {
                false => memory(&theirs),
                true => {
                    let file = std::fs::File::open(&file).unwrap();
                    Shared::File { file, bom: 0, len: theirs.len() }
                }
            };
            let pieces = vec![(starts[1], Container::Bodies), (starts[2], Container::Bodies)];
            let (Ok(arena), _) = read(source, second, &options, Some((pieces, first))) else {
                panic!("the pieces read")
            };
            let what = format!("helped from piece {first}, from a file: {in_file}");
            assert_eq!(arena.scene.bodies.len(), 4, "{what}");
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
            assert_eq!(arena.origins.bodies.iter().last(), Some(last), "{what}");
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
    // One piece: the second thread's text matches the calling thread's up to its start.
    let pieces = vec![(starts[2], Container::Bodies)];
    let (Ok(mut arena), _) = read(source, memory(&theirs), &options, Some((pieces, 0))) else {
        panic!("the pieces read")
    };
    let warnings = arena.findings.take_warnings();
    let wind: Vec<_> = theirs.match_indices("<Wind/>").map(|(at, _)| at).collect();
    let found: Vec<_> = warnings.iter().map(|w| (w.code, w.at)).collect();
    assert_eq!(
        found,
        wind.iter().map(|&at| (Code::UnknownElement, Spot::offset(at))).collect::<Vec<_>>()
    );

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
    let mut text_of = String::from("<World Version=\"1\"><Bodies>\n");
    for i in 0..40_000 {
        text_of += body;
        if i % 7 == 0 {
            text_of += "<!-- a comment between bodies -->\n";
        }
    }
    text_of += "</Bodies><Joints>";
    for i in 0..20_000 {
        text_of +=
            "<!-- joints -->\n<Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>\n";
        if i % 3 == 0 {
            text_of += "<Joint Type=\"Weld\"><BodyA>1</BodyA><BodyB>0</BodyB></Joint>\n";
        }
    }
    text_of += "</Joints></World>";
    let text = memory(&text_of);
    let found = boundaries(&text, &mut Vec::new());
    assert!(found.len() >= 8, "{} pieces", found.len());
    assert!(found.iter().any(|&(_, container)| container == Container::Joints));
    let options = LoadOptions::default();
    let mut buffer = Vec::new();
    let root = root(&text, &options, found[0].0, &mut buffer).unwrap();
    let pieces = pieces(&found, text_of.len()).unwrap();
    for (i, piece) in pieces.iter().enumerate() {
        let arena = Arena::new(false, false);
        let done = read_piece(&text, &options, (&root, piece), arena, None);
        let at = piece.from;
        assert!(done.is_some(), "piece {i} at {at}: {}", &text_of[at.saturating_sub(40)..at]);
    }
}

/// A large file from its path, with a byte-order mark and warnings in every piece, is read
/// in pieces (the text the calling thread would read alone differs, and is not what the
/// load gives) whose warnings and origins are placed as one thread reading the file places
/// them.
#[test]
fn a_file_read_in_pieces_is_placed_as_one_thread_places_it() {
    let body = |i: usize| {
        let odd = if i % 3 == 0 { "\n      <Wind/>" } else { "" };
        format!("    <Body Type=\"Static\">{odd}\n      <Position>{i} 0</Position>\n    </Body>\n")
    };
    let scene = |bodies: usize| {
        let all: String = (0..bodies).map(body).collect();
        format!(
            "\u{FEFF}<World Version=\"1\">\n  <Shapes />\n  <Bodies>\n{all}  </Bodies>\n</World>\n"
        )
    };
    let (mine, theirs) = (scene(20_000), scene(20_001));
    let dir = std::env::temp_dir();
    let file = |name: &str| dir.join(format!("box2scene-split-{name}-{}.xml", std::process::id()));
    let (mine_file, theirs_file) = (file("mine"), file("theirs"));
    std::fs::write(&mine_file, &mine).unwrap();
    std::fs::write(&theirs_file, &theirs).unwrap();
    let options = LoadOptions::default();
    let one = LoadOptions { threads: 1, ..options };
    let expected = shown(read_whole(Source::path(&theirs_file, &one).unwrap(), &one, false).0);
    assert!(expected.contains("UnknownElement"), "{}", &expected[..200]);
    let source = Source::path(&mine_file, &options).unwrap();
    let len = theirs.len() - 3;
    let text = Shared::File { file: std::fs::File::open(&theirs_file).unwrap(), bom: 3, len };
    let got = shown(read(source, text, &options, None).0);
    std::fs::remove_file(&mine_file).unwrap();
    std::fs::remove_file(&theirs_file).unwrap();
    assert_same(&got, &expected, format_args!("a file read in pieces"));
}
