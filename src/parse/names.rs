//! Element names. Nearly every name has at most 16 bytes and is kept in one 128-bit
//! number, so that reading it, matching its end tag and looking it up among an object's
//! known elements take a few integer operations instead of byte loops.

/// The most bytes a name kept in one number has.
pub(super) const SHORT: usize = 16;

/// An element name.
#[derive(Clone)]
pub(super) enum Name {
    /// A name of at most [`SHORT`] bytes, none of them a control character or a space:
    /// how many, and its bytes in order, then zeros.
    Short(u8, [u8; SHORT]),
    Long(Box<str>),
}

impl Name {
    pub fn new(name: &str) -> Name {
        let mut short = [0; SHORT];
        match short.get_mut(..name.len()) {
            Some(bytes) if name.bytes().all(|b| b > b' ') => {
                bytes.copy_from_slice(name.as_bytes());
                Name::Short(name.len() as u8, short)
            }
            _ => Name::Long(name.into()),
        }
    }

    /// The name made of the first `len` bytes of `head`, which a caller found to be one.
    #[inline]
    pub fn from_head(head: &[u8; SHORT], len: usize) -> Name {
        let bytes = u128::from_le_bytes(*head) & low_bytes(len);
        Name::Short(len as u8, bytes.to_le_bytes())
    }

    #[inline]
    pub fn len(&self) -> usize {
        match self {
            Name::Short(len, _) => usize::from(*len),
            Name::Long(name) => name.len(),
        }
    }

    pub fn as_bytes(&self) -> &[u8] {
        match self {
            Name::Short(len, bytes) => &bytes[..usize::from(*len)],
            Name::Long(name) => name.as_bytes(),
        }
    }

    pub fn as_str(&self) -> &str {
        // Whole names are copied, so the bytes are text.
        std::str::from_utf8(self.as_bytes()).unwrap_or_default()
    }

    /// The name with ASCII letters folded to lower case; 0 for a long name, which no
    /// known element has.
    #[inline]
    pub fn key(&self) -> u128 {
        match self {
            Name::Short(len, bytes) => fold(u128::from_le_bytes(*bytes), usize::from(*len)),
            Name::Long(_) => 0,
        }
    }

    /// How long this name's usual end tag `</Name>` is, when `text` starts with it. A short
    /// name of at most 13 bytes has its end tag in 16 bytes: one comparison of a number.
    #[inline(always)]
    pub fn end_tag_len(&self, text: &[u8]) -> Option<usize> {
        if let (Name::Short(len @ ..=13, bytes), Some(head)) = (self, text.first_chunk::<SHORT>()) {
            let len = usize::from(*len);
            let end_tag = u128::from_le_bytes(*bytes) << 16 | END_TAGS[len];
            return (u128::from_le_bytes(*head) & low_bytes(len + 3) == end_tag).then_some(len + 3);
        }
        match text {
            [b'<', b'/', after @ ..] if self.ends(after) => Some(3 + self.len()),
            _ => None,
        }
    }

    /// Whether `after_slash`, the text after `</`, is this name and `>`: the usual end tag.
    #[inline]
    pub fn ends(&self, after_slash: &[u8]) -> bool {
        let len = self.len();
        match (self, after_slash.first_chunk::<SHORT>()) {
            (Name::Short(_, bytes), Some(head)) => {
                u128::from_le_bytes(*head) & low_bytes(len) == u128::from_le_bytes(*bytes)
                    && after_slash.get(len) == Some(&b'>')
            }
            _ => after_slash.get(len) == Some(&b'>') && after_slash.starts_with(self.as_bytes()),
        }
    }
}

