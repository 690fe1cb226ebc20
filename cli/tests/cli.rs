//! The `box2scene` command line, run as a level pipeline runs it: real files in a scratch
//! directory, exact output lines and exit statuses.

use std::fs;
use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Stdio};

use box2scene::draw::Picture;
use box2scene::{LoadOptions, Position};
use serde_json::{Value, json};

/// A valid scene with no warnings: one circle on one dynamic body. The variants below each
/// change one line of it, so that every test differs from it in exactly one way.
const CLEAN: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<World Version="1">
  <Gravity>0 -10</Gravity>
  <Shapes>
    <Shape Type="Circle">
      <Radius>0.5</Radius>
      <Position>0 0</Position>
    </Shape>
  </Shapes>
  <Fixtures>
    <Fixture>
      <Shape>0</Shape>
      <Density>1</Density>
    </Fixture>
  </Fixtures>
  <Bodies>
    <Body Type="Dynamic">
      <Position>0 2</Position>
      <Bullet>False</Bullet>
      <Fixtures>
        <ID>0</ID>
      </Fixtures>
    </Body>
  </Bodies>
  <Joints />
</World>
"#;

/// [`CLEAN`] with one piece of text replaced.
fn clean_with(from: &str, to: &str) -> String {
    assert!(CLEAN.contains(from), "{from:?} is not in the clean scene");
    CLEAN.replacen(from, to, 1)
}

/// An unknown element inside a Body: warning `unknown-element` at its `<`.
fn with_unknown_element() -> String {
    clean_with("<Bullet>False</Bullet>", "<Foo/>")
}

/// No `Joints` container: warning `missing-container` at the `World` element.
fn without_joints() -> String {
    clean_with("  <Joints />\n", "")
}

/// A density that is not a number: error `invalid-float` at the value.
fn with_bad_density() -> String {
    clean_with("<Density>1</Density>", "<Density>abc</Density>")
}

/// 1-based line and column, in characters, of the first `needle` in `text`.
fn locate(text: &str, needle: &str) -> (usize, usize) {
    let offset = text.find(needle).unwrap_or_else(|| panic!("{needle:?} not in the text"));
    let before = &text[..offset];
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (before.matches('\n').count() + 1, before[line_start..].chars().count() + 1)
}

/// A scratch directory holding the test's files, removed when the test ends.
struct Sandbox {
    dir: PathBuf,
}

/// What one run of the binary did.
struct Run {
    status: i32,
    stdout: String,
    stderr: String,
}

impl Sandbox {
    /// `test` names the directory, so that tests running in parallel never share one.
    fn new(test: &str) -> Sandbox {
        let dir = std::env::temp_dir().join(format!("box2scene-cli-{}-{test}", std::process::id()));
        // A directory left by an earlier, killed run of the same process ID is stale.
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).expect("the temporary directory is writable");
        Sandbox { dir }
    }

    fn write(&self, name: &str, text: &str) -> &Sandbox {
        fs::write(self.dir.join(name), text).expect("the temporary directory is writable");
        self
    }

    /// Runs `box2scene ARGS` inside the sandbox, so that file names in the output are the
    /// relative names the test passed.
    fn run(&self, args: &[&str]) -> Run {
        let output = Command::new(env!("CARGO_BIN_EXE_box2scene"))
            .args(args)
            .current_dir(&self.dir)
            .output()
            .expect("the binary runs");
        Run {
            status: output.status.code().expect("the binary exits rather than being killed"),
            stdout: String::from_utf8(output.stdout).expect("stdout is UTF-8"),
            stderr: String::from_utf8(output.stderr).expect("stderr is UTF-8"),
        }
    }
}

impl Drop for Sandbox {
    fn drop(&mut self) {
        let _ = fs::remove_dir_all(&self.dir);
    }
}

/// Asserts that `line` is `prefix` followed by a message naming `culprit`: the message's
/// wording is the parser's to choose, but a level designer must see what is wrong.
fn assert_report(line: &str, prefix: &str, culprit: &str) {
    let message = line.strip_prefix(prefix).unwrap_or_else(|| {
        panic!("expected a line starting with\n  {prefix}\ngot\n  {line}");
    });
    assert!(message.contains(culprit), "the message of {line:?} does not name {culprit:?}");
}

fn lines(text: &str) -> Vec<&str> {
    text.lines().collect()
}

/// `check`'s report of one diagnostic: the `FILE:LINE:COLUMN: ...` line, the line of the
/// file it points at, and the caret line; in check's text output, then the file's summary,
/// which counts that one report (an error report in `dump`'s or `fmt`'s has none).
fn one_report(output: &str) -> [&str; 3] {
    match lines(output)[..] {
        [report, shown, caret] => [report, shown, caret],
        [report, shown, caret, summary] => {
            let one = if report.contains(": error[") {
                "1 error, 0 warnings"
            } else {
                "0 errors, 1 warning"
            };
            assert!(
                summary.ends_with(&format!(": {one}")),
                "{summary:?} does not count {report:?}"
            );
            [report, shown, caret]
        }
        _ => panic!("one report of three lines expected:\n{output}"),
    }
}

/// Asserts that `shown` is the line of `text` holding `needle` and that `caret` puts its
/// `^` under the needle's first character, with the line's tabs kept before it.
fn assert_points_at(shown: &str, caret: &str, text: &str, needle: &str) {
    let at = text.find(needle).unwrap_or_else(|| panic!("{needle:?} not in the text"));
    let start = text[..at].rfind('\n').map_or(0, |i| i + 1);
    let end = text[at..].find('\n').map_or(text.len(), |i| at + i);
    assert_eq!(shown, &text[start..end]);
    let lead: String =
        text[start..at].chars().map(|c| if c == '\t' { '\t' } else { ' ' }).collect();
    assert_eq!(caret, format!("{lead}^"));
}

#[test]
fn check_prints_only_the_summary_of_a_clean_file_and_exits_0() {
    let sandbox = Sandbox::new("clean");
    let run = sandbox.write("clean.xml", CLEAN).run(&["check", "clean.xml"]);
    assert_eq!(
        (run.status, run.stdout.as_str(), run.stderr.as_str()),
        (0, "clean.xml: no errors or warnings\n", "")
    );
}

#[test]
fn check_ends_each_file_with_its_counts() {
    let sandbox = Sandbox::new("counts");
    sandbox.write("level.xml", &with_unknown_element()).write("bad.xml", &with_bad_density());
    sandbox.write("clean.xml", CLEAN);
    let run = sandbox.run(&["check", "level.xml", "bad.xml", "clean.xml", "absent.xml"]);
    assert_eq!(run.status, 2, "{}", run.stderr);
    for summary in [
        "level.xml: 0 errors, 1 warning",
        "bad.xml: 1 error, 0 warnings",
        "clean.xml: no errors or warnings",
        "absent.xml: 1 error, 0 warnings",
    ] {
        assert!(run.stdout.lines().any(|line| line == summary), "{summary}: {}", run.stdout);
    }
    let json = sandbox.run(&["check", "--format=json", "level.xml", "clean.xml"]);
    assert_eq!(json.stdout.lines().count(), 1, "JSON lines are reports only: {}", json.stdout);
}

#[test]
fn check_reports_an_unknown_element_as_a_warning_and_exits_0() {
    let xml = with_unknown_element();
    let sandbox = Sandbox::new("unknown-element");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    let (line, column) = locate(&xml, "<Foo/>");
    assert_eq!(run.status, 0, "{}", run.stderr);
    let [report, shown, caret] = one_report(&run.stdout);
    assert_report(report, &format!("level.xml:{line}:{column}: warning[unknown-element]: "), "Foo");
    assert_eq!((shown, caret), ("      <Foo/>", "      ^"));
}

#[test]
fn check_reports_a_missing_container_at_the_world_element() {
    let xml = without_joints();
    let sandbox = Sandbox::new("missing-container");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    let (line, column) = locate(&xml, "<World");
    assert_eq!(run.status, 0, "{}", run.stderr);
    let [report, shown, caret] = one_report(&run.stdout);
    assert_report(
        report,
        &format!("level.xml:{line}:{column}: warning[missing-container]: "),
        "Joints",
    );
    assert_points_at(shown, caret, &xml, "<World");
}

