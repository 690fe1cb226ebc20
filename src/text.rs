//! Every text-to-value conversion of the format (docs/format.md, "Text, names and values").
//! Each takes the element's text, already trimmed, and returns the value or a [`Finding`]
//! whose `at` is the byte offset, within that text, of the offending part.
#![forbid(unsafe_code)]

use crate::bytes::{is_xml_space_byte, xml_trimmed_span};
use crate::error::{Code, Finding};
use crate::scene::Vec2;

fn bad(code: Code, at: usize, message: impl Into<String>) -> Finding {
    Finding::new(code, at, message)
}

/// XML white space (not Unicode's), for `trim_*_matches`.
pub(crate) const XML_SPACE: [char; 4] = [' ', '\t', '\r', '\n'];

/// `s` without leading and trailing XML white space, and where that starts in `s`. The
/// white space is ASCII, so the cut points are always character boundaries.
pub fn trim_xml_at(s: &str) -> (usize, &str) {
    let (start, end) = xml_trimmed_span(s.as_bytes());
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
        float(trimmed).map_err(|e| Finding { at: e.at.map_offset(|o| at + lead + o), ..e })
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
mod tests;
