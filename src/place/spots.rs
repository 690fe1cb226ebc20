//! Where a later stage may point: a [`Spot`] (a position, or only an offset of a text that
//! stays in memory), and [`Spots`], many of them kept small as [`Step`]s.

use crate::error::{Code, Finding, Position};

/// A [`Spot`] in 8 bytes, as the step to it from the spot before it: how many lines on,
/// its column, how many bytes on (see [`crate::arena::Spots`]). Or, for a spot no step
/// holds, the mark that it is kept aside, with its index there.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Step {
    lines: i16,
    column: u16,
    bytes: i32,
}

impl Step {
    /// The `lines` of the mark of a spot kept aside, which no step has.
    const ASIDE: i16 = i16::MIN;

    /// The mark of the spot kept aside at `index` (below 2^48).
    pub fn aside(index: usize) -> Step {
        let index = index as u64;
        Step { lines: Step::ASIDE, column: (index >> 32) as u16, bytes: index as u32 as i32 }
    }

    /// The index of the spot kept aside that this step marks.
    pub fn aside_index(self) -> Option<usize> {
        let index = (u64::from(self.column) << 32) | u64::from(self.bytes as u32);
        (self.lines == Step::ASIDE).then_some(index as usize)
    }
}

/// Where something a later stage may report is: its position, placed while its text was
/// at hand; or, when the whole text stays in memory, only its offset, placed if a finding
/// ever needs it. Both fit in a [`Position`]: an offset is kept as line 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Spot(Position);

impl Spot {
    /// Offset `at` of a text that stays in memory.
    pub const fn offset(at: usize) -> Spot {
        Spot(Position { line: 0, column: 0, byte_offset: at as u64 })
    }

    pub fn placed(position: Position) -> Spot {
        Spot(position)
    }

    /// This spot, counted from the start of a piece of the text, placed in the whole text
    /// where the piece begins at `start` (see [`Position::after`]); offsets are the whole
    /// text's already.
    pub fn after(self, start: Position) -> Spot {
        match self.0.line {
            0 => self,
            _ => Spot(self.0.after(start)),
        }
    }

    /// This spot as a step from `before`, when a [`Step`] holds it. (Offsets differ by
    /// less than 2^63: a text is at most `isize::MAX` bytes.)
    #[inline]
    pub fn step_from(self, before: Spot) -> Option<Step> {
        let (this, before) = (self.0, before.0);
        let lines = i16::try_from(i64::from(this.line) - i64::from(before.line)).ok()?;
        let bytes = this.byte_offset.wrapping_sub(before.byte_offset) as i64;
        match (lines, u16::try_from(this.column), i32::try_from(bytes)) {
            (Step::ASIDE, ..) | (_, Err(_), _) | (.., Err(_)) => None,
            (lines, Ok(column), Ok(bytes)) => Some(Step { lines, column, bytes }),
        }
    }

    /// The spot `step` leads to from this one.
    #[inline]
    pub fn stepped(self, step: Step) -> Spot {
        Spot(Position {
            line: self.0.line.wrapping_add_signed(step.lines.into()),
            column: step.column.into(),
            byte_offset: self.0.byte_offset.wrapping_add_signed(step.bytes.into()),
        })
    }

    /// A finding here.
    pub fn finding(self, code: Code, message: impl Into<String>) -> Finding {
        match self.0.line {
            0 => Finding::new(code, self.0.byte_offset as usize, message),
            _ => Finding::placed(code, 0, self.0, message),
        }
    }
}

/// Spots in half the memory of a `Vec<Spot>`: a load holds one per object and per
/// reference until it is checked. Each is the [`Step`] to it from the one before, in 8
/// bytes, as a file's spots go, a few lines and bytes apart and in short lines; one no
/// step holds is kept whole aside. They are read in order (a check looks up the few it
/// reports in one pass, see [`Spots::at`]): a piece of the file read on the second thread
/// then carries no small block beside its steps, which the calling thread would let go
/// and keep in its cache of small blocks, high in the helper's heap.
pub(crate) struct Spots {
    steps: Vec<Step>,
    aside: Vec<Spot>,
    /// The last spot, which the next is a step from.
    last: Spot,
}

