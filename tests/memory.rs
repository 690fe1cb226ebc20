//! What a load holds: the bytes allocated while it runs, counted by this binary's allocator.
//! Every test here holds [`alone`] from its first line to its last, so that no other test
//! allocates while one is measured; tests that do not measure belong in another binary.

use std::alloc::{GlobalAlloc, Layout, System};
use std::io::Write;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use box2scene::{Code, LoadOptions};

mod support;
#[cfg(unix)]
use support::named_pipe;
use support::{expect, load_bytes, load_from_a_file};

/// Counts the bytes this test binary holds, so that a test can see what a load allocates.
struct Counting;

static HELD: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is forwarded to the system allocator unchanged; only counted.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let held = HELD.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
        PEAK.fetch_max(held, Ordering::Relaxed);
        // SAFETY: the caller's layout, as GlobalAlloc requires.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        HELD.fetch_sub(layout.size(), Ordering::Relaxed);
        // SAFETY: allocated above with this layout.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Held for the whole of every test in this binary, since what tests on other threads
/// allocate is counted too.
static ALONE: Mutex<()> = Mutex::new(());

fn alone() -> std::sync::MutexGuard<'static, ()> {
    ALONE.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// The most bytes held at once while `run` ran, beyond those held when it started. The
/// caller holds [`alone`].
fn extra_bytes_while(run: impl FnOnce()) -> usize {
    let base = HELD.load(Ordering::Relaxed);
    PEAK.store(base, Ordering::Relaxed);
    run();
    PEAK.load(Ordering::Relaxed) - base
}

#[test]
fn a_100_mb_text_node_is_stopped_by_the_text_limit() {
    let _alone = alone();
    let mut xml = String::from("<World Version=\"1\"><Bodies><Body Type=\"Static\"><Name>");
    xml.push_str(&"x".repeat(100 << 20));
    xml.push_str("</Name></Body></Bodies></World>");
    let text_starts = xml.find("<Name>").unwrap() + "<Name>".len();
    let extra = extra_bytes_while(|| {
        let error = expect(xml.as_bytes(), Code::LimitExceeded, 1, text_starts as u32 + 1);
        assert!(error.message.contains("max_text_bytes"));
    });
    assert!(extra < 1 << 20, "the load held {extra} bytes more: the text must not be copied");
}

#[test]
fn twenty_million_elements_are_stopped_by_the_element_limit() {
    let _alone = alone();
    let xml = format!("<World Version=\"1\">{}</World>", "<a/>".repeat(20_000_000));
    let extra = extra_bytes_while(|| {
        let error = expect(xml.as_bytes(), Code::LimitExceeded, 1, 20 + 4 * 9_999_999);
        assert!(error.message.contains("max_elements"));
    });
    assert!(extra < 1 << 20, "the load held {extra} bytes more: its warnings must be capped");
}

#[test]
fn a_load_from_a_path_does_not_hold_the_file() {
    let _alone = alone();
    let body = "<Body Type=\"Dynamic\"><Name>a body</Name><Position>1.5 -2.25</Position>\
                <Angle>0.5</Angle><LinearVelocity>0 -1</LinearVelocity><Fixtures/></Body>\n";
    let count = 100_000;
    let xml = format!(
        "<World Version=\"1\"><Shapes/><Fixtures/><Bodies>\n{}</Bodies><Joints/></World>",
        body.repeat(count)
    );
    let load_from = |from_path: bool| {
        extra_bytes_while(|| {
            let scene = match from_path {
                true => load_from_a_file(xml.as_bytes(), "held"),
                false => load_bytes(xml.as_bytes()),
            };
            assert_eq!(scene.unwrap().bodies().len(), count);
        })
    };
    let (from_memory, from_path) = (load_from(false), load_from(true));
    // From memory the input is the caller's; from a path only a window of it is held
    // (a chunk or two).
    let window = 2 << 20;
    assert!(
        from_path < from_memory + window,
        "a {} byte file: {from_path} bytes held loading from its path, {from_memory} from memory",
        xml.len()
    );
}

