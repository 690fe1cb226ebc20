//! Any bytes, as a file the command checks (text and JSON reports), dumps and draws, as
//! `box2scene check`, `dump` and `render` run: no panic, an exit status of 0, 1 or 2, no
//! character a terminal must not get raw in any output (everything from the file is
//! escaped), and an SVG that parses, with a view box of finite numbers.
#![no_main]

use std::ffi::OsString;

use libfuzzer_sys::fuzz_target;

/// A control character but the tab and the line feed that ends a line of output, a line or
/// paragraph separator, a direction mark or override.
fn unsafe_on_a_terminal(c: char) -> bool {
    (c.is_control() && c != '\t' && c != '\n')
        || matches!(
            c,
            '\u{2028}'
                | '\u{2029}'
                | '\u{061C}'
                | '\u{200E}'
                | '\u{200F}'
                | '\u{202A}'..='\u{202E}'
                | '\u{2066}'..='\u{2069}'
        )
}

fn run(args: &[&str]) -> (String, String) {
    let args: Vec<OsString> = args.iter().map(OsString::from).collect();
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let status = box2scene_cli::run(&args, &mut out, &mut err);
    assert!(status <= 2, "exit status {status}");
    let (out, err) = (String::from_utf8(out).unwrap(), String::from_utf8(err).unwrap());
    for text in [&out, &err] {
        assert!(!text.chars().any(unsafe_on_a_terminal), "{args:?} printed {text:?}");
    }
    (out, err)
}

fuzz_target!(|bytes: &[u8]| {
    let path = std::env::temp_dir().join(format!("box2scene-fuzz-cli-{}.xml", std::process::id()));
    std::fs::write(&path, bytes).unwrap();
    let file = path.to_str().unwrap();
    run(&["check", file]);
    run(&["check", "--format=json", file]);
    run(&["dump", file]);
    let (svg, _) = run(&["render", file]);
    if !svg.is_empty() {
        let document = roxmltree::Document::parse(&svg).expect("the SVG parses");
        let root = document.root_element();
        let numbers = root.attribute("viewBox").unwrap().split(' ');
        let numbers = numbers.chain(["width", "height"].map(|a| root.attribute(a).unwrap()));
        for number in numbers {
            assert!(number.parse::<f32>().unwrap().is_finite(), "{number} in {svg}");
        }
    }
});
