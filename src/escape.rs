//! Text from a file, made safe for each kind of output that shows it: one function a kind
//! (a terminal, JSON, SVG), so that whatever a file holds, a report cannot be forged nor a
//! terminal driven by it, and a document stays one that parses to the text.
#![forbid(unsafe_code)]

use std::fmt::Write;

/// Whether `c` must not reach a terminal as it is: a control character (C0, DEL, C1; line
/// feeds and carriage returns among them, but not the tab), a line or paragraph separator,
/// or a character that changes the direction of the text after it.
fn unsafe_on_a_terminal(c: char) -> bool {
    (c.is_control() && c != '\t')
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

/// `c` as a terminal shows it, onto `out`: as it is, or, when it is unsafe there, as
/// `\u{1b}`. Bytes that were not text arrive as U+FFFD, which is shown.
pub fn terminal_char(c: char, out: &mut String) {
    match unsafe_on_a_terminal(c) {
        true => {
            let _ = write!(out, "\\u{{{:x}}}", u32::from(c));
        }
        false => out.push(c),
    }
}

/// Text for a terminal or a log: every character that could end the line, move the cursor
/// or turn the text around, escaped (see [`terminal_char`]).
pub fn terminal_text(text: &str) -> String {
    // Printable ASCII and tabs, most of any report, go as they are without a look at each
    // character; the first other byte starts a character (text is UTF-8).
    let plain = text.bytes().position(|b| !matches!(b, b' '..=b'~' | b'\t'));
    let plain = plain.unwrap_or(text.len());
    let mut out = String::with_capacity(text.len());
    out.push_str(&text[..plain]);
    for c in text[plain..].chars() {
        terminal_char(c, &mut out);
    }
    out
}

/// A JSON string literal: quotes and backslashes escaped, and every character a terminal
/// must not get raw (control characters, line and paragraph separators, which JavaScript
/// takes for line ends, and direction overrides) as `\uXXXX` (all fit one: the last is
/// U+2069), so that a record stays on its line and shows them visibly; everything else is
/// written as UTF-8.
pub fn json_string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if unsafe_on_a_terminal(c) => {
                let _ = write!(out, "\\u{:04x}", u32::from(c));
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// Text for an SVG (XML) element or attribute value: markup and quotes escaped; every
/// character a terminal must not get raw, and tabs, written as character references, so
/// that a parser gives them back as they were (a carriage return included) and the
/// document holds none of them raw; those XML cannot hold at all (C0 controls other than
/// tab, line feed and carriage return, U+FFFE, U+FFFF) shown as U+FFFD.
pub fn svg_text(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\u{0}'..='\u{8}'
            | '\u{B}'
            | '\u{C}'
            | '\u{E}'..='\u{1F}'
            | '\u{FFFE}'
            | '\u{FFFF}' => out.push(char::REPLACEMENT_CHARACTER),
            c if c == '\t' || unsafe_on_a_terminal(c) => {
                let _ = write!(out, "&#x{:X};", u32::from(c));
            }
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every control character (C0, DEL, C1), every line break (those of XML and of
    /// Unicode), every direction mark and override, a character XML forbids and what
    /// invalid bytes decode to (U+FFFD), between ordinary text.
    fn hostile() -> String {
        let mut text = String::from("a \"b\" & <c> \\ é 地 ");
        let controls = ('\u{0}'..='\u{1F}').chain(['\u{7F}']).chain('\u{80}'..='\u{9F}');
        let breaks = ['\u{2028}', '\u{2029}'];
        let bidi = ['\u{061C}', '\u{200E}', '\u{200F}'].into_iter();
        let bidi = bidi.chain('\u{202A}'..='\u{202E}').chain('\u{2066}'..='\u{2069}');
        for c in controls.chain(breaks).chain(bidi).chain(['\u{FFFE}', '\u{FFFF}']) {
            text.push(c);
            text.push('x');
        }
        text.push_str(&String::from_utf8_lossy(b"\xFF\xC3(\xE2\x82 end"));
        text
    }

    fn is_unsafe(c: char) -> bool {
        unsafe_on_a_terminal(c) || matches!(c, '\u{FFFE}' | '\u{FFFF}')
    }

    #[test]
    fn a_terminal_gets_no_control_break_or_direction_character_raw() {
        let text = hostile();
        let shown = terminal_text(&text);
        assert!(!shown.chars().any(unsafe_on_a_terminal), "{shown:?}");
        assert!(shown.contains("\\u{0}x\\u{1}x") && shown.contains("\\u{9b}x\\u{9c}"));
        assert!(shown.contains("\tx\\u{a}x\\u{b}x\\u{c}x\\u{d}x"), "{shown:?}");
        assert!(shown.contains("\\u{2028}x\\u{2029}x\\u{61c}x\\u{200e}x"), "{shown:?}");
        assert!(shown.contains("\\u{202e}x") && shown.contains("\\u{2069}x"), "{shown:?}");
        assert!(shown.starts_with("a \"b\" & <c> \\ é 地 "));
        assert!(shown.ends_with("\u{FFFD}\u{FFFD}(\u{FFFD} end"), "{shown:?}");
        let mut one = String::new();
        terminal_char('\u{1B}', &mut one);
        assert_eq!(one, "\\u{1b}");
    }

    #[test]
    fn json_gets_every_such_character_escaped_and_reads_back() {
        let text = hostile();
        let json = json_string(&text);
        assert!(!json.chars().any(unsafe_on_a_terminal), "{json:?}");
        let read: String = serde_json::from_str(&json).unwrap();
        assert_eq!(read, text);
        assert_eq!(json_string(r#"say "hi" \o/"#), r#""say \"hi\" \\o/""#);
        assert_eq!(json_string("a\tb\nc\r\u{0}\u{1f}"), r#""a\tb\nc\r\u0000\u001f""#);
        assert_eq!(json_string("del\u{7f} c1\u{85} \u{202e}"), r#""del\u007f c1\u0085 \u202e""#);
        assert_eq!(json_string("Grüße, 地面 ∞"), "\"Grüße, 地面 ∞\"");
        assert_eq!(json_string(""), "\"\"");
    }

    #[test]
    fn svg_holds_no_such_character_raw_and_parses_back_to_the_text() {
        let text = hostile();
        let escaped = svg_text(&text);
        assert!(!escaped.chars().any(|c| is_unsafe(c) || c == '\t'), "{escaped:?}");
        let document = format!("<svg a=\"{escaped}\"><title>{escaped}</title></svg>");
        let parsed = roxmltree::Document::parse(&document).unwrap();
        let xml_forbids = |c: char| {
            matches!(c, '\u{0}'..='\u{8}' | '\u{B}' | '\u{C}' | '\u{E}'..='\u{1F}')
                || matches!(c, '\u{FFFE}' | '\u{FFFF}')
        };
        let expected: String =
            text.chars().map(|c| if xml_forbids(c) { '\u{FFFD}' } else { c }).collect();
        let root = parsed.root_element();
        assert_eq!(root.first_child().unwrap().text(), Some(expected.as_str()));
        assert_eq!(root.attribute("a"), Some(expected.as_str()));
    }
}
