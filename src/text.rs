//! Every text-to-value conversion of the format (docs/format.md, "Text, names and values").
//! Each takes the element's text, already trimmed, and returns the value or a [`Finding`]
//! whose `at` is the byte offset, within that text, of the offending part.
#![forbid(unsafe_code)]

use crate::error::{Code, Finding};
use crate::scene::Vec2;

fn bad(code: Code, at: usize, message: impl Into<String>) -> Finding {
    Finding::new(code, at, message)
}

/// XML white space (not Unicode's), for `trim_*_matches`.
pub(crate) const XML_SPACE: [char; 4] = [' ', '\t', '\r', '\n'];

/// XML white space, as a byte of UTF-8 text. All four are ASCII, so a byte that matches is a
/// whole character and the text can be sliced next to it.
pub fn is_xml_space_byte(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | b'\n')
}

/// How many bytes of XML white space `bytes` starts with, looking at eight at a time:
/// indentation before a tag is often longer than that.
pub fn leading_space(bytes: &[u8]) -> usize {
    if !bytes.first().is_some_and(|&b| is_xml_space_byte(b)) {
        return 0;
    }
    let mut i = 0;
    while let Some(eight) = bytes[i..].first_chunk::<8>() {
        let word = u64::from_le_bytes(*eight);
        let space = [b' ', b'\t', b'\n', b'\r']
            .into_iter()
            .fold(0, |space, b| space | bytes_equal(word, b));
        let other = !space & HIGH_BITS;
        if other != 0 {
            return i + (other.trailing_zeros() / 8) as usize;
        }
        i += 8;
    }
    i + bytes[i..].iter().position(|&b| !is_xml_space_byte(b)).unwrap_or(bytes.len() - i)
}

const HIGH_BITS: u64 = u64::from_le_bytes([0x80; 8]);

/// The high bit of each byte of `word` that is `b`.
pub(crate) fn bytes_equal(word: u64, b: u8) -> u64 {
    zero_bytes(word ^ u64::from_le_bytes([b; 8]))
}

/// The high bit of each byte of `word` that is zero. Exact for every byte (no borrow
/// crosses from one byte to the next, as it can in the shorter formula).
fn zero_bytes(word: u64) -> u64 {
    let low = !HIGH_BITS;
    !(((word & low) + low) | word) & HIGH_BITS
}

/// Where `bytes` without leading and trailing XML white space starts and ends.
pub fn trimmed_span(bytes: &[u8]) -> (usize, usize) {
    let start = leading_space(bytes);
    let end = bytes.iter().rposition(|&b| !is_xml_space_byte(b)).map_or(start, |i| i + 1);
    (start, end)
}

/// `s` without leading and trailing XML white space, and where that starts in `s`. The
/// white space is ASCII, so the cut points are always character boundaries.
pub fn trim_xml_at(s: &str) -> (usize, &str) {
    let (start, end) = trimmed_span(s.as_bytes());
    (start, &s[start..end])
}

/// `s` without leading and trailing XML white space.
pub fn trim_xml(s: &str) -> &str {
    trim_xml_at(s).1
}

/// The spellings of infinity and NaN that writers produce (.NET, C, JavaScript).
fn is_non_finite_word(s: &str) -> bool {
    let word = s.trim_start_matches(['+', '-']);
    ["inf", "infinity", "nan", "∞"].iter().any(|w| word.eq_ignore_ascii_case(w))
}

/// A byte that can appear in a float as the format writes them: digits, point, exponent, sign.
fn is_float_byte(b: u8) -> bool {
    matches!(b, b'0'..=b'9' | b'.' | b'e' | b'E' | b'+' | b'-')
}

/// A decimal float, read with correct rounding to the nearest f32.
///
/// The common case takes one pass over the bytes to check that they can only spell a float,
/// then the standard library's parse. Such text cannot be empty, a non-finite word or a
/// decimal comma, so a parse error there is simply not a number. Everything else goes to
/// [`not_a_float`], which works out which mistake it is.
pub fn float(s: &str) -> Result<f32, Finding> {
    if let Some(value) = exact_float(s) {
        return Ok(value);
    }
    if s.is_empty() || !s.bytes().all(is_float_byte) {
        return Err(not_a_float(s));
    }
    match s.parse::<f32>() {
        Ok(value) if value.is_infinite() => {
            Err(bad(Code::NonFiniteFloat, 0, format!("{s} is too large for a 32-bit float")))
        }
        Ok(value) => Ok(value),
        Err(_) => Err(bad(Code::InvalidFloat, 0, format!("'{s}' is not a number"))),
    }
}

