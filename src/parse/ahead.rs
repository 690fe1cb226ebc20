//! Reading a large file on two threads. The text is cut into pieces at items (a `<Body>`
//! directly in `<Bodies>`), where the scan stage finds them: a helper thread scans the whole
//! text first (see [`crate::scan`]), then reads the pieces from the last one back, each with
//! the ordinary reader into an arena of its own, from its item up to the next piece's; the
//! calling thread reads from the start on, and learns where the pieces begin when the scan
//! has found them. Its reading's text ends before each piece's item from then on, where the
//! reading stops if it can (see [`Tokenizer::end_before`]). There the calling thread reads
//! the piece itself while the helper has not begun it, or else takes what the helper read
//! from there to the end of the file, when it can use all of it: each of those pieces read
//! without a problem (warnings are fine: they are appended in the order one reader finds
//! them) up to where the next one begins, the limits still hold and no world element was
//! read twice. Otherwise it reads on itself. Either way the scene, the warnings and the
//! first error are those of one reader reading the whole file; a busy core only moves
//! where the two meet. The text may be in memory or in a file: the helper reads a file's
//! pieces with a handle of its own, one piece at a time.

use std::sync::{Arc, Mutex, OnceLock, PoisonError, mpsc};
use std::thread::{Scope, ScopedJoinHandle};

use super::names::{Element, Name};
use super::tokenizer::{Halt, Reading, Stop, Tokenizer};
use super::world::WorldChild;
use super::{Reader, Seen, Tag};
use crate::arena::Arena;
use crate::bytes::ENDS_NAME;
use crate::containers::Container;
use crate::error::{Code, Position, problem};
use crate::input::{Pieces, Source};
use crate::options::LoadOptions;
use crate::scan::{Item, Scanner};

/// The smallest text worth a second thread: below it, starting one costs more than it
/// saves.
const MIN_BYTES: usize = 1 << 20;

/// About how long a piece is. The calling thread may wait for the piece the helper is
/// reading when they meet, so pieces are short; each costs a reader and a merge.
const PIECE_BYTES: usize = 256 << 10;

/// At most this many pieces, however large the text.
const MAX_PIECES: usize = 64;

/// Where a piece begins: the `<` of an item, and the container it is assumed to be in.
pub(super) type Boundary = (usize, Container);

/// Where the pieces begin, once the helper's scan has found them.
type Found = Arc<OnceLock<Vec<Boundary>>>;

/// The helper, as the calling thread sees it.
pub(super) struct Caller<'scope> {
    found: Found,
    claims: Arc<Mutex<Claims>>,
    done: mpsc::Receiver<(usize, Option<Done>)>,
    /// What the helper read, by piece (empty until the pieces are found).
    pieces: Vec<Piece>,
    /// The helper's thread, which ends with the buffer it read a file's pieces into: that
    /// is let go here, with this, once the pieces are taken (see [`Pieces::source`]).
    _thread: ScopedJoinHandle<'scope, Vec<u8>>,
}

/// Who reads which piece: the calling thread those before `caller`, the helper those from
/// `helper` on. Each claims a piece before it reads it, so they never read the same one:
/// the helper only one from `caller` on, the calling thread only one before `helper`.
struct Claims {
    caller: usize,
    helper: usize,
}

enum Piece {
    /// Not read by the helper, or not yet received.
    Waiting,
    Read(Box<Done>),
    /// Read with a problem, or not where the next piece begins.
    Unusable,
}

/// What the helper read of one piece, when it read it without a problem: what it built
/// (its kept text copied out of the piece's text, which is let go; its positions counted
/// from the piece's start), how many elements it read and where it ended.
struct Done {
    arena: Arena,
    elements: u64,
    /// Where it ended, counted from its start, when it placed what it found as it read (a
    /// piece of a file).
    end: Option<Position>,
    /// Where the tokenizer stopped, kept for the piece that ends the file: the calling
    /// thread reads on from there. The other pieces' is let go here, on the helper's
    /// thread, which allocated it: let go on the calling thread, so small a block would
    /// stay in that thread's cache of small blocks, high in the helper's heap, and keep
    /// the memory of the pieces under it from going back to the system as they are
    /// appended (up to 11 MB more at the peak of a 100 MB load from a path).
    stop: Option<Stop>,
    /// The world's elements it read, its own container among them.
    seen: Seen,
}

