"""What the tests share: the repository's scene files."""

from __future__ import annotations

import glob
import os

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SCENE_DIRS = [
    "tests/fixtures/scenes",
    "examples/scenes",
    "tests/fixtures/adapter",
    "tests/fixtures/corpus",
]


def scene_files():
    files = []
    for folder in SCENE_DIRS:
        files += sorted(glob.glob(os.path.join(ROOT, folder, "*.xml")))
    assert len(files) >= 14, "the scene files are missing"
    return files


def scene_id(path: str) -> str:
    return os.path.relpath(path, ROOT)


@pytest.fixture
def showcase() -> str:
    return os.path.join(ROOT, "examples", "scenes", "showcase.xml")