impl std::fmt::Display for Name {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// The key of a known element's name, as [`Name::key`] gives it for that name in any case.
/// Known names are ASCII letters and digits, at most [`SHORT`] of them.
#[inline]
pub(super) const fn key(name: &str) -> u128 {
    let bytes = name.as_bytes();
    assert!(bytes.len() <= SHORT, "a known element name has at most 16 bytes");
    let mut raw = 0u128;
    let mut i = bytes.len();
    while i > 0 {
        i -= 1;
        assert!(bytes[i].is_ascii_alphanumeric(), "known element names are letters and digits");
        raw = raw << 8 | bytes[i] as u128;
    }
    fold(raw, bytes.len())
}

/// Sets bit 5 of each of the first `len` bytes: that makes ASCII letters lower case and
/// leaves digits as they are. Another byte of a short name could only meet a letter or a
/// digit of a known name this way if it were a control character, which short names
/// never hold, or a byte of 0x80 or above, which a known name never has.
const fn fold(bytes: u128, len: usize) -> u128 {
    bytes | (u128::from_le_bytes([0x20; SHORT]) & low_bytes(len))
}

/// A mask of the first `len` bytes (`len` at most [`SHORT`]).
const fn low_bytes(len: usize) -> u128 {
    LOW_BYTES[len]
}

/// The end tag of a name of each length up to 13 without the name: `</`, then zeros where
/// the name goes, then `>`.
const END_TAGS: [u128; SHORT - 2] = {
    let mut tags = [0; SHORT - 2];
    let mut len = 0;
    while len < SHORT - 2 {
        tags[len] = (b'<' as u128) | (b'/' as u128) << 8 | (b'>' as u128) << (8 * (len + 2));
        len += 1;
    }
    tags
};

const LOW_BYTES: [u128; SHORT + 1] = {
    let mut masks = [u128::MAX; SHORT + 1];
    let mut len = 0;
    while len < SHORT {
        masks[len] = (1 << (8 * len)) - 1;
        len += 1;
    }
    masks
};

/// The known elements of one kind of object, as an enum: see [`elements!`].
pub(crate) trait Element: Copy + 'static {
    /// Their names, in the order of the variants.
    const NAMES: &'static Names;
    /// The variants, in order.
    const ALL: &'static [Self];

    fn index(self) -> usize;

    /// The element's name as the format spells it (files may use any case).
    fn name(self) -> &'static str {
        Self::NAMES.names[self.index()]
    }
}

/// Declares the known elements of one kind of object: an enum whose variants are named as
/// the elements are, in the order writers list them, and its [`Element`] table.
macro_rules! elements {
    ($(#[$meta:meta])* $vis:vis enum $Enum:ident { $($Variant:ident),+ $(,)? }) => {
        $(#[$meta])*
        #[derive(Clone, Copy, PartialEq, Eq, Debug)]
        $vis enum $Enum {
            $($Variant),+
        }

        impl $crate::parse::names::Element for $Enum {
            const NAMES: &'static $crate::parse::names::Names =
                &$crate::parse::names::Names::new(&[$(stringify!($Variant)),+]);
            const ALL: &'static [Self] = &[$($Enum::$Variant),+];

            fn index(self) -> usize {
                self as usize
            }
        }
    };
}
pub(super) use elements;

/// The known elements of an object, in the order writers list them, with their keys, and a
/// table that finds an element from its key in one probe.
pub(crate) struct Names {
    pub names: &'static [&'static str],
    keys: [u128; Names::MOST],
    /// The multiplier of [`Names::slot`] under which no two keys share a slot.
    multiplier: u64,
    /// For each slot, the index of the key hashed to it plus one; 0 for none.
    slots: [u8; Names::SLOTS],
}

impl Names {
    /// The most elements an object has (a joint's, with Farseer's spellings).
    const MOST: usize = 64;
    /// Slots of the table: with 64 keys at most in 1024 slots, a multiplier without
    /// collisions is found within a few tries.
    const SLOTS: usize = 1024;

    pub const fn new(names: &'static [&'static str]) -> Names {
        assert!(names.len() <= Names::MOST);
        let mut keys = [0; Names::MOST];
        let mut i = 0;
        while i < names.len() {
            keys[i] = key(names[i]);
            // Distinct keys: an element is then the same wherever the search starts.
            let mut j = 0;
            while j < i {
                assert!(keys[j] != keys[i], "two known elements differ only in case");
                j += 1;
            }
            i += 1;
        }
        // Odd multipliers from a fixed sequence, until one spreads the keys apart.
        let mut multiplier = 0x9E37_79B9_7F4A_7C15u64;
        loop {
            let mut slots = [0u8; Names::SLOTS];
            let mut i = 0;
            while i < names.len() {
                let slot = Names::slot(keys[i], multiplier);
                if slots[slot] != 0 {
                    break;
                }
                slots[slot] = i as u8 + 1;
                i += 1;
            }
            if i == names.len() {
                return Names { names, keys, multiplier, slots };
            }
            multiplier =
                multiplier.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407) | 1;
        }
    }

    /// The slot of `key` under `multiplier`: the top bits of the product of the key's two
    /// halves folded together.
    #[inline(always)]
    const fn slot(key: u128, multiplier: u64) -> usize {
        let folded = key as u64 ^ (key >> 64) as u64;
        (folded.wrapping_mul(multiplier) >> (64 - Names::SLOTS.trailing_zeros())) as usize
    }

    /// The index of the element whose key is `key`.
    #[inline]
    pub fn find(&self, key: u128) -> Option<usize> {
        let index = usize::from(self.slots[Names::slot(key, self.multiplier)]).checked_sub(1)?;
        (self.keys[index] == key).then_some(index)
    }
}

