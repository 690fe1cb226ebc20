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

/// `text` with its lines joined and the comment marks of C, CMake and TOML taken off, so that a
/// phrase broken across lines is found.
fn joined(text: &str) -> String {
    let words = text.lines().map(|line| line.trim().trim_start_matches(['*', '/', '#']).trim());
    words.collect::<Vec<_>>().join(" ")
}

/// The version of `crate_name` that a Cargo.lock pins.
fn pinned(lock: &str, crate_name: &str) -> String {
    let entry = format!("name = \"{crate_name}\"\nversion = \"");
    let at = lock.find(&entry).unwrap_or_else(|| panic!("the lock pins no {crate_name}"));
    let rest = &lock[at + entry.len()..];
    rest[..rest.find('"').expect("a quoted version")].to_string()
}

/// Every page and header that names the Box2D v3.2 the adapter serves names the tree the tests
/// build (upstream 56edae79, in the boxdd-sys that tools/box2d32 pins), the tree its API was
/// checked against (main 617d32ab), and says that the 3.2.0 release is not what was built.
#[test]
fn docs_name_the_box2d_v32_the_tests_build() {
    let version = pinned(&read("tools/box2d32/Cargo.lock"), "boxdd-sys");
    let sources = format!("boxdd-sys {version}");
    for page in [
        "README.md",
        "docs/box2d.md",
        "include/box2scene/box2d32.h",
        "include/box2scene/detail/box2d3/v32.h",
    ] {
        let text = joined(&read(page)).replace('`', "");
        for fact in [sources.as_str(), "56edae79 (June 2026", "617d32ab (August 2026)"] {
            assert!(text.contains(fact), "{page} does not say {fact:?}");
        }
        assert!(
            text.contains("3.2.0 release (October 2026)")
                && text.contains("not available here to build"),
            "{page} does not say that the 3.2.0 release is not the one built"
        );
    }
    for page in ["docs/layout.md", "docs/install.md"] {
        let text = joined(&read(page));
        assert!(text.contains("56edae79 (June 2026"), "{page} does not name the v3.2 tree");
        assert!(!text.contains("development snapshot"), "{page} calls it a 3.2.0 snapshot");
    }
}

/// docs/format.md's tables of codes hold one row for every code, with its number and name.
#[test]
fn docs_format_tables_every_code() {
    let page = read("docs/format.md");
    for &code in box2scene::Code::ALL {
        let row = format!("| {} | `{}` |", code as u32, code.name());
        assert!(page.contains(&row), "docs/format.md has no row {row}");
    }
}

/// Where the README describes `check`, it tells a level pipeline to run it with `--strict`,
/// since warnings alone exit 0.
#[test]
fn readme_recommends_strict_check_for_pipelines() {
    let readme = joined(&read("README.md"));
    assert!(readme.contains("a level pipeline runs `box2scene check --strict`"));
}

/// The tests a mapping table's last cell names, with the files of `c_tests/` they are in:
/// each file named (`physics_test.cpp`, or one version's program of a source compiled per v3
/// version, `box2d32_mapping_test`) holds the test names that follow it, up to the next file;
/// files named one after the other share the names that follow them.
fn held_by(cell: &str) -> Vec<(Vec<String>, String)> {
    let mut held = Vec::new();
    let (mut files, mut naming) = (Vec::new(), false);
    for token in cell.split('`').skip(1).step_by(2) {
        let file = [".c", ".cpp", ".py", "_test"].iter().any(|end| token.ends_with(end));
        if file {
            if naming {
                files.clear();
                naming = false;
            }
            files.push(token.to_string());
        } else {
            held.push((files.clone(), token.to_string()));
            naming = true;
        }
    }
    held
}

/// The programs a file named in a cell stands for: a `v3_*.c` source, compiled once per v3
/// version, its two programs `box2d3_*` and `box2d32_*`; any other name itself.
fn programs(file: &str) -> Vec<String> {
    match file.strip_prefix("v3_").and_then(|rest| rest.strip_suffix(".c")) {
        Some(rest) => vec![format!("box2d3_{rest}"), format!("box2d32_{rest}")],
        None => vec![file.to_string()],
    }
}

/// The lines of `source` that its build for v3 minor version `minor` compiles: every line but
/// those of an `#if V3_MINOR ...` branch that excludes that version (other conditionals are
/// taken as compiled, both branches).
fn compiled_for(source: &str, minor: u32) -> Vec<&str> {
    // One entry per open conditional: Some(whether its branch is compiled) for V3_MINOR.
    let mut open: Vec<Option<bool>> = Vec::new();
    let mut lines = Vec::new();
    for line in source.lines() {
        let directive: String = line.split_whitespace().collect::<Vec<_>>().join(" ");
        if let Some(condition) = directive.strip_prefix("#if ") {
            open.push(condition.strip_prefix("V3_MINOR ").map(|test| {
                let (op, version) = test.split_once(' ').unwrap_or_else(|| panic!("{line}"));
                let version: u32 = version.parse().unwrap_or_else(|_| panic!("{line}"));
                match op {
                    "==" => minor == version,
                    "!=" => minor != version,
                    ">=" => minor >= version,
                    "<=" => minor <= version,
                    ">" => minor > version,
                    "<" => minor < version,
                    _ => panic!("{line}: an unknown test of V3_MINOR"),
                }
            }));
        } else if directive.starts_with("#ifdef") || directive.starts_with("#ifndef") {
            open.push(None);
        } else if directive.starts_with("#elif") {
            assert!(open.last() == Some(&None), "{line}: #elif in a V3_MINOR block");
        } else if directive == "#else" || directive.starts_with("#else ") {
            if let Some(Some(kept)) = open.last_mut() {
                *kept = !*kept;
            }
        } else if directive.starts_with("#endif") {
            open.pop().unwrap_or_else(|| panic!("{line}: #endif without #if"));
        } else if open.iter().all(|kept| kept.unwrap_or(true)) {
            lines.push(line);
        }
    }
    lines
}

