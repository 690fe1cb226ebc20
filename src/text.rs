//! Every text-to-value conversion of the format (spec section 2). Each takes the element's
//! text, already trimmed, and returns the value or a [`BadValue`] whose `at` is the byte
//! offset, within that text, of the offending part.
#![forbid(unsafe_code)]

use crate::error::Code;
use crate::scene::Vec2;

/// Why a text is not a value of its type.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BadValue {
    pub code: Code,
    pub at: usize,
    pub message: String,
}

fn bad(code: Code, at: usize, message: impl Into<String>) -> BadValue {
    BadValue { code, at, message: message.into() }
}

/// XML white space (not Unicode's).
pub fn is_xml_space(c: char) -> bool {
    matches!(c, ' ' | '\t' | '\r' | '\n')
}

pub fn trim_xml(s: &str) -> &str {
    s.trim_matches(is_xml_space)
}

/// The spellings of infinity and NaN that writers produce (.NET, C, JavaScript).
fn is_non_finite_word(s: &str) -> bool {
    let word = s.trim_start_matches(['+', '-']);
    ["inf", "infinity", "nan", "∞"].iter().any(|w| word.eq_ignore_ascii_case(w))
}

/// A decimal float, read with correct rounding to the nearest f32.
pub fn float(s: &str) -> Result<f32, BadValue> {
    if s.is_empty() {
        return Err(bad(Code::InvalidFloat, 0, "expected a number, found nothing"));
    }
    if is_non_finite_word(s) {
        return Err(bad(Code::NonFiniteFloat, 0, format!("'{s}' is not a finite number")));
    }
    if let Some(comma) = s.find(',') {
        let digits = |t: &str| !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit() || b == b'-');
        if digits(&s[..comma]) && digits(&s[comma + 1..]) {
            return Err(bad(
                Code::FloatDecimalComma,
                comma,
                format!(
                    "'{s}' has a decimal comma: the file was written with a locale that uses \
                     one; numbers must use a decimal point"
                ),
            ));
        }
    }
    let well_formed =
        s.bytes().all(|b| b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'+' | b'-'));
    let value: f32 = match s.parse() {
        Ok(v) if well_formed => v,
        _ => return Err(bad(Code::InvalidFloat, 0, format!("'{s}' is not a number"))),
    };
    if value.is_infinite() {
        return Err(bad(Code::NonFiniteFloat, 0, format!("{s} is too large for a 32-bit float")));
    }
    Ok(value)
}

/// Two floats separated by white space and/or one comma; empty text is (0, 0).
pub fn vector2(s: &str) -> Result<Vec2, BadValue> {
    if s.is_empty() {
        return Ok(Vec2::ZERO);
    }
    let parts: Vec<(usize, &str)> = if s.contains(',') {
        pieces(s, |c| c == ',').collect()
    } else {
        pieces(s, is_xml_space).filter(|(_, part)| !part.is_empty()).collect()
    };
    if parts.len() > 2 && s.contains(',') && s.contains(is_xml_space) {
        let comma = s.find(',').unwrap_or(0);
        return Err(bad(
            Code::FloatDecimalComma,
            comma,
            format!(
                "'{s}' looks like two numbers with decimal commas: the file was written with a \
                 locale that uses one; numbers must use a decimal point"
            ),
        ));
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
            return Err(bad(Code::InvalidVector2, at, format!("'{s}' has an empty component")));
        }
        float(part).map_err(|e| BadValue { at: at + lead + e.at, ..e })
    };
    Ok(Vec2 { x: component(at_x, x)?, y: component(at_y, y)? })
}

/// The parts of `s` between single-byte separators, each with its offset in `s`.
fn pieces(s: &str, is_separator: fn(char) -> bool) -> impl Iterator<Item = (usize, &str)> {
    let mut next = 0;
    s.split(is_separator).map(move |part| {
        let at = next;
        next += part.len() + 1;
        (at, part)
    })
}

/// `true`/`false` in any letter case, or `1`/`0`.
pub fn boolean(s: &str) -> Result<bool, BadValue> {
    if s.eq_ignore_ascii_case("true") || s == "1" {
        Ok(true)
    } else if s.eq_ignore_ascii_case("false") || s == "0" {
        Ok(false)
    } else {
        Err(bad(Code::InvalidBool, 0, format!("'{s}' is not a boolean: expected true or false")))
    }
}

/// Optional sign, decimal digits; 32-bit.
pub fn int(s: &str) -> Result<i32, BadValue> {
    let digits = s.strip_prefix(['+', '-']).unwrap_or(s);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err(bad(Code::InvalidInt, 0, format!("'{s}' is not a whole number")));
    }
    s.parse().map_err(|_| bad(Code::OutOfRange, 0, format!("{s} is out of the 32-bit range")))
}

/// A 16-bit signed int (a group index).
pub fn int16(s: &str) -> Result<i16, BadValue> {
    let value = int(s)?;
    i16::try_from(value)
        .map_err(|_| bad(Code::OutOfRange, 0, format!("{s} is outside -32768..32767")))
}

/// A non-negative index into a container.
pub fn id(s: &str) -> Result<u32, BadValue> {
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

/// Collision bits, decimal or `0x` hexadecimal. Returns the value and whether it had to be
/// truncated to its low 16 bits.
pub fn bits(s: &str) -> Result<(u16, bool), BadValue> {
    let (digits, radix) = match s.strip_prefix("0x").or_else(|| s.strip_prefix("0X")) {
        Some(hex) => (hex, 16),
        None => (s.strip_prefix('+').unwrap_or(s), 10),
    };
    if s.starts_with('-') {
        return Err(bad(Code::InvalidBits, 0, format!("bits {s} are negative")));
    }
    let ok = !digits.is_empty() && digits.chars().all(|c| c.is_digit(radix));
    let value = (ok.then(|| u64::from_str_radix(digits, radix).ok()).flatten())
        .ok_or_else(|| bad(Code::InvalidBits, 0, format!("'{s}' is not a bit mask")))?;
    Ok(((value & 0xFFFF) as u16, value > 0xFFFF))
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
        assert_eq!(int("-32768").unwrap(), -32768);
        assert_eq!(int("3000000000").unwrap_err().code, Code::OutOfRange);
        assert_eq!(int16("40000").unwrap_err().code, Code::OutOfRange);
        assert_eq!(bits("0x00FF").unwrap(), (0xFF, false));
        assert_eq!(bits("65535").unwrap(), (0xFFFF, false));
        assert_eq!(bits("2147483647").unwrap(), (0xFFFF, true));
        assert_eq!(bits("-1").unwrap_err().code, Code::InvalidBits);
    }
}