/// The usual float, when it is exact in one step: `[sign] digits [. digits] [e|E [sign]
/// digits]` with at most 2^24 as its digits and a power of ten of at most 10^10 either way.
/// Both are exact f32s, so one multiplication or division rounds correctly to the same f32
/// the standard library's parse gives (Clinger's fast path, which that parse also takes
/// after more general work). None for anything else.
fn exact_float(s: &str) -> Option<f32> {
    exact_float_from(s.as_bytes(), 0).filter(|&(_, end)| end == s.len()).map(|(value, _)| value)
}

/// [`exact_float`] of the float that starts at `from` in `bytes`, and where it ends. None
/// when no float starts there, or one that is not exact in one step, or one whose exponent
/// has more than 3 digits. Inlined: its callers are few and call it for every value.
#[inline(always)]
fn exact_float_from(bytes: &[u8], from: usize) -> Option<(f32, usize)> {
    let (negative, start) = match bytes.get(from)? {
        b'-' => (true, from + 1),
        b'+' => (false, from + 1),
        _ => (false, from),
    };
    // The digits before and after the point in one loop, a byte at a time: reading eight
    // at a time takes more instructions for the six to eight digits floats usually have.
    let (mut i, mut mantissa, mut point) = (start, 0u64, None);
    loop {
        match bytes.get(i) {
            Some(&b) if b.wrapping_sub(b'0') < 10 => {
                mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(b - b'0'));
            }
            Some(b'.') if point.is_none() => point = Some(i),
            _ => break,
        }
        i += 1;
    }
    let fraction = point.map_or(0, |point| i - point - 1);
    let digits = i - start - usize::from(point.is_some());
    // At most 19 digits in all, so that the mantissa did not wrap.
    if digits == 0 || digits > 19 || mantissa > 1 << 24 {
        return None;
    }
    let mut scale = -(fraction as i32);
    if let Some(b'e' | b'E') = bytes.get(i) {
        i += 1;
        let negative_exponent = bytes.get(i) == Some(&b'-');
        if let Some(b'-' | b'+') = bytes.get(i) {
            i += 1;
        }
        // One to three digits: a byte at a time, as there are so few.
        let (mut exponent, digits_from) = (0, i);
        while let Some(digit) = bytes.get(i).map(|b| b.wrapping_sub(b'0')).filter(|&d| d < 10) {
            if i - digits_from == 3 {
                return None;
            }
            exponent = exponent * 10 + i32::from(digit);
            i += 1;
        }
        if i == digits_from {
            return None;
        }
        scale += if negative_exponent { -exponent } else { exponent };
    }
    if !(-10..=10).contains(&scale) {
        return None;
    }
    const POWERS: [f32; 11] = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10];
    let power = POWERS[scale.unsigned_abs() as usize];
    // At most 2^24, so the conversion is exact (and cheaper from 32 bits than from 64).
    let magnitude = mantissa as u32 as f32;
    let value = if scale < 0 { magnitude / power } else { magnitude * power };
    Some((if negative { -value } else { value }, i))
}

/// Why `s`, which is empty or has a byte no float has, is not a float: nothing at all, an
/// infinity or NaN, a decimal comma, or something else.
#[cold]
#[inline(never)]
fn not_a_float(s: &str) -> Finding {
    if s.is_empty() {
        return bad(Code::InvalidFloat, 0, "expected a number, found nothing");
    }
    if is_non_finite_word(s) {
        return bad(Code::NonFiniteFloat, 0, format!("'{s}' is not a finite number"));
    }
    if let Some(comma) = s.find(',') {
        let digits = |t: &str| !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit() || b == b'-');
        if digits(&s[..comma]) && digits(&s[comma + 1..]) {
            return bad(
                Code::FloatDecimalComma,
                comma,
                format!(
                    "'{s}' has a decimal comma: the file was written with a locale that uses \
                     one; numbers must use a decimal point"
                ),
            );
        }
    }
    bad(Code::InvalidFloat, 0, format!("'{s}' is not a number"))
}