/// The pieces of `source` a helper would read, when the options allow a thread and the
/// text, whose pieces a second reader may read (see [`Source::pieces`]), is large enough to
/// be worth it, or the test's `split` forces them. None for a load on one thread, which
/// then never enters this module's code again.
pub(super) fn helped<'a>(
    source: &Source<'a>,
    options: &LoadOptions,
    split: &Option<(Vec<Boundary>, usize)>,
) -> Option<Pieces<'a>> {
    if options.threads == 1 {
        return None;
    }
    let pieces = source.pieces()?;
    (split.is_some() || pieces.len() >= MIN_BYTES).then_some(pieces)
}

/// Starts the helper on `scope`, reading `pieces` (see [`helped`]). For tests, `split`
/// forces the boundaries and a first piece that is the helper's from the start, from which
/// on it reads them whatever the timing.
pub(super) fn start<'a, 'scope>(
    scope: &'scope Scope<'scope, '_>,
    pieces: Pieces<'a>,
    options: &'a LoadOptions,
    split: Option<(Vec<Boundary>, usize)>,
) -> Caller<'scope>
where
    'a: 'scope,
{
    let found = Found::default();
    let helped = match split {
        Some((boundaries, helped)) => {
            let _ = found.set(boundaries);
            helped
        }
        None => usize::MAX,
    };
    let claims = Arc::new(Mutex::new(Claims { caller: 0, helper: helped }));
    let (sender, done) = mpsc::channel();
    let (their_found, their_claims) = (Arc::clone(&found), Arc::clone(&claims));
    let thread = scope.spawn(move || help(pieces, options, &their_found, &their_claims, &sender));
    Caller { found, claims, done, pieces: Vec::new(), _thread: thread }
}

/// Reads the whole document with `reader`, the calling thread's, taking what the helper
/// read where the two meet.
pub(super) fn read(reader: &mut Reader, mut helper: Caller) -> Reading<()> {
    let mut seen = Seen::default();
    let found = Arc::clone(&helper.found);
    reader.tok.end_before_found(Box::new(move || found.get().map(|found| ends(found))));
    let mut read = reader.document(&mut seen);
    // Where the reading stopped before a piece's item.
    while matches!(read, Err(Halt::PieceEnd)) {
        let piece = reader.tok.pass_end();
        if !helper.claim(piece) && helper.take(reader, piece, &mut seen) {
            read = Ok(());
            break;
        }
        let Some((root, tag)) = reader.tok.open_item() else {
            return Err(problem(Code::Internal, 0, "a reading stopped outside a container"));
        };
        let container = helper.boundaries()[piece].1;
        read = reader.document_from_item((&root, &tag), container, &mut seen);
    }
    read?;
    reader.end_world(&seen)?;
    // Read already when the helper's pieces were taken: the last one read it.
    reader.epilog()
}

/// Where the readings end: before the item of each boundary, in its container.
fn ends(boundaries: &[Boundary]) -> Vec<(usize, Name)> {
    boundaries.iter().map(|&(at, container)| (at, Name::new(container.name()))).collect()
}

/// How much of the text the helper scans at a time, and how much of its start holds the
/// root's start tag.
const SCAN_BYTES: usize = 64 << 10;
const ROOT_BYTES: usize = 16 << 10;

/// Where the pieces of the text begin: at the first item from every [`PIECE_BYTES`] or so
/// on, found by a scan of the whole text, while `wanted` (asked at every [`SCAN_BYTES`]).
/// An item is a start tag directly in an element of the root, here one of the world's
/// containers, whose item it names.
fn boundaries(text: &Pieces, wanted: impl Fn() -> bool, buffer: &mut Vec<u8>) -> Vec<Boundary> {
    let len = text.len();
    let pieces = (len / PIECE_BYTES).clamp(2, MAX_PIECES);
    let step = len / pieces;
    let mut boundaries: Vec<Boundary> = Vec::with_capacity(pieces);
    let (mut scanner, mut parent) = (Scanner::new(), None);
    while scanner.scanned() < len && boundaries.len() < pieces - 1 && wanted() {
        let from = scanner.scanned();
        let Some(bytes) = text.bytes(from, (from + SCAN_BYTES).min(len), buffer) else { break };
        scanner.scan(bytes, from);
        if scanner.scanned() == from {
            // Markup the scan cannot read: the reader stops there.
            break;
        }
        for item in scanner.take_items() {
            // A comment right before an item goes with it, so a reading cannot stop between
            // the two (see `Tokenizer::end_before`): the next item is where the piece begins.
            if item.at < step * (boundaries.len() + 1)
                || boundaries.len() == pieces - 1
                || item.after_markup
            {
                continue;
            }
            boundaries.extend(in_container(text, item, &mut parent, buffer));
        }
    }
    boundaries
}

