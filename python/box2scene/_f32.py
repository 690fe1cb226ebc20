"""Single-precision arithmetic as the engines' C code does it, for the captures, which read
a world back into the values whose build gives its bits (a build computes nothing: the
library's plan does): NumPy's float32 operations round as C's float ones, and the C
library's own ``cosf``/``sinf``/``atan2f`` (called by the extension) turn angles and
rotations into each other as the C adapters do (NumPy's vectorised float32 cosine may
differ from them in the last bit)."""

from __future__ import annotations

import math
from typing import Callable, Tuple

import numpy as np

from ._native import atan2f, cosf, nextafterf, sinf

F = np.float32


def f32(x: float) -> float:
    """``x`` rounded to the nearest float, as a Python float."""
    return float(F(x))


def ulps_away(x: float, steps: int) -> float:
    toward = -math.inf if steps < 0 else math.inf
    for _ in range(abs(steps)):
        x = nextafterf(x, toward)
    return x


def search_ulps(guess: float, gives: Callable[[float], bool]) -> Tuple[bool, float]:
    """The float nearest ``guess`` (within 16 ulps) for which ``gives`` holds: an inverse
    computed in floats is a few ulps off the value whose forward computation gives the
    bits wanted. (False, guess) when none does."""
    for k in range(17):
        for sign in (-1, 1):
            x = ulps_away(guess, sign * k)
            if gives(x):
                return True, x
    return False, guess


def angle_of(c: float, s: float) -> Tuple[bool, float]:
    """An angle whose cosf and sinf are the rotation's."""
    return search_ulps(atan2f(s, c), lambda a: cosf(a) == c and sinf(a) == s)
