# SPDX-License-Identifier: GPL-3.0-or-later
"""Bulk repair of a folder of meshes on Dask distributed.

    python3 -m meshbridge.batch INDIR OUTDIR [--scheduler ADDRESS] [--workers N] [--json] ...

Every mesh file below INDIR (.obj .off .ply .stl, recursively) is read, repaired and written to
the same relative path below OUTDIR by the core's per-file job (``file_job.h``), the very code
``meshbridge batch`` runs, so the output files and the JSON Lines records are byte-identical to
it. One file is one Dask task; without ``--scheduler`` a LocalCluster on this machine runs them.

Resumable: every finished file (clean, repaired, failed or skipped) appends its record to a JSON
Lines log (default ``OUTDIR/.meshbridge-batch.jsonl``, the log ``meshbridge batch`` keeps too)
once its output is in place, with the options it was repaired with and the input's size and
time (``batch_log.h``). A rerun skips a file only when its last line says clean or repaired,
with the same options, from the same input, and the output is still there; every other file is
done again: a failed file is retried on every run (fix the input and rerun), a file whose input
or options changed is redone. After a kill every file ends up done exactly once. A bad file
gives one ``failed`` record and the run goes on; so does a file whose worker died on it.

Options as ``meshbridge batch``: ``--format obj|off|ply|stl|3mf``, ``--weld TOL|auto``,
``--fill-holes [MAX_EDGES]``, ``--pairing``, ``--print``, ``--self-intersections``; the same
options give the same output files and records.

Memory: tasks carry paths, not meshes; a worker reads its file itself, so a worker holds at most
``--threads-per-worker`` meshes (default 1), and the client keeps at most ``--in-flight`` tasks
submitted (default 4 per worker thread), so a folder of any size is never loaded at once.
``--memory-limit`` bounds each local worker (Dask restarts one that goes over, and its file is
recorded as failed after Dask's retries).

Exit status: 0 every file read and written, 2 some failed or were skipped, or bad arguments.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, Iterable, List, Optional, Tuple

from . import _core

__all__ = ["BatchSummary", "BatchWarnings", "main", "run_batch"]

#: Default log name inside OUTDIR.
LOG_NAME = ".meshbridge-batch.jsonl"


@dataclass
class BatchSummary:
    """What run_batch did. ``records`` maps each planned file name to its JSON Lines record."""

    records: Dict[str, str] = field(default_factory=dict)
    statuses: Dict[str, int] = field(default_factory=dict)
    done_before: int = 0  #: files the log already held (skipped by this run)
    done_now: int = 0  #: files finished by this run
    seconds: float = 0.0  #: wall time of this run, Dask's start included
    startup_seconds: float = 0.0  #: of which starting the LocalCluster or connecting to Dask
    #: the outputs' self-intersections were sought (``self_intersections=True``): the table's
    #: column and the summary's count of files with some
    self_intersections: bool = False

    @property
    def ok(self) -> bool:
        """True when every file was read and written (exit status 0)."""
        return self.statuses.get("failed", 0) == 0 and self.statuses.get("skipped", 0) == 0

    def sorted_records(self) -> List[str]:
        """The records in file name order (byte order, as the CLI sorts)."""
        return [self.records[name] for name in sorted(self.records, key=lambda n: n.encode())]

    def json_lines(self) -> str:
        """``meshbridge batch --json``'s stdout: the records one per line, by file name."""
        return "".join(record + "\n" for record in self.sorted_records())

    def table(self) -> str:
        """``meshbridge batch``'s stdout without --json: a Markdown table and the summary line."""
        crossing = self.self_intersections
        rows = [
            "| file | status | faces | singular edges | singular vertices | faces out | "
            "components after | watertight after | "
            + ("self-intersecting pairs | " if crossing else "") + "note |",
            "|---|---|---:|---:|---:|---:|---:|---|" + ("---:|" if crossing else "") + "---|",
        ]
        for line in self.sorted_records():
            r = json.loads(line)
            if r["status"] in ("clean", "repaired"):
                # An STL output counts as it will be re-read ("reread"), as in the CLI.
                after = r.get("reread", r["after"])
                pairs = f"{r['self_intersections']['face_pairs']} | " if crossing else ""
                rows.append(
                    f"| {r['file']} | {r['status']} | {r['faces_in']} | "
                    f"{r['before']['singular_edges']} | {r['before']['singular_vertices']} | "
                    f"{r['faces_out']} | {after['components']} | "
                    f"{'yes' if after['watertight'] else 'no'} | {pairs}|"
                )
            else:  # failed or skipped: no counts, the reason in the last column
                rows.append(f"| {r['file']} | {r['status']} | | | | | | | "
                            + ("| " if crossing else "") + f"{r.get('reason', '')} |")
        return "\n".join(rows) + "\n" + self.summary_line() + "\n"

    def summary_line(self) -> str:
        """``N file(s): c clean, r repaired, f failed, s skipped`` (with ``self_intersections``:
        ``; k with self-intersections``), as the CLI prints it."""
        counts = ", ".join(
            f"{self.statuses.get(s, 0)} {s}" for s in ("clean", "repaired", "failed", "skipped")
        )
        line = f"{len(self.records)} file(s): {counts}"
        if self.self_intersections:
            line += f"; {self.files_with_self_intersections()} with self-intersections"
        return line

    def files_with_self_intersections(self) -> int:
        """How many files' records count at least one self-intersecting face pair in the output."""
        return sum(1 for record in self.records.values()
                   if json.loads(record).get("self_intersections", {}).get("face_pairs", 0) > 0)


