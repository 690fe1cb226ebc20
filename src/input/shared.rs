//! The whole text of a file as the readers of its pieces share it: a load on two threads
//! cuts it into pieces, and each is read by a reader of its own, on either thread.

use std::borrow::Cow;
use std::fs::File;
use std::io::Read;

use super::{Encoding, Source};
use crate::bytes::first_non_char;

/// The text of a file, any piece of which can be read apart: whole in memory, or a piece at
/// a time from the file that is being read, through a handle of its own.
pub enum Shared<'a> {
    /// A text in memory, and whether its file began with a byte-order mark (for positions).
    Memory {
        text: &'a str,
        bom: bool,
    },
    File {
        file: File,
        bom: u64,
        len: usize,
    },
}

impl<'a> Shared<'a> {
    /// The length of the text.
    pub fn len(&self) -> usize {
        match self {
            Shared::Memory { text, .. } => text.len(),
            Shared::File { len, .. } => *len,
        }
    }

    /// The bytes of the text from `from` to `to` (within it), which may cut a character: a
    /// file's read into `buffer`, which they borrow.
    pub fn bytes<'s>(
        &'s self,
        from: usize,
        to: usize,
        buffer: &'s mut Vec<u8>,
    ) -> Option<&'s [u8]> {
        match self {
            Shared::Memory { text, .. } => text.as_bytes().get(from..to),
            Shared::File { .. } => {
                self.read_into(from, to, buffer)?;
                Some(buffer)
            }
        }
    }

    /// A source that holds the text from `from` to `to`, at its offsets in the whole, and
    /// ends there (see [`Source::ends_early`]): a text in memory, all of it up to `to`, which
    /// stays at hand, None unless that is all text (valid UTF-8, only characters XML
    /// allows); a piece of a file, read through a window as a whole file is (see
    /// [`Source::more`]), so that a reader never holds more of it than a window: where it
    /// is not all text, its window stops there, as a whole file's does.
    pub fn source(&self, from: usize, to: usize) -> Option<Source<'_>> {
        let ends_early = to < self.len();
        match self {
            Shared::Memory { text, bom } => {
                if first_non_char(text.as_bytes().get(from..to)?).is_some() {
                    return None;
                }
                let encoding = Encoding::Utf8 { bom: *bom };
                let source = Source::holding(Cow::Borrowed(text.get(..to)?), 0, None, encoding);
                Some(Source { ends_early, ..source })
            }
            Shared::File { file, bom, .. } => {
                let span = Span { file, at: bom + from as u64, end: bom + to as u64 };
                let source = Source::piece(Box::new(span), from, *bom)?;
                Some(Source { ends_early, ..source })
            }
        }
    }

    /// The whole text in memory, as it stays at hand once its pieces are read; None for a
    /// file, whose pieces placed what they found as they read.
    pub fn whole(&self) -> Option<Source<'a>> {
        let Shared::Memory { text, bom } = *self else { return None };
        Some(Source::holding(Cow::Borrowed(text), 0, None, Encoding::Utf8 { bom }))
    }

    /// Reads the bytes of a file's text from `from` to `to` into `buffer`, in place of what
    /// it held (only what it grows by is zeroed first: the read writes every byte).
    fn read_into(&self, from: usize, to: usize, buffer: &mut Vec<u8>) -> Option<()> {
        let Shared::File { file, bom, .. } = self else { return None };
        buffer.resize(to.checked_sub(from)?, 0);
        read_exact_at(file, buffer, bom + from as u64).ok()
    }
}

/// The bytes of a file from offset `at` to `end`, read at their offsets: a piece of the
/// text, which the window of its reader reads as it would a whole file.
struct Span<'a> {
    file: &'a File,
    at: u64,
    end: u64,
}

impl Read for Span<'_> {
    fn read(&mut self, bytes: &mut [u8]) -> std::io::Result<usize> {
        let room = usize::try_from(self.end.saturating_sub(self.at)).unwrap_or(usize::MAX);
        let len = bytes.len().min(room);
        let read = read_at(self.file, &mut bytes[..len], self.at)?;
        self.at += read as u64;
        Ok(read)
    }
}

/// A second handle on `file`, for the second thread: the very file the first reads (not
/// one opened anew by its path, which may have been replaced since), read at offsets of
/// its own that leave the first handle's position alone. Unix's positional reads promise
/// that; elsewhere a file is read on one thread.
#[cfg(unix)]
pub(super) fn second_handle(file: &File) -> Option<File> {
    file.try_clone().ok()
}

#[cfg(not(unix))]
pub(super) fn second_handle(_: &File) -> Option<File> {
    None
}

#[cfg(unix)]
fn read_at(file: &File, bytes: &mut [u8], offset: u64) -> std::io::Result<usize> {
    std::os::unix::fs::FileExt::read_at(file, bytes, offset)
}

#[cfg(not(unix))]
fn read_at(_: &File, _: &mut [u8], _: u64) -> std::io::Result<usize> {
    Err(std::io::ErrorKind::Unsupported.into())
}

#[cfg(unix)]
fn read_exact_at(file: &File, bytes: &mut [u8], offset: u64) -> std::io::Result<()> {
    std::os::unix::fs::FileExt::read_exact_at(file, bytes, offset)
}

#[cfg(not(unix))]
fn read_exact_at(_: &File, _: &mut [u8], _: u64) -> std::io::Result<()> {
    Err(std::io::ErrorKind::Unsupported.into())
}
