//! The scan stage: the structure of the text, found without reading it.
//!
//! A [`Scanner`] goes over the text once, [`BLOCK`] bytes at a time with the machine's
//! vector instructions, and follows its markup: every tag to its `>` (its quoted values
//! passed over), comments, CDATA and processing instructions to their ends. It carries its
//! state from one window of the text to the next, so a delimiter cut by the end of a window
//! is found once more text comes. It checks nothing: where the text is not well-formed it
//! stops or marks what it saw, and the reader reports the problem.
//!
//! It marks every piece of markup ([`Mark`]: a tag, an end tag, a comment, CDATA, a
//! processing instruction, from its `<` to its last byte), in order. The reader asks an
//! [`Index`] for the mark of the markup it stands at when it is not the usual markup it
//! reads itself (a short tag, a value and its end tag): the index scans from there up to
//! the first mark, and the scan costs nothing where the reader needs no mark.
#![forbid(unsafe_code)]

use crate::bytes::{BLOCK, block_masks};

#[cfg(test)]
mod tests;

/// A piece of markup: a tag, an end tag, a comment, CDATA or a processing instruction, from
/// its `<` (`at`) to its last byte (`end`: the `>` that ends it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Mark {
    pub at: usize,
    pub end: usize,
    /// Markup after which nothing can be read (see [`Mode::Stopped`]): `end` is where the
    /// scan stopped in it (the `--` of a comment that does not end there).
    pub stops: bool,
}

/// Where the scanned text stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    /// In text, between tags.
    Text,
    Comment,
    CData,
    Pi,
    /// At markup after which nothing can be read (a DOCTYPE, `--` in a comment, `<!` that
    /// XML does not have): the reader stops there.
    Stopped,
}

/// The scan's state, carried from one window of the text to the next.
pub(crate) struct Scanner {
    /// The offset up to which the text was scanned: the next byte to look at.
    at: usize,
    mode: Mode,
    /// The marks found, and what they carry from one call to the next.
    marks: Marks,
}

/// The marks of a scan: those found, and the start of the comment, CDATA or processing
/// instruction the scan is in.
#[derive(Default)]
struct Marks {
    list: Vec<Mark>,
    open: Option<usize>,
}

impl Marks {
    /// The markup begun (the comment, CDATA or processing instruction) ends at `end`.
    fn close(&mut self, end: usize, stops: bool) {
        if let Some(at) = self.open.take() {
            self.list.push(Mark { at, end, stops });
        }
    }
}

impl Scanner {
    /// A scan from offset `at` of a text, between markup.
    fn new(at: usize) -> Scanner {
        Scanner { at, mode: Mode::Text, marks: Marks::default() }
    }

    /// Scans on from offset `at`, between markup, with no mark: the list keeps its memory.
    fn restart(&mut self, at: usize) {
        (self.at, self.mode) = (at, Mode::Text);
        self.marks.list.clear();
        self.marks.open = None;
    }

    /// Scans `text`, which starts at offset `base`, where the scan stands. Markup that
    /// `text` cuts is left for the next call, with more text.
    pub fn scan(&mut self, text: &[u8], base: usize) {
        debug_assert_eq!(base, self.at, "the text goes on where the scan stands");
        let text_end = base + text.len();
        while self.at < text_end {
            let rest = &text[self.at - base..];
            let paused = match self.mode {
                Mode::Text => self.text(rest),
                Mode::Comment => self.comment(rest),
                Mode::CData => self.until(rest, b"]]>"),
                Mode::Pi => self.until(rest, b"?>"),
                Mode::Stopped => true,
            };
            if paused {
                return;
            }
        }
    }

    /// Text and tags up to other markup; true when the text at hand is too short to go on
    /// (markup it cuts), or a tag is marked.
    fn text(&mut self, rest: &[u8]) -> bool {
        match tags(rest, self.at, &mut self.marks.list) {
            Stop::End => {
                self.at += rest.len();
                false
            }
            Stop::Cut(at) | Stop::Marked(at) => {
                self.at = at;
                true
            }
            Stop::Markup(lt, at, mode) => {
                self.at = at;
                self.mode = mode;
                self.marks.open = Some(lt);
                if mode == Mode::Stopped {
                    self.marks.close(lt, true);
                }
                false
            }
        }
    }

