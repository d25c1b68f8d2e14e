"""What the study and plot scripts share: running `hpcontact run` on a case, and reading and
writing the numbers it leaves behind. Standard library only."""
import csv
import json
import os
import subprocess


def run_case(hpcontact, case, out_dir, sets=(), vtu=False):
    """Runs `hpcontact run CASE --out OUT_DIR -q` with `--set` overrides (and output.vtu=false
    unless vtu). Returns (summary.json as a dict, None), or (None, the program's error line
    (else its last line) without its "hpcontact: error: " prefix) when the run fails or leaves no summary."""
    cmd = [str(hpcontact), "run", str(case), "--out", str(out_dir), "-q"]
    for s in list(sets) + ([] if vtu else ["output.vtu=false"]):
        cmd += ["--set", s]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    summary_path = os.path.join(out_dir, "summary.json")
    if proc.returncode != 0 or not os.path.isfile(summary_path):
        lines = (proc.stderr or proc.stdout or "").strip().splitlines()
        # The error line; a command-line mistake (exit 2) follows it with the usage.
        errors = [line for line in lines if line.startswith("hpcontact: error: ")]
        msg = (errors or lines or [f"exit status {proc.returncode}, no message"])[-1]
        return None, msg.replace("hpcontact: error: ", "")
    with open(summary_path) as f:
        return json.load(f), None


def csv_number(v):
    """A value for a CSV cell: a number exactly as summary.json has it (repr round-trips),
    true/false, or '' if absent."""
    if v is None:
        return ""
    if isinstance(v, bool):
        return "true" if v else "false"
    return repr(v) if isinstance(v, float) else str(v)


def read_columns(path):
    """A CSV (pressure.csv, contact.csv, path.csv, ...) as {column: [values]}: numbers as
    floats, a text column (contact.csv's state) as strings."""
    cols = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            for k, v in row.items():
                try:
                    value = float(v)
                except ValueError:
                    value = v
                cols.setdefault(k, []).append(value)
    return cols