/// Two floats separated by white space and/or one comma; empty text is (0, 0).
///
/// One pass over the bytes counts the commas (keeping the first), notes any white space,
/// and finds the first two runs of non-white-space bytes (the parts of the white-space form).
/// Then, in this order:
/// - two or more commas and some white space, or one comma between two digits inside one of
///   two runs: decimal commas, pointing at the first comma;
/// - exactly one comma: the parts are either side of it (each may be padded with white space);
/// - no comma and exactly two runs: the parts are the runs;
/// - anything else is not a vector.
pub fn vector2(s: &str) -> Result<Vec2, Finding> {
    if let Some(v) = exact_vector2(s.as_bytes()) {
        return Ok(v);
    }
    if s.is_empty() {
        return Ok(Vec2::ZERO);
    }
    let mut commas = 0;
    let mut first_comma = 0;
    let mut has_space = false;
    let mut runs = 0;
    let mut in_run = false;
    let mut run_bounds = [(0, s.len()); 2];
    for (i, &b) in s.as_bytes().iter().enumerate() {
        if is_xml_space_byte(b) {
            has_space = true;
            if in_run {
                in_run = false;
                if runs <= 2 {
                    run_bounds[runs - 1].1 = i;
                }
            }
            continue;
        }
        if b == b',' {
            if commas == 0 {
                first_comma = i;
            }
            commas += 1;
        }
        if !in_run {
            in_run = true;
            runs += 1;
            if runs <= 2 {
                run_bounds[runs - 1].0 = i;
            }
        }
    }
    if (commas > 1 && has_space) || (commas == 1 && runs == 2 && between_digits(s, first_comma)) {
        return Err(decimal_commas(s, first_comma));
    }
    let ((at_x, x), (at_y, y)) = match (commas, runs) {
        (1, _) => ((0, &s[..first_comma]), (first_comma + 1, &s[first_comma + 1..])),
        (0, 2) => {
            let [(x_start, x_end), (y_start, y_end)] = run_bounds;
            ((x_start, &s[x_start..x_end]), (y_start, &s[y_start..y_end]))
        }
        _ => {
            return Err(bad(
                Code::InvalidVector2,
                0,
                format!("'{s}' is not a vector: expected two numbers such as '1 5' or '1, 5'"),
            ));
        }
    };
    let component = |at: usize, part: &str| {
        let (lead, trimmed) = trim_xml_at(part);
        if trimmed.is_empty() {
            return Err(bad(Code::InvalidVector2, at, format!("'{s}' has an empty component")));
        }
        float(trimmed).map_err(|e| Finding { at: at + lead + e.at, ..e })
    };
    Ok(Vec2 { x: component(at_x, x)?, y: component(at_y, y)? })
}

/// Whether the byte at `at` of `s` has an ASCII digit on either side: `0,5`, not `1, 5`.
fn between_digits(s: &str, at: usize) -> bool {
    let digit =
        |i: Option<usize>| i.and_then(|i| s.as_bytes().get(i)).is_some_and(u8::is_ascii_digit);
    digit(at.checked_sub(1)) && digit(Some(at + 1))
}

/// A vector whose components are written with decimal commas (`0,5 -20`, `0 -9,82`), the
/// first at `comma`.
#[cold]
fn decimal_commas(s: &str, comma: usize) -> Finding {
    bad(
        Code::FloatDecimalComma,
        comma,
        format!(
            "'{s}' looks like two numbers written with decimal commas: the file was written \
             with a locale that uses one; numbers must use a decimal point"
        ),
    )
}

/// The usual vector in one pass: an exact float, white space and/or one comma, an exact
/// float (see [`exact_float`]). None for anything else, which [`vector2`] reads in full.
fn exact_vector2(bytes: &[u8]) -> Option<Vec2> {
    let (x, mut i) = exact_float_from(bytes, 0)?;
    let separator = i;
    // A byte or two: one at a time.
    let skip_space = |i: &mut usize| {
        while bytes.get(*i).is_some_and(|&b| is_xml_space_byte(b)) {
            *i += 1;
        }
    };
    skip_space(&mut i);
    if bytes.get(i) == Some(&b',') {
        i += 1;
        skip_space(&mut i);
    }
    if i == separator {
        return None;
    }
    let (y, end) = exact_float_from(bytes, i)?;
    (end == bytes.len()).then_some(Vec2 { x, y })
}

/// `true`/`false` in any letter case, or `1`/`0`.
///
/// Both words are letters only, and the two cases of an ASCII letter differ in bit 5
/// alone (no other byte becomes a lower-case letter with that bit set): so a four-byte
/// text with bit 5 set in every byte is `true` exactly when the text is `true` in some
/// letter case. One comparison, and one more for `false`.
pub fn boolean(s: &str) -> Result<bool, Finding> {
    const LOWER: u32 = 0x2020_2020;
    let word = |four: [u8; 4]| u32::from_le_bytes(four) | LOWER;
    match *s.as_bytes() {
        [b'1'] => Ok(true),
        [b'0'] => Ok(false),
        [a, b, c, d] if word([a, b, c, d]) == word(*b"true") => Ok(true),
        [a, b, c, d, e] if word([a, b, c, d]) == word(*b"fals") && e | 0x20 == b'e' => Ok(false),
        _ => Err(bad(
            Code::InvalidBool,
            0,
            format!("'{s}' is not a boolean: expected true or false"),
        )),
    }
}

