"""What a build made, looked up both ways: the engine object of a named scene record, and
the scene record an engine object was made from (the C and C++ adapters' ``find_body``,
``body_index`` and their kin). Each builder's ``Built`` says how its engine tells objects
apart (``_same``)."""

from __future__ import annotations

from typing import List, Optional


def _position(objects: List[Optional[object]], wanted: object, same) -> Optional[int]:
    if wanted is None:
        return None
    return next((i for i, o in enumerate(objects) if o is not None and same(o, wanted)), None)


class Lookups:
    """The lookups of a ``Built``; None where the scene names nothing so, or the build made
    nothing of it (then its ``reports`` say why)."""

    def find_body(self, name: str):
        """The engine body made of the first scene body named ``name``."""
        index = self._scene.find_body(name)
        return None if index is None else self.bodies[index]

    def find_fixture(self, name: str):
        """The engine fixture (pyb2d3: shape or chain) made of the first scene fixture named
        ``name``, on the first body that has it."""
        index = self._scene.find_fixture(name)
        slot = next((k for k, f in enumerate(self._scene.fixture_ids) if f == index), None)
        return None if slot is None else self.fixtures[slot]

    def find_joint(self, name: str):
        """The engine joint made of the first scene joint named ``name``."""
        index = self._scene.find_joint(name)
        return None if index is None else self.joints[index]

    def body_index(self, body) -> Optional[int]:
        """The scene body ``body`` was made of."""
        return _position(self.bodies, body, self._same)

    def fixture_slot(self, fixture) -> Optional[int]:
        """The entry of the scene's ``fixture_ids`` ``fixture`` was made for."""
        return _position(self.fixtures, fixture, self._same)

    def joint_index(self, joint) -> Optional[int]:
        """The scene joint ``joint`` was made of."""
        return _position(self.joints, joint, self._same)
