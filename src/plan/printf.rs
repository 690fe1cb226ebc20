//! Numbers in reports as C's `printf` spells them with `%g` (six significant digits),
//! `%.9g` (nine: every `f32` reads back exact) and `%f` (six decimals, C++'s
//! `std::to_string`), so that a plan's messages are the texts the executors' reports always
//! had.

use std::fmt;

/// A value spelled as `%g`.
#[derive(Clone, Copy, Debug)]
pub struct G(pub f32);

/// A value spelled as `%.9g`.
#[derive(Clone, Copy, Debug)]
pub struct G9(pub f32);

/// A double spelled as `%.3g` (a magnitude a report only sketches).
#[derive(Clone, Copy, Debug)]
pub struct G3(pub f64);

/// A value spelled as `%f`.
#[derive(Clone, Copy, Debug)]
pub struct F(pub f32);

impl fmt::Display for G {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&general(f64::from(self.0), 6))
    }
}

impl fmt::Display for G9 {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&general(f64::from(self.0), 9))
    }
}

impl fmt::Display for G3 {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&general(self.0, 3))
    }
}

impl fmt::Display for F {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let value = f64::from(self.0);
        if value.is_finite() { write!(f, "{value:.6}") } else { f.write_str(&general(value, 6)) }
    }
}

/// `%.{precision}g`: the exponent form where the exponent is below -4 or not below the
/// precision, else the fixed form, trailing zeros removed from either.
fn general(value: f64, precision: usize) -> String {
    if value.is_nan() {
        return if value.is_sign_negative() { "-nan" } else { "nan" }.to_owned();
    }
    if value.is_infinite() {
        return if value < 0.0 { "-inf" } else { "inf" }.to_owned();
    }
    // Rounded to the precision first: the exponent of the rounded value decides the form.
    let scientific = format!("{:.*e}", precision - 1, value);
    let (mantissa, exponent) = scientific.split_once('e').expect("{:e} writes an exponent");
    let exponent: i32 = exponent.parse().expect("{:e} writes an integer exponent");
    if exponent < -4 || exponent >= precision as i32 {
        let sign = if exponent < 0 { '-' } else { '+' };
        format!("{}e{sign}{:02}", trimmed(mantissa), exponent.unsigned_abs())
    } else {
        let decimals = (precision as i32 - 1 - exponent) as usize;
        trimmed(&format!("{value:.decimals$}")).to_owned()
    }
}

fn trimmed(digits: &str) -> &str {
    if digits.contains('.') { digits.trim_end_matches('0').trim_end_matches('.') } else { digits }
}

#[cfg(test)]
mod tests {
    use super::*;

    // Each pair is what glibc's printf writes for the value.
    #[test]
    fn six_digits_as_printf_writes_them() {
        for (value, text) in [
            (0.0, "0"),
            (-0.0, "-0"),
            (0.005, "0.005"),
            (0.02, "0.02"),
            (1e4, "10000"),
            (1e5, "100000"),
            (1e6, "1e+06"),
            (1e-12, "1e-12"),
            (1e20, "1e+20"),
            (1.5e3, "1500"),
            (3.1104877, "3.11049"),
            (0.0001, "0.0001"),
            (0.00001, "1e-05"),
            (123456.7, "123457"),
            (999999.5, "1e+06"),
            (f32::MAX, "3.40282e+38"),
            (f32::INFINITY, "inf"),
            (f32::NEG_INFINITY, "-inf"),
            (f32::NAN, "nan"),
        ] {
            assert_eq!(G(value).to_string(), text, "{value}");
        }
    }

    #[test]
    fn nine_digits_as_printf_writes_them() {
        for (value, text) in [
            (0.1, "0.100000001"),
            (-10.0, "-10"),
            (1e10, "1e+10"),
            (123456789.0, "123456792"),
            (3.14159274, "3.14159274"),
            (1e-5, "9.99999975e-06"),
            (0.5, "0.5"),
            (-1.0e-7, "-1.00000001e-07"),
            (f32::NAN, "nan"),
        ] {
            assert_eq!(G9(value).to_string(), text, "{value}");
        }
    }

    #[test]
    fn three_digits_of_a_double_as_printf_writes_them() {
        for (value, text) in [
            (0.000123456, "0.000123"),
            (1.5e-8, "1.5e-08"),
            (0.1, "0.1"),
            (3.14159, "3.14"),
            (0.0, "0"),
            (1234.0, "1.23e+03"),
        ] {
            assert_eq!(G3(value).to_string(), text, "{value}");
        }
    }

    #[test]
    fn six_decimals_as_printf_writes_them() {
        for (value, text) in [
            (-0.5, "-0.500000"),
            (2.0, "2.000000"),
            (1e-7, "0.000000"),
            (-1e-7, "-0.000000"),
            (f32::NEG_INFINITY, "-inf"),
        ] {
            assert_eq!(F(value).to_string(), text, "{value}");
        }
    }
}