/// Optional sign, decimal digits; 32-bit.
///
/// The standard library's parse accepts exactly that (one optional sign, at least one digit),
/// so a successful parse is the answer in one pass; only a failure needs telling apart.
pub fn int(s: &str) -> Result<i32, Finding> {
    if let Ok(value) = s.parse() {
        return Ok(value);
    }
    let digits = s.strip_prefix(['+', '-']).unwrap_or(s);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err(bad(Code::InvalidInt, 0, format!("'{s}' is not a whole number")));
    }
    Err(bad(Code::OutOfRange, 0, format!("{s} is out of the 32-bit range")))
}

/// A 16-bit signed int (a group index).
pub fn int16(s: &str) -> Result<i16, Finding> {
    let value = int(s)?;
    i16::try_from(value)
        .map_err(|_| bad(Code::OutOfRange, 0, format!("{s} is outside -32768..32767")))
}

/// A non-negative index into a container.
///
/// As for [`int`], the standard library's parse of a `u32` accepts exactly an optional `+` and
/// digits, so a successful parse (short of the reserved `u32::MAX`) is the answer in one pass.
pub fn id(s: &str) -> Result<u32, Finding> {
    if let Ok(value @ 0..=0xFFFF_FFFE) = s.parse::<u32>() {
        return Ok(value);
    }
    let digits = s.strip_prefix('+').unwrap_or(s);
    if s.starts_with('-') && s.len() > 1 && s[1..].bytes().all(|b| b.is_ascii_digit()) {
        return Err(bad(Code::InvalidId, 0, format!("ID {s} is negative: IDs count from 0")));
    }
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err(bad(
            Code::InvalidId,
            0,
            format!("'{s}' is not an ID: expected an index such as 0"),
        ));
    }
    match digits.parse::<u32>() {
        Ok(v) if v != u32::MAX => Ok(v),
        _ => Err(bad(Code::IdOutOfRange, 0, format!("ID {s} is out of range"))),
    }
}

/// Collision bits, decimal or `0x` hexadecimal, 32 of them.
pub fn bits(s: &str) -> Result<u32, Finding> {
    let (digits, radix) = match s.strip_prefix("0x").or_else(|| s.strip_prefix("0X")) {
        Some(hex) => (hex, 16),
        None => (s.strip_prefix('+').unwrap_or(s), 10),
    };
    if s.starts_with('-') {
        return Err(bad(Code::InvalidBits, 0, format!("bits {s} are negative")));
    }
    let ok = !digits.is_empty() && digits.bytes().all(|b| char::from(b).is_digit(radix));
    let value = (ok.then(|| u64::from_str_radix(digits, radix).ok()).flatten())
        .ok_or_else(|| bad(Code::InvalidBits, 0, format!("'{s}' is not a bit mask")))?;
    u32::try_from(value)
        .map_err(|_| bad(Code::OutOfRange, 0, format!("bits {s} are more than 32 (4294967295)")))
}

#[cfg(test)]
mod tests {
    use super::*;

    // The editor's own text of pi and -pi/4.
    #[allow(clippy::approx_constant)]
    #[test]
    fn floats_in_every_spelling() {
        for (text, value) in [
            ("3.141593", 3.141593f32),
            ("-0.7853982", -0.7853982),
            ("8.369571E-36", 8.369571e-36),
            (".5", 0.5),
            ("5.", 5.0),
            ("+1", 1.0),
            ("1e5", 1e5),
            ("-0", -0.0),
        ] {
            assert_eq!(float(text).unwrap().to_bits(), value.to_bits(), "{text}");
        }
    }

