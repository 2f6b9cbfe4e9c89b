# SPDX-License-Identifier: GPL-3.0-or-later
"""python3 -m meshbridge.batch on Dask: killed half way and resumed, every file done exactly once;
output and JSON byte-identical to `meshbridge batch`."""

import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
import zipfile
from pathlib import Path

import pytest

import mesh_models

pytest.importorskip("distributed")

SOURCE = Path(os.environ.get("MESHBRIDGE_SOURCE_DIR", Path(__file__).parents[2]))
CLI = os.environ.get("MESHBRIDGE_CLI", "")
BAD = {"broken.obj": "this is not a mesh\n", "empty.stl": "", "bad/index.off": "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"}


def make_corpus(root: Path) -> int:
    """The real-world corpus, the bundled models, generated checkerboards and bad files."""
    for f in (SOURCE / "tests" / "data" / "realworld").iterdir():
        if f.suffix.lower() in (".obj", ".off", ".ply", ".stl"):
            shutil.copy(f, root / f.name)
    (root / "models").mkdir()
    for f in (SOURCE / "resources" / "models").glob("*.off"):
        shutil.copy(f, root / "models" / f.name)
    (root / "generated").mkdir()
    for n in range(6, 14):
        vertices, faces = mesh_models.checkerboard(n)
        mesh_models.write_obj(root / "generated" / f"checkerboard_{n:02d}.obj", vertices, faces)
    for name, text in BAD.items():
        (root / name).parent.mkdir(exist_ok=True)
        (root / name).write_text(text)
    return sum(1 for p in root.rglob("*") if p.is_file())


def batch(*args, **kwargs):
    return subprocess.run([sys.executable, "-m", "meshbridge.batch", *map(str, args)],
                          capture_output=True, text=True, timeout=600, **kwargs)


def log_records(log: Path):
    lines = log.read_text().splitlines() if log.exists() else []
    return [json.loads(line) for line in lines]


def test_killed_half_way_and_resumed_every_file_done_once(tmp_path):
    indir, outdir, log = tmp_path / "in", tmp_path / "out", tmp_path / "run.jsonl"
    indir.mkdir()
    total = make_corpus(indir)
    assert total == 8 + 10 + 8 + 3

    process = subprocess.Popen(
        [sys.executable, "-m", "meshbridge.batch", indir, outdir, "--workers", "2", "--log", log,
         "--in-flight", "2", "--quiet"], start_new_session=True)
    try:
        while process.poll() is None and len(log_records(log)) < total // 3:
            time.sleep(0.005)
    finally:
        os.killpg(process.pid, signal.SIGKILL)  # the client and its LocalCluster's workers
        process.wait()
    first = log_records(log)
    print(f"killed after {len(first)} of {total} records")
    assert 0 < len(first) < total, "the run was not killed half way"

    resumed = batch(indir, outdir, "--workers", "2", "--log", log, "--json")
    assert resumed.returncode == 2, resumed.stderr  # the bad files failed
    records = log_records(log)
    names = [r["file"] for r in records]
    assert len(names) == len(set(names)) == total  # every file exactly once
    # The first run's records were kept, not redone; its failed files were retried.
    kept = [r for r in first if r["status"] != "failed"]
    assert records[: len(kept)] == kept
    statuses = {r["file"]: r["status"] for r in records}
    assert {name for name, status in statuses.items() if status == "failed"} == set(BAD)
    for record in records:
        if record["status"] in ("clean", "repaired"):
            assert (outdir / record["output"]).is_file()
            assert record["after"]["singular_edges"] == record["after"]["singular_vertices"] == 0
            assert record["faces_out"] >= record["faces_in"] - record["faces_set_aside"]
    cubes = {r["file"]: r for r in records if r["file"].startswith("generated/")}
    for n in range(6, 14):
        r = cubes[f"generated/checkerboard_{n:02d}.obj"]
        assert r["after"]["components"] == (n ** 3 + 1) // 2 and r["after"]["boundary_edges"] == 0
    lines = resumed.stdout.splitlines()
    assert [json.loads(line)["file"] for line in lines] == sorted(names)

    again = batch(indir, outdir, "--log", log)
    assert again.returncode == 2
    bad = len(BAD)  # failed files are retried on every run
    assert f"{total - bad} file(s) done before (in the log), {bad} now" in again.stderr
    assert len(log_records(log)) == total

    if not CLI:
        pytest.skip("MESHBRIDGE_CLI not set: byte-identity with `meshbridge batch` not checked")
    cli_out = tmp_path / "cli_out"
    cli = subprocess.run([CLI, "batch", indir, cli_out, "--json", "--jobs", "2", "--quiet"],
                         capture_output=True, text=True, timeout=600)
    assert cli.returncode == 2, cli.stderr
    assert resumed.stdout == cli.stdout  # the same records, byte for byte
    table = subprocess.run([CLI, "batch", indir, tmp_path / "cli_table", "--quiet"],
                           capture_output=True, text=True, timeout=600)
    assert again.stdout == table.stdout  # and the same table
    # A worker killed while writing leaves its hidden temporary file (never a half-written
    # output), named by the atomic writer ".NAME.PID.N.RANDOM.tmp.EXT"; everything else is the
    # CLI's output, file for file.
    temporary = re.compile(r"\..+\.[0-9]+\.[0-9]+\.[0-9]+\.tmp\.\w+")
    ours = sorted(p.relative_to(outdir) for p in outdir.rglob("*")
                  if p.is_file() and not temporary.fullmatch(p.name))
    theirs = sorted(p.relative_to(cli_out) for p in cli_out.rglob("*")
                    if p.is_file() and p.name != ".meshbridge-batch.jsonl")
    assert ours == theirs
    for relative in ours:
        assert (outdir / relative).read_bytes() == (cli_out / relative).read_bytes(), relative


