//! The byte finders of the crate, every scan over raw bytes in one place: the characters
//! XML forbids, XML white space (exactly, for any text; and in one comparison a byte, for
//! the text a load reads, which holds no other control character), the ends of names, text
//! with no reference or carriage return, and the masks of a block for the scan stage.
//! Word-at-a-time tricks and vector instructions live here and nowhere else.
#![forbid(unsafe_code)]

/// The offset of the first character of `text` outside XML's Char production (the writer
/// and the builder check names with it too). Blocks of 64 bytes are screened by loops the
/// compiler vectorises for a suspect byte: a control character other than tab, line feed
/// and carriage return, or 0xEF (which begins U+FFFE and U+FFFF, and no other character
/// before U+F000). Only a block with one is looked at byte by byte; the usual file, with
/// no control characters and few characters from U+F000 on, has few.
pub(crate) fn first_non_char(text: &[u8]) -> Option<usize> {
    let non_char = |&i: &usize| match text[i] {
        0xEF => matches!(text[i + 1..], [0xBF, 0xBE | 0xBF, ..]),
        b => b < 0x20 && !matches!(b, b'\t' | b'\n' | b'\r'),
    };
    let mut from = 0;
    while let Some(block) = text[from..].first_chunk::<64>() {
        // Line feeds are in most blocks; tabs, carriage returns and bytes past ASCII (below
        // 0x20 too, as signed bytes) in few. So a first look, with fewer comparisons, lets
        // only line feeds through, and only the few blocks it stops get the full look.
        let rare = |b: u8| ((b as i8) < 0x20) & (b != b'\n');
        let suspect =
            |b: u8| ((b < 0x20) & (b != b'\t') & (b != b'\n') & (b != b'\r')) | (b == 0xEF);
        if block.iter().fold(false, |any, &b| any | rare(b))
            && block.iter().fold(false, |any, &b| any | suspect(b))
            && let Some(at) = (from..from + block.len()).find(non_char)
        {
            return Some(at);
        }
        from += block.len();
    }
    (from..text.len()).find(non_char)
}

/// XML white space, as a byte of UTF-8 text. All four are ASCII, so a byte that matches is a
/// whole character and the text can be sliced next to it.
pub(crate) fn is_xml_space_byte(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | b'\n')
}

