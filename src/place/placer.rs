//! Placing what a read left for later, once it is done.

use super::{Cursor, Lines};
use crate::error::Finding;
use crate::input::Source;

/// Places the findings a read left for later: those in a text that stayed whole in memory
/// (see [`Tokenizer::place`]), counting lines over it once, in the order of the findings.
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
        let mut order: Vec<&mut Finding> =
            findings.iter_mut().filter(|f| f.position.is_none()).collect();
        order.sort_by_key(|f| f.at);
        let mut lines = Lines::new(source.encoding(), Cursor::start(0));
        for finding in order {
            finding.position = Some(lines.locate(source.text(), 0, finding.at));
        }
    }
}