def test_running_scheduler_and_formats(tmp_path):
    """--scheduler ADDRESS: the work goes to a cluster that is already running."""
    from distributed import LocalCluster

    indir = tmp_path / "in"
    (indir / "sub").mkdir(parents=True)
    for name in ("twocubes", "prisms24"):
        shutil.copy(SOURCE / "resources" / "models" / f"{name}.obj", indir / "sub" / f"{name}.obj")
        shutil.copy(SOURCE / "resources" / "models" / f"{name}.off", indir / "sub" / f"{name}.off")
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        result = batch(indir, tmp_path / "out", "--scheduler", cluster.scheduler_address,
                       "--format", "ply", "--json")
    assert result.returncode == 0, result.stderr
    records = [json.loads(line) for line in result.stdout.splitlines()]
    assert [r["output"] for r in records] == ["sub/prisms24.ply", "sub/prisms24-off.ply",
                                              "sub/twocubes.ply", "sub/twocubes-off.ply"]
    assert all(r["status"] == "repaired" for r in records)
    assert "[4/4]" in result.stderr  # progress


def test_bad_arguments_exit_2_with_a_message(tmp_path):
    missing = batch(tmp_path / "nope", tmp_path / "out")
    assert missing.returncode == 2 and "nope: no such folder" in missing.stderr
    (tmp_path / "in").mkdir()
    inside = batch(tmp_path / "in", tmp_path / "in" / "out")
    assert inside.returncode == 2 and "inside the input folder" in inside.stderr
    workers = batch(tmp_path / "in", tmp_path / "out", "--workers", "0")
    assert workers.returncode == 2 and "--workers must be at least 1" in workers.stderr
    corrupt = tmp_path / "corrupt.jsonl"
    corrupt.write_text("not json\n")
    (tmp_path / "in" / "a.obj").write_text("v 0 0 0\n")
    bad_log = batch(tmp_path / "in", tmp_path / "out", "--log", corrupt)
    assert bad_log.returncode == 2 and "corrupt.jsonl, line 1: not a batch record" in bad_log.stderr


def output_files(folder: Path):
    """Each output's bytes; a 3MF's parts unzipped, with the random UUIDs lib3mf gives each
    object and build item blanked (two runs of the CLI differ there too)."""
    files = {}
    for p in folder.rglob("*"):
        if not p.is_file() or p.name == ".meshbridge-batch.jsonl":
            continue
        data = p.read_bytes()
        if p.suffix == ".3mf":
            with zipfile.ZipFile(p) as archive:
                data = b"".join(name.encode() + re.sub(rb'UUID="[^"]*"', b'UUID=""', archive.read(name))
                                for name in sorted(archive.namelist()))
        files[p.relative_to(folder)] = data
    return files


