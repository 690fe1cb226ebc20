//! Placing what a read left for later, once it is done.

use super::{Cursor, Lines};
use crate::error::{Finding, Spot};
use crate::input::Source;

/// Places the findings a read left for later: those in a text that stayed whole in memory
/// (see [`Tokenizer::place`](crate::markup::Tokenizer::place)), counting lines over it once, in the order of the findings.
pub(crate) struct Placer<'a> {
    whole: Option<Source<'a>>,
}

impl<'a> Placer<'a> {
    pub(crate) fn new(source: Source<'a>) -> Placer<'a> {
        Placer { whole: source.is_whole().then_some(source) }
    }

    /// Places every finding of `findings` that is not placed.
    pub fn place(&self, findings: &mut [Finding]) {
        let Some(source) = &self.whole else { return };
        let mut order: Vec<(usize, &mut Finding)> = findings
            .iter_mut()
            .filter_map(|f| match f.at {
                Spot::Offset(at) => Some((at, f)),
                Spot::Placed(_) => None,
            })
            .collect();
        order.sort_by_key(|&(at, _)| at);
        let mut lines = Lines::new(source.encoding(), Cursor::start(0));
        for (at, finding) in order {
            finding.at = Spot::placed(lines.locate(source.text(), 0, at));
        }
    }
}