/// The known name nearest `name` in spelling (letters compared in any case), for a "did
/// you mean" hint: one whose edit distance, counting a swap of two neighbouring letters as
/// one edit, is at most a third of the longer name's length (and at least 1), the first
/// of the nearest in `known`'s order. None when no name is that near, and for a name
/// longer than any known one could be near.
pub(crate) fn nearest<'k>(name: &str, known: &[&'k str]) -> Option<&'k str> {
    const LONGEST: usize = 2 * SHORT;
    let name = name.as_bytes();
    if name.is_empty() || name.len() > LONGEST {
        return None;
    }
    let mut best: Option<(usize, &str)> = None;
    for &candidate in known {
        let bound = name.len().max(candidate.len()).max(3) / 3;
        if candidate.len() > LONGEST || name.len().abs_diff(candidate.len()) > bound {
            continue;
        }
        let distance = edit_distance(name, candidate.as_bytes());
        if distance <= bound && best.is_none_or(|(d, _)| distance < d) {
            best = Some((distance, candidate));
        }
    }
    best.map(|(_, candidate)| candidate)
}

/// The optimal string alignment distance between `a` and `b` (at most `2 * SHORT` bytes
/// each): insertions, deletions, substitutions and swaps of neighbours, ASCII letters
/// equal in any case.
fn edit_distance(a: &[u8], b: &[u8]) -> usize {
    const WIDTH: usize = 2 * SHORT + 1;
    let same = |x: u8, y: u8| x.eq_ignore_ascii_case(&y);
    // Three rows of the table: two back, one back, this one.
    let mut rows = [[0usize; WIDTH]; 3];
    for (j, cell) in rows[0].iter_mut().enumerate().take(b.len() + 1) {
        *cell = j;
    }
    for i in 1..=a.len() {
        let (back2, back1, row) = ((i + 1) % 3, (i + 2) % 3, i % 3);
        rows[row][0] = i;
        for j in 1..=b.len() {
            let cost = usize::from(!same(a[i - 1], b[j - 1]));
            let mut d =
                (rows[back1][j] + 1).min(rows[row][j - 1] + 1).min(rows[back1][j - 1] + cost);
            if i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]) {
                d = d.min(rows[back2][j - 2] + 1);
            }
            rows[row][j] = d;
        }
    }
    rows[a.len() % 3][b.len()]
}

#[cfg(test)]
mod tests;
