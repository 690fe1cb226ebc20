//! Loading from a path reads the file a chunk at a time. Whatever falls on a chunk boundary
//! (a tag, a value, a reference, a character of several bytes, UserData kept verbatim, a
//! bad byte), the result must be exactly that of loading the same bytes from memory: the
//! same scene, or the same error at the same position.

use std::path::PathBuf;

use box2scene::{Code, Error, LoadOptions, load, load_path};

/// The bytes a path load reads at a time (`input::CHUNK`).
const CHUNK: usize = 1 << 16;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Loads `bytes` from memory and from a file, checks that both give the same, and says
/// whether the load succeeded.
fn same_both_ways(bytes: &[u8], what: &str) -> bool {
    same_both_ways_with(bytes, what, &LoadOptions::default()).is_ok()
}

/// [`same_both_ways`] with `options`, giving the error both gave.
fn same_both_ways_with(bytes: &[u8], what: &str, options: &LoadOptions) -> Result<(), Error> {
    let file =
        std::env::temp_dir().join(format!("box2scene-streaming-{}-{what}.xml", std::process::id()));
    std::fs::write(&file, bytes).unwrap();
    let options = *options;
    let from_path = load_path(&file, &options).map(|s| s.to_json());
    std::fs::remove_file(&file).unwrap();
    let from_memory = load(bytes, &options).map(|s| s.to_json());
    // The reference: memory, one thread.
    let one = load(bytes, &LoadOptions { threads: 1, ..options }).map(|s| s.to_json());
    if let (Ok(a), Ok(b)) = (&one, &from_memory) {
        let line = a.lines().zip(b.lines()).find(|(m, p)| m != p);
        assert!(line.is_none(), "{what}: one thread and two differ: {line:?}");
    }
    assert!(one == from_memory, "{what}: memory on one thread and on two differ");
    match (from_memory, from_path) {
        (Ok(memory), Ok(path)) => {
            if memory != path {
                let line = memory.lines().zip(path.lines()).find(|(m, p)| m != p);
                panic!("{what}: the scenes differ: {line:?}");
            }
            Ok(())
        }
        (Err(memory), Err(path)) => {
            assert_eq!(memory, path, "{what}");
            Err(memory)
        }
        (memory, path) => {
            let (memory, path) = (memory.map(|_| "a scene"), path.map(|_| "a scene"));
            panic!("{what}: from memory {memory:?}, from the path {path:?}")
        }
    }
}

/// A body with a name of several-byte characters, a reference, a line end to normalise,
/// CDATA, a comment and editor-form UserData, all of which must survive any cut.
fn body(i: usize) -> String {
    format!(
        "    <Body Type=\"Dynamic\">\r\n      <Name>b&amp;{i} é€日本&#x1F600;\r\n</Name>\n      \
         <Position>{i}.5 -1.25e-1</Position><!-- c{i} -->\n      <AllowSleep>true</AllowSleep>\n      \
         <UserData><Type>T{i}</Type><Value><x a=\"{i}\">{i} <![CDATA[<raw & {i}>]]></x></Value></UserData>\n      \
         <Fixtures><ID>0</ID></Fixtures>\n    </Body>\n"
    )
}

/// A scene of `bodies` such bodies after a comment of `padding` bytes, which moves every
/// chunk boundary by one byte per unit.
fn scene(bodies: usize, padding: usize) -> String {
    let mut xml = format!(
        "\u{FEFF}<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<!--{}-->\n<World Version=\"2\">\n  \
         <Shapes><Shape Type=\"Circle\"><Radius>0.5</Radius><Position>0 0</Position></Shape></Shapes>\n  \
         <Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>\n  <Bodies>\n",
        "p".repeat(padding)
    );
    for i in 0..bodies {
        xml.push_str(&body(i));
    }
    xml.push_str(
        "  </Bodies>\n  <Joints/>\n  <Unknown>warned about at the end</Unknown>\n</World>\n",
    );
    xml
}

#[test]
fn every_scene_and_corpus_file_loads_the_same_from_a_path() {
    let dirs = [root().join("tests/fixtures/scenes"), root().join("tests/fixtures/corpus")];
    let mut count = 0;
    for dir in dirs {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "xml") {
                let name = path.file_stem().unwrap().to_string_lossy().into_owned();
                assert!(same_both_ways(&std::fs::read(&path).unwrap(), &name), "{name}");
                count += 1;
            }
        }
    }
    assert!(count >= 9, "found only {count} files");
}

#[test]
fn a_chunk_boundary_anywhere_in_a_body_changes_nothing() {
    let period = body(1000).len();
    let bodies = CHUNK / period + 20;
    assert!(scene(bodies, 0).len() > CHUNK + period);
    // Every shift of the boundary across one whole body (its line ends, characters and
    // references included), and a scene that crosses several boundaries.
    for padding in 0..period {
        assert!(same_both_ways(scene(bodies, padding).as_bytes(), &format!("shift-{padding}")));
    }
    assert!(same_both_ways(scene(2000, 7).as_bytes(), "several-chunks"));
}

