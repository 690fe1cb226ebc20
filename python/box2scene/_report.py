"""What a builder or a capture could not represent, as the C adapters report it."""

from __future__ import annotations

from typing import NamedTuple, Optional


class Report(NamedTuple):
    """One thing a build or capture left out or approximated.

    ``code`` is the kebab-case name of the library's code (``"skipped-joint"``,
    ``"beyond-box2d-range"``, ...), ``object`` is ``"world"``, ``"shape"``, ``"fixture"``,
    ``"body"`` or ``"joint"``, ``index`` its index in the scene (in a capture, in the scene
    being made), ``name`` its name when it has one, ``message`` what happened and why.
    """

    code: str
    object: str
    index: int
    name: Optional[str]
    message: str
