//! Numbers as the format spells them: the shortest text that reads back to the same
//! `f32`, and integers, without `core::fmt`.

use std::fmt::Write as _;

/// Appends the shortest text that reads back to the same f32 as `value`: plain
/// decimals for ordinary magnitudes, an exponent for tiny and huge ones (as .NET wrote
/// `8.369571E-36`). That is the text `Display` gives for the first and `{:e}` for the
/// others, laid out from ryu's shortest digits, which cost a fraction of `core::fmt`'s.
pub(super) fn push_float(out: &mut String, value: f32) {
    if !value.is_finite() {
        let _ = write!(out, "{value}");
        return;
    }
    if value.is_sign_negative() {
        out.push('-');
    }
    if value == 0.0 {
        out.push('0');
        return;
    }
    let mut buffer = ryu::Buffer::new();
    let text = buffer.format_finite(value.abs());
    let plain = (1e-5..1e16).contains(&value.abs());
    if plain && !text.contains('e') && !may_be_a_tie(value.abs()) {
        // Most values: ryu's own layout is the one wanted, but for its `.0` on whole
        // numbers.
        out.push_str(text.strip_suffix(".0").unwrap_or(text));
        return;
    }
    let mut shortest = Shortest::of(text);
    shortest.break_ties_upwards(value.abs());
    let digits = shortest.digits();
    let point = shortest.point;
    if plain {
        if point <= 0 {
            out.push_str("0.");
            push_zeros(out, -point);
            out.push_str(digits);
        } else if point as usize >= digits.len() {
            out.push_str(digits);
            push_zeros(out, point - digits.len() as i32);
        } else {
            let (whole, fraction) = digits.split_at(point as usize);
            for piece in [whole, ".", fraction] {
                out.push_str(piece);
            }
        }
    } else {
        let (first, rest) = digits.split_at(1);
        out.push_str(first);
        if !rest.is_empty() {
            out.push('.');
            out.push_str(rest);
        }
        out.push('e');
        out.push_str(integer_text(i64::from(point - 1), &mut [0; 20]));
    }
}

fn push_zeros(out: &mut String, count: i32) {
    for _ in 0..count {
        out.push('0');
    }
}

/// `value` in decimal, in `buffer`.
pub(super) fn integer_text(value: i64, buffer: &mut [u8; 20]) -> &str {
    let mut at = buffer.len();
    let mut rest = value.unsigned_abs();
    loop {
        at -= 1;
        buffer[at] = b'0' + (rest % 10) as u8;
        rest /= 10;
        if rest == 0 {
            break;
        }
    }
    if value < 0 {
        at -= 1;
        buffer[at] = b'-';
    }
    std::str::from_utf8(&buffer[at..]).unwrap_or_default()
}

/// A positive float as m x 2^e.
fn binary(value: f32) -> (u128, i32) {
    let bits = value.to_bits();
    let (fraction, biased) = (u128::from(bits & 0x7f_ffff), (bits >> 23) & 0xff);
    match biased {
        0 => (fraction, -149),
        _ => (fraction | 1 << 23, biased as i32 - 150),
    }
}

/// Whether a positive float could lie half way between two texts of its shortest
/// length. A tie has at most 10 digits, so its exact value is a fraction over at most
/// 2^14 (5^k digits need 2^k below them).
fn may_be_a_tie(value: f32) -> bool {
    let (m, e) = binary(value);
    -e - m.trailing_zeros() as i32 <= 14
}

/// A positive float's shortest digits, without leading or trailing zeros, and where
/// its decimal point goes: the value is 0.`digits` x 10^`point`.
struct Shortest {
    digits: [u8; 32],
    len: usize,
    point: i32,
}

impl Shortest {
    /// Reads them from ryu's text, whichever of its layouts (`1e-7`, `1.5e20`,
    /// `0.001`, `12.5`, `100.0`) it chose.
    fn of(text: &str) -> Self {
        let text = text.as_bytes();
        let (mantissa, exponent) = match text.iter().position(|&b| b == b'e') {
            Some(e) => (&text[..e], Self::exponent(&text[e + 1..])),
            None => (text, 0),
        };
        let dot = mantissa.iter().position(|&b| b == b'.').unwrap_or(mantissa.len());
        let mut shortest = Shortest { digits: [0; 32], len: 0, point: exponent };
        for (at, &b) in mantissa.iter().enumerate().filter(|&(_, &b)| b != b'.') {
            if b == b'0' && shortest.len == 0 {
                continue;
            }
            if shortest.len == 0 {
                shortest.point += dot as i32 - at as i32 + i32::from(at > dot);
            }
            shortest.digits[shortest.len] = b;
            shortest.len += 1;
        }
        while shortest.len > 1 && shortest.digits[shortest.len - 1] == b'0' {
            shortest.len -= 1;
        }
        shortest
    }

    /// `core::fmt` breaks a tie between two shortest texts upwards, ryu to the even
    /// last digit: moves ryu's digits of `value` up where the two differ.
    fn break_ties_upwards(&mut self, value: f32) {
        let last = self.digits[self.len - 1] - b'0';
        if last % 2 == 1 || !self.is_just_below_half_way(value) {
            return;
        }
        self.digits[self.len - 1] += 1;
    }

    /// Whether `value` lies exactly half way between these digits and the next ones
    /// up, compared as integers: m x 2^e against (10 x digits + 5) x 10^q. Where a side
    /// overflows u128 the two differ.
    fn is_just_below_half_way(&self, value: f32) -> bool {
        if !may_be_a_tie(value) {
            return false;
        }
        let (m, e) = binary(value);
        let digits = self.digits().bytes().fold(0u128, |n, d| n * 10 + u128::from(d - b'0'));
        let q = self.point - self.len as i32 - 1;
        let times = |n: u128, base: u128, power: i32| {
            base.checked_pow(power.max(0) as u32).and_then(|p| n.checked_mul(p))
        };
        let left = times(m, 2, e).and_then(|n| times(n, 10, -q));
        let right = times(digits * 10 + 5, 10, q).and_then(|n| times(n, 2, -e));
        matches!((left, right), (Some(l), Some(r)) if l == r)
    }

    fn exponent(text: &[u8]) -> i32 {
        let (negative, digits) = match text {
            [b'-', digits @ ..] => (true, digits),
            _ => (false, text),
        };
        let magnitude = digits.iter().fold(0, |n, &d| n * 10 + i32::from(d - b'0'));
        if negative { -magnitude } else { magnitude }
    }

    fn digits(&self) -> &str {
        std::str::from_utf8(&self.digits[..self.len]).unwrap_or_default()
    }
}
