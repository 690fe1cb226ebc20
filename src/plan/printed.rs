//! Floats in a report's message as C's `printf` spells them, so that a plan's messages read
//! as the executors' always have: `%.9g` for a value (every digit that tells it from its
//! neighbours), `%g` for a bound (as short as it reads), `%f` where C++'s `std::to_string`
//! was used.

use std::fmt;

/// `%.9g` of the value (as C promotes a float to double).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Exact(pub f32);

/// `%g`: six significant digits.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Short(pub f32);

/// `%f`: six decimals.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Fixed(pub f32);

impl fmt::Display for Exact {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        general(f, f64::from(self.0), 9)
    }
}

impl fmt::Display for Short {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        general(f, f64::from(self.0), 6)
    }
}

impl fmt::Display for Fixed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match special(f64::from(self.0)) {
            Some(text) => f.write_str(text),
            None => write!(f, "{:.6}", self.0),
        }
    }
}

/// glibc's spelling of what has no digits.
fn special(v: f64) -> Option<&'static str> {
    match (v.is_nan(), v.is_infinite(), v.is_sign_negative()) {
        (true, _, false) => Some("nan"),
        (true, _, true) => Some("-nan"),
        (_, true, false) => Some("inf"),
        (_, true, true) => Some("-inf"),
        _ => None,
    }
}

/// `%.{precision}g`: the exponent of the value rounded to `precision` digits chooses
/// between fixed and scientific notation; trailing zeros go.
fn general(f: &mut fmt::Formatter<'_>, v: f64, precision: usize) -> fmt::Result {
    if let Some(text) = special(v) {
        return f.write_str(text);
    }
    let scientific = format!("{:.*e}", precision - 1, v);
    let (mantissa, exponent) = scientific.split_once('e').expect("`{:e}` has an exponent");
    let exponent: i32 = exponent.parse().expect("`{:e}` gives a decimal exponent");
    if (-4..precision as i32).contains(&exponent) {
        let decimals = (precision as i32 - 1 - exponent) as usize;
        return f.write_str(without_trailing_zeros(&format!("{v:.decimals$}")));
    }
    let sign = if exponent < 0 { '-' } else { '+' };
    write!(f, "{}e{sign}{:02}", without_trailing_zeros(mantissa), exponent.unsigned_abs())
}

fn without_trailing_zeros(text: &str) -> &str {
    if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.') } else { text }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_gives_nine_significant_digits_as_printf_does() {
        let cases = [
            (0.1f32, "0.100000001"),
            (1.0, "1"),
            (-2.5, "-2.5"),
            (0.0, "0"),
            (-0.0, "-0"),
            (1e-5, "9.99999975e-06"),
            (0.0001, "9.99999975e-05"),
            (123456789.0, "123456792"),
            (1e9, "1e+09"),
            (3.4028235e38, "3.40282347e+38"),
            (1e-40, "9.9999461e-41"),
            (f32::INFINITY, "inf"),
            (f32::NEG_INFINITY, "-inf"),
            (f32::NAN, "nan"),
        ];
        for (v, text) in cases {
            assert_eq!(Exact(v).to_string(), text, "{v}");
        }
    }

    #[test]
    fn short_and_fixed_round_as_printf_does() {
        assert_eq!(Short(1e6).to_string(), "1e+06");
        assert_eq!(Short(100000.0).to_string(), "100000");
        assert_eq!(Short(0.5).to_string(), "0.5");
        assert_eq!(Short(1e-4).to_string(), "0.0001");
        assert_eq!(Short(3.4028235e38).to_string(), "3.40282e+38");
        assert_eq!(Short(0.00001).to_string(), "1e-05");
        assert_eq!(Fixed(-0.5).to_string(), "-0.500000");
        assert_eq!(Fixed(2.0).to_string(), "2.000000");
    }
}
