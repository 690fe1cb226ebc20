//! Any bytes, with load options taken from the input's first bytes (tiny limits included),
//! loaded from memory on one thread, on several, and from a file: the same answer.
#![no_main]

use box2scene::LoadOptions;
use libfuzzer_sys::fuzz_target;

#[path = "same.rs"]
mod same;

fuzz_target!(|data: &[u8]| {
    let Some((&[limits, more], bytes)) = data.split_first_chunk::<2>() else { return };
    // Each limit is either its default or small enough for a fuzzed input to reach.
    let small = |bits: u8, value: u64, default: u64| if limits & bits != 0 { value } else { default };
    let defaults = LoadOptions::default();
    let options = LoadOptions {
        max_input_bytes: small(1, 2048, defaults.max_input_bytes),
        max_elements: small(2, 40, defaults.max_elements),
        max_text_bytes: small(4, u64::from(more >> 1) + 1, defaults.max_text_bytes),
        max_depth: small(8, 4, defaults.max_depth.into()) as u32,
        max_chain_vertices: small(16, 3, defaults.max_chain_vertices.into()) as u32,
        strict: more & 1 != 0,
        threads: 0,
    };
    same::check(bytes, &options);
});