    /// The one-step path against the standard library's parse, bit for bit, over a million
    /// numbers of the shapes writers produce, most of them within its reach.
    #[test]
    fn exact_floats_match_the_standard_parse() {
        let mut state = 0x2545F4914F6CDD1Du64;
        let mut next = |n: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state % n
        };
        let mut fast = 0;
        for _ in 0..1_000_000 {
            let digits = |count: u64, next: &mut dyn FnMut(u64) -> u64| {
                (0..count).map(|_| char::from(b'0' + next(10) as u8)).collect::<String>()
            };
            let mut text = String::from(["", "-", "+"][next(3) as usize]);
            text += &digits(next(9), &mut next);
            if next(2) == 0 {
                text.push('.');
                text += &digits(next(9), &mut next);
            }
            if next(3) == 0 {
                text.push(['e', 'E'][next(2) as usize]);
                text.push_str(["", "-", "+"][next(3) as usize]);
                text += &digits(1 + next(2), &mut next);
            }
            let expected = text.parse::<f32>().ok().filter(|v| v.is_finite());
            if let Some(value) = exact_float(&text) {
                fast += 1;
                assert_eq!(Some(value.to_bits()), expected.map(f32::to_bits), "{text}");
            }
            let read = float(&text).ok().map(f32::to_bits);
            assert_eq!(read, expected.map(f32::to_bits), "{text}");
        }
        assert!(fast > 300_000, "only {fast} took the one-step path");
    }

    #[test]
    fn bad_floats_have_their_codes() {
        for (text, code) in [
            ("", Code::InvalidFloat),
            ("abc", Code::InvalidFloat),
            ("1.2.3", Code::InvalidFloat),
            ("0x10", Code::InvalidFloat),
            ("NaN", Code::NonFiniteFloat),
            ("Infinity", Code::NonFiniteFloat),
            ("-inf", Code::NonFiniteFloat),
            ("∞", Code::NonFiniteFloat),
            ("1e39", Code::NonFiniteFloat),
            ("0,5", Code::FloatDecimalComma),
        ] {
            assert_eq!(float(text).unwrap_err().code, code, "{text}");
        }
    }

    #[test]
    fn vectors_in_every_spelling() {
        for text in ["1 5", "1,5", "1, 5", "1 ,5", "1\t\n5", "1.0 , 5.0"] {
            assert_eq!(vector2(text).unwrap(), Vec2::new(1.0, 5.0), "{text}");
        }
        assert_eq!(vector2("").unwrap(), Vec2::ZERO);
    }

    #[test]
    fn bad_vectors_point_at_the_culprit() {
        let e = vector2("1").unwrap_err();
        assert_eq!((e.code, e.at), (Code::InvalidVector2, 0));
        assert_eq!(vector2("1 2 3").unwrap_err().code, Code::InvalidVector2);
        let e = vector2("1,,2").unwrap_err();
        assert_eq!(e.code, Code::InvalidVector2);
        let e = vector2("1, x").unwrap_err();
        assert_eq!((e.code, e.at), (Code::InvalidFloat, 3));
        assert_eq!(vector2("0,5 1,5").unwrap_err().code, Code::FloatDecimalComma);
        for (text, comma) in [("0,5 -20", 1), ("0 -9,82", 4), ("1,5\t2", 1)] {
            let e = vector2(text).unwrap_err();
            assert_eq!((e.code, e.at), (Code::FloatDecimalComma, comma), "{text}");
        }
        assert_eq!(vector2("1, 5").unwrap(), Vec2::new(1.0, 5.0));
        assert_eq!(vector2("1 NaN").unwrap_err().code, Code::NonFiniteFloat);
    }

    #[test]
    fn booleans_ids_ints_and_bits() {
        for (text, value) in [("True", true), ("FALSE", false), ("1", true), ("0", false)] {
            assert_eq!(boolean(text).unwrap(), value);
        }
        assert_eq!(boolean("yes").unwrap_err().code, Code::InvalidBool);
        assert_eq!(id("12").unwrap(), 12);
        assert_eq!(id("-1").unwrap_err().code, Code::InvalidId);
        assert_eq!(id("x").unwrap_err().code, Code::InvalidId);
        assert_eq!(id("99999999999").unwrap_err().code, Code::IdOutOfRange);
        assert_eq!(id("4294967295").unwrap_err().code, Code::IdOutOfRange);
        assert_eq!(id("+5").unwrap(), 5);
        assert_eq!(id("-").unwrap_err().code, Code::InvalidId);
        assert_eq!(int("+7").unwrap(), 7);
        assert_eq!(int("-").unwrap_err().code, Code::InvalidInt);
        assert_eq!(bits("0x").unwrap_err().code, Code::InvalidBits);
        assert_eq!(bits("1é").unwrap_err().code, Code::InvalidBits);
        assert_eq!(int("-32768").unwrap(), -32768);
        assert_eq!(int("3000000000").unwrap_err().code, Code::OutOfRange);
        assert_eq!(int16("40000").unwrap_err().code, Code::OutOfRange);
        assert_eq!(bits("0x00FF").unwrap(), 0xFF);
        assert_eq!(bits("65535").unwrap(), 0xFFFF);
        assert_eq!(bits("2147483647").unwrap(), 0x7FFF_FFFF);
        assert_eq!(bits("0xFFFFFFFF").unwrap(), u32::MAX);
        assert_eq!(bits("4294967296").unwrap_err().code, Code::OutOfRange);
        assert_eq!(bits("-1").unwrap_err().code, Code::InvalidBits);
    }

    /// The implementations before the byte-level rewrite, verbatim, as references that the
    /// new ones must match exactly (values, codes, offsets and messages).
    mod old {
        use super::super::{Code, Finding, Vec2, bad, is_non_finite_word};

        pub fn is_xml_space(c: char) -> bool {
            matches!(c, ' ' | '\t' | '\r' | '\n')
        }

        pub fn trim_xml(s: &str) -> &str {
            s.trim_matches(is_xml_space)
        }

        pub fn float(s: &str) -> Result<f32, Finding> {
            if s.is_empty() {
                return Err(bad(Code::InvalidFloat, 0, "expected a number, found nothing"));
            }
            if is_non_finite_word(s) {
                return Err(bad(Code::NonFiniteFloat, 0, format!("'{s}' is not a finite number")));
            }
            if let Some(comma) = s.find(',') {
                let digits =
                    |t: &str| !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit() || b == b'-');
                if digits(&s[..comma]) && digits(&s[comma + 1..]) {
                    return Err(bad(
                        Code::FloatDecimalComma,
                        comma,
                        format!(
                            "'{s}' has a decimal comma: the file was written with a locale that \
                             uses one; numbers must use a decimal point"
                        ),
                    ));
                }
            }
            let well_formed = s
                .bytes()
                .all(|b| b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'+' | b'-'));
            let value: f32 = match s.parse() {
                Ok(v) if well_formed => v,
                _ => return Err(bad(Code::InvalidFloat, 0, format!("'{s}' is not a number"))),
            };
            if value.is_infinite() {
                return Err(bad(
                    Code::NonFiniteFloat,
                    0,
                    format!("{s} is too large for a 32-bit float"),
                ));
            }
            Ok(value)
        }

        pub fn vector2(s: &str) -> Result<Vec2, Finding> {
            if s.is_empty() {
                return Ok(Vec2::ZERO);
            }
            let parts: Vec<(usize, &str)> = if s.contains(',') {
                pieces(s, |c| c == ',').collect()
            } else {
                pieces(s, is_xml_space).filter(|(_, part)| !part.is_empty()).collect()
            };
            let comma = s.find(',').unwrap_or(0);
            let runs = pieces(s, is_xml_space).filter(|(_, part)| !part.is_empty()).count();
            let digit = |i: usize| s.as_bytes().get(i).is_some_and(u8::is_ascii_digit);
            let one_decimal_comma =
                parts.len() == 2 && runs == 2 && comma > 0 && digit(comma - 1) && digit(comma + 1);
            if (parts.len() > 2 && s.contains(',') && s.contains(is_xml_space)) || one_decimal_comma
            {
                return Err(super::super::decimal_commas(s, comma));
            }
            let [(at_x, x), (at_y, y)] = parts[..] else {
                return Err(bad(
                    Code::InvalidVector2,
                    0,
                    format!("'{s}' is not a vector: expected two numbers such as '1 5' or '1, 5'"),
                ));
            };
            let component = |at: usize, part: &str| {
                let lead = part.len() - part.trim_start_matches(is_xml_space).len();
                let part = trim_xml(part);
                if part.is_empty() {
                    return Err(bad(
                        Code::InvalidVector2,
                        at,
                        format!("'{s}' has an empty component"),
                    ));
                }
                float(part).map_err(|e| Finding { at: at + lead + e.at, ..e })
            };
            Ok(Vec2 { x: component(at_x, x)?, y: component(at_y, y)? })
        }

        /// The one-step float reader before it read the whole part and the fraction in one
        /// loop.
        pub fn exact_float_prefix(bytes: &[u8]) -> Option<(f32, usize)> {
            let (negative, mut i) = match bytes.first()? {
                b'-' => (true, 1),
                b'+' => (false, 1),
                _ => (false, 0),
            };
            let mut mantissa = 0u64;
            let mut digits = |i: &mut usize| {
                let from = *i;
                while let Some(digit) =
                    bytes.get(*i).map(|b| b.wrapping_sub(b'0')).filter(|&d| d < 10)
                {
                    mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(digit));
                    *i += 1;
                }
                *i - from
            };
            let whole = digits(&mut i);
            let fraction = match bytes.get(i) {
                Some(b'.') => {
                    i += 1;
                    digits(&mut i)
                }
                _ => 0,
            };
            if whole + fraction == 0 || whole + fraction > 19 || mantissa > 1 << 24 {
                return None;
            }
            let mut scale = -(fraction as i32);
            if let Some(b'e' | b'E') = bytes.get(i) {
                i += 1;
                let negative_exponent = bytes.get(i) == Some(&b'-');
                if let Some(b'-' | b'+') = bytes.get(i) {
                    i += 1;
                }
                let exponent_digits =
                    bytes[i..].iter().take(4).take_while(|b| b.is_ascii_digit()).count();
                if !(1..=3).contains(&exponent_digits) {
                    return None;
                }
                let exponent = bytes[i..i + exponent_digits]
                    .iter()
                    .fold(0, |e, &b| e * 10 + i32::from(b - b'0'));
                scale += if negative_exponent { -exponent } else { exponent };
                i += exponent_digits;
            }
            if !(-10..=10).contains(&scale) {
                return None;
            }
            const POWERS: [f32; 11] = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10];
            let power = POWERS[scale.unsigned_abs() as usize];
            let magnitude = mantissa as f32;
            let value = if scale < 0 { magnitude / power } else { magnitude * power };
            Some((if negative { -value } else { value }, i))
        }

        pub fn boolean(s: &str) -> Result<bool, Finding> {
            if s.eq_ignore_ascii_case("true") || s == "1" {
                Ok(true)
            } else if s.eq_ignore_ascii_case("false") || s == "0" {
                Ok(false)
            } else {
                Err(bad(
                    Code::InvalidBool,
                    0,
                    format!("'{s}' is not a boolean: expected true or false"),
                ))
            }
        }

        fn pieces(s: &str, is_separator: fn(char) -> bool) -> impl Iterator<Item = (usize, &str)> {
            let mut next = 0;
            s.split(is_separator).map(move |part| {
                let at = next;
                next += part.len() + 1;
                (at, part)
            })
        }
    }

    /// Calls `check` with every string of up to `max_len` symbols drawn from `alphabet`.
    fn for_all_strings(alphabet: &[&str], max_len: usize, mut check: impl FnMut(&str)) {
        let mut text = String::new();
        let mut digits = Vec::new();
        loop {
            text.clear();
            digits.iter().for_each(|&d: &usize| text.push_str(alphabet[d]));
            check(&text);
            // Count up in base alphabet.len(), growing by one symbol on carry out.
            let mut i = 0;
            loop {
                if i == digits.len() {
                    if digits.len() == max_len {
                        return;
                    }
                    digits.push(0);
                    break;
                }
                digits[i] += 1;
                if digits[i] < alphabet.len() {
                    break;
                }
                digits[i] = 0;
                i += 1;
            }
        }
    }

    #[rustfmt::skip]
    const HAND_PICKED: &[&str] = &[
        "", " ", "8.369571E-36", ".5", "5.", "1e39", "-1e39", "3.4028235e38", "3.4028236e38",
        "1e-46", "NaN", "nan", "-NaN", "inf", "+inf", "-inf", "--inf", "+-Infinity", "INFINITY",
        "∞", "-∞", "+∞", "∞ ∞", "infinite", "0,5", "-0,5", "0,-5", ",5", "5,", "1,2,3", " 1 , 5 ",
        "1\t\n5", "1\r5", "1 ,5", "1, 5", "1,5", "1,,2", "1 2 3", "0,5 1,5", "0,5\t1,5", "1, x",
        "x, 1", "1 NaN", "NaN, 1", "1, 1e39", "1e39 1", "é 1", "1 é", "1,é", "1 , ", " , 1",
        ",", ", ", " ,", "  ", "0x10", "1.2.3", "1e", "e1", "+", "-", ".", "1_000", "١", "1 ١",
        "3.141593", "-0.7853982", "+1", "1e5", "-0", "1.0 , 5.0", "  1   5  ", "1\u{a0}5",
        "1\u{2003}5", "4294967295", "4294967294", "4294967296", "-4294967295", "2147483647",
        "2147483648", "-2147483648", "-2147483649", "+-1", "-+1", "++1", "--1", "0x", "0X",
        "0xFFFF", "0x10000", "0xffffffffffffffff", "0x10000000000000000", "18446744073709551615",
        "18446744073709551616", "0x+1", "0x-1", "+0x1", "-0x1", "true", "TRUE", "fAlSe", "yes",
        "01", "00", "0b1", "1 ", " 1",
    ];

    /// Compares a new conversion with its old reference on `text`: `Ok` floats by their bits.
    fn same<T: PartialEq + std::fmt::Debug>(
        name: &str,
        text: &str,
        new: Result<T, Finding>,
        old: Result<T, Finding>,
    ) {
        assert_eq!(new, old, "{name}({text:?})");
    }

    fn same_float(text: &str) {
        same("float", text, float(text).map(f32::to_bits), old::float(text).map(f32::to_bits));
    }

    fn same_vector2(text: &str) {
        let bits = |v: Vec2| (v.x.to_bits(), v.y.to_bits());
        same("vector2", text, vector2(text).map(bits), old::vector2(text).map(bits));
    }

    fn same_trim(text: &str) {
        assert_eq!(trim_xml(text), old::trim_xml(text), "trim_xml({text:?})");
    }

    /// The float at the start of `bytes` against the old reader, and after 1 to 9 bytes of
    /// something else.
    fn same_prefix(bytes: &[u8]) {
        let bits = |r: Option<(f32, usize)>| r.map(|(v, end)| (v.to_bits(), end));
        let expected = bits(old::exact_float_prefix(bytes));
        let text = String::from_utf8_lossy(bytes);
        assert_eq!(bits(exact_float_from(bytes, 0)), expected, "{text:?}");
        for before in 1..10 {
            let mut padded = b"9.e-, 1234"[..before].to_vec();
            padded.extend_from_slice(bytes);
            let shifted = expected.map(|(v, end)| (v, end + before));
            assert_eq!(bits(exact_float_from(&padded, before)), shifted, "{text:?} after {before}");
        }
    }

    #[test]
    fn the_float_prefix_matches_the_old_one() {
        let alphabet = ["0", "9", "5", ".", "-", "+", "e", "E", " ", "x"];
        for_all_strings(&alphabet, 6, |text| same_prefix(text.as_bytes()));
        // Long runs of digits, across the eights, at every length of text.
        let mut state = 0x2545F4914F6CDD1Du64;
        let mut next = |n: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state % n
        };
        for _ in 0..1_000_000 {
            let mut text = String::from(["", "-", "+"][next(3) as usize]);
            for _ in 0..next(22) {
                text.push(char::from(b'0' + next(10) as u8));
            }
            if next(2) == 0 {
                text.push('.');
                for _ in 0..next(22) {
                    text.push(char::from(b'0' + next(10) as u8));
                }
            }
            if next(2) == 0 {
                text.push(['e', 'E'][next(2) as usize]);
                text.push_str(["", "-", "+"][next(3) as usize]);
                for _ in 0..next(6) {
                    text.push(char::from(b'0' + next(10) as u8));
                }
            }
            text.push_str(
                ["", " 1", ",2", "x", "\t-0.5", ".", ".5", "e-1", "E+05"][next(9) as usize],
            );
            same_prefix(text.as_bytes());
        }
    }

    #[test]
    fn booleans_match_the_old_ones() {
        let same_bool = |text: &str| same("boolean", text, boolean(text), old::boolean(text));
        let alphabet =
            ["t", "T", "r", "R", "u", "U", "e", "E", "f", "F", "a", "A", "l", "L", "s", "S", "1"];
        for_all_strings(&alphabet, 5, same_bool);
        for_all_strings(&["4", "\u{14}", "T", "e", "é", " ", "true"], 4, same_bool);
        for &text in HAND_PICKED {
            same_bool(text);
        }
    }

    #[test]
    fn leading_space_stops_at_the_first_other_byte() {
        let spaces = b" \t\n\r";
        for len in 0..20 {
            for b in 0..=u8::MAX {
                // `len` white space bytes of every kind, `b`, then more white space.
                let mut bytes: Vec<u8> = (0..len).map(|i| spaces[i % 4]).collect();
                bytes.push(b);
                bytes.extend(spaces);
                let expected = match spaces.contains(&b) {
                    true => bytes.len(),
                    false => len,
                };
                assert_eq!(super::leading_space(&bytes), expected, "{bytes:?}");
                assert_eq!(super::leading_space(&bytes[..len]), len);
            }
        }
    }

    #[test]
    fn rewritten_conversions_match_the_old_ones_on_hand_picked_text() {
        for &text in HAND_PICKED {
            same_trim(text);
            same_float(text);
            same_vector2(text);
            // Padded, as the vector's components and untrimmed callers see them.
            for padded in [format!(" {text}"), format!("{text}\t"), format!("\r\n{text} \n")] {
                same_trim(&padded);
                same_float(&padded);
                same_vector2(&padded);
            }
        }
        // Every pair of hand-picked texts, as both vector forms.
        for &a in HAND_PICKED {
            for &b in HAND_PICKED {
                same_vector2(&format!("{a} {b}"));
                same_vector2(&format!("{a},{b}"));
                same_vector2(&format!("{a} , {b}"));
            }
        }
    }

    #[test]
    fn rewritten_conversions_match_the_old_ones_on_every_short_text() {
        let alphabet = ["0", "1", ".", ",", "-", "+", "e", "E", " ", "\t", "\n", "\r", "x"];
        for_all_strings(&alphabet, 5, |text| {
            same_trim(text);
            same_float(text);
            same_vector2(text);
        });
        let alphabet = ["0", "5", ".", ",", "-", "e", " ", "\t"];
        for_all_strings(&alphabet, 6, |text| {
            same_float(text);
            same_vector2(text);
        });
        // Words and non-ASCII next to numbers.
        let alphabet = ["1", "-", "inf", "NaN", "∞", "é", ",", " ", "e9"];
        for_all_strings(&alphabet, 4, |text| {
            same_trim(text);
            same_float(text);
            same_vector2(text);
        });
    }
}