#[test]
fn strict_check_turns_a_warning_into_an_error_and_exits_1() {
    let xml = with_unknown_element();
    let sandbox = Sandbox::new("strict");
    let run = sandbox.write("level.xml", &xml).run(&["check", "--strict", "level.xml"]);
    let (line, column) = locate(&xml, "<Foo/>");
    assert_eq!(run.status, 1, "{}", run.stderr);
    let [report, shown, caret] = one_report(&run.stdout);
    assert_report(report, &format!("level.xml:{line}:{column}: error[unknown-element]: "), "Foo");
    assert_points_at(shown, caret, &xml, "<Foo/>");
}

#[test]
fn check_warns_of_a_joint_that_starts_violated() {
    // The hinge holds the ball 12 m up; the file puts it 2 m up.
    let xml = clean_with(
        "  </Bodies>\n  <Joints />",
        "    <Body Type=\"Static\"/>\n  </Bodies>\n  <Joints><Joint Type=\"Revolute\">\
         <BodyA>1</BodyA><BodyB>0</BodyB><LocalAnchorA>0 12</LocalAnchorA></Joint></Joints>",
    );
    let sandbox = Sandbox::new("violated");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    assert_eq!(run.status, 0, "{}", run.stderr);
    assert!(
        run.stdout.contains("warning[joint-starts-violated]: joint 0 starts "),
        "{}",
        run.stdout
    );
}

#[test]
fn strict_check_of_a_clean_file_exits_0() {
    let sandbox = Sandbox::new("strict-clean");
    let run = sandbox.write("clean.xml", CLEAN).run(&["check", "clean.xml", "--strict"]);
    assert_eq!((run.status, run.stdout.as_str()), (0, "clean.xml: no errors or warnings\n"));
}

#[test]
fn check_reports_an_invalid_float_at_its_value_and_exits_1() {
    let xml = with_bad_density();
    let sandbox = Sandbox::new("invalid-float");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    let (line, column) = locate(&xml, "abc");
    assert_eq!(run.status, 1, "{}", run.stderr);
    let [report, shown, caret] = one_report(&run.stdout);
    assert_report(report, &format!("level.xml:{line}:{column}: error[invalid-float]: "), "abc");
    assert_eq!((shown, caret), ("      <Density>abc</Density>", "               ^"));
}

#[test]
fn a_value_is_located_at_its_first_non_blank_character() {
    let xml = clean_with("<Density>1</Density>", "<Density>\n        abc\n      </Density>");
    let sandbox = Sandbox::new("value-position");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    let (line, column) = locate(&xml, "abc");
    assert_eq!(run.status, 1, "{}", run.stderr);
    let [report, shown, caret] = one_report(&run.stdout);
    assert_report(report, &format!("level.xml:{line}:{column}: error[invalid-float]: "), "abc");
    assert_points_at(shown, caret, &xml, "abc");
}

#[test]
fn the_caret_counts_characters_not_bytes_and_keeps_tabs() {
    let xml =
        clean_with("      <Bullet>False</Bullet>", "\t\t<Name>Kiste für Äpfel</Name>\t<Foo/>");
    assert_eq!(locate(&xml, "<Foo/>"), (19, 32), "the test's own arithmetic");
    let sandbox = Sandbox::new("columns");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    assert_eq!(run.status, 0, "{}", run.stderr);
    let [report, shown, caret] = one_report(&run.stdout);
    assert_report(report, "level.xml:19:32: warning[unknown-element]: ", "Foo");
    assert_eq!(shown, "\t\t<Name>Kiste für Äpfel</Name>\t<Foo/>");
    assert_eq!(caret, format!("\t\t{}\t^", " ".repeat(28)));
}

/// A terminal draws an East Asian wide character in two columns: after a body name of
/// eight of them, the caret stands sixteen columns on, under the bad value, and a
/// combining mark takes none.
#[test]
fn the_caret_counts_wide_characters_as_a_terminal_draws_them() {
    let name = "大きな木箱と小箱";
    assert_eq!(name.chars().count(), 8);
    let xml = clean_with(
        "      <Bullet>False</Bullet>",
        &format!("      <Name>{name}</Name><Name2>e\u{301}</Name2><Bullet>Tru</Bullet>"),
    );
    let sandbox = Sandbox::new("wide-columns");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    let (line, column) = locate(&xml, "Tru");
    assert_eq!(run.status, 1, "{}", run.stderr);
    let reports = lines(&run.stdout);
    let at = reports.iter().position(|l| l.contains("error[invalid-bool]")).expect("the error");
    assert_report(reports[at], &format!("level.xml:{line}:{column}: error[invalid-bool]: "), "Tru");
    let (shown, caret) = (reports[at + 1], reports[at + 2]);
    assert_eq!(
        shown,
        format!("      <Name>{name}</Name><Name2>e\u{301}</Name2><Bullet>Tru</Bullet>")
    );
    let columns =
        6 + "<Name>".len() + 2 * 8 + "</Name><Name2>".len() + 1 + "</Name2><Bullet>".len();
    assert_eq!(caret, format!("{}^", " ".repeat(columns)));
}

/// A file with `bad` fixtures whose densities do not convert, each on a line of its own
/// (`bad-N` marks the Nth): an error apiece.
fn with_bad_densities(bad: usize) -> String {
    let fixtures: String = (1..=bad)
        .map(|n| format!("    <Fixture><Shape>0</Shape><Density>bad-{n}</Density></Fixture>\n"))
        .collect();
    clean_with("  <Fixtures>\n", &format!("  <Fixtures>\n{fixtures}"))
}

/// A check goes on past a hundred errors and stops at the next: for a file with three
/// hundred, it says so, and where, rather than leave "101 errors" to read as the file's
/// count; a file with a hundred is checked to its end.
#[test]
fn check_says_where_it_stopped_after_a_hundred_errors() {
    let xml = with_bad_densities(300);
    let sandbox = Sandbox::new("error-limit");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    assert_eq!(run.status, 1, "{}", run.stderr);
    let out = lines(&run.stdout);
    let (line, column) = locate(&xml, "bad-101<");
    let [.., note, summary] = out[..] else { panic!("{}", run.stdout) };
    assert_eq!(
        note,
        format!(
            "level.xml:{line}:{column}: note: the check stopped at this error, after a hundred \
             others: what follows it is not checked"
        )
    );
    assert_eq!(summary, "level.xml: 101 errors, 0 warnings");
    let reported = out.iter().filter(|l| l.contains(": error[invalid-float]: ")).count();
    assert_eq!(reported, 101);
    assert!(!run.stdout.contains("bad-102<"), "nothing past the stop is checked");

    let xml = with_bad_densities(100);
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    let out = lines(&run.stdout);
    assert_eq!(out.last(), Some(&"level.xml: 100 errors, 0 warnings"));
    assert!(!run.stdout.contains(": note: "), "{}", run.stdout);
}

/// In JSON too, a check that stopped after a hundred errors says so, and where: one object of
/// severity `note` after the findings, so that a pipeline reading JSON does not take 101
/// errors for the file's count.
#[test]
fn check_json_says_where_it_stopped_after_a_hundred_errors() {
    let xml = with_bad_densities(300);
    let sandbox = Sandbox::new("error-limit-json");
    let run = sandbox.write("level.xml", &xml).run(&["check", "--format=json", "level.xml"]);
    assert_eq!(run.status, 1, "{}", run.stderr);
    let reports: Vec<Value> =
        lines(&run.stdout).iter().map(|l| serde_json::from_str(l).unwrap()).collect();
    let [findings @ .., note] = &reports[..] else { panic!("{}", run.stdout) };
    assert_eq!(findings.len(), 101);
    assert!(findings.iter().all(|r| r["code"] == "invalid-float"), "{}", run.stdout);
    let (line, column) = locate(&xml, "bad-101<");
    let message =
        "the check stopped at this error, after a hundred others: what follows it is not checked";
    assert_eq!(
        (&note["severity"], &note["code"], &note["line"], &note["column"], &note["message"]),
        (&json!("note"), &json!("check-stopped"), &json!(line), &json!(column), &json!(message))
    );

    let xml = with_bad_densities(100);
    let run = sandbox.write("level.xml", &xml).run(&["check", "--format=json", "level.xml"]);
    assert!(!run.stdout.contains("\"note\""), "{}", run.stdout);
    assert_eq!(lines(&run.stdout).len(), 100);
}