#[test]
fn problems_in_a_later_chunk_are_reported_alike() {
    let xml = scene(1200, 0);
    let late = 3 * CHUNK + 100;
    let name = late + xml[late..].find("<Name>").unwrap() + "<Name>".len();
    for (what, byte) in [("invalid-utf8", 0xFF), ("nul", 0)] {
        let mut bytes = xml.clone().into_bytes();
        bytes[name + 2] = byte;
        assert!(!same_both_ways(&bytes, what));
    }
    for cut in [CHUNK - 1, CHUNK, CHUNK + 1, 2 * CHUNK + 3, xml.len() - 2] {
        assert!(!same_both_ways(&xml.as_bytes()[..cut], &format!("truncated-{cut}")));
    }
    let mismatched = xml.replacen("</Position>", "</Positio>", 900);
    assert!(!same_both_ways(mismatched.as_bytes(), "mismatched"));
    let unknown_entity = xml.replacen("&amp;", "&nope;", 1100);
    assert!(!same_both_ways(unknown_entity.as_bytes(), "unknown-entity"));
}

#[test]
fn a_character_cut_by_a_boundary_is_joined() {
    let head = "<World Version=\"1\"><Shapes/><Fixtures/><Bodies><Body Type=\"Static\"><Name>";
    for offset in 0..4 {
        let before = CHUNK - head.len() - offset;
        let xml = format!(
            "{head}{}€😀{}</Name></Body></Bodies><Joints/></World>",
            "x".repeat(before),
            "y".repeat(10)
        );
        assert!(same_both_ways(xml.as_bytes(), &format!("cut-character-{offset}")));
        let json = load(xml.as_bytes(), &LoadOptions::default()).unwrap().to_json();
        assert!(json.contains("€😀"));
        // The file ends inside the character that the boundary cuts: that character is
        // where the text stops, both ways.
        let character = CHUNK - offset;
        for end in character + 1..character + 3 {
            let what = format!("cut-character-{offset}-ends-at-{end}");
            let options = LoadOptions::default();
            let error = same_both_ways_with(&xml.as_bytes()[..end], &what, &options).unwrap_err();
            assert_eq!(error.code, Code::InvalidUtf8, "{what}");
            assert_eq!(error.position.byte_offset as usize, character, "{what}");
        }
    }
}

#[test]
fn utf16_files_load_the_same_from_a_path() {
    let xml = scene(300, 3).replace("utf-8", "utf-16");
    for big_endian in [false, true] {
        let mut bytes = if big_endian { vec![0xFE, 0xFF] } else { vec![0xFF, 0xFE] };
        for unit in xml.trim_start_matches('\u{FEFF}').encode_utf16() {
            let pair = if big_endian { unit.to_be_bytes() } else { unit.to_le_bytes() };
            bytes.extend(pair);
        }
        assert!(same_both_ways(&bytes, &format!("utf16-{big_endian}")));
    }
}

/// The text limit holds every node to the same length, whether it lies in the text at hand
/// or crosses a chunk boundary: a tag, a comment, a processing instruction, CDATA, text.
#[test]
fn the_text_limit_means_the_same_from_a_path() {
    let open = "<World Version=\"1\"><Shapes/><Fixtures/><Bodies><Body Type=\"Static\">";
    let close = "</Body></Bodies><Joints/></World>";
    let big = "x".repeat((1 << 20) + (100 << 10));
    let nodes = [
        ("comment", format!("<!--{big}-->")),
        ("instruction", format!("<?pi {big}?>")),
        ("attribute", format!("<Name a=\"{big}\">n</Name>")),
        ("tag", format!("<Name{}>n</Name>", " ".repeat(big.len()))),
        ("cdata", format!("<Name><![CDATA[{big}]]></Name>")),
        ("text", format!("<Name>{big}</Name>")),
    ];
    for (what, node) in nodes {
        // The node starts before the first chunk boundary and ends after it.
        let pad = "<!-- -->".repeat(CHUNK / 16);
        let xml = format!("{open}{pad}{node}{close}");
        let error =
            same_both_ways_with(xml.as_bytes(), what, &LoadOptions::default()).expect_err(what);
        assert_eq!(error.code, Code::LimitExceeded, "{what}: {error:?}");
        // Where the node starts: its `<`, or its first character for text.
        let within = match what {
            "cdata" => node.find("<![").unwrap(),
            "text" => "<Name>".len(),
            _ => 0,
        };
        let at = open.len() + pad.len() + within;
        assert_eq!(error.position.byte_offset as usize, at, "{what}");
        assert_eq!((error.position.line, error.position.column), (1, at as u32 + 1), "{what}");
        assert!(error.message.contains("max_text_bytes"), "{what}");
        // Just within the limit, it loads both ways.
        let raised = LoadOptions { max_text_bytes: 2 << 20, ..LoadOptions::default() };
        same_both_ways_with(xml.as_bytes(), what, &raised).unwrap();
    }
}