/// Where a piece may begin at `item`: when its parent is one of the world's containers and
/// it names that container's item. `parent` keeps the last parent looked at, the container
/// it is if it is one: items come by the thousand from each.
fn in_container(
    text: &Pieces,
    item: Item,
    parent: &mut Option<(usize, Option<Container>)>,
    buffer: &mut Vec<u8>,
) -> Option<Boundary> {
    if parent.is_none_or(|(at, _)| at != item.parent) {
        let container =
            Container::ALL.into_iter().find(|c| names(text, item.parent, c.name(), buffer));
        *parent = Some((item.parent, container));
    }
    let container = (*parent)?.1?;
    names(text, item.at, container.item(), buffer).then_some((item.at, container))
}

/// Whether the start tag at `at` names the element `name` (a file's read into `buffer`).
fn names(text: &Pieces, at: usize, name: &str, buffer: &mut Vec<u8>) -> bool {
    let to = (at + name.len() + 2).min(text.len());
    let Some(tag) = text.bytes(at, to, buffer) else { return false };
    let [b'<', rest @ ..] = tag else { return false };
    rest.strip_prefix(name.as_bytes())
        .and_then(|after| after.first())
        .is_some_and(|&b| ENDS_NAME[usize::from(b)])
}

/// The helper: finds where the pieces begin (unless they were given), reads the root's start
/// tag, then claims and reads the pieces from the last one back until it reaches one the
/// calling thread has claimed, or one it cannot use (the pieces before it could not be used
/// either: the calling thread takes the pieces from one on to the end). Returns the buffer
/// it read a file's pieces into.
fn help(
    text: Pieces<'_>,
    options: &LoadOptions,
    found: &OnceLock<Vec<Boundary>>,
    claims: &Mutex<Claims>,
    sender: &mpsc::Sender<(usize, Option<Done>)>,
) -> Vec<u8> {
    let mut buffer = Vec::new();
    // The scan stops once the calling thread is done: the load waits for this thread.
    let wanted = || claims.lock().unwrap_or_else(PoisonError::into_inner).caller != usize::MAX;
    let boundaries = found.get_or_init(|| boundaries(&text, wanted, &mut buffer));
    let Some(&(first, _)) = boundaries.first() else { return buffer };
    let Some((root, version)) = root(&text, options, first, &mut buffer) else {
        return buffer;
    };
    for piece in (0..boundaries.len()).rev() {
        {
            let mut claims = claims.lock().unwrap_or_else(PoisonError::into_inner);
            if piece < claims.helper.min(claims.caller) {
                break;
            }
            claims.helper = claims.helper.min(piece);
        }
        let end = boundaries.get(piece + 1).copied();
        let at = boundaries[piece].0;
        let done = text
            .source(at, end.map_or(text.len(), |(end, _)| end), &mut buffer)
            .and_then(|source| read_piece(source, options, &root, version, boundaries[piece], end));
        let usable = done.is_some();
        if sender.send((piece, done)).is_err() || !usable {
            break;
        }
    }
    buffer
}

/// The root's start tag and the Version it says, read from the start of the text (before
/// `first`, the first piece's start, and its last `<` within the first [`ROOT_BYTES`]),
/// a file's into `buffer`.
fn root(
    text: &Pieces,
    options: &LoadOptions,
    first: usize,
    buffer: &mut Vec<u8>,
) -> Option<(Tag, u32)> {
    let head = text.bytes(0, first.min(ROOT_BYTES), buffer)?;
    let end = memchr::memrchr(b'<', head)?;
    let mut reader = Reader::new(Tokenizer::new(text.source(0, end, buffer)?, options), false);
    let root = reader.root().ok()?;
    reader.read_version(&root).ok()?;
    Some((root, reader.arena.version))
}

/// Reads `source`, the text of one piece, from its start on as if it began an item of its
/// container, up to the item of `end` (the next piece) or to the end of the file.
fn read_piece(
    source: Source<'_>,
    options: &LoadOptions,
    root: &Tag,
    version: u32,
    (at, container): Boundary,
    end: Option<Boundary>,
) -> Option<Done> {
    let mut reader = Reader::new(Tokenizer::new(source, options), false);
    reader.arena.version = version;
    let tag = Tag::item(Name::new(container.name()), at);
    reader.tok.start_item(at, vec![(root.name.clone(), root.at), (tag.name.clone(), at)]);
    reader.tok.end_before(ends(end.as_slice()));
    let mut seen = Seen::default();
    seen.bits |= 1 << WorldChild::of(container).index();
    let read = reader.document_from_item((root, &tag), container, &mut seen);
    let ended = match read {
        // To the end of the file: the last piece.
        Ok(()) => end.is_none() && reader.epilog().is_ok(),
        Err(stopped) => matches!(stopped, Halt::PieceEnd),
    };
    if !ended {
        return None;
    }
    let Reader { tok, mut arena, .. } = reader;
    arena.scene.pool_kept_text(|from, to| tok.slice(from, to));
    arena.scene.shrink_to_fit();
    let stop = tok.stop();
    let (elements, stopped) = (stop.elements(), stop.end());
    Some(Done { arena, elements, end: stopped, stop: end.is_none().then_some(stop), seen })
}