    /// A comment up to its `-->`, or to `--` that does not end it.
    fn comment(&mut self, rest: &[u8]) -> bool {
        let Some(i) = memchr::memmem::find(rest, b"--") else {
            // A `-` at the end may begin the `--`.
            self.at += rest.len() - usize::from(rest.last() == Some(&b'-'));
            return rest.len() < 2;
        };
        let Some(&after) = rest.get(i + 2) else {
            self.at += i;
            return true;
        };
        self.at += i;
        if after == b'>' {
            self.marks.close(self.at + 2, false);
            self.at += 3;
            self.mode = Mode::Text;
        } else {
            self.marks.close(self.at, true);
            self.mode = Mode::Stopped;
        }
        false
    }

    /// CDATA or a processing instruction up to `delimiter`.
    fn until(&mut self, rest: &[u8], delimiter: &[u8]) -> bool {
        let Some(i) = memchr::memmem::find(rest, delimiter) else {
            // The end may hold the start of the delimiter.
            let keep =
                (1..delimiter.len()).rev().find(|&n| rest.ends_with(&delimiter[..n])).unwrap_or(0);
            self.at += rest.len() - keep;
            return keep == rest.len();
        };
        self.at += i + delimiter.len();
        self.marks.close(self.at - 1, false);
        self.mode = Mode::Text;
        false
    }
}

/// How much text an [`Index`] scans at first when the reader asks for a mark: a block,
/// twice as much each time it finds none, so that long text or markup costs a few calls.
const CHUNK: usize = BLOCK;

/// The scan of the text a reader reads, from where the reader asks for a mark: the marks
/// of its markup from there, in order, which the reader takes as it reads each, passing
/// those of the markup it read itself.
pub(crate) struct Index {
    scanner: Scanner,
    /// The next mark the reader takes, in the scanner's list.
    next: usize,
}

impl Index {
    /// An index of the text from offset `at` on, which is between markup.
    pub fn new(at: usize) -> Index {
        Index { scanner: Scanner::new(at), next: 0 }
    }

    /// The offset up to which the text is scanned: the text from there on must stay at hand.
    pub fn scanned(&self) -> usize {
        self.scanner.at
    }

    /// The first mark from offset `at` on, where the reading stands between markup, in the
    /// text at hand, `text`, which starts at offset `base`: the marks before `at` are
    /// those of markup the reader read itself. Scans on when the marks found are all
    /// passed. None when the text at hand holds no more (the end of its next markup is not
    /// in it).
    #[inline(always)]
    pub fn next(&mut self, at: usize, text: &[u8], base: usize) -> Option<Mark> {
        while let Some(&mark) = self.scanner.marks.list.get(self.next) {
            if mark.at >= at {
                return Some(mark);
            }
            self.next += 1;
        }
        self.catch_up(at);
        self.scan_on(text, base)
    }

    /// The reading stands at `at`, between markup, having read what lies before it
    /// itself: a scan that stands behind it starts again there, in text, with no mark.
    #[inline(always)]
    pub fn catch_up(&mut self, at: usize) {
        if self.scanner.at < at {
            self.scanner.restart(at);
            self.next = 0;
        }
    }

    /// Takes the next mark, which the reader has read past.
    #[inline(always)]
    pub fn take(&mut self) {
        self.next += 1;
    }

    /// Where the next markup begins when the text at hand holds its start but not its end
    /// (its mark is not made yet).
    pub fn next_start(&self, text: &[u8], base: usize) -> Option<usize> {
        let at = self.scanner.at;
        self.scanner.marks.open.or((text.get(at - base) == Some(&b'<')).then_some(at))
    }

    /// Scans on, a chunk at a time, until a mark is found or the text at hand ends.
    #[inline(never)]
    fn scan_on(&mut self, text: &[u8], base: usize) -> Option<Mark> {
        self.scanner.marks.list.clear();
        self.next = 0;
        let mut size = CHUNK;
        loop {
            let from = self.scanner.at;
            let rest = &text[from - base..];
            let chunk = &rest[..rest.len().min(size)];
            self.scanner.scan(chunk, from);
            if let Some(&mark) = self.scanner.marks.list.first() {
                return Some(mark);
            }
            if chunk.len() == rest.len() {
                return None;
            }
            size *= 2;
        }
    }
}

/// Where [`tags`] stopped: at the end of the text, at markup the text cuts, after the tag
/// it marked (where the scan goes on), or after the start of other markup (its `<`, where
/// the scan goes on, and the mode it goes on in).
enum Stop {
    End,
    Cut(usize),
    Marked(usize),
    Markup(usize, usize, Mode),
}

