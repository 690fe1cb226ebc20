//! A check goes on past the errors it can and reports every one, at its place, in the order
//! of the file; what it cannot read on from ends it; a file without errors is the scene a
//! load gives. Each case marks with `⌖` the places its errors must point at.

use std::io::Write;
use std::sync::atomic::{AtomicUsize, Ordering};

use box2scene::{Checked, Code, Error, LoadOptions, check, check_file, check_reader, load};

const MARK: char = '⌖';

/// The input without its markers, and each marker's line and column.
fn unmark(marked: &str) -> (String, Vec<(u32, u32)>) {
    let mut places = Vec::new();
    let (mut line, mut column) = (1, 1);
    let mut text = String::new();
    for c in marked.chars() {
        match c {
            MARK => places.push((line, column)),
            '\n' => {
                (line, column) = (line + 1, 1);
                text.push(c);
            }
            _ => {
                column += 1;
                text.push(c);
            }
        }
    }
    (text, places)
}

fn codes_and_places(errors: &[Error]) -> Vec<(Code, u32, u32)> {
    errors.iter().map(|e| (e.code, e.position.line, e.position.column)).collect()
}

/// Checks `marked` from memory, from a file and from a stream, which must agree, and expects
/// errors with `codes` at its markers, in order; a load stops at one of them (the first it
/// meets: a shape's geometry, say, is judged once the whole shape is read).
fn expect_errors(marked: &str, codes: &[Code]) -> Checked {
    let (xml, places) = unmark(marked);
    assert_eq!(codes.len(), places.len(), "a code for every marker");
    let expected: Vec<_> = codes.iter().zip(&places).map(|(&c, &(l, col))| (c, l, col)).collect();
    let options = LoadOptions::default();
    let checked = check(xml.as_bytes(), &options);
    assert!(checked.scene.is_none());
    assert_eq!(codes_and_places(&checked.errors), expected, "{:#?}", checked.errors);
    let first = load(xml.as_bytes(), &options).expect_err("a file with errors does not load");
    assert!(checked.errors.contains(&first), "a load stopped at {first:?}");
    // One file a call: the tests run on several threads of one process.
    static CALLS: AtomicUsize = AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, Ordering::Relaxed);
    let name = format!("box2scene-check-{}-{call}.xml", std::process::id());
    let path = std::env::temp_dir().join(name);
    std::fs::File::create(&path).unwrap().write_all(xml.as_bytes()).unwrap();
    let from_file = check_file(std::fs::File::open(&path).unwrap(), &path, &options);
    std::fs::remove_file(&path).unwrap();
    let from_stream = check_reader(xml.as_bytes(), "stream.xml", &options);
    for other in [from_file, from_stream] {
        assert_eq!(other.errors, checked.errors);
        assert_eq!(other.warnings, checked.warnings);
    }
    checked
}

fn world(shapes: &str, fixtures: &str, bodies: &str, joints: &str) -> String {
    format!(
        "<World Version=\"1\">\n<Shapes>{shapes}</Shapes>\n<Fixtures>{fixtures}</Fixtures>\n\
         <Bodies>{bodies}</Bodies>\n<Joints>{joints}</Joints>\n</World>"
    )
}

const CIRCLE: &str = "<Shape Type=\"Circle\"><Radius>1</Radius><Position>0 0</Position></Shape>";

#[test]
fn every_bad_value_and_every_id_that_names_nothing_is_reported() {
    let marked = world(
        &format!(
            "{CIRCLE}\n<Shape Type=\"Circle\"><Radius>⌖-2</Radius><Position>0 ⌖y</Position></Shape>"
        ),
        "\n<Fixture><Shape>⌖7</Shape><Density>1</Density><Friction>⌖lots</Friction></Fixture>",
        "\n<Body Type=\"⌖Dynamc\"><Angle>⌖1,5.2</Angle><Fixtures><ID>0</ID><ID>⌖4</ID></Fixtures></Body>\
         \n<Body Type=\"Static\"><Wind/><AllowSleep>⌖maybe</AllowSleep></Body>",
        "\n<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>⌖9</BodyB></Joint>",
    );
    let checked = expect_errors(
        &marked,
        &[
            Code::BadRadius,
            Code::InvalidFloat,
            Code::IdOutOfRange,
            Code::InvalidFloat,
            Code::UnknownType,
            Code::InvalidFloat,
            Code::IdOutOfRange,
            Code::InvalidBool,
            Code::IdOutOfRange,
        ],
    );
    // The warnings of a file with errors are reported too.
    let warnings = codes_and_places(&checked.warnings);
    assert_eq!(warnings, [(Code::UnknownElement, 8, 21)], "{:#?}", checked.warnings);
}

/// An ID that is not a number is one error, not also one for the body it then names.
#[test]
fn an_id_that_is_no_number_is_reported_once() {
    let marked =
        world("", "", "", "<Joint Type=\"Weld\"><BodyA>⌖x</BodyA><BodyB>⌖-1</BodyB></Joint>");
    expect_errors(&marked, &[Code::InvalidId, Code::InvalidId]);
}

