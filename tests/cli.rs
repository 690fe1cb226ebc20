//! The `box2scene` command line, run as a level pipeline runs it: real files in a scratch
//! directory, exact output lines and exit statuses.

use std::fs;
use std::path::PathBuf;
use std::process::Command;

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

#[test]
fn check_prints_nothing_for_a_clean_file_and_exits_0() {
    let sandbox = Sandbox::new("clean");
    let run = sandbox.write("clean.xml", CLEAN).run(&["check", "clean.xml"]);
    assert_eq!((run.status, run.stdout.as_str(), run.stderr.as_str()), (0, "", ""));
}

#[test]
fn check_reports_an_unknown_element_as_a_warning_and_exits_0() {
    let xml = with_unknown_element();
    let sandbox = Sandbox::new("unknown-element");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    let (line, column) = locate(&xml, "<Foo/>");
    assert_eq!(run.status, 0, "{}", run.stderr);
    let [report] = lines(&run.stdout)[..] else { panic!("one line expected:\n{}", run.stdout) };
    assert_report(report, &format!("level.xml:{line}:{column}: warning[unknown-element]: "), "Foo");
}

#[test]
fn check_reports_a_missing_container_at_the_world_element() {
    let xml = without_joints();
    let sandbox = Sandbox::new("missing-container");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    let (line, column) = locate(&xml, "<World");
    assert_eq!(run.status, 0, "{}", run.stderr);
    let [report] = lines(&run.stdout)[..] else { panic!("one line expected:\n{}", run.stdout) };
    assert_report(
        report,
        &format!("level.xml:{line}:{column}: warning[missing-container]: "),
        "Joints",
    );
}

#[test]
fn strict_check_turns_a_warning_into_an_error_and_exits_1() {
    let xml = with_unknown_element();
    let sandbox = Sandbox::new("strict");
    let run = sandbox.write("level.xml", &xml).run(&["check", "--strict", "level.xml"]);
    let (line, column) = locate(&xml, "<Foo/>");
    assert_eq!(run.status, 1, "{}", run.stderr);
    let [report] = lines(&run.stdout)[..] else { panic!("one line expected:\n{}", run.stdout) };
    assert_report(report, &format!("level.xml:{line}:{column}: error[unknown-element]: "), "Foo");
}

#[test]
fn strict_check_of_a_clean_file_exits_0() {
    let sandbox = Sandbox::new("strict-clean");
    let run = sandbox.write("clean.xml", CLEAN).run(&["check", "clean.xml", "--strict"]);
    assert_eq!((run.status, run.stdout.as_str()), (0, ""));
}

#[test]
fn check_reports_an_invalid_float_at_its_value_and_exits_1() {
    let xml = with_bad_density();
    let sandbox = Sandbox::new("invalid-float");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    let (line, column) = locate(&xml, "abc");
    assert_eq!(run.status, 1, "{}", run.stderr);
    let [report] = lines(&run.stdout)[..] else { panic!("one line expected:\n{}", run.stdout) };
    assert_report(report, &format!("level.xml:{line}:{column}: error[invalid-float]: "), "abc");
}

#[test]
fn a_value_is_located_at_its_first_non_blank_character() {
    let xml = clean_with("<Density>1</Density>", "<Density>\n        abc\n      </Density>");
    let sandbox = Sandbox::new("value-position");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    let (line, column) = locate(&xml, "abc");
    assert_eq!(run.status, 1, "{}", run.stderr);
    let [report] = lines(&run.stdout)[..] else { panic!("one line expected:\n{}", run.stdout) };
    assert_report(report, &format!("level.xml:{line}:{column}: error[invalid-float]: "), "abc");
}

#[test]
fn columns_count_characters_not_bytes() {
    let xml = clean_with("<Bullet>False</Bullet>", "<Name>Kiste für Äpfel</Name><Foo/>");
    assert_eq!(locate(&xml, "<Foo/>"), (19, 35), "the test's own arithmetic");
    let sandbox = Sandbox::new("columns");
    let run = sandbox.write("level.xml", &xml).run(&["check", "level.xml"]);
    assert_eq!(run.status, 0, "{}", run.stderr);
    let [report] = lines(&run.stdout)[..] else { panic!("one line expected:\n{}", run.stdout) };
    assert_report(report, "level.xml:19:35: warning[unknown-element]: ", "Foo");
}

