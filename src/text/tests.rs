use super::*;
use crate::error::Spot;

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
    let mut random = crate::Xorshift(0x2545F4914F6CDD1D);
    let mut next = |n: u64| random.next() % n;
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
    assert_eq!((e.code, e.at), (Code::InvalidVector2, Spot::offset(0)));
    assert_eq!(vector2("1 2 3").unwrap_err().code, Code::InvalidVector2);
    let e = vector2("1,,2").unwrap_err();
    assert_eq!(e.code, Code::InvalidVector2);
    let e = vector2("1, x").unwrap_err();
    assert_eq!((e.code, e.at), (Code::InvalidFloat, Spot::offset(3)));
    assert_eq!(vector2("0,5 1,5").unwrap_err().code, Code::FloatDecimalComma);
    for (text, comma) in [("0,5 -20", 1), ("0 -9,82", 4), ("1,5\t2", 1)] {
        let e = vector2(text).unwrap_err();
        assert_eq!((e.code, e.at), (Code::FloatDecimalComma, Spot::offset(comma)), "{text}");
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
        let well_formed =
            s.bytes().all(|b| b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'+' | b'-'));
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
        if (parts.len() > 2 && s.contains(',') && s.contains(is_xml_space)) || one_decimal_comma {
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
                return Err(bad(Code::InvalidVector2, at, format!("'{s}' has an empty component")));
            }
            float(part).map_err(|e| Finding { at: e.at.map_offset(|o| at + lead + o), ..e })
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
            while let Some(digit) = bytes.get(*i).map(|b| b.wrapping_sub(b'0')).filter(|&d| d < 10)
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
            let exponent =
                bytes[i..i + exponent_digits].iter().fold(0, |e, &b| e * 10 + i32::from(b - b'0'));
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
    let mut random = crate::Xorshift(0x2545F4914F6CDD1D);
    let mut next = |n: u64| random.next() % n;
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
        text.push_str(["", " 1", ",2", "x", "\t-0.5", ".", ".5", "e-1", "E+05"][next(9) as usize]);
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
