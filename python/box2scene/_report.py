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


class Check:
    """The first value of one object found beyond an engine's working range."""

    def __init__(self, engine: str) -> None:
        self.engine = engine
        self.problem = ""

    @property
    def passed(self) -> bool:
        return not self.problem

    def fail(self, message: str) -> None:
        if self.passed:
            self.problem = message

    def magnitude(self, field: str, value: float, bound: float, unit: str) -> None:
        if not abs(value) <= bound:
            self.fail(
                f"{field} {value:.9g} lies beyond {self.engine}'s working range "
                f"(within +-{bound:g} {unit})"
            )

    def vector(self, field: str, v, bound: float, unit: str) -> None:
        if not (abs(v[0]) <= bound and abs(v[1]) <= bound):
            self.fail(
                f"{field} ({v[0]:.9g}, {v[1]:.9g}) lies beyond {self.engine}'s working range "
                f"(each component within +-{bound:g} {unit})"
            )

    def zero_or_within(self, field: str, value: float, low: float, high: float, unit: str):
        if value != 0.0 and not (low <= value <= high):
            self.fail(
                f"{field} {value:.9g} {unit} lies beyond {self.engine}'s working range "
                f"(0 or within [{low:g}, {high:g}] {unit})"
            )
