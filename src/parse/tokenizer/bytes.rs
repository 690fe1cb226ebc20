//! The byte finders of the markup: name ends, white space, trimmed spans.

/// ASCII letters, digits, `_`, `:`, `-` and `.`: the names of attributes read without
/// quick-xml.
pub(super) fn is_plain_name_byte(b: u8) -> bool {
    b.is_ascii_alphanumeric() || matches!(b, b'_' | b':' | b'-' | b'.')
}

/// The bytes that end a name in the usual tags: white space (and the control characters,
/// which no name has), `/`, `>` and quotes.
pub(super) const ENDS_NAME: [bool; 256] = {
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

/// How many bytes of white space the text at hand `text` starts with. Every byte of it up to
/// 0x20 is white space, as the source stops before any other control character: so the
/// test is one comparison a byte, made eight at a time.
#[inline(always)]
pub(super) fn space_len(text: &[u8]) -> usize {
    if text.first().is_none_or(|&b| b > b' ') {
        return 0;
    }
    const HIGH: u64 = u64::from_le_bytes([0x80; 8]);
    const OVER_SPACE: u64 = u64::from_le_bytes([0x80 - 0x21; 8]);
    let mut i = 0;
    while let Some(eight) = text[i..].first_chunk::<8>() {
        let word = u64::from_le_bytes(*eight);
        // The high bit of each byte above 0x20: the low seven bits plus 0x5F reach 0x80
        // from 0x21 on and never carry out of their byte (0x7F + 0x5F < 0x100); a byte of
        // 0x80 or more has it already.
        let other = (((word & !HIGH) + OVER_SPACE) | word) & HIGH;
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
pub(super) fn trimmed_span(text: &[u8]) -> (usize, usize) {
    let start = space_len(text);
    let end = text.iter().rposition(|&b| b > b' ').map_or(start, |i| i + 1);
    (start, end)
}

/// The offset of the first of three bytes in `hay`. Nodes are short: their first 32 bytes
/// are looked at eight at a time, which is cheaper than setting up memchr, which takes the
/// rest.
#[inline]
pub(super) fn find3(hay: &[u8], a: u8, b: u8, c: u8) -> Option<usize> {
    let mut i = 0;
    while let Some(eight) = hay[i..].first_chunk::<8>().filter(|_| i < 32) {
        let word = u64::from_le_bytes(*eight);
        let found = first_equal(word, a) | first_equal(word, b) | first_equal(word, c);
        if found != 0 {
            return Some(i + (found.trailing_zeros() / 8) as usize);
        }
        i += 8;
    }
    memchr::memchr3(a, b, c, &hay[i..]).map(|found| i + found)
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
/// not zero (0x01 becomes 0xFF). So OR-ing the masks of several bytes keeps the first byte
/// equal to any of them as the lowest set bit, which is all [`find3`] looks at; the exact
/// test ([`text::bytes_equal`]) takes more instructions for every byte.
#[inline(always)]
pub(super) fn first_equal(word: u64, b: u8) -> u64 {
    const ONES: u64 = u64::from_le_bytes([0x01; 8]);
    const HIGH: u64 = u64::from_le_bytes([0x80; 8]);
    let x = word ^ u64::from_le_bytes([b; 8]);
    x.wrapping_sub(ONES) & !x & HIGH
}