/// Whether the file a cell names runs `test`: a source of `c_tests/` calls `RUN_TEST(test)`,
/// in both versions' builds when it is a `v3_*.c` source; one version's program of such a
/// source (`box2d32_mapping_test`, v3.2) calls it in that version's build; a Python test
/// file of `python/tests/` defines it.
fn runs(file: &str, test: &str) -> bool {
    let call = format!("RUN_TEST({test})");
    let calls = |source: &str, minor| compiled_for(source, minor).iter().any(|l| l.contains(&call));
    let program = [("box2d32_", 2), ("box2d3_", 1)].into_iter().find_map(|(prefix, minor)| {
        let rest = file.strip_prefix(prefix)?;
        (!file.contains('.')).then(|| (format!("v3_{rest}.c"), minor))
    });
    if let Some((source, minor)) = program {
        return calls(&read(&format!("c_tests/{source}")), minor);
    }
    if file.ends_with(".py") {
        return read(&format!("python/tests/{file}")).contains(&format!("\ndef {test}("));
    }
    let source = read(&format!("c_tests/{file}"));
    if programs(file).len() == 2 {
        [1, 2].into_iter().all(|minor| calls(&source, minor))
    } else {
        source.contains(&call)
    }
}

/// Every row of the tables of how a scene maps onto Box2D (docs/box2d.md's three versions
/// side by side, docs/format.md's 2.4.1 and v3.1, docs/python.md's Box2D 2.3 beside 2.4)
/// names, in its last column, the tests that hold it in each engine the table covers (Box2D
/// 2.4's C++ tests, v3.1's `box2d3_*`, v3.2's `box2d32_*`, both of them a `v3_*.c` source,
/// pybox2d's `test_pybox2d.py`), each a test its file runs (in each version it is compiled
/// for).
#[test]
fn docs_name_the_tests_that_hold_each_mapping_row() {
    let tables: [(&str, &str, &[&str], usize); 4] = [
        ("docs/box2d.md", "### How each version maps", &[".cpp", "box2d3_", "box2d32_"], 14),
        ("docs/format.md", "## Onto Box2D 2.4.1", &[".cpp"], 20),
        ("docs/format.md", "## Onto Box2D v3.1", &["box2d3_"], 24),
        ("docs/python.md", "## Into pybox2d (Box2D 2.3)", &["test_pybox2d.py", ".cpp"], 7),
    ];
    for (page, heading, engines, at_least) in tables {
        let text = read(page);
        let table = text.split(heading).nth(1).unwrap_or_else(|| panic!("{page}: {heading}"));
        let rows = table.lines().skip_while(|l| !l.starts_with('|'));
        let rows: Vec<&str> = rows.take_while(|l| l.starts_with('|')).skip(2).collect();
        assert!(rows.len() >= at_least, "{page}, {heading}: only {} rows", rows.len());
        for row in rows {
            let cells: Vec<&str> = row.split('|').collect();
            let (scene, last) = (cells[1].trim(), cells[cells.len() - 2]);
            let held = held_by(last);
            for engine in engines {
                let of_engine = |file: &String| programs(file).iter().any(|p| p.contains(engine));
                assert!(
                    held.iter().any(|(files, _)| files.iter().any(of_engine)),
                    "{page}: the row {scene} names no test of {engine}"
                );
            }
            for (files, test) in &held {
                assert!(!files.is_empty(), "{page}: the row {scene} names {test} before a file");
                for file in files {
                    assert!(
                        runs(file, test),
                        "{page}: the row {scene} names {test}, which {file} does not run"
                    );
                }
            }
        }
    }
}

#[test]
fn a_cell_names_tests_by_the_files_before_them() {
    let cell = " `a.cpp` `x`; `b.c`, `c.c` `y`, `z`; `c.c` `w`; `box2d32_d_test` `v` ";
    let pair = |files: &[&str], test: &str| {
        (files.iter().map(|f| f.to_string()).collect::<Vec<_>>(), test.to_string())
    };
    assert_eq!(
        held_by(cell),
        [
            pair(&["a.cpp"], "x"),
            pair(&["b.c", "c.c"], "y"),
            pair(&["b.c", "c.c"], "z"),
            pair(&["c.c"], "w"),
            pair(&["box2d32_d_test"], "v")
        ]
    );
}

#[test]
fn a_v3_source_compiles_each_line_for_the_versions_its_blocks_name() {
    let source = "a\n#if V3_MINOR == 1\nb\n#else\nc\n#endif\n#ifndef X\nd\n#else\nf\n#endif\n\
                  #if V3_MINOR >= 2\ne\n#endif\n";
    assert_eq!(compiled_for(source, 1), ["a", "b", "d", "f"]);
    assert_eq!(compiled_for(source, 2), ["a", "c", "d", "f", "e"]);
}
