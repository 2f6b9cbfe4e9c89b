# SPDX-License-Identifier: GPL-3.0-or-later
"""The type stubs describe the compiled module exactly: every public name, every member."""

import ast
from pathlib import Path

import meshbridge
from meshbridge import _core


def stub_tree():
    path = Path(_core.__file__).with_name("_core.pyi")
    return ast.parse(path.read_text())


def test_stub_names_match_the_module():
    tree = stub_tree()
    stubbed = {n.name for n in tree.body if isinstance(n, (ast.ClassDef, ast.FunctionDef))}
    stubbed |= {n.target.id for n in tree.body if isinstance(n, ast.AnnAssign)}  # constants
    public = {name for name in dir(_core) if not name.startswith("_")}
    assert stubbed == public


def test_stub_members_match_the_classes():
    for node in stub_tree().body:
        if not isinstance(node, ast.ClassDef) or issubclass(getattr(_core, node.name), BaseException):
            continue
        members = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
        members |= {n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
        members.discard("__init__")
        actual = {m for m in dir(getattr(_core, node.name)) if not m.startswith("_")}
        if node.name == "PairingPolicy":
            actual = {m for m in actual if m in ("geometric", "combinatorial", "name", "value")}
        assert members == actual, node.name


def test_package_is_typed_and_documented():
    package = Path(meshbridge.__file__).parent
    assert (package / "py.typed").exists()
    for function in (meshbridge.read, meshbridge.write, meshbridge.check, meshbridge.repair):
        assert "(n, 3)" in function.__doc__ or function is meshbridge.write, function.__name__
        assert "Raises" in function.__doc__, function.__name__