/// With a small text limit, a tag across a chunk boundary is refused from a path exactly
/// when it is from memory: every shift of the boundary across a whole body, in a file whose
/// text nodes are all shorter than the limit, with limits below and above its longest tag.
#[test]
fn a_small_text_limit_refuses_the_same_nodes_both_ways() {
    let body = "<Body Type=\"Static\"><Position>1 2</Position><Angle>0</Angle></Body>\n";
    let bodies = body.repeat(CHUNK / body.len() + 5);
    for (max_text_bytes, loads) in [(8, false), (24, true)] {
        let options = LoadOptions { max_text_bytes, ..LoadOptions::default() };
        for shift in 0..body.len() {
            // Blank text between elements moves every boundary by one byte per unit.
            let xml = format!(
                "<World>{}<Shapes/><Fixtures/><Bodies>{bodies}</Bodies><Joints/></World>",
                " ".repeat(shift)
            );
            let what = format!("small-limit-{max_text_bytes}-{shift}");
            match same_both_ways_with(xml.as_bytes(), &what, &options) {
                Ok(()) => assert!(loads, "{what} loaded"),
                Err(e) => {
                    assert!(!loads, "{what}: {e:?}");
                    assert_eq!(e.code, Code::LimitExceeded, "{what}");
                    // `<Fixtures/>` is the first node longer than 8 bytes up to its `>`.
                    assert_eq!(e.position.byte_offset as usize, xml.find("<Fixtures/>").unwrap());
                }
            }
        }
    }
}

/// A file large enough for two threads loads from its path as from memory on one thread:
/// clean, with warnings in the pieces the second thread reads, with an error there, with
/// a byte that is not text there, and cut short.
#[test]
fn a_large_file_loads_from_its_path_on_two_threads_as_on_one() {
    let xml = scene(4000, 3);
    assert!(xml.len() > 1 << 20, "{} bytes: too small for two threads", xml.len());
    assert!(same_both_ways(xml.as_bytes(), "large"));
    let late = xml.len() * 3 / 4;
    let name = late + xml[late..].find("<Name>").unwrap() + "<Name>".len();
    let warned =
        xml.replace("<AllowSleep>true</AllowSleep>", "<AllowSleep>true</AllowSleep><Wind/>");
    same_both_ways_with(warned.as_bytes(), "large-warnings", &LoadOptions::default()).unwrap();
    let strict = LoadOptions { strict: true, ..LoadOptions::default() };
    let error = same_both_ways_with(warned.as_bytes(), "large-strict", &strict).unwrap_err();
    assert_eq!(error.code, Code::UnknownElement);
    let mut bytes = xml.clone().into_bytes();
    bytes[name + 2] = 0xFF;
    let error = same_both_ways_with(&bytes, "large-utf8", &LoadOptions::default()).unwrap_err();
    assert_eq!(error.code, Code::InvalidUtf8);
    // Characters XML does not allow are found by the reader that reads them, on either
    // thread, early or late in the file, the first one first.
    let early = xml.len() / 8 + xml[xml.len() / 8..].find("<Name>").unwrap() + "<Name>".len();
    for (what, at, byte, code) in [
        ("large-control", name + 2, 0x01, Code::MalformedXml),
        ("large-nul", name + 2, 0, Code::NulByte),
        ("large-early-control", early, 0x1F, Code::MalformedXml),
    ] {
        let mut bytes = xml.clone().into_bytes();
        bytes[at] = byte;
        let error = same_both_ways_with(&bytes, what, &LoadOptions::default()).unwrap_err();
        assert_eq!((error.code, error.position.byte_offset as usize), (code, at), "{what}");
        bytes[name + 3] = 0xFF;
        let error = same_both_ways_with(&bytes, what, &LoadOptions::default()).unwrap_err();
        assert_eq!((error.code, error.position.byte_offset as usize), (code, at), "{what}");
    }
    let mut mismatched = xml.clone();
    let at = late + xml[late..].find("</Position>").unwrap();
    mismatched.replace_range(at..at + "</Position>".len(), "</Positio>");
    let options = LoadOptions::default();
    let error = same_both_ways_with(mismatched.as_bytes(), "large-mismatched", &options);
    // The byte offset counts the byte-order mark.
    assert_eq!(error.unwrap_err().position.byte_offset as usize, at);
    assert!(!same_both_ways(&xml.as_bytes()[..late], "large-truncated"));
}

