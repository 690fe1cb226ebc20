"""The one exception box2scene raises for what a file or a call gets wrong."""

from __future__ import annotations


class Error(Exception):
    """A load, write or build that failed: nothing was returned or written.

    ``code`` is the kebab-case name of the library's code (``"id-out-of-range"``, listed in
    the repository's docs/format.md), ``line`` and ``column`` are 1-based (0 when unknown,
    as for a scene built in memory), ``byte_offset`` counts from the start of the input and
    ``message`` says what is wrong. ``str(error)`` reads ``line:column: error[code]: message``.
    """

    code: str
    line: int
    column: int
    byte_offset: int
    message: str

    def __init__(self, code: str, line: int, column: int, byte_offset: int, message: str):
        super().__init__(code, line, column, byte_offset, message)
        self.code = code
        self.line = line
        self.column = column
        self.byte_offset = byte_offset
        self.message = message

    def __str__(self) -> str:
        return f"{self.line}:{self.column}: error[{self.code}]: {self.message}"