def _job_options(options: Dict[str, Any]) -> "_core.FileJobOptions":
    from . import _repair_options

    native = _core.FileJobOptions()
    native.format = options.get("format", "")
    native.elements = bool(options.get("elements", False))
    native.separate_stl_copies = bool(options.get("separate_stl_copies", True))
    native.repair = _repair_options(options.get("repair", {}))
    if options.get("print_preset"):
        native.print = True
        native.print_keeps_weld = "weld" in options.get("repair", {})
        native.print_keeps_fill_holes = "fill_holes" in options.get("repair", {})
    native.self_intersections = bool(options.get("self_intersections", False))
    return native


def run_file(job: Tuple[str, str, str, str], options: Dict[str, Any]) -> Tuple[str, str, str, str]:
    """One task: read -> repair -> write ``job`` = (input, output, name, output_name) with the
    core's run_file_job; returns (status, reason, record, warning lines). Runs on a Dask worker; the GIL is
    released while the core works. The files are the parallel work: the core uses one thread
    per file unless MESHBRIDGE_THREADS says otherwise."""
    os.environ.setdefault("MESHBRIDGE_THREADS", "1")
    return _core.run_file_job(*job, _job_options(options))


def read_log(path: str) -> Dict[str, str]:
    """The lines of a JSON Lines log by file name (the last line of a file wins). A last line without its newline (the run
    was killed while writing it) is cut off the file, so appending goes on cleanly."""
    records: Dict[str, str] = {}
    if not os.path.exists(path):
        return records
    with open(path, "rb+") as log:
        data = log.read()
        end = data.rfind(b"\n") + 1
        if end < len(data):
            log.truncate(end)
    for number, line in enumerate(data[:end].decode("utf-8").splitlines(), start=1):
        if not line.strip():
            continue
        try:
            name = json.loads(line)["file"]
        except (ValueError, KeyError, TypeError) as error:
            raise ValueError(f"{path}, line {number}: not a batch record ({error})") from None
        records[name] = line
    return records


