"""The wheel a user installs: abi3, manylinux2014, stripped, accepted by auditwheel, no
ctypes, the engines in compatible ranges; and the tests run against it, not the sources."""

from __future__ import annotations

import ast
import os
import platform
import struct
import subprocess
from importlib import metadata

import pytest

import box2scene
from box2scene import _native

from conftest import ROOT


def installed_files():
    dist = metadata.distribution("box2scene")
    return [dist.locate_file(f) for f in dist.files or ()]


def the_wheel() -> str:
    wheel = os.environ.get("B2S_WHEEL")
    if not wheel:
        pytest.skip("B2S_WHEEL names no wheel (python/tests/run sets it)")
    return wheel


def test_the_package_imported_is_the_installed_wheel():
    package = os.path.dirname(os.path.abspath(box2scene.__file__))
    assert not package.startswith(os.path.join(ROOT, "python") + os.sep)
    assert os.path.abspath(_native.__file__) in {os.path.abspath(str(f)) for f in installed_files()}


def test_the_wheel_is_abi3_for_manylinux2014():
    wheel_file = next(f for f in installed_files() if str(f).endswith(".dist-info/WHEEL"))
    with open(wheel_file) as f:
        tags = {line.split(":", 1)[1].strip() for line in f if line.startswith("Tag:")}
    machine = platform.machine()
    assert tags == {f"cp39-abi3-manylinux_2_17_{machine}", f"cp39-abi3-manylinux2014_{machine}"}
    assert os.path.basename(_native.__file__) == "_native.abi3.so"


def section_names(path: str):
    """The names of an ELF64 little-endian file's sections."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:4] == b"\x7fELF" and data[4] == 2 and data[5] == 1
    shoff, = struct.unpack_from("<Q", data, 0x28)
    shentsize, shnum, shstrndx = struct.unpack_from("<HHH", data, 0x3A)
    headers = [struct.unpack_from("<IIQQQQ", data, shoff + i * shentsize) for i in range(shnum)]
    strings_at = headers[shstrndx][4]
    return {data[strings_at + h[0] : data.index(b"\0", strings_at + h[0])].decode() for h in headers}


def test_the_extension_is_stripped():
    names = section_names(_native.__file__)
    assert ".text" in names and ".dynsym" in names
    assert not {n for n in names if n.startswith(".debug") or n == ".symtab"}


def test_auditwheel_accepts_the_wheel():
    auditwheel = os.environ.get("B2S_AUDITWHEEL")
    if not auditwheel:
        pytest.skip("B2S_AUDITWHEEL names no auditwheel (python/tests/run sets it)")
    shown = subprocess.run([auditwheel, "show", the_wheel()], capture_output=True, text=True, check=True).stdout
    assert 'consistent with the following platform tag: "manylinux_2_17_' in " ".join(shown.split())


def test_no_module_of_the_package_uses_ctypes():
    sources = [str(f) for f in installed_files() if str(f).endswith(".py") and "/box2scene/" in str(f)]
    assert len(sources) >= 8
    for source in sources:
        with open(source) as f:
            tree = ast.parse(f.read())
        imported = {a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names}
        imported |= {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom) and n.module}
        assert "ctypes" not in imported, source


def test_single_precision_math_is_the_c_librarys():
    """Values of glibc's cosf and sinf, as the C adapters compute them."""
    assert _native.cosf(1.0) == 0.5403022766113281
    assert _native.sinf(1.0) == 0.8414709568023682
    assert _native.cosf(0.1) == 0.9950041770935059


def test_the_extras_take_compatible_ranges():
    requires = metadata.requires("box2scene") or []
    engines = {r.split(";")[0].strip() for r in requires if r.startswith(("pyb2d3", "box2d"))}
    assert engines == {"pyb2d3~=0.11.1", "box2d~=2.3.10"}
