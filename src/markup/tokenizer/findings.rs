//! The errors the tokenizer puts in words about the elements it reads: a repeated
//! container, a missing element, an element the file does not close, a load limit passed.

use super::{Tag, Tokenizer};
use crate::error::{Code, Problem, problem};

impl Tokenizer<'_> {
    /// The error for a repeated container.
    #[cold]
    pub fn duplicate_container<E: From<Problem>>(&self, parent: &Tag, child: &Tag) -> E {
        problem(
            Code::DuplicateContainer,
            child.at,
            format!(
                "<{}> appears twice in <{}>: the indices of its items would be ambiguous",
                child.name(),
                parent.name()
            ),
        )
    }

    #[cold]
    pub fn missing<E: From<Problem>>(&self, tag: &Tag, what: &str) -> E {
        problem(Code::MissingElement, tag.at, format!("<{}> has no {what}", tag.name()))
    }

    #[cold]
    pub fn unclosed<E: From<Problem>>(&self, tag: &Tag) -> E {
        problem(
            Code::MalformedXml,
            self.window.end(),
            format!(
                "malformed XML: the file ends before </{}> (opened at byte {})",
                tag.name(),
                tag.at
            ),
        )
    }

    #[cold]
    pub fn limit<E: From<Problem>>(&self, at: usize, name: &str, value: u64) -> E {
        problem(
            Code::LimitExceeded,
            at,
            format!(
                "the file exceeds a load limit here ({name} = {value}); raise it in the load options if the file is trusted"
            ),
        )
    }
}
