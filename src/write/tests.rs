use super::numbers::push_float;
use crate::holds::escape;

fn float_text(value: f32) -> String {
    let mut out = String::new();
    push_float(&mut out, value);
    out
}

#[test]
fn floats_are_shortest_and_read_back_to_the_same_bits() {
    for (value, text) in [
        (1.0f32, "1"),
        (0.2, "0.2"),
        (-1.2345679, "-1.2345679"),
        (-0.0, "-0"),
        (8.369571e-36, "8.369571e-36"),
        (f32::MAX, "3.4028235e38"),
        (f32::from_bits(1), "1e-45"),
        (1e-5, "0.00001"),
    ] {
        assert_eq!(float_text(value), text);
        assert_eq!(crate::text::float(text).unwrap().to_bits(), value.to_bits(), "{text}");
    }
}

/// The writer's floats before ryu: `core::fmt`'s text, which stays the contract.
fn core_fmt_text(value: f32) -> String {
    let magnitude = value.abs();
    if magnitude == 0.0 || (1e-5..1e16).contains(&magnitude) {
        format!("{value}")
    } else {
        format!("{value:e}")
    }
}

#[test]
fn floats_are_written_as_core_fmt_writes_them() {
    let mut random = crate::Xorshift(0x9e37_79b9_7f4a_7c15);
    let mut random_bits = || random.next() as u32;
    let edges = [0u32, 1, 0x007f_ffff, 0x0080_0000, 0x7f7f_ffff, 0x3f80_0000, 0x4b80_0000]
        .into_iter()
        .chain([1e-5f32, 9.99999e-6, 1e16, 9.999999e15, 0.1, 123_456_790.0].map(f32::to_bits))
        .chain((-45..=38).map(|e| format!("1e{e}").parse::<f32>().unwrap().to_bits()));
    for bits in edges.chain((0..2_000_000).map(|_| random_bits())) {
        for value in [f32::from_bits(bits), -f32::from_bits(bits)] {
            assert_eq!(float_text(value), core_fmt_text(value), "{bits:#x}");
        }
    }
}

/// Every f32, a few minutes in release:
/// `cargo test --release --lib every_float -- --ignored`.
#[test]
#[ignore]
fn every_float_is_written_as_core_fmt_writes_it() {
    std::thread::scope(|scope| {
        for half in [0u32, 1] {
            scope.spawn(move || {
                for bits in (half << 31..=(half << 31 | 0x7fff_ffff)).step_by(1) {
                    let value = f32::from_bits(bits);
                    assert_eq!(float_text(value), core_fmt_text(value), "{bits:#x}");
                }
            });
        }
    });
}

#[test]
fn text_escapes_markup_and_carriage_returns() {
    assert_eq!(escape("a<b & \"c\">\r\né"), "a&lt;b &amp; &quot;c&quot;&gt;&#13;\né");
}
