//! What the tokenizer keeps at hand for the reader, apart from the window that holds it:
//! the text kept as written (pins), the comments read since the reader last took them, and
//! the text after the piece the reader last kept for the writer. The window lets go of
//! nothing from the first of them on (see [`Keeping::first`]).

/// The offsets from which text stays at hand for the reader.
#[derive(Default)]
pub(crate) struct Keeping {
    /// Set while text is kept verbatim (UserData, an unknown element, a Farseer-only
    /// joint, one inside another): the text from the first on stays at hand.
    pins: Vec<usize>,
    /// The comments read since the reader last took them, as spans of the text.
    comments: Vec<(usize, usize)>,
    /// Where the text the reader last kept for the writer ends, while text kept next at
    /// the same place may join it (see [`Keeping::hold`]).
    held: Option<usize>,
}

impl Keeping {
    /// The first offset kept at hand, if any.
    pub fn first(&self) -> Option<usize> {
        let comment = self.comments.first().map(|&(at, _)| at);
        [self.pins.first().copied(), comment, self.held].into_iter().flatten().min()
    }

    /// Keeps the text from `from` on at hand (UserData keeps its inner XML verbatim), until
    /// the pin is taken back.
    pub fn pin(&mut self, from: usize) {
        self.pins.push(from);
    }

    /// Takes back the last pin: where it kept the text from.
    pub fn unpin(&mut self) -> Option<usize> {
        self.pins.pop()
    }

    /// Whether text is being kept verbatim (see [`Keeping::pin`]).
    pub fn pinned(&self) -> bool {
        !self.pins.is_empty()
    }

    /// A comment read from `from` to `to`, kept for the reader unless it lies in text kept
    /// verbatim.
    pub(super) fn comment(&mut self, from: usize, to: usize) {
        if self.pins.is_empty() {
            self.comments.push((from, to));
        }
    }

    /// Whether comments were read since [`Keeping::take_comments`] was last called.
    #[inline(always)]
    pub fn has_comments(&self) -> bool {
        !self.comments.is_empty()
    }

    /// The comments read since the last call, as spans of the text at hand; None when
    /// there are none, as between most elements.
    pub fn take_comments(&mut self) -> Option<Vec<(usize, usize)>> {
        (!self.comments.is_empty()).then(|| std::mem::take(&mut self.comments))
    }

    /// Keeps the text from `end`, where the text the reader kept for the writer ends, at
    /// hand until [`Keeping::release`]: text kept next at the same place joins it, with
    /// the white space between them, however the windows fall.
    pub fn hold(&mut self, end: usize) {
        self.held = Some(end);
    }

    /// Lets go of the text held by [`Keeping::hold`].
    pub fn release(&mut self) {
        self.held = None;
    }

    /// Where the text held by [`Keeping::hold`] starts.
    pub fn held(&self) -> Option<usize> {
        self.held
    }

    /// Whether nothing read waits for the reader (text kept verbatim, comments), as where
    /// a reading may end before an item.
    pub(super) fn waits_for_nothing(&self) -> bool {
        self.pins.is_empty() && self.comments.is_empty()
    }
}