impl Caller<'_> {
    /// Where the pieces begin: known once the calling thread's reading stops before one.
    fn boundaries(&self) -> &[Boundary] {
        self.found.get().map_or(&[], Vec::as_slice)
    }

    /// Claims `piece` for the calling thread, which has reached or passed where it begins,
    /// and keeps the helper from those before it; whether the helper had not claimed it.
    fn claim(&self, piece: usize) -> bool {
        let mut claims = self.claims.lock().unwrap_or_else(PoisonError::into_inner);
        claims.caller = claims.caller.max(piece + 1);
        piece < claims.helper
    }

    /// Waits until the helper has read or given up every piece from `first` on.
    fn receive(&mut self, first: usize) {
        if self.pieces.is_empty() {
            self.pieces = self.boundaries().iter().map(|_| Piece::Waiting).collect();
        }
        while self.pieces[first..].iter().any(|p| matches!(p, Piece::Waiting)) {
            let Ok((piece, done)) = self.done.recv() else {
                for p in &mut self.pieces[first..] {
                    if matches!(p, Piece::Waiting) {
                        *p = Piece::Unusable;
                    }
                }
                return;
            };
            self.pieces[piece] = done.map_or(Piece::Unusable, |done| Piece::Read(Box::new(done)));
        }
    }

    /// Appends to `reader`'s arena what the helper read from `first` on, to the end of the
    /// file, and goes on reading where it ends, when every piece of it is usable and all
    /// of it together keeps the limits; whether it did.
    fn take(&mut self, reader: &mut Reader, first: usize, seen: &mut Seen) -> bool {
        self.receive(first);
        let (mut bits, mut elements) = (seen.bits, reader.tok.elements());
        for (piece, &(_, container)) in self.pieces[first..].iter().zip(&self.boundaries()[first..])
        {
            let Piece::Read(done) = piece else { return false };
            // Each piece has the container it begins in, as does the one before it.
            if bits & done.seen.bits & !(1 << WorldChild::of(container).index()) != 0 {
                return false;
            }
            bits |= done.seen.bits;
            elements += done.elements;
        }
        if elements > reader.tok.options().max_elements {
            return false;
        }
        // Where each piece starts, for what the pieces of a file placed as they were read:
        // the first here, each next where the one before ends. Pieces of a text in memory
        // placed nothing, and counting its lines here would be wasted.
        let placed = self.pieces[first..]
            .iter()
            .any(|p| matches!(p, Piece::Read(done) if done.end.is_some()));
        let mut start = match placed {
            true => reader.tok.locate(reader.tok.position()),
            false => Position::default(),
        };
        let mut starts = Vec::with_capacity(self.pieces.len() - first);
        for piece in &self.pieces[first..] {
            let Piece::Read(done) = piece else { return false };
            starts.push(start);
            start = done.end.map_or(start, |end| end.after(start));
        }
        // A file is read on from where the last piece ends.
        let taken = self.pieces[first..].iter_mut().map(|p| std::mem::replace(p, Piece::Unusable));
        let mut done: Vec<Done> = taken
            .filter_map(|p| if let Piece::Read(done) = p { Some(*done) } else { None })
            .collect();
        let Some(last) = done.pop() else { return false };
        let last_start = starts[done.len()];
        let Some(stop) = last.stop else { return false };
        if !reader.tok.resume(stop, last_start, elements) {
            return false;
        }
        for (piece, &start) in done.into_iter().zip(&starts) {
            reader.arena.append(piece.arena, start);
        }
        reader.arena.append(last.arena, last_start);
        seen.bits = bits;
        true
    }
}

impl Drop for Caller<'_> {
    /// The helper starts no piece once the calling thread is done with them.
    fn drop(&mut self) {
        self.claims.lock().unwrap_or_else(PoisonError::into_inner).caller = usize::MAX;
    }
}

#[cfg(test)]
mod tests;
