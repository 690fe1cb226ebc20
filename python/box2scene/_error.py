"""The exception box2scene raises for what a file or a call gets wrong, and its kinds for a
file that cannot be opened."""

from __future__ import annotations

import os
from typing import Dict, Type


class Error(Exception):
    """A load, write or build that failed: nothing was returned or written.

    ``code`` is the kebab-case name of the library's code (``"id-out-of-range"``, listed in
    the repository's docs/format.md), ``line`` and ``column`` are 1-based (0 when unknown,
    as for a scene built in memory), ``byte_offset`` counts from the start of the input and
    ``message`` says what is wrong. ``str(error)`` reads ``line:column: error[code]: message``,
    or ``error[code]: message`` when the error has no position.

    A file that cannot be opened raises an ``Error`` that is also the ``OSError`` Python
    raises for the reason (``FileNotFoundError``, ``PermissionError``, ...), with its
    ``errno``, ``strerror`` and ``filename``.
    """

    code: str
    line: int
    column: int
    byte_offset: int
    message: str

    def __init__(self, code: str, line: int, column: int, byte_offset: int, message: str):
        super().__init__(code, line, column, byte_offset, message)
        self._describe(code, line, column, byte_offset, message)

    def _describe(self, code: str, line: int, column: int, byte_offset: int, message: str) -> None:
        self.code = code
        self.line = line
        self.column = column
        self.byte_offset = byte_offset
        self.message = message

    def __str__(self) -> str:
        if self.line == 0:
            return f"error[{self.code}]: {self.message}"
        return f"{self.line}:{self.column}: error[{self.code}]: {self.message}"


class _CannotOpen(Error):
    """An :class:`Error` that is also an ``OSError`` of one kind (the class is made per kind
    below)."""

    def __init__(self, errno: int, strerror: str, filename: str, message: str):
        OSError.__init__(self, errno, strerror, filename)
        self._describe("io-error", 0, 0, 0, message)


def _cannot_open_kind(kind: Type[OSError]) -> Type[_CannotOpen]:
    return type(kind.__name__, (_CannotOpen, kind), {"__module__": "box2scene", "__qualname__": kind.__name__})


_OS_KINDS: Dict[Type[OSError], Type[_CannotOpen]] = {
    kind: _cannot_open_kind(kind)
    for kind in (
        OSError,
        FileNotFoundError,
        PermissionError,
        IsADirectoryError,
        NotADirectoryError,
        InterruptedError,
        BlockingIOError,
        TimeoutError,
    )
}


def cannot_open(errno: int, filename: str, message: str) -> Error:
    """The error of a file that cannot be opened, of the ``OSError`` kind Python gives
    ``errno`` (0 when the system gave none); the extension raises it."""
    strerror = os.strerror(errno) if errno else message
    kind = type(OSError(errno, strerror))
    return _OS_KINDS.get(kind, _OS_KINDS[OSError])(errno, strerror, filename, message)