def run_batch(
    in_dir: str,
    out_dir: str,
    *,
    client: Any = None,
    scheduler: Optional[str] = None,
    workers: Optional[int] = None,
    threads_per_worker: int = 1,
    memory_limit: Any = "auto",
    log_path: Optional[str] = None,
    format: str = "",
    elements: bool = False,
    repair: Optional[Dict[str, Any]] = None,
    in_flight: Optional[int] = None,
    in_place: bool = False,
    separate_stl_copies: bool = True,
    print_preset: bool = False,
    self_intersections: bool = False,
    progress: Optional[Callable[[int, int, str, str], None]] = None,
    warnings: Optional[Callable[[str, str], None]] = None,
) -> BatchSummary:
    """Repairs every mesh below ``in_dir`` into ``out_dir`` on the Dask ``client``.

    Dask: ``client`` (a distributed.Client, e.g. of a dask-jobqueue cluster), else a running
    ``scheduler`` address, else a LocalCluster of ``workers`` processes (default: one per core)
    with ``threads_per_worker`` threads and ``memory_limit`` each, started only when there is
    work left and closed at the end.
    ``log_path`` (default ``out_dir/.meshbridge-batch.jsonl``) makes the run resumable.
    ``in_place``: as ``meshbridge batch --in-place`` (OUTDIR may be INDIR or inside it).
    ``separate_stl_copies``: STL outputs move split vertex copies apart so that the file re-reads
    as repaired (default True; False keeps positions exact, as ``meshbridge batch --separate 0``).
    ``repair``: options of :func:`meshbridge.repair`. ``print_preset``: the slicer route of
    ``meshbridge batch --print`` (outputs 3MF; gap closing and hole filling of the preset unless
    ``repair`` names ``weld`` / ``fill_holes``). ``self_intersections``: as ``meshbridge batch
    --self-intersections``, each record gains the ``self_intersections`` object of the output as
    written (crossing face pairs, faces, component pairs); noted in the log, so a rerun without
    it redoes every file. ``in_flight``: tasks submitted at once
    (default 4 per worker thread). ``progress(done, total, name, status)`` is called per file,
    ``warnings(name, lines)`` per file this run finished with warnings (lines as the CLI prints
    them; :class:`BatchWarnings` prints them as the CLI does).
    Raises ValueError for a missing INDIR, OUTDIR inside INDIR, a bad format (a format other than
    3mf with ``print_preset``) or a corrupt log.
    """
    from distributed import as_completed

    if print_preset:
        if format.lower() not in ("", "3mf"):
            raise ValueError(f"print_preset writes 3MF, the format slicers read with units, "
                             f"objects and no re-weld; got format {format!r}")
        format = "3mf"
    options = {"format": format, "elements": elements, "repair": dict(repair or {}),
               "separate_stl_copies": separate_stl_copies, "print_preset": print_preset,
               "self_intersections": self_intersections}
    native = _job_options(options)
    jobs, unreadable = _core.plan_batch(in_dir, out_dir, native, in_place)
    log_path = log_path or os.path.join(out_dir, LOG_NAME)
    os.makedirs(os.path.dirname(os.path.abspath(log_path)), exist_ok=True)
    logged = read_log(log_path)
    by_name = {job[2]: job for job in jobs}
    # Kept: files done before with these options from the same input; the rest is done again.
    kept = {name: line for name, line in logged.items()
            if name in by_name and _core.is_done_in_log(line, by_name[name], native)[0]}
    _core.write_batch_log(log_path, list(kept.values()))
    summary = BatchSummary(records={name: _core.record_of_log_line(line)
                                    for name, line in kept.items()},
                           self_intersections=self_intersections)
    summary.done_before = len(summary.records)
    total = len(by_name) + len(unreadable)

    start = time.perf_counter()
    own_client = None
    own_cluster = None
    with open(log_path, "a", encoding="utf-8") as log:

        def finish(job: Tuple[str, str, str, str], status: str, record: str) -> None:
            name = job[2]
            log.write(_core.batch_log_line(record, job, native) + "\n")
            log.flush()
            summary.records[name] = record
            summary.done_now += 1
            if progress:
                progress(len(summary.records), total, name, status)

        for name, reason in unreadable:
            finish((os.path.join(in_dir, name), "", name, ""), "skipped",
                   _core.skipped_record(name, reason))

        todo = [job for job in jobs if job[2] not in summary.records]
        if not todo:
            summary.seconds = time.perf_counter() - start
            return _count(summary)
        if client is None:
            from distributed import Client, LocalCluster

            if scheduler:
                client = own_client = Client(scheduler)
            else:
                import logging

                own_cluster = LocalCluster(
                    n_workers=workers or os.cpu_count() or 1,
                    threads_per_worker=threads_per_worker,
                    memory_limit=memory_limit,
                    processes=True,
                    dashboard_address=None,
                    silence_logs=logging.ERROR,
                )
                client = own_client = Client(own_cluster)
            summary.startup_seconds = time.perf_counter() - start
        if in_flight is None:
            in_flight = 4 * max(1, sum(client.nthreads().values()))
        pending = iter(todo)
        futures = as_completed()
        by_key: Dict[str, Tuple[str, str, str, str]] = {}

        def submit_next() -> bool:
            job = next(pending, None)
            if job is None:
                return False
            future = client.submit(run_file, job, options, pure=False)
            by_key[future.key] = job
            futures.add(future)
            return True

        for _ in range(max(1, in_flight)):
            if not submit_next():
                break
        try:
            for future in futures:
                job = by_key.pop(future.key)
                lines = ""
                try:
                    status, _reason, record, lines = future.result()
                except Exception as error:  # the worker died on it (e.g. memory limit), etc.
                    status = "failed"
                    record = _core.failed_record(
                        job[2], job[3], f"{job[0]}: the Dask task failed ({type(error).__name__}: {error})"
                    )
                future.release()
                if lines and warnings:
                    warnings(job[2], lines)
                finish(job, status, record)
                submit_next()
        finally:
            if own_client is not None:
                own_client.close()
            if own_cluster is not None:
                own_cluster.close()
    summary.seconds = time.perf_counter() - start
    return _count(summary)


