# SPDX-License-Identifier: GPL-3.0-or-later
"""Files per second of `python3 -m meshbridge.batch` (Dask, 1 and 2 workers) against
`meshbridge batch --jobs 1/2` on the same folder, side by side.

    PYTHONPATH=build/release/python:tests/python python3 python/bench/batch_throughput.py \
        build/release/cli/meshbridge [FILES] [ROUNDS]

The folder (made in a temporary directory): the real-world corpus (tests/data/realworld), the
bundled models (resources/models/*.off) and generated 3D checkerboards of 6..19 cells a side
(1,296 to 41,160 triangles) up to FILES files (default 120). Each round runs every method once,
in turn, each into a fresh OUTDIR, as whole processes (Dask's start included); the table shows
the best round of ROUNDS (default 3), and for Dask also the rate without its start-up (the
closing line of meshbridge.batch says how long starting the LocalCluster took).
"""

import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import mesh_models

SOURCE = Path(__file__).resolve().parents[2]


def make_folder(root: Path, files: int) -> int:
    for f in (SOURCE / "tests" / "data" / "realworld").iterdir():
        if f.suffix.lower() in (".obj", ".off", ".ply", ".stl"):
            shutil.copy(f, root / f.name)
    for f in (SOURCE / "resources" / "models").glob("*.off"):
        shutil.copy(f, root / f.name)
    count = sum(1 for _ in root.iterdir())
    i = 0
    while count < files:
        n = 6 + i % 14
        vertices, faces = mesh_models.checkerboard(n)
        mesh_models.write_obj(root / f"checkerboard_{i:03d}_n{n}.obj", vertices, faces)
        i += 1
        count += 1
    return count


def run(command, out: Path):
    shutil.rmtree(out, ignore_errors=True)
    start = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        raise SystemExit(f"{command} failed ({done.returncode}): {done.stderr[-2000:]}")
    startup = re.search(r"; ([0-9.]+) s of it starting Dask", done.stderr)
    return seconds, float(startup.group(1)) if startup else 0.0


def main() -> None:
    cli = sys.argv[1]
    files = int(sys.argv[2]) if len(sys.argv) > 2 else 120
    rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        indir = tmp / "in"
        indir.mkdir()
        total = make_folder(indir, files)
        methods = {
            "meshbridge batch --jobs 1": [cli, "batch", indir, tmp / "out", "--json", "--quiet", "--jobs", "1"],
            "meshbridge batch --jobs 2": [cli, "batch", indir, tmp / "out", "--json", "--quiet", "--jobs", "2"],
            "python3 -m meshbridge.batch --workers 1": [sys.executable, "-m", "meshbridge.batch", indir, tmp / "out", "--json", "--workers", "1"],
            "python3 -m meshbridge.batch --workers 2": [sys.executable, "-m", "meshbridge.batch", indir, tmp / "out", "--json", "--workers", "2"],
        }
        best = {name: (float("inf"), 0.0) for name in methods}
        for _ in range(rounds):
            for name, command in methods.items():
                seconds, startup = run([str(c) for c in command], tmp / "out")
                if seconds < best[name][0]:
                    best[name] = (seconds, startup)
        print(f"{total} files; best of {rounds} rounds, whole processes")
        print("| method | wall s | files/s | files/s without Dask's start |\n|---|---:|---:|---:|")
        for name, (seconds, startup) in best.items():
            steady = f"{total / (seconds - startup):.1f}" if startup else "–"
            print(f"| `{name}` | {seconds:.2f} | {total / seconds:.1f} | {steady} |")


if __name__ == "__main__":
    main()