/// What a load keeps for the writer is the same from a path as from memory, wherever the
/// windows end: a comment, a line break and an unknown element are written back as they
/// were, the white space between them too, when the window ends before, inside or after
/// any of them.
#[test]
fn kept_text_is_written_alike_from_a_path_and_from_memory() {
    let kept = "<!-- a note -->\n  <Wind Speed=\"3\"><Gust/></Wind>";
    let scene = |pad: usize| {
        format!(
            "<World Version=\"1\"><!--{}--><Shapes/><Fixtures/><Bodies/><Joints/>\n  {kept}\n\
             <!--{}-->\n</World>\n",
            "p".repeat(pad),
            "q".repeat(2 * CHUNK)
        )
    };
    let first = CHUNK - kept.len() - 4 - scene(0).find(kept).unwrap();
    let file = std::env::temp_dir().join(format!("box2scene-kept-{}.xml", std::process::id()));
    for pad in first..first + kept.len() + 8 {
        let xml = scene(pad);
        std::fs::write(&file, &xml).unwrap();
        let options = LoadOptions::default();
        let written = |scene: box2scene::Scene| {
            box2scene::write(&scene, &box2scene::WriteOptions::default()).unwrap()
        };
        let from_memory = written(load(xml.as_bytes(), &options).unwrap());
        let from_path = written(load_path(&file, &options).unwrap());
        assert!(from_memory.contains(kept), "the kept text is written back as it was");
        let differ = from_memory.lines().zip(from_path.lines()).find(|(m, p)| m != p);
        assert!(
            from_path == from_memory,
            "the window ends {} bytes into the kept text: {differ:?}",
            CHUNK as i64 - xml.find(kept).unwrap() as i64
        );
    }
    std::fs::remove_file(&file).unwrap();
}

/// The attributes of a start tag are read where the tag is written, from the text at hand:
/// wherever a window ends inside the start tag of an object (a shape, a fixture, a body, a
/// joint) with attributes, plain, quoted either way, with a reference, unknown, a load from
/// a path reads them as one from memory does: the same scene, the same warnings at the same
/// lines and columns, and the unknown ones written back alike.
#[test]
fn attributes_of_a_tag_across_a_window_end_read_the_same_from_a_path() {
    let objects = "<Shapes>\n<Shape Type=\"Circle\" Name=\"round\" Colour=\"r&amp;d\"><Radius>0.5</Radius><Position>0 0</Position></Shape>\
         <Shape Type='Polygon' Tint='blue'><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex>\
         <Vertex>0 1</Vertex></Vertices></Shape></Shapes>\n<Fixtures><Fixture Note=\"f\">\
         <Shape>0</Shape><Density>1</Density></Fixture><Fixture><Shape>1</Shape></Fixture></Fixtures>\n\
         <Bodies><Body Type=\"Dynamic\" Label=\"b &#x3C; c\"><Fixtures><ID>0</ID></Fixtures></Body>\
         <Body\n Type = 'Static'><Fixtures><ID>1</ID></Fixtures></Body></Bodies>\n\
         <Joints><Joint Type=\"Rope\" Spring=\"no\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint></Joints>\n";
    let scene = |pad: usize| {
        format!("<World Version=\"2\"><!--{}-->\n{objects}</World>\n", "p".repeat(pad))
    };
    let at = scene(0).find(objects).unwrap();
    // Each byte of the objects: inside a start tag with attributes, and inside an object
    // whose start tag was read before the window ended.
    let bytes = at..at + objects.len();
    let file = std::env::temp_dir().join(format!("box2scene-attrs-{}.xml", std::process::id()));
    let options = LoadOptions::default();
    let read = |scene: box2scene::Scene| {
        let warnings: Vec<_> = (scene.diagnostics().iter())
            .map(|d| (d.code, d.line, d.column, scene.text(d.message).unwrap().to_string()))
            .collect();
        let written = scene.to_xml(&box2scene::WriteOptions::default()).unwrap();
        (scene.to_json(), warnings, written)
    };
    for byte in bytes {
        // The first window ends at byte CHUNK: here.
        let xml = scene(CHUNK - byte);
        std::fs::write(&file, &xml).unwrap();
        let from_memory = read(load(xml.as_bytes(), &options).unwrap());
        let from_path = read(load_path(&file, &options).unwrap());
        let unknown = from_memory.1.iter().filter(|w| w.0 == Code::UnknownElement as u32);
        assert_eq!(unknown.count(), 5, "every unknown attribute is warned about");
        assert!(from_memory.2.contains(" Colour=\"r&amp;d\""), "{}", from_memory.2);
        assert!(from_memory.2.contains(" Label=\"b &#x3C; c\""), "{}", from_memory.2);
        assert!(from_path == from_memory, "the window ends at byte {byte} of the file");
    }
    std::fs::remove_file(&file).unwrap();
}
