//! Where a later stage may point: [`Spot`]s, placed in a piece of the text and kept many
//! together, small, as [`Step`]s in [`Spots`].

use crate::error::{Position, Spot};

/// A [`Spot`] in 8 bytes, as the step to it from the spot before it: how many lines on,
/// its column, how many bytes on (see [`Spots`]). Or, for a spot no step
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

impl Spot {
    /// This spot, counted from the start of a piece of the text, placed in the whole text
    /// where the piece begins at `start` (see [`Position::after`]); offsets are the whole
    /// text's already.
    pub fn after(self, start: Position) -> Spot {
        match self {
            Spot::Offset(_) => self,
            Spot::Placed(position) => Spot::Placed(position.after(start)),
        }
    }

    /// The start of the text, as a spot of this one's kind: what the first spot of
    /// [`Spots`] is a step from.
    fn origin(self) -> Spot {
        match self {
            Spot::Offset(_) => Spot::Offset(0),
            Spot::Placed(_) => Spot::Placed(Position::default()),
        }
    }

    /// This spot as a step from `before`, of the same kind, when a [`Step`] holds it.
    /// (Offsets differ by less than 2^63: a text is at most `isize::MAX` bytes.)
    #[inline]
    pub fn step_from(self, before: Spot) -> Option<Step> {
        let (lines, column, bytes) = match (self, before) {
            (Spot::Offset(this), Spot::Offset(before)) => (0, 0, this.wrapping_sub(before) as u64),
            (Spot::Placed(this), Spot::Placed(before)) => (
                i64::from(this.line) - i64::from(before.line),
                this.column,
                this.byte_offset.wrapping_sub(before.byte_offset),
            ),
            _ => return None,
        };
        match (i16::try_from(lines), u16::try_from(column), i32::try_from(bytes as i64)) {
            (Ok(Step::ASIDE), ..) | (Err(_), ..) | (_, Err(_), _) | (.., Err(_)) => None,
            (Ok(lines), Ok(column), Ok(bytes)) => Some(Step { lines, column, bytes }),
        }
    }

    /// The spot `step` leads to from this one.
    #[inline]
    pub fn stepped(self, step: Step) -> Spot {
        match self {
            Spot::Offset(at) => Spot::Offset(at.wrapping_add_signed(step.bytes as isize)),
            Spot::Placed(position) => Spot::Placed(Position {
                line: position.line.wrapping_add_signed(step.lines.into()),
                column: step.column.into(),
                byte_offset: position.byte_offset.wrapping_add_signed(step.bytes.into()),
            }),
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
#[derive(Default)]
pub(crate) struct Spots {
    steps: Vec<Step>,
    aside: Vec<Spot>,
    /// What the first spot is a step from: the start of the text, as a spot of the first
    /// one's kind.
    start: Spot,
    /// The last spot, which the next is a step from.
    last: Option<Spot>,
}

impl Spots {
    #[inline]
    pub fn push(&mut self, spot: Spot) {
        let before = match self.last.replace(spot) {
            Some(before) => before,
            None => {
                self.start = spot.origin();
                self.start
            }
        };
        let step = spot.step_from(before).unwrap_or_else(|| {
            self.aside.push(spot);
            Step::aside(self.aside.len() - 1)
        });
        self.steps.push(step);
    }

    pub fn iter(&self) -> impl Iterator<Item = Spot> + '_ {
        self.steps.iter().scan(self.start, |spot, &step| {
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
        let mut found = vec![self.start; indices.len()];
        let (mut spots, mut next, mut spot) = (self.iter(), 0, self.start);
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
        (self.start, self.last) = (Spot::default(), None);
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