#[test]
fn a_long_line_is_shown_around_the_column() {
    let (before, after) = ("x".repeat(300), "z".repeat(300));
    let long = format!("<Name>{before}</Name><Foo/><!-- {after} -->");
    let xml = clean_with("<Bullet>False</Bullet>", &long);
    let sandbox = Sandbox::new("long-line");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    let [report, shown, caret] = one_report(&run.stdout);
    assert_report(report, "level.xml:19:320: warning[unknown-element]: ", "Foo");
    // 120 characters of the line, the column in the middle, "..." where it was cut.
    assert_eq!(caret, format!("{}^", " ".repeat(63)));
    let expected = format!("...{}</Name><Foo/><!-- {}...", "x".repeat(53), "z".repeat(49));
    assert_eq!(shown, expected);
    assert!(shown[63..].starts_with("<Foo/>"));
}

#[test]
fn a_crlf_file_shows_its_lines_without_the_carriage_return() {
    let xml = with_unknown_element();
    let sandbox = Sandbox::new("crlf");
    let run = sandbox.write("level.xml", &xml.replace('\n', "\r\n")).run(&["check", "level.xml"]);
    let (line, column) = locate(&xml, "<Foo/>");
    let [report, shown, caret] = one_report(&run.stdout);
    assert_report(report, &format!("level.xml:{line}:{column}: warning[unknown-element]: "), "Foo");
    assert_points_at(shown, caret, &xml, "<Foo/>");
}

#[test]
fn check_goes_on_after_an_unreadable_file_and_exits_2() {
    let sandbox = Sandbox::new("missing-file");
    sandbox.write("level.xml", &with_unknown_element()).write("bad.xml", &with_bad_density());
    let run = sandbox.run(&["check", "absent.xml", "level.xml", "bad.xml"]);
    assert_eq!(run.status, 2, "{}", run.stderr);
    // A report without a position has no line to show.
    let [absent, _, warning, _, _, _, error, _, _, _] = lines(&run.stdout)[..] else {
        panic!(
            "one line and two reports of three lines, each file's summary after, expected:\n{}",
            run.stdout
        )
    };
    assert_report(absent, "absent.xml: error[io-error]: ", "absent.xml");
    assert!(warning.starts_with("level.xml:"), "{warning}");
    assert!(error.starts_with("bad.xml:"), "{error}");
}

#[test]
fn check_exits_1_when_any_file_has_an_error() {
    let sandbox = Sandbox::new("many-files");
    sandbox.write("bad.xml", &with_bad_density()).write("clean.xml", CLEAN);
    let run = sandbox.run(&["check", "bad.xml", "clean.xml"]);
    assert_eq!(run.status, 1, "{}", run.stderr);
    let (bad, clean) = run.stdout.split_at(run.stdout.find("clean.xml:").expect("a summary"));
    let [error, _, _] = one_report(bad);
    assert!(error.starts_with("bad.xml:"), "{error}");
    assert_eq!(clean, "clean.xml: no errors or warnings\n");
}

/// `check` reports every error it can go on past with the warnings, in the order of the
/// file, and counts them; a misspelt element is named with the one it may be.
#[test]
fn check_reports_every_error_and_warning_of_a_file_in_order() {
    let sandbox = Sandbox::new("every-error");
    let xml = clean_with("<Density>1</Density>", "<Density>abc</Density>")
        .replacen("<Bullet>False</Bullet>", "<Bulet>False</Bulet>", 1)
        .replacen("<ID>0</ID>", "<ID>3</ID>", 1);
    sandbox.write("level.xml", &xml);
    let run = sandbox.run(&["check", "level.xml"]);
    assert_eq!(run.status, 1, "{}", run.stderr);
    let headers: Vec<&str> = lines(&run.stdout).into_iter().step_by(3).collect();
    let at = |needle: &str| {
        let (line, column) = locate(&xml, needle);
        format!("level.xml:{line}:{column}: ")
    };
    let expected = [
        format!("{}error[invalid-float]: <Density>: 'abc' is not a number", at("abc")),
        format!(
            "{}warning[unknown-element]: unknown element <Bulet> in <Body> ignored (did you mean <Bullet>?)",
            at("<Bulet>")
        ),
        format!(
            "{}error[id-out-of-range]: body 0 names fixture 3, but the file has 1 fixture",
            at("3</ID>")
        ),
        "level.xml: 2 errors, 1 warning".to_owned(),
    ];
    assert_eq!(headers, expected, "{}", run.stdout);
    let json = sandbox.run(&["check", "--format=json", "level.xml"]);
    let codes: Vec<String> = lines(&json.stdout)
        .iter()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap()["code"].to_string())
        .collect();
    assert_eq!(codes, ["\"invalid-float\"", "\"unknown-element\"", "\"id-out-of-range\""]);
}

#[test]
fn check_json_prints_one_object_a_line_per_diagnostic() {
    let sandbox = Sandbox::new("json");
    let (warned, bad) = (with_unknown_element(), with_bad_density());
    sandbox.write("level.xml", &warned).write("bad.xml", &bad).write("clean.xml", CLEAN);
    let run =
        sandbox.run(&["check", "--format=json", "absent.xml", "level.xml", "clean.xml", "bad.xml"]);
    assert_eq!((run.status, run.stderr.as_str()), (2, ""));
    let [absent, warning, error] = lines(&run.stdout)[..] else {
        panic!("three lines expected:\n{}", run.stdout)
    };
    let position = |xml: &str, needle: &str| {
        let (line, column) = locate(xml, needle);
        (line, column, xml.find(needle).expect("the needle is there"))
    };
    let expected = [
        (absent, "absent.xml", (0, 0, 0), "error", "io-error", "absent.xml"),
        (warning, "level.xml", position(&warned, "<Foo/>"), "warning", "unknown-element", "Foo"),
        (error, "bad.xml", position(&bad, "abc"), "error", "invalid-float", "abc"),
    ];
    for (text, file, (line, column, byte_offset), severity, code, culprit) in expected {
        let mut report: Value = serde_json::from_str(text).expect("each line is JSON");
        let message = report["message"].take();
        assert!(message.as_str().is_some_and(|m| m.contains(culprit)), "{text}");
        let fields = json!({
            "file": file, "line": line, "column": column, "byte_offset": byte_offset,
            "severity": severity, "code": code, "message": null,
        });
        assert_eq!(report, fields);
    }
}

#[test]
fn check_json_escapes_what_json_must() {
    let sandbox = Sandbox::new("json-escape");
    let name = "a \"tricky\"\\name.xml";
    let run = sandbox.run(&["check", "--format", "json", name]);
    assert_eq!(run.status, 2);
    let report: Value = serde_json::from_str(&run.stdout).expect("one line of JSON");
    assert_eq!(report["file"], name);
    assert!(report["message"].as_str().is_some_and(|m| m.contains(name)), "{}", run.stdout);
}

