//! The reference pages name every public function: each one the C headers declare appears in
//! the page that documents its header.

use std::path::Path;

fn read(path: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(path);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The names of the functions `header` declares: a line that starts with a return type and
/// holds `prefix...(` (comments and struct fields start otherwise).
fn declared(header: &str, prefix: &str) -> Vec<String> {
    let mut names = Vec::new();
    for line in read(header).lines() {
        let starts_declaration =
            line.starts_with(|c: char| c.is_ascii_alphabetic()) && !line.starts_with("typedef");
        if !starts_declaration {
            continue;
        }
        for (at, _) in line.match_indices(prefix) {
            let rest = &line[at..];
            let end = rest.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'));
            if let Some(end) = end.filter(|&end| rest[end..].starts_with('(')) {
                names.push(rest[..end].to_string());
            }
        }
    }
    names.sort();
    names.dedup();
    names
}

/// `page` names `function` as a whole word.
fn names(page: &str, function: &str) -> bool {
    page.match_indices(function).any(|(at, _)| {
        let word = |c: char| c.is_ascii_alphanumeric() || c == '_';
        let before = page[..at].chars().next_back().is_none_or(|c| !word(c));
        let after = page[at + function.len()..].chars().next().is_none_or(|c| !word(c));
        before && after
    })
}

fn assert_documented(header: &str, prefix: &str, page: &str, at_least: usize) {
    let functions = declared(header, prefix);
    assert!(functions.len() >= at_least, "{header}: only {functions:?} found");
    let text = read(page);
    let missing: Vec<_> = functions.iter().filter(|f| !names(&text, f)).collect();
    assert!(missing.is_empty(), "{page} does not name {missing:?}, which {header} declares");
}

#[test]
fn docs_api_names_every_function_of_the_c_api() {
    assert_documented("include/box2scene.h", "b2s_", "docs/api.md", 28);
}

#[test]
fn docs_box2d_names_every_function_of_the_v3_adapters() {
    assert_documented("include/box2scene/box2d3.h", "b2s_box2d3_", "docs/box2d.md", 7);
    assert_documented("include/box2scene/box2d32.h", "b2s_box2d32_", "docs/box2d.md", 7);
}

#[test]
fn a_function_the_page_does_not_name_is_found() {
    let text = "`b2s_load_file` and b2s_scene_free_all";
    assert!(names(text, "b2s_load_file"));
    assert!(!names(text, "b2s_scene_free"));
    assert!(!names(text, "b2s_load"));
}