class BatchWarnings:
    """The CLI's way with a batch's warnings on stderr: lost data (texture coordinates, normals,
    groups, colours, ...) one line per file, each harmless kind (STL solid names, float rounding)
    once at the end with the number of files (``finish()``)."""

    def __init__(self, stream: Any = None) -> None:
        self.stream = stream or sys.stderr
        self.files: Dict[str, int] = {}  # kind -> files, in order of first sight

    def __call__(self, name: str, lines: str) -> None:
        seen = set()
        for line in lines.splitlines():
            kind = _core.harmless_warning_kind(line)
            if not kind:
                print(f"meshbridge.batch: warning: {name}: {line}", file=self.stream, flush=True)
            elif kind not in seen:
                seen.add(kind)
                self.files[kind] = self.files.get(kind, 0) + 1

    def finish(self) -> None:
        for kind, n in self.files.items():
            print(f"meshbridge.batch: warning: {n} file{'s' if n != 1 else ''}: {kind}",
                  file=self.stream)


def _count(summary: BatchSummary) -> BatchSummary:
    for record in summary.records.values():
        status = json.loads(record)["status"]
        summary.statuses[status] = summary.statuses.get(status, 0) + 1
    return summary


def _weld(text: str) -> Any:
    """--weld: 'auto' or a distance >= 0."""
    if text.lower() == "auto":
        return "auto"
    try:
        value = float(text)
    except ValueError:
        value = -1.0
    if not value >= 0 or value == float("inf"):
        raise argparse.ArgumentTypeError(f"must be 'auto' or a distance >= 0, got {text!r}")
    return value


def _whole(text: str) -> int:
    """--fill-holes: a whole number >= 0."""
    if not text.isdigit():
        raise argparse.ArgumentTypeError(f"must be a whole number of edges >= 0, got {text!r}")
    return int(text)