/// `ARGS` with `input` on standard input.
fn run_with_input(sandbox: &Sandbox, args: &[&str], input: &str) -> Run {
    let mut child = Command::new(env!("CARGO_BIN_EXE_box2scene"))
        .args(args)
        .current_dir(&sandbox.dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let mut stdin = child.stdin.take().expect("standard input is piped");
    stdin.write_all(input.as_bytes()).expect("the binary reads its input");
    drop(stdin);
    let output = child.wait_with_output().expect("the binary ends");
    Run {
        status: output.status.code().expect("the binary exits rather than being killed"),
        stdout: String::from_utf8(output.stdout).expect("stdout is UTF-8"),
        stderr: String::from_utf8(output.stderr).expect("stderr is UTF-8"),
    }
}

#[test]
fn a_dash_reads_standard_input_for_every_command() {
    let xml = with_unknown_element();
    let sandbox = Sandbox::new("stdin");
    sandbox.write("level.xml", &xml);
    for command in [&["check"][..], &["check", "--format=json"], &["dump"], &["fmt"], &["render"]] {
        let from_file = sandbox.run(&[command, &["level.xml"]].concat());
        let from_stdin = run_with_input(&sandbox, &[command, &["-"]].concat(), &xml);
        assert_eq!((from_stdin.status, from_stdin.stderr.as_str()), (0, ""), "{command:?}");
        assert!(!from_stdin.stdout.is_empty(), "{command:?}");
        // The drawing's title is XML text.
        let name = if command == ["render"] { "&lt;stdin&gt;" } else { "<stdin>" };
        assert_eq!(from_stdin.stdout, from_file.stdout.replace("level.xml", name));
    }
}

#[test]
fn an_error_on_standard_input_is_reported_as_stdin() {
    let xml = with_bad_density();
    let run = run_with_input(&Sandbox::new("stdin-error"), &["dump", "-"], &xml);
    let (line, column) = locate(&xml, "abc");
    assert_eq!((run.status, run.stdout.as_str()), (1, ""));
    let [report, shown, caret] = one_report(&run.stderr);
    assert_report(report, &format!("<stdin>:{line}:{column}: error[invalid-float]: "), "abc");
    assert_points_at(shown, caret, &xml, "abc");
}

/// A command line that cannot be run exits 2 with clap's error on standard error, naming
/// what is wrong: the argument, or what is missing.
#[test]
fn a_usage_slip_exits_2_naming_the_argument() {
    let sandbox = Sandbox::new("usage");
    sandbox.write("clean.xml", CLEAN);
    let mistakes: &[(&[&str], &str)] = &[
        (&["frobnicate", "clean.xml"], "unrecognized subcommand 'frobnicate'"),
        (&["help", "frobnicate"], "unrecognized subcommand 'frobnicate'"),
        (&["help", "check", "dump"], "unrecognized subcommand 'dump'"),
        (&["check"], "<FILE>"),
        (&["check", "--x", "clean.xml"], "'--x'"),
        (&["check", "-s", "clean.xml"], "'-s'"),
        (&["check", "--format=xml", "clean.xml"], "invalid value 'xml' for '--format <FORMAT>'"),
        (&["check", "clean.xml", "--format"], "'--format <FORMAT>'"),
        (&["check", "-", "clean.xml", "-"], "standard input ('-') can be read only once"),
        (&["dump"], "<FILE>"),
        (&["dump", "clean.xml", "clean.xml"], "unexpected argument 'clean.xml'"),
        (&["dump", "--pretty", "clean.xml"], "'--pretty'"),
        (&["dump", "-o", "x", "clean.xml"], "'-o'"),
        (&["fmt"], "<FILE>"),
        (&["fmt", "clean.xml", "-o"], "'-o <OUT>'"),
        (&["fmt", "clean.xml", "clean.xml"], "unexpected argument 'clean.xml'"),
        (&["fmt", "--format=json", "clean.xml"], "'--format'"),
        (&["fmt", "--dialect", "farseer", "clean.xml"], "invalid value 'farseer'"),
        (&["render"], "<FILE>"),
        (&["render", "--all-fields", "clean.xml"], "'--all-fields'"),
    ];
    for (args, culprit) in mistakes {
        let run = sandbox.run(args);
        assert_eq!((run.status, run.stdout.as_str()), (2, ""), "box2scene {args:?}");
        assert!(run.stderr.starts_with("error: "), "box2scene {args:?}: {}", run.stderr);
        assert!(run.stderr.contains(culprit), "box2scene {args:?}: {}", run.stderr);
    }
    // No command at all: the help, on standard error.
    let run = sandbox.run(&[]);
    assert_eq!((run.status, run.stdout.as_str()), (2, ""));
    assert!(run.stderr.contains("Usage: box2scene COMMAND"), "{}", run.stderr);
}

#[test]
fn a_file_after_a_double_dash_may_start_with_a_dash() {
    let sandbox = Sandbox::new("double-dash");
    let run =
        sandbox.write("-level.xml", &with_unknown_element()).run(&["check", "--", "-level.xml"]);
    assert_eq!(run.status, 0, "{}", run.stderr);
    assert!(run.stdout.starts_with("-level.xml:"), "{}", run.stdout);
}

#[test]
fn help_lists_every_command_and_exits_0() {
    let sandbox = Sandbox::new("help");
    let help = sandbox.run(&["help"]);
    assert_eq!((help.status, help.stderr.as_str()), (0, ""));
    for command in ["check", "dump", "fmt", "render", "help"] {
        assert!(help.stdout.contains(&format!("\n  {command}  ")), "{command}: {}", help.stdout);
    }
    for same in [&["--help"][..], &["-h"]] {
        let run = sandbox.run(same);
        assert_eq!(
            (run.status, &run.stdout, run.stderr.as_str()),
            (0, &help.stdout, ""),
            "{same:?}"
        );
    }
    let about_help = sandbox.run(&["help", "help"]);
    assert_eq!((about_help.status, about_help.stderr.as_str()), (0, ""));
    assert!(about_help.stdout.contains("Usage: box2scene help [COMMAND]"), "{}", about_help.stdout);
}

#[test]
fn each_command_has_its_own_help() {
    let sandbox = Sandbox::new("command-help");
    let mut seen = Vec::new();
    for command in ["check", "dump", "fmt", "render"] {
        let help = sandbox.run(&["help", command]);
        assert_eq!((help.status, help.stderr.as_str()), (0, ""), "{command}");
        let usage = format!("Usage: box2scene {command} [--strict] ");
        assert!(help.stdout.starts_with(&usage), "{command}: {}", help.stdout);
        // --help wins wherever it is and whatever else is wrong with the command line.
        let asked: [&[&str]; 4] = [
            &[command, "--help"],
            &[command, "-h"],
            &[command, "level.xml", "--bogus", "--help"],
            &[command, "a.xml", "b.xml", "-h"],
        ];
        for args in asked {
            let run = sandbox.run(args);
            assert_eq!(
                (run.status, &run.stdout, run.stderr.as_str()),
                (0, &help.stdout, ""),
                "{args:?}"
            );
        }
        assert!(!seen.contains(&help.stdout), "{command}'s help is its own");
        seen.push(help.stdout);
    }
}

#[test]
fn version_is_the_one_in_cargo_toml() {
    let manifest = fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../Cargo.toml"))
        .expect("Cargo.toml is readable");
    // The library's manifest, the workspace's root: its first `version` is the package's,
    // as [package] comes first.
    let version = manifest
        .lines()
        .find_map(|line| line.strip_prefix("version = \""))
        .and_then(|rest| rest.strip_suffix('"'))
        .expect("Cargo.toml has a version");
    assert_eq!(env!("CARGO_PKG_VERSION"), version, "the command's crate has the library's version");
    let run = Sandbox::new("version").run(&["--version"]);
    assert_eq!((run.status, run.stderr.as_str()), (0, ""));
    assert_eq!(run.stdout, format!("box2scene {version}\n"));
}

/// A JSON number as the dump spelled it (serde_json keeps the text), so that a test can
/// assert the exact shortest float form.
fn number(value: &Value) -> String {
    value.as_number().unwrap_or_else(|| panic!("expected a number, got {value}")).to_string()
}

/// The spellings of an array of numbers (a vector, a list of indices).
fn numbers(value: &Value) -> Vec<String> {
    value
        .as_array()
        .unwrap_or_else(|| panic!("expected an array, got {value}"))
        .iter()
        .map(number)
        .collect()
}

/// Every kind of record, a name with characters JSON must escape, editor-style user data,
/// and the editor's garbage gravity, whose shortest float text is known.
const DUMPED: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<World Version="1">
  <Gravity>8.369571E-36 1.001022E-38</Gravity>
  <Shapes>
    <Shape Type="Circle">
      <Name>wheel &quot;A&quot; &amp; tab&#9;end</Name>
      <Radius>0.5</Radius>
      <Position>0 0.25</Position>
    </Shape>
    <Shape Type="Polygon">
      <Vertices>
        <Vertex>-40 0</Vertex>
        <Vertex>40 0</Vertex>
      </Vertices>
    </Shape>
  </Shapes>
  <Fixtures>
    <Fixture>
      <Shape>0</Shape>
      <Density>5</Density>
      <Friction>0.2</Friction>
    </Fixture>
    <Fixture>
      <Shape>1</Shape>
    </Fixture>
  </Fixtures>
  <Bodies>
    <Body Type="Dynamic">
      <Position>0 12</Position>
      <Fixtures>
        <ID>0</ID>
      </Fixtures>
    </Body>
    <Body Type="Static">
      <UserData><Type>System.String</Type><Value><string>Ground</string></Value></UserData>
      <Fixtures>
        <ID>1</ID>
      </Fixtures>
    </Body>
  </Bodies>
  <Joints>
    <Joint Type="Revolute">
      <BodyA>1</BodyA>
      <BodyB>0</BodyB>
      <LocalAnchorA>0 12</LocalAnchorA>
    </Joint>
  </Joints>
</World>
"#;

#[test]
fn dump_prints_the_scene_as_json() {
    let sandbox = Sandbox::new("dump");
    let run = sandbox.write("level.xml", DUMPED).run(&["dump", "level.xml"]);
    assert_eq!((run.status, run.stderr.as_str()), (0, ""));
    assert!(run.stdout.ends_with("}\n"), "the dump is a text file: {:?}", run.stdout);
    let scene: Value = serde_json::from_str(&run.stdout).expect("the dump is JSON");

    assert_eq!(number(&scene["version"]), "1");
    assert_eq!(numbers(&scene["gravity"]), ["8.369571e-36", "1.001022e-38"]);

    let wheel = &scene["shapes"][0];
    assert_eq!(wheel["kind"], "circle");
    assert_eq!(wheel["name"], "wheel \"A\" & tab\tend");
    assert_eq!(number(&wheel["radius"]), "0.5");
    assert_eq!(numbers(&wheel["position"]), ["0.0", "0.25"]);
    assert_eq!(wheel["vertices"], json!([]));
    let ground = &scene["shapes"][1];
    assert_eq!(ground["kind"], "polygon");
    assert!(ground["name"].is_null());
    assert_eq!(numbers(&ground["vertices"][0]), ["-40.0", "0.0"]);
    assert_eq!(numbers(&ground["vertices"][1]), ["40.0", "0.0"]);
    assert!(ground["centroid"].is_null(), "an absent centroid is not (0, 0)");

    let fixture = &scene["fixtures"][0];
    assert_eq!(number(&fixture["shape"]), "0");
    assert_eq!(number(&fixture["density"]), "5.0");
    assert_eq!(number(&fixture["friction"]), "0.2");
    assert_eq!(number(&fixture["filter"]["mask_bits"]), "65535");
    assert_eq!(number(&scene["fixtures"][1]["friction"]), "0.2", "the default friction");

    let wagon = &scene["bodies"][0];
    assert_eq!(wagon["kind"], "dynamic");
    assert_eq!(numbers(&wagon["position"]), ["0.0", "12.0"]);
    assert_eq!(numbers(&wagon["fixtures"]), ["0"]);
    assert!(wagon["mass_data"]["mass"].is_null());
    assert!(wagon["user_data"].is_null());
    let user_data = &scene["bodies"][1]["user_data"];
    assert_eq!(
        user_data["raw"],
        "<Type>System.String</Type><Value><string>Ground</string></Value>"
    );
    assert_eq!(user_data["type_name"], "System.String");
    assert_eq!(user_data["value"], "Ground");

    let hinge = &scene["joints"][0];
    assert_eq!(hinge["kind"], "revolute");
    assert_eq!((number(&hinge["body_a"]), number(&hinge["body_b"])), ("1".into(), "0".into()));
    assert!(hinge["joint_a"].is_null(), "NONE is null");
    assert_eq!(numbers(&hinge["local_anchor_a"]), ["0.0", "12.0"]);
    assert_eq!(hinge["collide_connected"], false);

    assert_eq!(scene["diagnostics"], json!([]));
}

#[test]
fn dump_includes_the_warnings() {
    let xml = with_unknown_element();
    let sandbox = Sandbox::new("dump-warning");
    let run = sandbox.write("level.xml", &xml).run(&["dump", "level.xml"]);
    assert_eq!((run.status, run.stderr.as_str()), (0, ""));
    let scene: Value = serde_json::from_str(&run.stdout).expect("the dump is JSON");
    let (line, column) = locate(&xml, "<Foo/>");
    let [warning] = &scene["diagnostics"].as_array().expect("an array")[..] else {
        panic!("one diagnostic expected")
    };
    assert_eq!(warning["severity"], "warning");
    assert_eq!(warning["code"], "unknown-element");
    assert_eq!(warning["line"], line);
    assert_eq!(warning["column"], column);
    let byte_offset = xml.find("<Foo/>").expect("the element is there");
    assert_eq!(warning["byte_offset"], byte_offset);
}

#[test]
fn dump_of_a_bad_file_prints_the_error_on_stderr_and_exits_1() {
    let xml = with_bad_density();
    let sandbox = Sandbox::new("dump-error");
    let run = sandbox.write("level.xml", &xml).run(&["dump", "--strict", "level.xml"]);
    let (line, column) = locate(&xml, "abc");
    assert_eq!((run.status, run.stdout.as_str()), (1, ""));
    let [report, shown, caret] = one_report(&run.stderr);
    assert_report(report, &format!("level.xml:{line}:{column}: error[invalid-float]: "), "abc");
    assert_points_at(shown, caret, &xml, "abc");
}

#[test]
fn strict_dump_of_a_file_with_a_warning_exits_1() {
    let sandbox = Sandbox::new("dump-strict");
    let run = sandbox.write("level.xml", &without_joints()).run(&["dump", "--strict", "level.xml"]);
    assert_eq!((run.status, run.stdout.as_str()), (1, ""));
    assert!(run.stderr.contains(": error[missing-container]: "), "{}", run.stderr);
}

#[test]
fn dump_of_a_missing_file_exits_2() {
    let run = Sandbox::new("dump-missing").run(&["dump", "absent.xml"]);
    assert_eq!((run.status, run.stdout.as_str()), (2, ""));
    assert_report(run.stderr.trim_end(), "absent.xml: error[io-error]: ", "absent.xml");
}

#[test]
fn fmt_prints_the_canonical_form_that_reads_back_the_same() {
    let sandbox = Sandbox::new("fmt-stdout");
    sandbox.write(
        "level.xml",
        &CLEAN
            .replace("<World Version=\"1\">", "<world version=\"1\">")
            .replace("</World>", "</world>"),
    );
    let run = sandbox.run(&["fmt", "level.xml"]);
    assert_eq!((run.status, run.stderr.as_str()), (0, ""));
    assert!(run.stdout.starts_with("<World Version=\"1\">\n"), "{}", run.stdout);
    sandbox.write("formatted.xml", &run.stdout);
    let again = sandbox.run(&["fmt", "formatted.xml"]);
    assert_eq!(again.stdout, run.stdout, "formatting is idempotent");
    assert_eq!(
        sandbox.run(&["dump", "formatted.xml"]).stdout,
        sandbox.run(&["dump", "level.xml"]).stdout
    );
}

#[test]
fn fmt_writes_in_place_only_when_asked() {
    let sandbox = Sandbox::new("fmt-in-place");
    sandbox.write("level.xml", CLEAN);
    let printed = sandbox.run(&["fmt", "--all-fields", "level.xml"]).stdout;
    assert_eq!(
        fs::read_to_string(sandbox.dir.join("level.xml")).unwrap(),
        CLEAN,
        "untouched without -o"
    );
    let run = sandbox.run(&["fmt", "--all-fields", "-o", "level.xml", "level.xml"]);
    assert_eq!((run.status, run.stdout.as_str(), run.stderr.as_str()), (0, "", ""));
    assert_eq!(fs::read_to_string(sandbox.dir.join("level.xml")).unwrap(), printed);
    assert!(printed.contains("<AllowSleep>true</AllowSleep>"), "--all-fields writes defaults too");
}

#[test]
fn fmt_of_a_bad_file_writes_nothing_and_exits_1() {
    let sandbox = Sandbox::new("fmt-bad");
    sandbox.write("bad.xml", &with_bad_density());
    let run = sandbox.run(&["fmt", "-o", "out.xml", "bad.xml"]);
    assert_eq!((run.status, run.stdout.as_str()), (1, ""));
    assert!(
        run.stderr.starts_with("bad.xml:") && run.stderr.contains("error[invalid-float]"),
        "{}",
        run.stderr
    );
    assert!(!sandbox.dir.join("out.xml").exists());
}

/// Every kind of shape on bodies of every type, one of them turned a quarter turn, and two
/// joints, one a pulley. Everything drawn lies within x -10..10 and y 0..10.
/// `render` draws the library's picture (`box2scene::draw`, whose tests say what it holds)
/// of the scene where its file puts every body, titled with the file's name as given.
#[test]
fn render_draws_the_library_s_picture_titled_with_the_file() {
    let sandbox = Sandbox::new("render-picture");
    let run = sandbox.write("level.xml", CLEAN).run(&["render", "level.xml"]);
    assert_eq!((run.status, run.stderr.as_str()), (0, ""));
    let scene = box2scene::load(CLEAN.as_bytes(), &LoadOptions::default()).unwrap();
    let picture = Picture { title: "level.xml", ..Picture::default() };
    assert_eq!(run.stdout, box2scene::draw::svg(&scene, &picture).unwrap());
    let document = roxmltree::Document::parse(&run.stdout).unwrap();
    assert_eq!(
        document.root_element().children().find(|n| n.has_tag_name("title")).unwrap().text(),
        Some("level.xml")
    );
}

#[test]
fn render_writes_to_a_file_when_asked() {
    let sandbox = Sandbox::new("render-out");
    sandbox.write("level.xml", CLEAN);
    let printed = sandbox.run(&["render", "level.xml"]).stdout;
    let run = sandbox.run(&["render", "-o", "level.svg", "level.xml"]);
    assert_eq!((run.status, run.stdout.as_str(), run.stderr.as_str()), (0, "", ""));
    assert_eq!(fs::read_to_string(sandbox.dir.join("level.svg")).unwrap(), printed);
}

#[test]
fn render_of_a_bad_file_writes_nothing_and_exits_1() {
    let xml = with_bad_density();
    let sandbox = Sandbox::new("render-bad");
    let run = sandbox.write("bad.xml", &xml).run(&["render", "-o", "bad.svg", "bad.xml"]);
    assert_eq!((run.status, run.stdout.as_str()), (1, ""));
    let [report, shown, caret] = one_report(&run.stderr);
    let (line, column) = locate(&xml, "abc");
    assert_report(report, &format!("bad.xml:{line}:{column}: error[invalid-float]: "), "abc");
    assert_points_at(shown, caret, &xml, "abc");
    assert!(!sandbox.dir.join("bad.svg").exists());
}

#[test]
fn strict_render_of_a_file_with_a_warning_exits_1() {
    let sandbox = Sandbox::new("render-strict");
    let run =
        sandbox.write("level.xml", &without_joints()).run(&["render", "--strict", "level.xml"]);
    assert_eq!((run.status, run.stdout.as_str()), (1, ""));
    assert!(run.stderr.contains(": error[missing-container]: "), "{}", run.stderr);
}

#[test]
fn render_reports_an_output_it_cannot_write_and_exits_2() {
    let sandbox = Sandbox::new("render-unwritable");
    let run =
        sandbox.write("level.xml", CLEAN).run(&["render", "-o", "absent/level.svg", "level.xml"]);
    assert_eq!((run.status, run.stdout.as_str()), (2, ""));
    assert!(run.stderr.starts_with("box2scene: cannot write absent/level.svg: "), "{}", run.stderr);
}

/// Whether `c` must not reach a terminal raw: a control character but the tab and the line
/// feed that ends each line of a report, a line or paragraph separator, a direction mark
/// or override.
fn unsafe_on_a_terminal(c: char) -> bool {
    (c.is_control() && c != '\t' && c != '\n')
        || matches!(
            c,
            '\u{2028}' | '\u{2029}' | '\u{061C}' | '\u{200E}' | '\u{200F}' | '\u{202A}'..='\u{202E}'
                | '\u{2066}'..='\u{2069}'
        )
}

/// Every character of that kind that XML allows (tab, line feed and carriage return among
/// them, as character references; DEL and the C1 controls; U+2028, U+2029; every direction
/// mark, embedding, override and isolate), each followed by an `x`.
fn hostile_references() -> String {
    let chars = [0x9, 0xA, 0xD, 0x7F].into_iter().chain(0x80..=0x9F);
    let chars = chars.chain([0x2028, 0x2029, 0x61C, 0x200E, 0x200F]);
    let chars = chars.chain(0x202A..=0x202E).chain(0x2066..=0x2069);
    chars.map(|c| format!("&#x{c:X};x")).collect()
}

/// The text `hostile_references` stands for.
fn hostile_text() -> String {
    let xml = format!("<a>{}</a>", hostile_references());
    roxmltree::Document::parse(&xml).unwrap().root_element().text().unwrap().to_owned()
}

fn assert_terminal_safe(text: &str) {
    let found: Vec<char> = text.chars().filter(|&c| unsafe_on_a_terminal(c)).collect();
    assert!(found.is_empty(), "{found:?} reach the terminal raw in\n{text}");
}

/// A value holding line breaks cannot make `check` print a report of its own, nor C1
/// controls (CSI, OSC) reach the terminal in the message: the text is escaped in the
/// message as in the quoted line.
#[test]
fn check_escapes_a_value_that_would_forge_a_diagnostic() {
    let forged = "1&#xA;/etc/passwd:1:1: error[forged]: owned&#x9B;2J&#x9D;0;title&#x9C;";
    let xml = clean_with("<Density>1</Density>", &format!("<Density>{forged}</Density>"));
    let sandbox = Sandbox::new("forged");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    assert_eq!(run.status, 1, "{}", run.stdout);
    let [report, _, _] = one_report(&run.stdout);
    assert!(report.starts_with("level.xml:"), "{report}");
    assert!(report.contains("\\u{a}/etc/passwd:1:1: error[forged]: owned\\u{9b}2J"), "{report}");
    assert!(!run.stdout.lines().any(|line| line.starts_with("/etc/passwd")), "{}", run.stdout);
    assert_terminal_safe(&run.stdout);
}

/// Every control character, line break and direction override a file can hold, and bytes
/// that are not text, reach no output of the command raw: the text report (its message and
/// its quoted line), the JSON reports and dump (which read back to the text), and the SVG
/// (which parses back to it).
#[test]
fn every_output_escapes_what_comes_from_the_file() {
    let sandbox = Sandbox::new("escaped-outputs");
    let hostile = hostile_references();
    let named = clean_with("<Bullet>False</Bullet>", &format!("<Name>{hostile}</Name><Foo/>"))
        .replace("<Joints />", &format!("<Joints />\n<Wind>{hostile}</Wind>"));
    let hostile_name = hostile_text().trim().to_owned();
    let bad = clean_with("<Density>1</Density>", &format!("<Density>{hostile}</Density>"));
    // Raw in the file: a C0 control, DEL, C1 and a direction override on the line of the
    // first error (a character XML forbids), and bytes that are not UTF-8 on another.
    let raw = clean_with(
        "<Density>1</Density>",
        "<Density>1</Density><!-- \u{7f}\u{85}\u{202e} \u{1b}[2J -->",
    );
    let mut not_text = CLEAN.as_bytes().to_vec();
    let at = CLEAN.find("<Joints").unwrap();
    not_text.splice(at..at, b"<!-- \xC3( \xFF \xE2\x82 -->".iter().copied());
    fs::write(sandbox.dir.join("not-text.xml"), not_text).unwrap();
    sandbox.write("named.xml", &named).write("bad.xml", &bad).write("raw.xml", &raw);
    let files = ["named.xml", "bad.xml", "raw.xml", "not-text.xml"];

    let text = sandbox.run(&[&["check"][..], &files].concat());
    assert_eq!(text.status, 1);
    assert_terminal_safe(&text.stdout);
    let reports = text.stdout.lines().filter(|line| line.contains(".xml:")).count() - files.len();
    assert!(reports >= 5, "{}", text.stdout);
    assert_eq!(text.stdout.lines().count(), 3 * reports + files.len(), "{}", text.stdout);
    assert!(text.stdout.contains("\\u{1b}[2J"), "{}", text.stdout);
    assert!(text.stdout.contains("\u{FFFD}("), "the bytes that are not text: {}", text.stdout);

    let json = sandbox.run(&[&["check", "--format=json"][..], &files].concat());
    assert_terminal_safe(&json.stdout);
    let messages: Vec<String> = json
        .stdout
        .lines()
        .map(|line| {
            serde_json::from_str::<Value>(line).unwrap()["message"].as_str().unwrap().to_owned()
        })
        .collect();
    assert_eq!(messages.len(), reports);
    let hostile = hostile_text();
    assert!(messages.iter().any(|m| m.contains(hostile.trim())), "{messages:?}");

    let dump = sandbox.run(&["dump", "named.xml"]);
    assert_eq!(dump.status, 0, "{}", dump.stderr);
    assert_terminal_safe(&dump.stdout);
    let scene: Value = serde_json::from_str(&dump.stdout).unwrap();
    assert_eq!(scene["bodies"][0]["name"], json!(hostile_name));

    let svg = sandbox.run(&["render", "named.xml"]);
    assert_eq!(svg.status, 0, "{}", svg.stderr);
    assert!(!svg.stdout.chars().any(|c| unsafe_on_a_terminal(c) || c == '\t'), "{}", svg.stdout);
    let document = roxmltree::Document::parse(&svg.stdout).unwrap();
    let body = format!("body 0 \"{hostile_name}\" (dynamic)");
    assert!(document.descendants().any(|n| n.has_tag_name("title") && n.text() == Some(&body)));
}

/// Lines that end with a lone carriage return are lines, as the loader counts them: the
/// report quotes the line it names, in a file of CR line ends alone or of all three kinds.
#[test]
fn check_quotes_the_line_of_a_file_with_lone_carriage_returns() {
    let sandbox = Sandbox::new("lone-cr");
    let unknown = with_unknown_element();
    let cr_only = unknown.replace('\n', "\r");
    let mixed: String = unknown
        .split_inclusive('\n')
        .enumerate()
        .map(|(i, line)| match i % 3 {
            0 => line.replace('\n', "\r"),
            1 => line.replace('\n', "\r\n"),
            _ => line.to_owned(),
        })
        .collect();
    let (line, column) = locate(&unknown, "<Foo/>");
    for (name, xml) in [("cr.xml", &cr_only), ("mixed.xml", &mixed)] {
        let run = sandbox.write(name, xml).run(&["check", name]);
        assert_eq!(run.status, 0, "{}", run.stdout);
        let [report, shown, caret] = one_report(&run.stdout);
        assert_report(
            report,
            &format!("{name}:{line}:{column}: warning[unknown-element]: "),
            "Foo",
        );
        assert_eq!(shown, "      <Foo/>", "{name}");
        assert_eq!(caret, "      ^", "{name}");
    }
}

/// Runs `box2scene ARGS` in `dir` with `stdin`, and returns what it printed and its peak
/// resident memory in bytes, as GNU time measures it (the child's `ru_maxrss`).
fn peak_rss(args: &[&str], dir: &std::path::Path, stdin: Stdio) -> (std::process::Output, u64) {
    let time = std::path::Path::new("/usr/bin/time");
    assert!(time.exists(), "GNU time (/usr/bin/time, Debian's package time) measures peak memory");
    let report = dir.join("peak-rss");
    let output = Command::new(time)
        .args(["-f", "%M", "-o"])
        .arg(&report)
        .arg(env!("CARGO_BIN_EXE_box2scene"))
        .args(args)
        .current_dir(dir)
        .stdin(stdin)
        .output()
        .expect("GNU time runs");
    // After "Command exited with non-zero status N", when it did.
    let measured = fs::read_to_string(&report).unwrap();
    let kib: u64 = measured.lines().last().unwrap().trim().parse().unwrap();
    (output, kib * 1024)
}

/// One line of `count` unknown elements, each after `pad` blanks: the kind of file a tool
/// writes on one line, of which the scene keeps nothing but the warnings.
fn one_line_with_warnings(count: usize, pad: usize) -> String {
    let item = format!("{}<Wind/>", " ".repeat(pad));
    format!(
        "<World Version=\"1\"><Shapes/><Fixtures/><Bodies/><Joints/>{}</World>",
        item.repeat(count)
    )
}

/// The instructions `box2scene check` runs on `file` in `dir`, as valgrind's callgrind
/// counts them: the same count for the same binary and input, whatever else the machine does.
fn instructions(file: &str, dir: &std::path::Path) -> u64 {
    let counts = dir.join("callgrind.out");
    let output = Command::new("valgrind")
        .args(["--tool=callgrind", "--callgrind-out-file=callgrind.out"])
        .arg(env!("CARGO_BIN_EXE_box2scene"))
        .args(["check", file])
        .current_dir(dir)
        .stdout(Stdio::null())
        .output()
        .expect("valgrind (tools/setup installs it) counts the instructions");
    assert!(output.status.code() == Some(0), "{}", String::from_utf8_lossy(&output.stderr));
    let text = fs::read_to_string(&counts).unwrap();
    let total = text.lines().find_map(|line| line.strip_prefix("summary: "));
    total.expect("callgrind's summary line").trim().parse().unwrap()
}

/// The text report of a one-line file costs work linear in the file and the number of
/// warnings: four times the file and four times the warnings take about four times the
/// instructions (quoting each warning's whole line took sixteen times), and it holds less
/// than the file.
#[test]
fn the_text_report_of_a_one_line_file_is_linear_in_the_file_and_the_warnings() {
    let sandbox = Sandbox::new("one-line");
    let pad = 8000;
    sandbox.write("small.xml", &one_line_with_warnings(100, pad));
    sandbox.write("large.xml", &one_line_with_warnings(400, pad));
    for (name, count) in [("small.xml", 100), ("large.xml", 400)] {
        let text = sandbox.run(&["check", name]).stdout;
        assert_eq!(text.lines().count(), 3 * count + 1, "three short lines a warning, a summary");
        assert!(text.lines().all(|line| line.len() < 400), "{text}");
    }
    let ratio = instructions("large.xml", &sandbox.dir) as f64
        / instructions("small.xml", &sandbox.dir) as f64;
    assert!(ratio < 5.0, "4x the file and the warnings took {ratio:.2}x the instructions");
    // Large enough that the file, not the program, is what a copy of it would weigh.
    sandbox.write("larger.xml", &one_line_with_warnings(1000, pad));
    let (output, peak) = peak_rss(&["check", "larger.xml"], &sandbox.dir, Stdio::null());
    assert_eq!(String::from_utf8(output.stdout).unwrap().lines().count(), 3 * 1000 + 1);
    let size = fs::metadata(sandbox.dir.join("larger.xml")).unwrap().len();
    assert!(peak < size, "{peak} bytes resident checking a {size} byte file");
}

/// `check` refuses a file larger than the input limit from its size, as a host's load
/// does, with the same error, and holds none of it.
#[test]
fn check_refuses_a_file_over_the_limit_from_its_size() {
    let sandbox = Sandbox::new("huge");
    let path = sandbox.dir.join("huge.xml");
    let file = fs::File::create(&path).unwrap();
    // Sparse: 2 GiB that take no room on the disk.
    file.set_len(2 << 30).unwrap();
    let expected = box2scene::load_path(&path, &box2scene::LoadOptions::default()).unwrap_err();
    let (output, peak) = peak_rss(&["check", "huge.xml"], &sandbox.dir, Stdio::null());
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert_eq!(
        stdout,
        format!(
            "huge.xml: error[limit-exceeded]: {}\nhuge.xml: 1 error, 0 warnings\n",
            expected.message
        )
    );
    assert!(peak < 32 << 20, "{peak} bytes resident refusing a 2 GiB file");
}

/// `check` reads a device and standard input as the loader reads a stream, a window at a
/// time, and stops where the loader stops: the same error as a host's load, and a few
/// megabytes held where reading a gigabyte first held one.
#[test]
fn check_reads_a_device_and_standard_input_as_streams() {
    let sandbox = Sandbox::new("streams");
    let expected =
        box2scene::load_path("/dev/zero", &box2scene::LoadOptions::default()).unwrap_err();
    let report = |name: &str| {
        let Position { line, column, .. } = expected.position;
        format!("{name}:{line}:{column}: error[{}]: {}\n", expected.code.name(), expected.message)
    };
    for (file, name) in [("/dev/zero", "/dev/zero"), ("-", "<stdin>")] {
        let stdin = fs::File::open("/dev/zero").unwrap();
        let (output, peak) = peak_rss(&["check", file], &sandbox.dir, stdin.into());
        let stdout = String::from_utf8(output.stdout).unwrap();
        assert!(stdout.starts_with(&report(name)), "{stdout}");
        assert!(peak < 32 << 20, "{peak} bytes resident checking {name}");
    }
}

/// `fmt -o` and `render -o` follow one rule through a link whose target does not exist
/// yet: the target is written, and the link stays a link.
#[cfg(unix)]
#[test]
fn fmt_and_render_write_through_a_link_to_a_file_not_yet_there() {
    let sandbox = Sandbox::new("dangling-link");
    sandbox.write("level.xml", CLEAN);
    fs::create_dir(sandbox.dir.join("out")).unwrap();
    for (command, link, target) in
        [("fmt", "formatted.xml", "out/formatted.xml"), ("render", "drawn.svg", "out/drawn.svg")]
    {
        std::os::unix::fs::symlink(target, sandbox.dir.join(link)).unwrap();
        let run = sandbox.run(&[command, "-o", link, "level.xml"]);
        assert_eq!((run.status, run.stderr.as_str()), (0, ""), "{command}");
        let printed = sandbox.run(&[command, "level.xml"]).stdout;
        assert_eq!(fs::read_to_string(sandbox.dir.join(target)).unwrap(), printed, "{command}");
        let meta = fs::symlink_metadata(sandbox.dir.join(link)).unwrap();
        assert!(meta.file_type().is_symlink(), "{command}");
    }
}

#[test]
fn fmt_writes_for_the_reader_dialect_names_and_keeps_an_engines_own() {
    let sandbox = Sandbox::new("fmt-dialect");
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    let velcro =
        std::fs::read_to_string(root.join("tests/fixtures/dialects/farseer-3.5.xml")).unwrap();
    sandbox.write("level.xml", &velcro);
    let kept = sandbox.run(&["fmt", "level.xml"]);
    assert_eq!((kept.status, kept.stdout.as_str()), (0, velcro.as_str()));
    let farseer = sandbox.run(&["fmt", "--dialect", "farseer-2013", "level.xml"]);
    assert_eq!(farseer.status, 0, "{}", farseer.stderr);
    assert!(farseer.stdout.starts_with("<World Version=\"2\">\n"), "{}", farseer.stdout);
    assert!(farseer.stdout.contains("<Fixture Id=\"0\"><Shape>0</Shape>"), "{}", farseer.stdout);
    let editor = sandbox.run(&["fmt", "--dialect=box2scene", "level.xml"]);
    assert!(editor.stdout.starts_with("<World Version=\"2\">\n"), "{}", editor.stdout);
    let refused = sandbox.run(&["fmt", "--dialect", "farseer-3.3", "level.xml"]);
    assert_eq!(refused.status, 1);
    assert!(refused.stderr.contains("error[dialect-cannot-hold]"), "{}", refused.stderr);
    let unknown = sandbox.run(&["fmt", "--dialect", "farseer", "level.xml"]);
    assert_eq!(unknown.status, 2);
    assert!(unknown.stderr.contains("invalid value 'farseer'"), "{}", unknown.stderr);
    assert!(unknown.stderr.contains("farseer-3.5, aether"), "the names: {}", unknown.stderr);
}

/// A level pipeline learns from `check`'s help to run it with `--strict`, and so a door whose
/// limit is misspelt, or written in degrees, fails the build with exit 1 instead of passing
/// with warnings.
#[test]
fn check_recommends_strict_for_pipelines_which_then_fail_on_a_door_in_degrees() {
    let sandbox = Sandbox::new("pipeline");
    let help = sandbox.run(&["help", "check"]);
    assert!(
        help.stdout.contains("in a level pipeline, run check --strict, so that\n"),
        "{}",
        help.stdout
    );
    let xml = clean_with(
        "  </Bodies>\n  <Joints />",
        "    <Body Type=\"Static\"/>\n  </Bodies>\n  <Joints><Joint Type=\"Revolute\">\
         <BodyA>1</BodyA><BodyB>0</BodyB><EnableLimit>true</EnableLimit>\
         <LowerAngel>-0.7</LowerAngel><LowerAngle>-45</LowerAngle></Joint></Joints>",
    );
    let sandbox = sandbox.write("door.xml", &xml);
    let run = sandbox.run(&["check", "door.xml"]);
    assert_eq!(run.status, 0, "{}", run.stderr);
    assert!(run.stdout.contains("(did you mean <LowerAngle>?)"), "{}", run.stdout);
    assert!(
        run.stdout.contains("warning[angle-in-degrees]: <LowerAngle> is -45"),
        "{}",
        run.stdout
    );
    let strict = sandbox.run(&["check", "--strict", "door.xml"]);
    assert_eq!(strict.status, 1, "{}", strict.stdout);
    assert!(strict.stdout.contains("error[unknown-element]"), "{}", strict.stdout);
}

/// An engine's file holding what its reader cannot take (a comment): plain `fmt -o` keeps
/// its dialect, so it fails naming the object and the way out, and writes nothing.
#[test]
fn fmt_of_an_engine_file_its_dialect_cannot_hold_fails_naming_the_object() {
    let sandbox = Sandbox::new("fmt-keeps-dialect");
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    let aether = std::fs::read_to_string(root.join("tests/fixtures/dialects/aether.xml")).unwrap();
    sandbox.write("level.xml", &aether.replace("<Bodies>", "<Bodies>\n    <!-- crates -->"));
    let run = sandbox.run(&["fmt", "level.xml", "-o", "out.xml"]);
    assert_eq!((run.status, run.stdout.as_str()), (1, ""));
    assert_report(
        run.stderr.lines().next().unwrap(),
        "out.xml: error[dialect-cannot-hold]: ",
        "body 0 holds comments",
    );
    assert!(run.stderr.contains("--dialect box2scene"), "{}", run.stderr);
    assert!(!sandbox.dir.join("out.xml").exists());
    let asked = sandbox.run(&["fmt", "--dialect", "box2scene", "level.xml", "-o", "out.xml"]);
    assert_eq!((asked.status, asked.stderr.as_str()), (0, ""));
    let written = fs::read_to_string(sandbox.dir.join("out.xml")).unwrap();
    assert!(written.contains("<!-- crates -->"), "{written}");
}
