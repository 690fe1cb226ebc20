//! The known elements of each kind of object, found by the keys of their names
//! ([`Name::key`](crate::markup::Name::key)) in one probe, and the known name nearest a
//! misspelt one.

use crate::markup::{SHORT, key};

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