def test_failed_files_retried_changed_options_redone_same_as_cli(tmp_path):
    """A failed file is retried on the next run; a file whose options or input changed is redone
    (the log keeps the options); --format 3mf --weld --fill-holes give the CLI's outputs."""
    indir, outdir = tmp_path / "in", tmp_path / "out"
    indir.mkdir()
    for name in ("twocubes", "prisms24", "cube_with_hole"):
        shutil.copy(SOURCE / "resources" / "models" / f"{name}.obj", indir / f"{name}.obj")
    (indir / "broken.obj").write_text("this is not a mesh\n")

    first = batch(indir, outdir, "--workers", "1")
    assert first.returncode == 2, first.stderr
    shutil.copy(SOURCE / "resources" / "models" / "bowtie.obj", indir / "broken.obj")
    fixed = batch(indir, outdir, "--workers", "1")
    assert fixed.returncode == 0, fixed.stderr
    assert "3 file(s) done before (in the log), 1 now" in fixed.stderr

    options = ["--format", "3mf", "--weld", "1e-5", "--fill-holes"]
    changed = batch(indir, outdir, "--workers", "1", "--json", *options)
    assert changed.returncode == 0, changed.stderr
    assert "0 file(s) done before (in the log), 4 now" in changed.stderr
    records = {json.loads(line)["file"]: json.loads(line) for line in changed.stdout.splitlines()}
    assert records["cube_with_hole.obj"]["holes"]["holes_filled"] == 1
    assert records["cube_with_hole.obj"]["output"] == "cube_with_hole.3mf"
    log = [json.loads(line) for line in (outdir / ".meshbridge-batch.jsonl").read_text().splitlines()]
    assert all("format=3mf weld=1.0000000000000001e-05" in r["batch_log"]["options"] for r in log)
    assert all(" fill_holes=32 " in r["batch_log"]["options"] for r in log)

    same = batch(indir, outdir, "--workers", "1", *options)
    assert "4 file(s) done before (in the log), 0 now" in same.stderr, same.stderr
    time.sleep(0.01)
    (indir / "twocubes.obj").write_text((indir / "twocubes.obj").read_text() + "# edited\n")
    edited = batch(indir, outdir, "--workers", "1", *options)
    assert "3 file(s) done before (in the log), 1 now" in edited.stderr, edited.stderr

    if not CLI:
        pytest.skip("MESHBRIDGE_CLI not set: the CLI's outputs not compared")
    cli_out = tmp_path / "cli_out"
    cli = subprocess.run([CLI, "batch", indir, cli_out, "--json", "--quiet", *options],
                         capture_output=True, text=True, timeout=600)
    assert cli.returncode == 0, cli.stderr
    assert cli.stdout == edited_json(indir, outdir, options)
    ours, theirs = output_files(outdir), output_files(cli_out)
    ours = {relative: data for relative, data in ours.items() if relative.suffix == ".3mf"}
    assert sorted(ours) == sorted(theirs) == [Path(f"{n}.3mf") for n in
                                              ("broken", "cube_with_hole", "prisms24", "twocubes")]
    for relative in ours:
        assert ours[relative] == theirs[relative], relative
    # The CLI's --resume reads the same log: nothing to redo for the same options.
    resumed = subprocess.run([CLI, "batch", indir, outdir, "--json", "--resume", *options],
                             capture_output=True, text=True, timeout=600)
    assert resumed.returncode == 0 and "4 skipped" in resumed.stderr, resumed.stderr


