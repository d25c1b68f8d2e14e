#!/usr/bin/env python3
"""Times the 24-row study bench/hertz-24.yaml run by the local executor (--jobs 2) and as a Slurm
job array on a one-node cluster of 2 CPUs started for the purpose (tests/slurm/conftest.py), and
writes the section "Studies: local processes and a Slurm job array" of BENCHMARKS.md (replacing
that section only; bench/report.py keeps it when it rewrites the rest).

    /usr/bin/python3 bench/study_executors.py [--hpcontact build/hpcontact] [--repeat 3]
"""
import argparse
import csv
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sections  # noqa: E402
sys.path.insert(0, os.path.join(ROOT, "tests", "slurm"))
from conftest import boot, require_slurm, start  # noqa: E402  (the tests' cluster)

STUDY = os.path.join(ROOT, "bench", "hertz-24.yaml")
BEGIN, END = "<!-- kept: study-executors -->", "<!-- /kept: study-executors -->"


def timed(argv, env):
    t0 = time.monotonic()
    r = subprocess.run(argv, env=env, capture_output=True, text=True, timeout=600)
    seconds = time.monotonic() - t0
    if r.returncode != 0:
        sys.exit(f"study_executors.py: {' '.join(argv)} failed ({r.returncode}):\n{r.stdout}{r.stderr}")
    return seconds


def row_seconds(out):
    with open(os.path.join(out, "study.csv"), newline="") as f:
        return [float(r["wall_time_s"]) for r in csv.DictReader(f)]


def section(local, slurm, rows, run_mean, repeat, cpu, load):
    per_task = (statistics.median(slurm) - statistics.median(local)) * 2 / rows
    fmt = lambda xs: f"{statistics.median(xs):.2f} s" + (f" ({min(xs):.2f}–{max(xs):.2f})" if len(xs) > 1 else "")
    return "\n".join([
        BEGIN,
        "## Studies: local processes and a Slurm job array (issue 19)",
        "",
        f"Written by `bench/study_executors.py` on {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, {cpu}, "
        f"load average at start {', '.join(f'{x:.1f}' for x in load)} (other work on the machine slows "
        "both executors alike). "
        f"The {rows}-row study `bench/hertz-24.yaml` (Hertz p-version, degrees 2–9 at three loads; one "
        f"run takes {run_mean * 1000:.0f} ms on average, its own `wall_time_s`) from the command to the "
        f"written study.csv, the median of {repeat} (range in brackets): locally with `--jobs 2`, and "
        "with `--executor slurm --wait` on a one-node cluster of 2 CPUs on the same machine "
        "(slurmctld and slurmd of Debian's slurm-wlm 22.05, `sched/backfill`, a task per CPU, "
        "the follower asking `scontrol` every 2 s).",
        "",
        "| executor | study of 24 rows | per row |",
        "|---|---:|---:|",
        f"| local, `--jobs 2` | {fmt(local)} | {statistics.median(local) / rows * 1000:.0f} ms |",
        f"| Slurm job array, 2 CPUs | {fmt(slurm)} | {statistics.median(slurm) / rows * 1000:.0f} ms |",
        "",
        f"The scheduler's overhead per task, (Slurm − local) × 2 CPUs / {rows} rows: "
        f"**{per_task:.2f} s** of a CPU slot. Most of it is waiting for the scheduler: slurmctld starts "
        "pending array tasks in its scheduling passes, 0–3 s after a CPU frees (its log shows the "
        "allocations in waves), not at once; then the start by slurmd and slurmstepd, and the "
        "follower's polling interval (up to 2 s at the end). A row of a study on a cluster should run "
        "much longer than that; with rows this short the local executor is the faster one.",
        END,
        ""])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--hpcontact", default=os.path.join(ROOT, "build", "hpcontact"),
                        help="the hpcontact executable (default build/hpcontact)")
    parser.add_argument("--repeat", type=int, default=3,
                        help="runs of the study per executor; the median is shown (default 3)")
    parser.add_argument("--output", default=os.path.join(ROOT, "BENCHMARKS.md"),
                        help="the file whose section is replaced (default BENCHMARKS.md)")
    args = parser.parse_args()
    exe = os.path.abspath(args.hpcontact)
    load = os.getloadavg()
    require_slurm()
    folder = tempfile.mkdtemp(prefix="hpcontact-bench-slurm-")
    c = boot(folder)
    local, slurm, runs = [], [], []
    try:
        start(c)
        for k in range(args.repeat):
            out = os.path.join(folder, f"local-{k}")
            local.append(timed([exe, "study", STUDY, "--jobs", "2", "--out", out, "-q"], c.env))
            runs += row_seconds(out)
            out = os.path.join(folder, f"slurm-{k}")
            slurm.append(timed([exe, "study", STUDY, "--executor", "slurm", "--wait", "--out", out, "-q"], c.env))
    finally:
        try:
            c.cancel_all()
        finally:
            c.stop()
    text = section(local, slurm, 24, statistics.mean(runs), args.repeat, sections.cpu_name(), load)
    sections.replace_section(args.output, text, BEGIN, END)
    shutil.rmtree(folder, ignore_errors=True)
    print(text)


if __name__ == "__main__":
    main()
