# SPDX-License-Identifier: GPL-3.0-or-later
"""Every ```python block of README's "Python" section runs, from a copy of the repository root's
resources. A block that imports a module this machine does not have (pymeshlab, dask_jobqueue)
is reported as skipped; the pymeshlab example then also runs against a stand-in of pymeshlab."""

import importlib.util
import os
import re
import sys
from pathlib import Path

import pytest

SOURCE = Path(os.environ.get("MESHBRIDGE_SOURCE_DIR", Path(__file__).parents[2]))
OPTIONAL = ("pymeshlab", "dask_jobqueue", "open3d")


def python_blocks():
    readme = (SOURCE / "README.md").read_text()
    section = readme[readme.index("\n## Python\n"):]
    section = section[: section.index("\n## ", 1)]
    return re.findall(r"```python\n(.*?)```", section, flags=re.S)


BLOCKS = python_blocks()


def imported_optional(code):
    return [m for m in OPTIONAL if re.search(rf"^\s*(import|from) {m}\b", code, flags=re.M)]


def run_block(code, where, name):
    os.chdir(where)
    (where / "resources").symlink_to(SOURCE / "resources")
    exec(compile(code, f"README.md, Python block {name}", "exec"), {"__name__": "__readme__"})


def test_readme_has_the_examples():
    assert len(BLOCKS) == 5
    assert any("pymeshlab" in b for b in BLOCKS) and any("open3d" in b for b in BLOCKS)


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_readme_python_block(index, tmp_path, monkeypatch):
    code = BLOCKS[index]
    for module in imported_optional(code):
        if importlib.util.find_spec(module) is None:
            pytest.skip(f"README block {index} needs {module}, which is not installed here")
    monkeypatch.chdir(tmp_path)
    run_block(code, tmp_path, index)


def test_readme_pymeshlab_block_with_stand_in(tmp_path, monkeypatch):
    (code,) = [b for b in BLOCKS if "import pymeshlab" in b]
    monkeypatch.syspath_prepend(str(Path(__file__).parent / "standin"))
    monkeypatch.delitem(sys.modules, "pymeshlab", raising=False)
    monkeypatch.chdir(tmp_path)
    run_block(code, tmp_path, "pymeshlab (stand-in)")
    assert (tmp_path / "twocubes_repaired.ply").is_file()
    import meshbridge

    back = meshbridge.read(tmp_path / "twocubes_repaired.ply")
    assert (back.num_vertices, back.num_faces) == (16, 24)