def test_print_preset_as_repair_print_in_both_batches(tmp_path):
    """--print in the Dask batch and in `meshbridge batch` is `meshbridge repair IN OUT.3mf
    --print` per file: 3MF outputs with the same meshes, records with the same counts; the log
    keeps the preset (a run without it redoes every file); another --format is refused."""
    if not CLI:
        pytest.skip("MESHBRIDGE_CLI not set")
    indir = tmp_path / "in"
    indir.mkdir()
    for name in ("twocubes.obj", "cube_with_hole.obj", "prisms24.off"):
        shutil.copy(SOURCE / "resources" / "models" / name, indir / name)
    shutil.copy(SOURCE / "tests" / "data" / "realworld2" / "sumo_tram.obj", indir / "sumo_tram.obj")
    dask_out, cli_out = tmp_path / "dask", tmp_path / "cli"
    ours = batch(indir, dask_out, "--workers", "1", "--json", "--quiet", "--print")
    assert ours.returncode == 0, ours.stderr
    theirs = subprocess.run([CLI, "batch", indir, cli_out, "--json", "--quiet", "--print"],
                            capture_output=True, text=True, timeout=600)
    assert theirs.returncode == 0, theirs.stderr
    assert ours.stdout == theirs.stdout
    assert output_files(dask_out) == output_files(cli_out)
    records = {json.loads(line)["file"]: json.loads(line) for line in ours.stdout.splitlines()}
    assert sorted(r["output"] for r in records.values()) == [
        "cube_with_hole.3mf", "prisms24.3mf", "sumo_tram.3mf", "twocubes.3mf"]
    assert records["cube_with_hole.obj"]["holes"]["holes_filled"] == 1  # the preset fills
    for name, record in records.items():
        report = tmp_path / f"{name}.json"
        single = subprocess.run([CLI, "repair", indir / name, tmp_path / f"{name}.3mf", "--print",
                                 "--report", report], capture_output=True, text=True, timeout=600)
        assert single.returncode == 0, single.stderr
        alone = json.loads(report.read_text())
        for key in ("faces_out", "vertices_out", "duplicate_faces_removed",
                    "zero_area_faces_removed", "holes", "gaps", "after", "reread"):
            assert record.get(key) == alone.get(key), (name, key)
    log = (dask_out / ".meshbridge-batch.jsonl").read_text()
    assert log.count(" print=1 ") == 4
    again = batch(indir, dask_out, "--workers", "1", "--print", "--format", "3mf")
    assert "4 file(s) done before (in the log), 0 now" in again.stderr, again.stderr
    plain = batch(indir, dask_out, "--workers", "1", "--format", "3mf")
    assert "0 file(s) done before (in the log), 4 now" in plain.stderr, plain.stderr
    refused = batch(indir, dask_out, "--workers", "1", "--print", "--format", "stl")
    assert refused.returncode == 2 and "print_preset writes 3MF" in refused.stderr
    cli_refused = subprocess.run([CLI, "batch", indir, cli_out, "--print", "--format", "stl"],
                                 capture_output=True, text=True, timeout=600)
    assert cli_refused.returncode == 2 and "--print writes 3MF" in cli_refused.stderr