/// The first tag of `rest`, text that starts at offset `start`, marked on `marks`, or the
/// other markup before it: the reader asks for one mark at a time.
/// A block's masks of `<`, `>` and each quote give each tag: its end is the first `>` after
/// its `<` outside quoted values (see [`tag_end_in`]); a tag the block does not end is
/// followed into the next blocks, inside a quoted value or not. The byte after a `<` tells
/// start tags from end tags and sends the rest of markup to [`classify`].
fn tags(rest: &[u8], start: usize, marks: &mut Vec<Mark>) -> Stop {
    // The tag begun in an earlier block: its `<`, and the quoted value it is in at the end
    // of the last block.
    let mut open: Option<(usize, Quoted)> = None;
    let mut from = 0;
    let mut padded = [0; BLOCK];
    while from < rest.len() {
        let block = match rest[from..].first_chunk::<BLOCK>() {
            Some(block) => block,
            None => {
                // The last bytes, after which zeros match nothing.
                padded[..rest.len() - from].copy_from_slice(&rest[from..]);
                &padded
            }
        };
        let masks = block_masks(block, [b'<', b'>', b'"', b'\'']);
        let mut ended = |i: usize, gt: usize| {
            marks.push(Mark { at: start + i, end: start + gt, stops: false });
            Stop::Marked(start + gt + 1)
        };
        if let Some((i, quoted)) = open {
            match tag_end_in(u64::MAX, quoted, masks) {
                Ok(end) => return ended(i, from + end),
                Err(quoted) => {
                    open = Some((i, quoted));
                    from += BLOCK;
                    continue;
                }
            }
        }
        if masks[0] != 0 {
            let bit = masks[0].trailing_zeros() as usize;
            let i = from + bit;
            let Some(&next) = rest.get(i + 1) else {
                return Stop::Cut(start + i);
            };
            if next == b'!' || next == b'?' {
                return match classify(&rest[i..]) {
                    Some((mode, len)) => Stop::Markup(start + i, start + i + len, mode),
                    None => Stop::Cut(start + i),
                };
            }
            // The usual tag: its `>` before any quote.
            let after = above(bit);
            let gt = (masks[1] & after).trailing_zeros() as usize;
            let quote = ((masks[2] | masks[3]) & after).trailing_zeros() as usize;
            let end = match quote > gt {
                true => Ok(gt),
                false => tag_end_in(after, Quoted::No, masks),
            };
            match end {
                Ok(end) => return ended(i, from + end),
                Err(quoted) => open = Some((i, quoted)),
            }
        }
        from += BLOCK;
    }
    match open {
        Some((i, _)) => Stop::Cut(start + i),
        None => Stop::End,
    }
}

/// Whether a tag's search stands in a quoted value, and which quote opened it.
#[derive(Clone, Copy)]
enum Quoted {
    No,
    Double,
    Single,
}

/// The bit of a block that ends a tag, the first `>` among the bits of `after` outside
/// quoted values, from the block's masks of `<`, `>` and double and single quotes, the
/// search starting in a quoted value or not (`quoted`); where it stands at the block's end
/// when the block does not hold it.
#[inline(always)]
fn tag_end_in(
    mut after: u64,
    mut quoted: Quoted,
    [_, gts, doubles, singles]: [u64; 4],
) -> Result<usize, Quoted> {
    loop {
        let same = match quoted {
            Quoted::No => {
                let gt = (gts & after).trailing_zeros() as usize;
                let quote = ((doubles | singles) & after).trailing_zeros() as usize;
                if quote > gt {
                    return Ok(gt);
                }
                if quote == BLOCK {
                    return Err(Quoted::No);
                }
                after = above(quote);
                quoted = match doubles >> quote & 1 {
                    1 => Quoted::Double,
                    _ => Quoted::Single,
                };
                continue;
            }
            Quoted::Double => doubles,
            Quoted::Single => singles,
        };
        let close = (same & after).trailing_zeros() as usize;
        if close == BLOCK {
            return Err(quoted);
        }
        after = above(close);
        quoted = Quoted::No;
    }
}

/// The bits of a block's mask above bit `bit`, one of its 64.
#[inline(always)]
fn above(bit: usize) -> u64 {
    u64::MAX << bit << 1
}

/// The mode that markup other than a tag, `text` (which starts with `<!` or `<?`), begins,
/// and how many bytes say so; None when too few are at hand to tell.
#[cold]
fn classify(text: &[u8]) -> Option<(Mode, usize)> {
    if text.get(1) == Some(&b'?') {
        return Some((Mode::Pi, 2));
    }
    for (prefix, mode) in [(&b"<!--"[..], Mode::Comment), (b"<![CDATA[", Mode::CData)] {
        let n = prefix.len().min(text.len());
        if text[..n] == prefix[..n] {
            return (n == prefix.len()).then_some((mode, n));
        }
    }
    Some((Mode::Stopped, 2))
}
