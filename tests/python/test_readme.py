# SPDX-License-Identifier: GPL-3.0-or-later
"""Every ```python block of README.md and docs/python.md runs as a user runs it: saved as a file
and run with `python3 FILE` in a fresh folder that holds the repository's resources (so a Dask
example without its `if __name__ == "__main__":` guard fails here as it does for a user). A block
that imports a module this machine does not have (pymeshlab, dask_jobqueue) is reported as
skipped; the pymeshlab example then also runs against a stand-in of pymeshlab."""

import importlib.util
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

SOURCE = Path(os.environ.get("MESHBRIDGE_SOURCE_DIR", Path(__file__).parents[2]))
OPTIONAL = ("pymeshlab", "dask_jobqueue", "open3d")
PAGES = ("README.md", "docs/python.md")


def python_blocks():
    blocks = []
    for page in PAGES:
        text = (SOURCE / page).read_text()
        blocks += re.findall(r"```python\n(.*?)```", text, flags=re.S)
    return blocks


BLOCKS = python_blocks()


def imported_optional(code):
    return [m for m in OPTIONAL if re.search(rf"^\s*(import|from) {m}\b", code, flags=re.M)]


def run_block(code, where, name, extra_path=()):
    """Saves the block as where/example_NAME.py and runs `python3 example_NAME.py` in `where`;
    fails with its output unless it exits 0 within 5 minutes."""
    (where / "resources").symlink_to(SOURCE / "resources")
    script = where / f"example_{name}.py"
    script.write_text(code)
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([*map(str, extra_path), env.get("PYTHONPATH", "")])
    result = subprocess.run([sys.executable, script.name], cwd=where, env=env,
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, f"python3 {script.name} exited {result.returncode}:\n" \
        f"{result.stdout[-3000:]}\n{result.stderr[-3000:]}"
    return result


def test_readme_has_the_examples():
    assert len(BLOCKS) == 5
    assert any("pymeshlab" in b for b in BLOCKS) and any("open3d" in b for b in BLOCKS)
    # Every block that starts Dask processes keeps the work under the guard.
    for block in BLOCKS:
        if "Cluster(" in block:
            assert 'if __name__ == "__main__":' in block, block


def test_readme_quick_start_is_short():
    """README opens with the quick start: the two commands and three things to try, in under
    30 lines."""
    lines = (SOURCE / "README.md").read_text().splitlines()
    end = lines.index("## More")
    assert end < 30, end
    quick = "\n".join(lines[:end])
    for command in ("bash scripts/demo.sh", "bash scripts/test.sh", "meshbridge check",
                    "meshbridge repair", ".3mf", "repair.mlx"):
        assert command in quick, command


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_readme_python_block(index, tmp_path):
    code = BLOCKS[index]
    for module in imported_optional(code):
        if importlib.util.find_spec(module) is None:
            pytest.skip(f"README block {index} needs {module}, which is not installed here")
    run_block(code, tmp_path, index)


def test_readme_pymeshlab_block_with_stand_in(tmp_path):
    (code,) = [b for b in BLOCKS if "import pymeshlab" in b]
    run_block(code, tmp_path, "pymeshlab", extra_path=[Path(__file__).parent / "standin"])
    assert (tmp_path / "twocubes_repaired.ply").is_file()
    import meshbridge

    back = meshbridge.read(tmp_path / "twocubes_repaired.ply")
    assert (back.num_vertices, back.num_faces) == (16, 24)