# Two unit cubes as quads, the second moved by (0.5, 0.5, 0.5): its three low faces cross the
# first one's three high faces, two each (as tests/cli/cli_test.sh writes it).
CROSSING_CUBES = "".join(
    [f"v {x + d} {y + d} {z + d}\n" for d in (0, 0.5) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    + [f"f {' '.join(str(i + 8 * c) for i in face)}\n" for c in (0, 1) for face in (
        (1, 3, 4, 2), (5, 6, 8, 7), (1, 2, 6, 5), (3, 7, 8, 4), (1, 5, 7, 3), (2, 4, 8, 6))])


def test_self_intersections_counted_in_both_batches(tmp_path):
    """--self-intersections in the Dask batch and in `meshbridge batch` (one and two jobs): the
    same records and table, the crossing cubes' 6 face pairs (6 faces, 1 pair of shells), the
    two cubes touching along an edge 0 (also as STL, whose split copies are moved apart), as
    `repair --self-intersections` counts them; the log keeps the option, so a run without it
    redoes every file."""
    if not CLI:
        pytest.skip("MESHBRIDGE_CLI not set")
    indir = tmp_path / "in"
    indir.mkdir()
    (indir / "crossing.obj").write_text(CROSSING_CUBES)
    shutil.copy(SOURCE / "resources" / "models" / "twocubes.obj", indir / "twocubes.obj")
    shutil.copy(SOURCE / "resources" / "models" / "twocubes.off", indir / "twocubes.off")
    ours = batch(indir, tmp_path / "dask", "--workers", "1", "--json", "--quiet",
                 "--self-intersections")
    assert ours.returncode == 0, ours.stderr
    records = {json.loads(line)["file"]: json.loads(line) for line in ours.stdout.splitlines()}
    crossing = records["crossing.obj"]["self_intersections"]
    assert (crossing["face_pairs"], crossing["faces"], crossing["component_pairs"]) == (6, 6, 1)
    for name in ("twocubes.obj", "twocubes.off"):
        assert records[name]["status"] == "repaired"
        assert records[name]["self_intersections"]["face_pairs"] == 0
    for jobs in ("1", "2"):
        theirs = subprocess.run([CLI, "batch", indir, tmp_path / f"cli{jobs}", "--json", "--quiet",
                                 "--self-intersections", "--jobs", jobs],
                                capture_output=True, text=True, timeout=600)
        assert theirs.returncode == 0, theirs.stderr
        assert ours.stdout == theirs.stdout
    for name in records:
        report = tmp_path / f"{name}.json"
        single = subprocess.run([CLI, "repair", indir / name, tmp_path / name, "--report", report,
                                 "--self-intersections"], capture_output=True, text=True, timeout=600)
        assert single.returncode == 0, single.stderr
        assert json.loads(report.read_text())["self_intersections"] == \
            records[name]["self_intersections"]
    # The table: a column, and the files with some in the summary.
    table = batch(indir, tmp_path / "table", "--workers", "1", "--quiet", "--self-intersections")
    cli_table = subprocess.run([CLI, "batch", indir, tmp_path / "cli_table", "--quiet",
                                "--self-intersections"], capture_output=True, text=True, timeout=600)
    assert table.stdout == cli_table.stdout
    assert "| watertight after | self-intersecting pairs | note |" in table.stdout
    assert "| crossing.obj | clean | 12 | 0 | 0 | 12 | 2 | yes | 6 | |" in table.stdout
    assert "3 file(s): 1 clean, 2 repaired, 0 failed, 0 skipped; 1 with self-intersections" \
        in table.stdout
    # STL outputs: counted on the repaired polygons as written (as repair counts them), the
    # touching copies moved apart by the separation: still 0.
    stl = batch(indir, tmp_path / "stl", "--workers", "1", "--json", "--quiet", "--format", "stl",
                "--self-intersections")
    cli_stl = subprocess.run([CLI, "batch", indir, tmp_path / "cli_stl", "--json", "--quiet",
                              "--format", "stl", "--self-intersections"],
                             capture_output=True, text=True, timeout=600)
    assert stl.stdout == cli_stl.stdout
    as_stl = {json.loads(line)["file"]: json.loads(line) for line in stl.stdout.splitlines()}
    assert as_stl["crossing.obj"]["self_intersections"]["face_pairs"] == 6
    assert as_stl["crossing.obj"]["self_intersections"]["component_pairs"] == 1
    assert as_stl["twocubes.obj"]["self_intersections"]["face_pairs"] == 0
    # The log keeps the option: the same run again does nothing, one without it everything.
    log = (tmp_path / "dask" / ".meshbridge-batch.jsonl").read_text()
    assert log.count(" self_intersections=1") == 3
    again = batch(indir, tmp_path / "dask", "--workers", "1", "--self-intersections")
    assert "3 file(s) done before (in the log), 0 now" in again.stderr, again.stderr
    assert "; 1 with self-intersections" in again.stdout  # (from the logged records)
    plain = batch(indir, tmp_path / "dask", "--workers", "1", "--json")
    assert "0 file(s) done before (in the log), 3 now" in plain.stderr, plain.stderr
    assert '"self_intersections"' not in plain.stdout


def edited_json(indir: Path, outdir: Path, options) -> str:
    """The Python batch's --json records of a run with nothing left to do (all from its log)."""
    result = batch(indir, outdir, "--workers", "1", "--json", *options)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_warnings_once_per_harmless_kind_lost_data_per_file_quiet_none(tmp_path):
    indir = tmp_path / "in"
    indir.mkdir()
    for n in (1, 2, 3):
        (indir / f"s{n}.stl").write_text(
            f"solid part{n}\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
            f"vertex 0 1 0\nendloop\nendfacet\nendsolid part{n}\n")
        (indir / f"uv{n}.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n")
    result = batch(indir, tmp_path / "out", "--workers", "1", "--format", "stl")
    assert result.returncode == 0, result.stderr
    warnings = [line for line in result.stderr.splitlines() if "warning" in line]
    assert warnings.count("meshbridge.batch: warning: 3 files: ASCII STL solid names not written "
                          "(MeshBridge reads past them)") == 1, result.stderr
    for n in (1, 2, 3):
        assert (f"meshbridge.batch: warning: uv{n}.obj: output uv{n}.stl: 1 texture coordinate "
                "(vt) not written: STL holds none per corner (write OBJ to keep them)") in warnings, result.stderr
    assert len(warnings) == 4, result.stderr
    quiet = batch(indir, tmp_path / "quiet", "--workers", "1", "--format", "stl", "--quiet")
    assert quiet.returncode == 0 and quiet.stderr == "", quiet.stderr