impl Default for Spots {
    fn default() -> Spots {
        Spots { steps: Vec::new(), aside: Vec::new(), last: Spots::START }
    }
}

impl Spots {
    /// What the first spot is a step from.
    const START: Spot = Spot::offset(0);

    #[inline]
    pub fn push(&mut self, spot: Spot) {
        let before = std::mem::replace(&mut self.last, spot);
        let step = spot.step_from(before).unwrap_or_else(|| {
            self.aside.push(spot);
            Step::aside(self.aside.len() - 1)
        });
        self.steps.push(step);
    }

    pub fn iter(&self) -> impl Iterator<Item = Spot> + '_ {
        self.steps.iter().scan(Spots::START, |spot, &step| {
            *spot = match step.aside_index() {
                Some(index) => self.aside[index],
                None => spot.stepped(step),
            };
            Some(*spot)
        })
    }

    /// The spots at `indices`, in their order, found in one pass over the steps (the start
    /// of the text for an index past the last).
    pub fn at(&self, indices: &[usize]) -> Vec<Spot> {
        let mut order: Vec<usize> = (0..indices.len()).collect();
        order.sort_by_key(|&i| indices[i]);
        let mut found = vec![Spots::START; indices.len()];
        let (mut spots, mut next, mut spot) = (self.iter(), 0, Spots::START);
        for i in order {
            while next <= indices[i] {
                let Some(following) = spots.next() else { return found };
                (spot, next) = (following, next + 1);
            }
            found[i] = spot;
        }
        found
    }

    pub fn clear(&mut self) {
        self.steps.clear();
        self.aside.clear();
        self.last = Spots::START;
    }
}

impl Extend<Spot> for Spots {
    fn extend<I: IntoIterator<Item = Spot>>(&mut self, spots: I) {
        for spot in spots {
            self.push(spot);
        }
    }
}

impl std::fmt::Debug for Spots {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Position;

    /// Every spot comes back as it went in, whether a step from the one before holds it or
    /// it is kept aside: far apart in lines or bytes, back in the file, past 4 GiB, on a
    /// long line, on line `u32::MAX`; in order, and picked in any order.
    #[test]
    fn spots_come_back_as_they_went_in() {
        let at = |line, column, byte_offset| Spot::placed(Position { line, column, byte_offset });
        let big = u64::from(u32::MAX);
        let odd = [
            Spot::offset(0),
            Spot::offset(u32::MAX as usize),
            at(0, 0, big + 1),
            at(1, 1, 0),
            at(7, 3, big),
            at(7, 4, big + (1 << 31)),
            at(7, 4, 1),
            at(u32::MAX, 2, 9),
            at(u32::MAX - 1, u32::MAX, 1 << 40),
            at(40_000, 65_535, 1 << 40),
            at(40_000, 65_536, (1 << 40) + 1),
            at(2, 5, 40),
            at(2 + 32_767, 5, 40 + (1 << 31) - 1),
            at(2, 5, 40),
        ];
        // Ordinary spots a few lines apart, with the odd ones among them.
        let spots: Vec<Spot> = (0..200)
            .flat_map(|i: u32| {
                let ordinary = at(3 * i + 1, i % 90 + 1, u64::from(i) * 97);
                std::iter::once(ordinary).chain(odd.get(i as usize % 20).copied())
            })
            .collect();
        let mut kept = Spots::default();
        kept.extend(spots.iter().copied().filter(|s| !odd.contains(s)));
        assert!(kept.aside.is_empty(), "{} aside", kept.aside.len());
        kept.clear();
        kept.extend(spots.iter().copied());
        assert_eq!(kept.iter().collect::<Vec<_>>(), spots);
        let picked = [spots.len() - 1, 3, 0, 3, 200, 17];
        assert_eq!(kept.at(&picked), picked.map(|k| spots[k]));
        assert_eq!(kept.at(&[]), []);
        assert_eq!(format!("{kept:?}"), format!("{spots:?}"));

        kept.clear();
        assert_eq!(kept.iter().count(), 0);
        kept.extend(odd);
        assert_eq!(kept.iter().collect::<Vec<_>>(), odd);
    }
}