/// How many bytes of XML white space `bytes` starts with, looking at eight at a time:
/// indentation before a tag is often longer than that. Exact for any bytes (see
/// [`space_len`] for the text a load reads).
pub(crate) fn xml_space_len(bytes: &[u8]) -> usize {
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
fn bytes_equal(word: u64, b: u8) -> u64 {
    zero_bytes(word ^ u64::from_le_bytes([b; 8]))
}

/// The high bit of each byte of `word` that is zero. Exact for every byte (no borrow
/// crosses from one byte to the next, as it can in the shorter formula).
fn zero_bytes(word: u64) -> u64 {
    let low = !HIGH_BITS;
    !(((word & low) + low) | word) & HIGH_BITS
}

/// Where `bytes` without leading and trailing XML white space starts and ends.
pub(crate) fn xml_trimmed_span(bytes: &[u8]) -> (usize, usize) {
    let start = xml_space_len(bytes);
    let end = bytes.iter().rposition(|&b| !is_xml_space_byte(b)).map_or(start, |i| i + 1);
    (start, end)
}

/// ASCII letters, digits, `_`, `:`, `-` and `.`: the names of attributes read without
/// quick-xml.
pub(crate) const fn is_plain_name_byte(b: u8) -> bool {
    b.is_ascii_alphanumeric() || matches!(b, b'_' | b':' | b'-' | b'.')
}

/// How many bytes at the start of `text` are [`is_plain_name_byte`]: one look-up a byte
/// rather than its five comparisons.
#[inline(always)]
pub(crate) fn plain_name_len(text: &[u8]) -> usize {
    const PLAIN: [bool; 256] = {
        let mut plain = [false; 256];
        let mut b = 0;
        while b < 256 {
            plain[b] = is_plain_name_byte(b as u8);
            b += 1;
        }
        plain
    };
    text.iter().position(|&b| !PLAIN[usize::from(b)]).unwrap_or(text.len())
}

/// The bytes that end the value of an attribute read without quick-xml: either quote, and
/// what it leaves to quick-xml (`&`, `<`, a tab or a line break, which it normalises).
pub(crate) const ENDS_PLAIN_VALUE: [bool; 256] = {
    let mut ends = [false; 256];
    let stops = *b"\"'&<\t\n\r";
    let mut k = 0;
    while k < stops.len() {
        ends[stops[k] as usize] = true;
        k += 1;
    }
    ends
};

/// The bytes that end a name in the usual tags: white space (and the control characters,
/// which no name has), `/`, `>` and quotes.
pub(crate) const ENDS_NAME: [bool; 256] = {
    let mut ends = [false; 256];
    let mut b = 0;
    while b <= b' ' {
        ends[b as usize] = true;
        b += 1;
    }
    ends[b'/' as usize] = true;
    ends[b'>' as usize] = true;
    ends[b'"' as usize] = true;
    ends[b'\'' as usize] = true;
    ends
};

/// How long the name a usual tag's first sixteen bytes after its `<` begin with is: the
/// index of the first byte that ends a name there (see [`ENDS_NAME`]), or of a byte from
/// `!` to `&`, which no XML name holds (a name that has one is read by the general path);
/// None when none of the sixteen does. With SSE2, the sixteen bytes are looked at in a few
/// instructions: a look at one byte at a time cost a load 0.7 instructions a byte more.
#[inline(always)]
pub(crate) fn short_name_len(head: &[u8; 16]) -> Option<usize> {
    #[cfg(target_arch = "x86_64")]
    {
        use safe_arch::{
            bitor_m128i, cmp_eq_mask_i8_m128i, load_unaligned_m128i, max_u8_m128i,
            move_mask_i8_m128i, set_splat_i8_m128i,
        };
        let v = load_unaligned_m128i(head);
        let splat = |b: u8| set_splat_i8_m128i(b as i8);
        // Up to `'`: the bytes the unsigned maximum with it leaves as `'`.
        let low = cmp_eq_mask_i8_m128i(max_u8_m128i(v, splat(b'\'')), splat(b'\''));
        let marks =
            bitor_m128i(cmp_eq_mask_i8_m128i(v, splat(b'/')), cmp_eq_mask_i8_m128i(v, splat(b'>')));
        let ends = move_mask_i8_m128i(bitor_m128i(low, marks)) as u32;
        (ends != 0).then(|| ends.trailing_zeros() as usize)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        head.iter().position(|&b| b <= b'\'' || b == b'/' || b == b'>')
    }
}

/// How many bytes of white space the text at hand `text` starts with. Every byte of it up to
/// 0x20 is white space, as the source stops before any other control character
/// ([`first_non_char`]): so the test is one comparison a byte, made eight at a time. For
/// text nothing checked, [`xml_space_len`].
#[inline(always)]
pub(crate) fn space_len(text: &[u8]) -> usize {
    if text.first().is_none_or(|&b| b > b' ') {
        return 0;
    }
    const OVER_SPACE: u64 = u64::from_le_bytes([0x80 - 0x21; 8]);
    let mut i = 0;
    while let Some(eight) = text[i..].first_chunk::<8>() {
        let word = u64::from_le_bytes(*eight);
        // The high bit of each byte above 0x20: the low seven bits plus 0x5F reach 0x80
        // from 0x21 on and never carry out of their byte (0x7F + 0x5F < 0x100); a byte of
        // 0x80 or more has it already.
        let other = (((word & !HIGH_BITS) + OVER_SPACE) | word) & HIGH_BITS;
        if other != 0 {
            return i + (other.trailing_zeros() / 8) as usize;
        }
        i += 8;
    }
    i + text[i..].iter().position(|&b| b > b' ').unwrap_or(text.len() - i)
}

/// Where the text at hand `text` without leading and trailing white space starts and ends
/// (see [`space_len`]).
#[inline(always)]
pub(crate) fn trimmed_span(text: &[u8]) -> (usize, usize) {
    let start = space_len(text);
    let end = text.iter().rposition(|&b| b > b' ').map_or(start, |i| i + 1);
    (start, end)
}

/// Whether `text` is plain: no reference (`&`) or carriage return in it, which a reader must
/// resolve or normalise. Values are short: eight bytes at a time, then one at a time.
#[inline]
pub(crate) fn is_plain(text: &[u8]) -> bool {
    let words = text.chunks_exact(8);
    let tail = words.remainder();
    words.flat_map(<[u8; 8]>::try_from).all(|eight| {
        let word = u64::from_le_bytes(eight);
        first_equal(word, b'&') | first_equal(word, b'\r') == 0
    }) && !tail.iter().any(|&b| b == b'&' || b == b'\r')
}

/// Where the first `<` of `text` is: a value's end tag, found in its first sixteen bytes
/// with SSE2 in a few instructions, as it usually is, and with memchr past them.
#[inline(always)]
pub(crate) fn first_lt(text: &[u8]) -> Option<usize> {
    #[cfg(target_arch = "x86_64")]
    if let Some(sixteen) = text.first_chunk::<16>() {
        use safe_arch::{
            cmp_eq_mask_i8_m128i, load_unaligned_m128i, move_mask_i8_m128i, set_splat_i8_m128i,
        };
        let v = load_unaligned_m128i(sixteen);
        let lts = move_mask_i8_m128i(cmp_eq_mask_i8_m128i(v, set_splat_i8_m128i(b'<' as i8)));
        if lts != 0 {
            return Some(lts.trailing_zeros() as usize);
        }
        return memchr::memchr(b'<', &text[16..]).map(|i| 16 + i);
    }
    memchr::memchr(b'<', text)
}

/// Where the first `len` bytes of the text at hand `rest` start and end without leading and
/// trailing white space (see [`trimmed_span`]), when they are plain (see [`is_plain`]): the
/// usual value, which a reader takes as it stands. A value of at most sixteen bytes with
/// sixteen at hand is looked at in one pass with SSE2: its references, carriage returns and
/// white space all at once. (Two passes of sixteen for longer values measured no cheaper
/// than the eight bytes at a time of the others.)
#[inline(always)]
pub(crate) fn plain_trimmed(rest: &[u8], len: usize) -> Option<(usize, usize)> {
    #[cfg(target_arch = "x86_64")]
    if let Some(sixteen) = rest.first_chunk::<16>().filter(|_| len <= 16) {
        use safe_arch::{
            bitor_m128i, cmp_eq_mask_i8_m128i, load_unaligned_m128i, max_u8_m128i,
            move_mask_i8_m128i, set_splat_i8_m128i,
        };
        let v = load_unaligned_m128i(sixteen);
        let splat = |b: u8| set_splat_i8_m128i(b as i8);
        let within = (1u32 << len) - 1;
        let mask = |m| move_mask_i8_m128i(m) as u32 & within;
        let rare = bitor_m128i(
            cmp_eq_mask_i8_m128i(v, splat(b'&')),
            cmp_eq_mask_i8_m128i(v, splat(b'\r')),
        );
        if mask(rare) != 0 {
            return None;
        }
        // Up to 0x20: the bytes the unsigned maximum with a space leaves as a space.
        let space = mask(cmp_eq_mask_i8_m128i(max_u8_m128i(v, splat(b' ')), splat(b' ')));
        let other = !space & within;
        return Some(match other {
            0 => (len, len),
            _ => (other.trailing_zeros() as usize, 32 - other.leading_zeros() as usize),
        });
    }
    let text = &rest[..len];
    is_plain(text).then(|| trimmed_span(text))
}

/// A mask whose lowest set bit is the high bit of the first byte (the lowest, read little
/// endian) of `word` that is `b`; 0 when no byte is. Bits above that one may be set too.
///
/// With `x = word ^ [b; 8]`, the bytes equal to `b` are the zero bytes of `x`, and
/// `(x - 0x01..01) & !x & 0x80..80` flags the lowest of them exactly. Going up from the
/// lowest byte, as long as no borrow comes in: a byte `x_i` that is not zero borrows
/// nothing from the next, and `x_i - 1` has its high bit set only when `x_i` is 0x81 or
/// more, when `!x_i` has not, so it is not flagged; the first zero byte becomes 0xFF, high
/// bit set, with `!x_i` high bit set: flagged. Only past it can a borrow flag a byte that is
/// not zero (0x01 becomes 0xFF). So the masks of several bytes OR-ed together are 0 exactly
/// when no byte is any of them, which is all [`is_plain`] looks at; the exact test
/// ([`bytes_equal`]) takes more instructions for every byte.
#[inline(always)]
pub(crate) fn first_equal(word: u64, b: u8) -> u64 {
    const ONES: u64 = u64::from_le_bytes([0x01; 8]);
    let x = word ^ u64::from_le_bytes([b; 8]);
    x.wrapping_sub(ONES) & !x & HIGH_BITS
}

/// The bytes the scan stage looks at a block at a time.
pub(crate) const BLOCK: usize = 64;

/// The masks of the bytes of `block` that are each of `bytes`: bit `i` of a mask for byte
/// `i`. The block is loaded once for all of them. With SSE2, which every x86-64 machine has,
/// sixteen bytes are compared in one instruction; elsewhere a byte at a time.
#[inline(always)]
pub(crate) fn block_masks<const K: usize>(block: &[u8; BLOCK], bytes: [u8; K]) -> [u64; K] {
    #[cfg(target_arch = "x86_64")]
    {
        use safe_arch::{
            cmp_eq_mask_i8_m128i, load_unaligned_m128i, move_mask_i8_m128i, set_splat_i8_m128i,
        };
        let mut masks = [0; K];
        for (k, sixteen) in block.chunks_exact(16).enumerate() {
            let Ok(sixteen) = <&[u8; 16]>::try_from(sixteen) else { continue };
            let v = load_unaligned_m128i(sixteen);
            for (mask, b) in masks.iter_mut().zip(bytes) {
                let hits = cmp_eq_mask_i8_m128i(v, set_splat_i8_m128i(b as i8));
                *mask |= u64::from(move_mask_i8_m128i(hits) as u16) << (16 * k);
            }
        }
        masks
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        bytes.map(|b| (0..BLOCK).fold(0, |mask, i| mask | u64::from(block[i] == b) << i))
    }
}

#[cfg(test)]
mod tests;