/// A named pipe of 64 MiB that starts with a UTF-16 byte-order mark is read no further than
/// the 1 MiB input limit, holding little more than that, and the error is where the limit
/// stopped the reading (its line and byte), as for the same pipe in UTF-8.
#[cfg(unix)]
#[test]
fn max_input_bytes_bounds_a_utf16_stream() {
    let _alone = alone();
    let max = 1u64 << 20;
    let options = LoadOptions { max_input_bytes: max, ..LoadOptions::default() };
    let start = "<World Version=\"1\">";
    for utf16 in [true, false] {
        let path = named_pipe(&format!("limit-{utf16}"));
        let encode = move |text: &str| -> Vec<u8> {
            match utf16 {
                true => text.encode_utf16().flat_map(u16::to_le_bytes).collect(),
                false => text.as_bytes().to_vec(),
            }
        };
        let writer = {
            let (path, first, lines) = (path.clone(), encode(start), encode(&"\n".repeat(1 << 16)));
            std::thread::spawn(move || {
                let mut pipe = std::fs::OpenOptions::new().write(true).open(path).unwrap();
                let bom: &[u8] = if utf16 { &[0xFF, 0xFE] } else { &[] };
                let mut sent = pipe.write_all(bom).and_then(|()| pipe.write_all(&first));
                let mut total = 0;
                while sent.is_ok() && total < 64 << 20 {
                    sent = pipe.write_all(&lines);
                    total += lines.len();
                }
                // The reader stopped reading long before the end.
                sent.is_err()
            })
        };
        let mut error = None;
        let held = extra_bytes_while(|| error = box2scene::load_path(&path, &options).err());
        let error = error.expect("the limit stops the load");
        assert!(writer.join().unwrap(), "the pipe was not read to its end");
        std::fs::remove_file(&path).unwrap();
        // The text within the limit: the byte-order mark, then whole characters.
        let (units, offset) = match utf16 {
            true => ((max - 2) / 2, max),
            false => (max, max),
        };
        let line = 1 + units - start.len() as u64;
        assert_eq!(error.code, Code::LimitExceeded, "{error:?}");
        assert_eq!(
            (u64::from(error.position.line), error.position.column, error.position.byte_offset),
            (line, 1, offset),
            "{error:?}"
        );
        assert!(error.message.contains("max_input_bytes = 1048576"), "{}", error.message);
        assert!(held < 4 * max as usize, "{held} bytes held reading a 64 MiB pipe (utf16 {utf16})");
    }
}

/// The most bytes a load of `xml` from memory held at once beyond what was held before it,
/// and whether it gave a scene. The caller holds [`alone`].
fn extra_bytes_loading(xml: &str) -> (usize, bool) {
    let mut loaded = false;
    let extra = extra_bytes_while(|| loaded = load_bytes(xml.as_bytes()).is_ok());
    (extra, loaded)
}