def _parse(argv: Optional[List[str]]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog="python3 -m meshbridge.batch",
        description="Repair every mesh below INDIR into OUTDIR (same relative paths) on Dask "
        "distributed; resumable through a JSON Lines log. Output files and --json records are "
        "byte-identical to `meshbridge batch`.",
    )
    parser.add_argument("in_dir", metavar="INDIR", help="folder searched recursively for meshes")
    parser.add_argument("out_dir", metavar="OUTDIR", help="folder the repaired meshes go to")
    parser.add_argument("--scheduler", metavar="ADDRESS",
                        help="a running Dask scheduler (tcp://host:8786); default: a LocalCluster")
    parser.add_argument("--workers", type=int, default=None,
                        help="LocalCluster worker processes (default: one per core)")
    parser.add_argument("--threads-per-worker", type=int, default=1,
                        help="files each local worker repairs at once (default 1)")
    parser.add_argument("--memory-limit", default="auto",
                        help="memory limit of each local worker, e.g. 4GiB (default: RAM / workers)")
    parser.add_argument("--in-flight", type=int, default=None,
                        help="tasks submitted at once (default: 4 per worker thread)")
    parser.add_argument("--log", default=None,
                        help=f"JSON Lines log of finished files (default: OUTDIR/{LOG_NAME})")
    parser.add_argument("--format", choices=["obj", "off", "ply", "stl", "3mf"], default="",
                        type=str.lower, help="write every result in this format (default: each "
                        "file's own); 3mf for a slicer")
    parser.add_argument("--weld", default=None, type=_weld, metavar="TOL|auto",
                        help="gap closing before pairing, as in `meshbridge repair` (default "
                        "auto; 0 = off)")
    parser.add_argument("--fill-holes", nargs="?", const=_core.DEFAULT_FILL_HOLES_MAX_EDGES,
                        default=None, type=_whole, metavar="MAX_EDGES",
                        help="close holes of at most MAX_EDGES edges after the repair (bare: "
                        f"{_core.DEFAULT_FILL_HOLES_MAX_EDGES}; default off)")
    parser.add_argument("--separate", choices=["auto", "0"], default="auto",
                        help="STL outputs: auto moves split vertex copies apart so the file "
                        "re-reads as repaired; 0 keeps positions exact (default auto)")
    parser.add_argument("--nested-shells", choices=["material", "cavity"], default="material",
                        type=str.lower, help="as in `meshbridge repair` (default material)")
    parser.add_argument("--pairing", choices=["geometric", "combinatorial"], default="geometric",
                        type=str.lower, help="as in `meshbridge repair` (default geometric)")
    parser.add_argument("--print", action="store_true", dest="print_preset",
                        help="the slicer route of `meshbridge batch --print`: the preset's gap "
                        "closing and hole filling (unless --weld / --fill-holes), duplicate and "
                        "zero-area faces removed unless that opens the surface, 3MF outputs")
    parser.add_argument("--self-intersections", action="store_true",
                        help="also count the faces of each output that cross or overlap (as "
                        "`meshbridge batch --self-intersections`): a table column, the records' "
                        "self_intersections, the files with some in the summary")
    parser.add_argument("--in-place", action="store_true",
                        help="allow OUTDIR to be INDIR or inside it (originals are replaced)")
    parser.add_argument("--json", action="store_true",
                        help="print every file's record (JSON Lines, sorted by file) on stdout "
                        "instead of the table; the summary goes to stderr")
    parser.add_argument("--elements", action="store_true", help="element lists in the records")
    parser.add_argument("--quiet", action="store_true", help="no progress and no summary on stderr")
    arguments = parser.parse_args(argv)
    for name in ("workers", "threads_per_worker", "in_flight"):
        value = getattr(arguments, name)
        if value is not None and value < 1:
            parser.error(f"--{name.replace('_', '-')} must be at least 1, got {value}")
    return arguments


def main(argv: Optional[List[str]] = None) -> int:
    arguments = _parse(argv)
    started = time.perf_counter()
    finished_here = [0]

    def progress(done: int, total: int, name: str, status: str) -> None:
        finished_here[0] += 1
        if arguments.quiet:
            return
        rate = finished_here[0] / max(time.perf_counter() - started, 1e-9)
        print(f"[{done}/{total}] {name}: {status} ({rate:.1f} files/s)", file=sys.stderr, flush=True)

    warnings = None if arguments.quiet else BatchWarnings()
    try:
        summary = run_batch(
            arguments.in_dir,
            arguments.out_dir,
            scheduler=arguments.scheduler,
            workers=arguments.workers,
            threads_per_worker=arguments.threads_per_worker,
            memory_limit=arguments.memory_limit,
            log_path=arguments.log,
            format=arguments.format,
            elements=arguments.elements,
            in_flight=arguments.in_flight,
            in_place=arguments.in_place,
            separate_stl_copies=arguments.separate == "auto",
            print_preset=arguments.print_preset,
            self_intersections=arguments.self_intersections,
            repair=dict({"pairing": arguments.pairing, "nested_shells": arguments.nested_shells},
                        **{name: value for name, value in (("weld", arguments.weld),
                                                           ("fill_holes", arguments.fill_holes))
                           if value is not None}),
            progress=progress,
            warnings=warnings,
        )
    except (ValueError, OSError, TimeoutError) as error:
        print(f"meshbridge.batch: {error}", file=sys.stderr)
        return 2

    if warnings:
        warnings.finish()
    sys.stdout.write(summary.json_lines() if arguments.json else summary.table())
    if not arguments.quiet:
        rate = summary.done_now / summary.seconds if summary.seconds > 0 else 0.0
        print(f"meshbridge.batch: {summary.done_before} file(s) done before (in the log), "
              f"{summary.done_now} now in {summary.seconds:.1f} s ({rate:.2f} files/s; "
              f"{summary.startup_seconds:.1f} s of it starting Dask)"
              + ("; " + summary.summary_line() if arguments.json else ""), file=sys.stderr)
    return 0 if summary.ok else 2


if __name__ == "__main__":
    sys.exit(main())
