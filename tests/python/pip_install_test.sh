#!/usr/bin/env bash
# `pip install --no-build-isolation .` of the repository into a fresh virtual environment that
# sees Debian's packages (numpy, dask), with no package index (no network), then the installed
# module used from outside the source tree.
# Usage: pip_install_test.sh PYTHON SOURCE_DIR WORK_DIR
set -euo pipefail
python="$1" source="$2" work="$3"
rm -rf "$work"
mkdir -p "$work"
"$python" -m venv --system-site-packages "$work/venv"
# The CMake build goes below WORK_DIR (setup.py: MESHBRIDGE_BUILD_TEMP), not into the source tree.
MESHBRIDGE_BUILD_TEMP="$work/build" "$work/venv/bin/pip" install --no-build-isolation --no-index \
  --quiet "$source"
cd "$work"
"$work/venv/bin/python" - "$source" <<'PY'
import sys
from pathlib import Path

import meshbridge

source = Path(sys.argv[1])
assert Path(meshbridge.__file__).resolve().is_relative_to(Path(sys.prefix).resolve()), meshbridge.__file__
assert (Path(meshbridge.__file__).parent / "_core.pyi").exists()
assert (Path(meshbridge.__file__).parent / "py.typed").exists()
result = meshbridge.repair(meshbridge.read(source / "resources/models/twocubes.obj"))
assert (len(result.vertices), len(result.faces)) == (16, 24), result.report
assert result.report["after"]["components"] == 2
print("installed:", meshbridge.__file__)
PY
"$work/venv/bin/python" -m meshbridge.batch --help | grep -q -- "--scheduler"
echo "pip_install_test: 1 passed, 0 failed"