/// What the checks after the read find costs no memory for each finding beyond those a
/// load keeps: a hundred thousand fixtures that name no shape, or a hundred thousand joints
/// that start apart, hold about what the same file holds with every fixture and joint
/// right (the same bytes but one digit each).
#[test]
fn the_checks_after_the_read_hold_no_finding_each() {
    let _alone = alone();
    let count = 100_000;
    let fixtures = |shape: u32| {
        let fixture = format!("<Fixture><Shape>{shape}</Shape></Fixture>\n");
        format!(
            "<World Version=\"1\"><Shapes><Shape Type=\"Circle\"><Radius>1</Radius>\
             <Position>0 0</Position></Shape></Shapes><Fixtures>\n{}</Fixtures><Bodies/><Joints/></World>",
            fixture.repeat(count)
        )
    };
    let (right, loaded) = extra_bytes_loading(&fixtures(0));
    assert!(loaded);
    let (broken, loaded) = extra_bytes_loading(&fixtures(1));
    assert!(!loaded, "a fixture that names no shape is an error");
    assert!(
        broken < right + (1 << 20),
        "{count} fixtures naming no shape held {broken} bytes, naming one {right}"
    );
    let joints = |x: u32| {
        let joint = format!(
            "<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB>\
             <LocalAnchorA>0 0</LocalAnchorA><LocalAnchorB>{x} 0</LocalAnchorB></Joint>\n"
        );
        let body = "<Body Type=\"Static\"><Position>0 0</Position></Body>";
        format!(
            "<World Version=\"1\"><Shapes/><Fixtures/><Bodies>{body}{body}</Bodies>\
             <Joints>\n{}</Joints></World>",
            joint.repeat(count)
        )
    };
    let (satisfied, loaded) = extra_bytes_loading(&joints(0));
    assert!(loaded);
    let (apart, loaded) = extra_bytes_loading(&joints(5));
    assert!(loaded);
    // The thousand warnings kept, and the scene's diagnostics made of them.
    assert!(
        apart < satisfied + (2 << 20),
        "{count} joints that start apart held {apart} bytes, that start satisfied {satisfied}"
    );
}

/// `xml` written to a file of its own, checked from it as `box2scene check` checks a file:
/// the check, and the most bytes it held at once. The caller holds [`alone`].
fn checked_from_a_file(xml: &str, name: &str) -> (box2scene::Checked, usize) {
    let path = std::env::temp_dir().join(format!("box2scene-{name}-{}.xml", std::process::id()));
    std::fs::write(&path, xml).unwrap();
    let mut checked = None;
    let held = extra_bytes_while(|| {
        let file = std::fs::File::open(&path).unwrap();
        checked = Some(box2scene::check_file(file, &path, &LoadOptions::default()));
    });
    std::fs::remove_file(&path).unwrap();
    (checked.unwrap(), held)
}

/// 64 MiB of white space between the items of a container is passed a window at a time,
/// as any text is: neither a check nor a load from the path holds it.
#[test]
fn blank_text_between_items_is_not_held() {
    let _alone = alone();
    let blank = " \r\n\t".repeat(16 << 20);
    let xml = format!(
        "<World Version=\"1\"><Shapes/><Fixtures/><Bodies><Body Type=\"Static\"/>{blank}\
         </Bodies><Joints/></World>"
    );
    let (checked, held) = checked_from_a_file(&xml, "blank");
    assert!(checked.errors.is_empty(), "{:?}", checked.errors);
    assert_eq!(checked.scene.unwrap().bodies().len(), 1);
    assert!(held < 32 << 20, "{held} bytes held checking {} bytes of blank text", blank.len());
    let held = extra_bytes_while(|| {
        assert_eq!(load_from_a_file(xml.as_bytes(), "blank").unwrap().bodies().len(), 1);
    });
    assert!(held < 32 << 20, "{held} bytes held loading {} bytes of blank text", blank.len());
}

/// A check writes nothing, so it keeps no unknown element's text for a writer: 8 MiB of
/// `<a/>` holds what its capped warnings hold, not 2 million pieces of kept text.
#[test]
fn a_check_keeps_no_text_for_the_writer() {
    let _alone = alone();
    let count = 2 << 20;
    let xml = format!(
        "<World Version=\"1\"><Shapes/><Fixtures/><Bodies/><Joints/>{}</World>",
        "<a/>".repeat(count)
    );
    let (checked, held) = checked_from_a_file(&xml, "unknown");
    assert!(checked.errors.is_empty(), "{:?}", checked.errors);
    assert!(checked.scene.is_some());
    assert_eq!(checked.warnings.len(), box2scene::error::MAX_WARNINGS + 1);
    assert!(held < 32 << 20, "{held} bytes held checking {count} unknown elements");
}