/// What leaves nothing to read on from ends the check, after the errors before it.
#[test]
fn a_markup_error_ends_the_check() {
    let marked = world(
        "<Shape Type=\"Circle\"><Radius>⌖0</Radius><Position>0 0</Position></Shape>",
        "<Fixture><Shape>0</Shape>⌖</Fixtur>",
        "<Body Type=\"Static\"><Angle>wrong</Angle></Body>",
        "",
    );
    let checked = expect_errors(&marked, &[Code::BadRadius, Code::MalformedXml]);
    assert!(checked.warnings.is_empty());
    // The warnings found before the end are reported with the errors.
    let shape = "<Shape Type=\"Circle\"><Radius>1</Radius><Position>0 0</Position><Wind/></Shape>";
    let warned = world(shape, "<Fixture>⌖</Fixtur>", "", "");
    let checked = expect_errors(&warned, &[Code::MalformedXml]);
    assert_eq!(codes_and_places(&checked.warnings), [(Code::UnknownElement, 2, 72)]);
    // A missing element is found at the end of its object, and points at its start.
    let missing = world(
        &format!(
            "{CIRCLE}⌖<Shape Type=\"Circle\"><Radius>⌖x</Radius></Shape><Shape Type=\"Circle\"/>"
        ),
        "",
        "",
        "",
    );
    expect_errors(&missing, &[Code::MissingElement, Code::InvalidFloat]);
}

/// In strict mode every warning is an error, and the check reports each.
#[test]
fn a_strict_check_reports_every_warning_as_an_error() {
    let marked = world(
        "",
        "",
        "<Body Type=\"Static\">⌖<Wind/></Body><Body Type=\"Static\">⌖<Spin/></Body>",
        "",
    );
    let (xml, places) = unmark(&marked);
    let strict = LoadOptions { strict: true, ..LoadOptions::default() };
    let checked = check(xml.as_bytes(), &strict);
    let expected: Vec<_> = places.iter().map(|&(l, c)| (Code::UnknownElement, l, c)).collect();
    assert_eq!(codes_and_places(&checked.errors), expected, "{:#?}", checked.errors);
    assert!(checked.errors.iter().all(|e| e.message.ends_with("(strict mode)")));
}

/// A check records a hundred errors; the next ends it.
#[test]
fn a_check_ends_after_a_hundred_errors() {
    let bodies = "<Body Type=\"Static\"><Angle>x</Angle></Body>\n".repeat(150);
    let checked = check(world("", "", &bodies, "").as_bytes(), &LoadOptions::default());
    assert_eq!(checked.errors.len(), 101);
    let lines: Vec<u32> = checked.errors.iter().map(|e| e.position.line).collect();
    assert_eq!(lines, (4..105).collect::<Vec<_>>());
    assert_eq!(checked.stopped_at, Some(checked.errors[100].position), "where it stopped");
    // A hundred errors are all the file holds: it is checked to its end.
    let bodies = "<Body Type=\"Static\"><Angle>x</Angle></Body>\n".repeat(100);
    let checked = check(world("", "", &bodies, "").as_bytes(), &LoadOptions::default());
    assert_eq!((checked.errors.len(), checked.stopped_at), (100, None));
}

/// The cap counts every error alike: a hundred IDs that name nothing, and the next ends it.
#[test]
fn a_check_ends_after_a_hundred_errors_of_references_too() {
    let fixtures = "<Fixture><Shape>5</Shape></Fixture>\n".repeat(150);
    let checked = check(world("", &fixtures, "", "").as_bytes(), &LoadOptions::default());
    assert_eq!(checked.errors.len(), 101, "{:#?}", &checked.errors[..3]);
    assert!(checked.errors.iter().all(|e| e.code == Code::IdOutOfRange));
    assert_eq!(checked.stopped_at, Some(checked.errors[100].position));
}

/// Past a hundred errors, the ones kept are still the first in the file, whichever check
/// found them first: here the joints' unknown bodies come before the fixtures' unknown
/// shapes in the file, and there are hundreds of each.
#[test]
fn the_hundred_errors_kept_are_the_first_in_the_file() {
    let joints = "<Joint Type=\"Weld\"><BodyA>7</BodyA><BodyB>0</BodyB></Joint>\n".repeat(300);
    let fixtures = "<Fixture><Shape>5</Shape></Fixture>\n".repeat(300);
    let xml = format!(
        "<World Version=\"1\">\n<Joints>\n{joints}</Joints>\n<Shapes/><Fixtures>\n{fixtures}\
         </Fixtures>\n<Bodies><Body Type=\"Static\"/></Bodies>\n</World>"
    );
    let checked = check(xml.as_bytes(), &LoadOptions::default());
    let lines: Vec<u32> = checked.errors.iter().map(|e| e.position.line).collect();
    assert_eq!(lines, (3..104).collect::<Vec<_>>(), "{:#?}", &checked.errors[..3]);
    assert!(checked.errors.iter().all(|e| e.message.starts_with("joint ")));
    assert_eq!(checked.stopped_at, Some(checked.errors[100].position));
    let first = load(xml.as_bytes(), &LoadOptions::default()).unwrap_err();
    assert_eq!(first, checked.errors[0]);
}

/// A file without errors checks as the scene a load gives, with the same warnings.
#[test]
fn a_file_without_errors_checks_as_it_loads() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = 0;
    for dir in ["tests/fixtures/corpus", "tests/fixtures/scenes"] {
        for entry in std::fs::read_dir(root.join(dir)).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_none_or(|e| e != "xml") {
                continue;
            }
            let bytes = std::fs::read(&path).unwrap();
            let options = LoadOptions::default();
            let Ok(scene) = load(&bytes, &options) else { continue };
            let checked = check(&bytes, &options);
            assert!(checked.errors.is_empty(), "{}: {:?}", path.display(), checked.errors);
            assert_eq!(checked.scene.expect("a scene").to_json(), scene.to_json());
            let warnings: Vec<_> = checked.warnings.iter().map(|w| w.code as u32).collect();
            let diagnostics: Vec<_> = scene.diagnostics().iter().map(|d| d.code).collect();
            assert_eq!(warnings, diagnostics, "{}", path.display());
            files += 1;
        }
    }
    assert!(files >= 10, "only {files} files");
}