#[test]
fn check_goes_on_after_an_unreadable_file_and_exits_2() {
    let sandbox = Sandbox::new("missing-file");
    sandbox.write("level.xml", &with_unknown_element()).write("bad.xml", &with_bad_density());
    let run = sandbox.run(&["check", "absent.xml", "level.xml", "bad.xml"]);
    assert_eq!(run.status, 2, "{}", run.stderr);
    let [absent, warning, error] = lines(&run.stdout)[..] else {
        panic!("three lines expected:\n{}", run.stdout)
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
    let [error] = lines(&run.stdout)[..] else { panic!("one line expected:\n{}", run.stdout) };
    assert!(error.starts_with("bad.xml:"), "{error}");
}

#[test]
fn usage_errors_exit_2_with_the_usage_on_stderr() {
    let sandbox = Sandbox::new("usage");
    sandbox.write("clean.xml", CLEAN);
    let mistakes: &[&[&str]] = &[
        &[],
        &["frobnicate", "clean.xml"],
        &["check"],
        &["check", "--bogus", "clean.xml"],
        &["check", "-s", "clean.xml"],
        &["dump"],
        &["dump", "clean.xml", "clean.xml"],
        &["dump", "--pretty", "clean.xml"],
        &["fmt"],
        &["fmt", "clean.xml", "-o"],
        &["fmt", "clean.xml", "clean.xml"],
    ];
    for args in mistakes {
        let run = sandbox.run(args);
        assert_eq!(run.status, 2, "box2scene {args:?}");
        assert_eq!(run.stdout, "", "box2scene {args:?}");
        assert!(run.stderr.starts_with("box2scene: "), "box2scene {args:?}: {}", run.stderr);
        assert!(run.stderr.contains("Usage:"), "box2scene {args:?}: {}", run.stderr);
    }
}

#[test]
fn help_prints_the_usage_and_exits_0() {
    let sandbox = Sandbox::new("help");
    for flag in ["--help", "-h"] {
        let run = sandbox.run(&[flag]);
        assert_eq!((run.status, run.stderr.as_str()), (0, ""), "{flag}");
        assert!(run.stdout.starts_with("Usage:"), "{flag}: {}", run.stdout);
        assert!(run.stdout.contains("box2scene check [--strict] FILE..."), "{}", run.stdout);
    }
}

#[test]
fn version_prints_the_crate_version() {
    let run = Sandbox::new("version").run(&["--version"]);
    assert_eq!(run.status, 0);
    assert_eq!(run.stdout, format!("box2scene {}\n", env!("CARGO_PKG_VERSION")));
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
      <Position>0 20</Position>
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
    let scene = json::parse(&run.stdout);

    assert_eq!(scene["version"].number(), "1");
    assert_eq!(scene["gravity"].numbers(), ["8.369571e-36", "1.001022e-38"]);

    let wheel = &scene["shapes"][0];
    assert_eq!(wheel["kind"].string(), "circle");
    assert_eq!(wheel["name"].string(), "wheel \"A\" & tab\tend");
    assert_eq!(wheel["radius"].number(), "0.5");
    assert_eq!(wheel["position"].numbers(), ["0.0", "0.25"]);
    assert_eq!(wheel["vertices"].items().len(), 0);
    let ground = &scene["shapes"][1];
    assert_eq!(ground["kind"].string(), "polygon");
    assert!(ground["name"].is_null());
    assert_eq!(ground["vertices"][0].numbers(), ["-40.0", "0.0"]);
    assert_eq!(ground["vertices"][1].numbers(), ["40.0", "0.0"]);
    assert!(ground["centroid"].is_null(), "an absent centroid is not (0, 0)");

    let fixture = &scene["fixtures"][0];
    assert_eq!(fixture["shape"].number(), "0");
    assert_eq!(fixture["density"].number(), "5.0");
    assert_eq!(fixture["friction"].number(), "0.2");
    assert_eq!(fixture["filter"]["mask_bits"].number(), "65535");
    assert_eq!(scene["fixtures"][1]["friction"].number(), "0.2", "the default friction");

    let wagon = &scene["bodies"][0];
    assert_eq!(wagon["kind"].string(), "dynamic");
    assert_eq!(wagon["position"].numbers(), ["0.0", "20.0"]);
    assert_eq!(wagon["fixtures"].numbers(), ["0"]);
    assert!(wagon["mass_data"]["mass"].is_null());
    assert!(wagon["user_data"].is_null());
    let user_data = &scene["bodies"][1]["user_data"];
    assert_eq!(
        user_data["raw"].string(),
        "<Type>System.String</Type><Value><string>Ground</string></Value>"
    );
    assert_eq!(user_data["type_name"].string(), "System.String");
    assert_eq!(user_data["value"].string(), "Ground");

    let hinge = &scene["joints"][0];
    assert_eq!(hinge["kind"].string(), "revolute");
    assert_eq!((hinge["body_a"].number(), hinge["body_b"].number()), ("1", "0"));
    assert!(hinge["joint_a"].is_null(), "NONE is null");
    assert_eq!(hinge["local_anchor_a"].numbers(), ["0.0", "12.0"]);
    assert_eq!(hinge["collide_connected"], json::Value::Bool(false));

    assert_eq!(scene["diagnostics"].items().len(), 0);
}

#[test]
fn dump_includes_the_warnings() {
    let xml = with_unknown_element();
    let sandbox = Sandbox::new("dump-warning");
    let run = sandbox.write("level.xml", &xml).run(&["dump", "level.xml"]);
    assert_eq!((run.status, run.stderr.as_str()), (0, ""));
    let scene = json::parse(&run.stdout);
    let (line, column) = locate(&xml, "<Foo/>");
    let [warning] = scene["diagnostics"].items() else { panic!("one diagnostic expected") };
    assert_eq!(warning["severity"].string(), "warning");
    assert_eq!(warning["code"].string(), "unknown-element");
    assert_eq!(warning["line"].number(), line.to_string());
    assert_eq!(warning["column"].number(), column.to_string());
    let byte_offset = xml.find("<Foo/>").expect("the element is there");
    assert_eq!(warning["byte_offset"].number(), byte_offset.to_string());
}

#[test]
fn dump_of_a_bad_file_prints_the_error_on_stderr_and_exits_1() {
    let xml = with_bad_density();
    let sandbox = Sandbox::new("dump-error");
    let run = sandbox.write("level.xml", &xml).run(&["dump", "--strict", "level.xml"]);
    let (line, column) = locate(&xml, "abc");
    assert_eq!((run.status, run.stdout.as_str()), (1, ""));
    let [report] = lines(&run.stderr)[..] else { panic!("one line expected:\n{}", run.stderr) };
    assert_report(report, &format!("level.xml:{line}:{column}: error[invalid-float]: "), "abc");
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

/// Just enough JSON to check a dump: a strict reader of RFC 8259 text that keeps numbers
/// as their text, so that tests can assert the exact (shortest) float form.
mod json {
    use std::ops::Index;

    #[derive(Debug, PartialEq)]
    pub enum Value {
        Null,
        Bool(bool),
        Number(String),
        String(String),
        Array(Vec<Value>),
        Object(Vec<(String, Value)>),
    }

    /// Parses a whole document; panics with the offset on anything that is not JSON.
    pub fn parse(text: &str) -> Value {
        let mut reader = Reader { text, at: 0 };
        let value = reader.value();
        reader.skip_blanks();
        assert_eq!(reader.at, text.len(), "text after the JSON value");
        value
    }

    impl Value {
        pub fn is_null(&self) -> bool {
            *self == Value::Null
        }
        pub fn number(&self) -> &str {
            match self {
                Value::Number(text) => text,
                other => panic!("expected a number, got {other:?}"),
            }
        }
        pub fn string(&self) -> &str {
            match self {
                Value::String(text) => text,
                other => panic!("expected a string, got {other:?}"),
            }
        }
        pub fn items(&self) -> &[Value] {
            match self {
                Value::Array(items) => items,
                other => panic!("expected an array, got {other:?}"),
            }
        }
        /// The texts of an array of numbers (a vector, a list of indices).
        pub fn numbers(&self) -> Vec<&str> {
            self.items().iter().map(Value::number).collect()
        }
    }

    impl Index<usize> for Value {
        type Output = Value;
        fn index(&self, i: usize) -> &Value {
            self.items().get(i).unwrap_or_else(|| panic!("no item {i} in {self:?}"))
        }
    }

    impl Index<&str> for Value {
        type Output = Value;
        fn index(&self, key: &str) -> &Value {
            let Value::Object(fields) = self else { panic!("expected an object, got {self:?}") };
            let found = fields.iter().find(|(k, _)| k == key);
            &found.unwrap_or_else(|| panic!("no key {key:?} in {self:?}")).1
        }
    }

    struct Reader<'t> {
        text: &'t str,
        at: usize,
    }

    impl Reader<'_> {
        fn value(&mut self) -> Value {
            self.skip_blanks();
            match self.peek() {
                Some('{') => self.object(),
                Some('[') => self.array(),
                Some('"') => Value::String(self.string()),
                Some('t') => self.word("true", Value::Bool(true)),
                Some('f') => self.word("false", Value::Bool(false)),
                Some('n') => self.word("null", Value::Null),
                _ => self.number(),
            }
        }

        fn object(&mut self) -> Value {
            let mut fields = Vec::new();
            self.expect('{');
            if !self.closes('}') {
                loop {
                    self.skip_blanks();
                    let key = self.string();
                    self.skip_blanks();
                    self.expect(':');
                    fields.push((key, self.value()));
                    if self.closes('}') {
                        break;
                    }
                    self.expect(',');
                }
            }
            Value::Object(fields)
        }

        fn array(&mut self) -> Value {
            let mut items = Vec::new();
            self.expect('[');
            if !self.closes(']') {
                loop {
                    items.push(self.value());
                    if self.closes(']') {
                        break;
                    }
                    self.expect(',');
                }
            }
            Value::Array(items)
        }

        fn string(&mut self) -> String {
            self.expect('"');
            let mut out = String::new();
            loop {
                match self.take_char() {
                    '"' => return out,
                    '\\' => out.push(self.escape()),
                    c if u32::from(c) < 0x20 => self.fail("a raw control character in a string"),
                    c => out.push(c),
                }
            }
        }

        fn escape(&mut self) -> char {
            match self.take_char() {
                c @ ('"' | '\\' | '/') => c,
                'b' => '\u{8}',
                'f' => '\u{c}',
                'n' => '\n',
                'r' => '\r',
                't' => '\t',
                'u' => {
                    let hex = self.text.get(self.at..self.at + 4).unwrap_or("");
                    let code = u32::from_str_radix(hex, 16).unwrap_or_else(|_| self.fail("\\u"));
                    self.at += 4;
                    // The dump escapes only control characters, never a surrogate pair.
                    char::from_u32(code).unwrap_or_else(|| self.fail("a surrogate escape"))
                }
                _ => self.fail("an unknown escape"),
            }
        }

        /// `-? (0 | [1-9][0-9]*) (. [0-9]+)? ([eE] [+-]? [0-9]+)?`, kept as text.
        fn number(&mut self) -> Value {
            let start = self.at;
            self.eat('-');
            if !self.eat('0') {
                self.digits();
            }
            if self.eat('.') {
                self.digits();
            }
            if self.eat('e') || self.eat('E') {
                let _ = self.eat('+') || self.eat('-');
                self.digits();
            }
            Value::Number(self.text[start..self.at].to_owned())
        }

        fn digits(&mut self) {
            let count = self.text[self.at..].chars().take_while(char::is_ascii_digit).count();
            if count == 0 {
                self.fail("a digit");
            }
            self.at += count;
        }

        fn word(&mut self, word: &str, value: Value) -> Value {
            if !self.text[self.at..].starts_with(word) {
                self.fail(word);
            }
            self.at += word.len();
            value
        }

        /// Consumes `close` if it comes next, after blanks.
        fn closes(&mut self, close: char) -> bool {
            self.skip_blanks();
            self.eat(close)
        }

        fn expect(&mut self, c: char) {
            self.skip_blanks();
            if !self.eat(c) {
                self.fail(&format!("{c:?}"));
            }
        }

        fn eat(&mut self, c: char) -> bool {
            let here = self.peek() == Some(c);
            if here {
                self.at += c.len_utf8();
            }
            here
        }

        fn take_char(&mut self) -> char {
            let c = self.peek().unwrap_or_else(|| self.fail("more text"));
            self.at += c.len_utf8();
            c
        }

        fn peek(&self) -> Option<char> {
            self.text[self.at..].chars().next()
        }

        fn skip_blanks(&mut self) {
            let rest = &self.text[self.at..];
            self.at += rest.len() - rest.trim_start_matches([' ', '\t', '\n', '\r']).len();
        }

        fn fail(&self, expected: &str) -> ! {
            panic!("not JSON at byte {}: expected {expected}", self.at)
        }
    }
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
    assert!(
        run.stdout
            .starts_with("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<World Version=\"1\">\n"),
        "{}",
        run.stdout
    );
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
