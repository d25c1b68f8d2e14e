"""What the study and plot scripts share: running `hpcontact run` on a case, and reading and
writing the numbers it leaves behind. Standard library only, but for read_vtu (numpy)."""
import argparse
import csv
import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

SCRIPTS = os.path.dirname(os.path.abspath(__file__))


def script_parser(doc):
    """The command line of a script whose docstring is its manual: the first paragraph is the
    description, the rest the epilog of --help, as written."""
    head, _, rest = doc.partition("\n\n")
    return argparse.ArgumentParser(description=head, epilog=rest or None,
                                   formatter_class=argparse.RawDescriptionHelpFormatter)


def default_hpcontact():
    """The hpcontact program a script starts unless told otherwise: build/hpcontact of the
    repository the script is in; for a script installed in <prefix>/share/hpcontact/scripts,
    <prefix>/bin/hpcontact; else hpcontact on PATH (else the first, for the error message)."""
    built = os.path.join(os.path.dirname(SCRIPTS), "build", "hpcontact")
    installed = os.path.normpath(os.path.join(SCRIPTS, "..", "..", "..", "bin", "hpcontact"))
    for path in (built, installed):
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return path
    return shutil.which("hpcontact") or built


# Quantities of the plots, as powers of the input's force F and length L (a 2D model: forces
# and energies per unit thickness).
QUANTITIES = {"length": (0, 1), "displacement": (0, 1), "stress": (1, -2), "pressure": (1, -2),
              "force": (1, 0), "force per thickness": (1, -1), "energy per thickness": (1, 0),
              "penalty": (1, -3), "strain": (0, 0)}


def units_of(summary):
    """The units a run names: summary.json's "units" (a mapping {"length": "mm", "force": "N"},
    or one string such as "N, mm"), else None (the input has no unit system: its numbers are in
    whatever consistent units the user chose)."""
    units = (summary or {}).get("units")
    return units if isinstance(units, (dict, str)) and units else None


def unit_text(quantity, units=None):
    """How a plot names the unit of `quantity` (a key of QUANTITIES): "[N/mm²]" from a units
    mapping with force and length, "(stress, units: N, mm)" from a units string, else
    "(stress, input units)"; strain is "[-]"."""
    force, length = QUANTITIES[quantity]
    if force == 0 and length == 0:
        return "[-]"
    if isinstance(units, dict) and "length" in units and (force == 0 or "force" in units):
        if quantity == "energy per thickness":
            return f"[{units['force']}·{units['length']}/{units['length']}]"
        power = {1: "", 2: "²", 3: "³"}
        text = units["force"] if force else ""
        if length > 0:
            text = (f"{text}·" if text else "") + units["length"] + power[length]
        elif length < 0:
            text += f"/{units['length']}{power[-length]}"
        return f"[{text}]"
    if isinstance(units, str):
        return f"({quantity}, units: {units})"
    return f"({quantity}, input units)"


def axis_label(name, quantity, units=None):
    """An axis or colour-bar label: the name and its unit, e.g. "X [mm]" or
    "X (length, input units)"."""
    return f"{name} {unit_text(quantity, units)}"


class StudyError(Exception):
    """A study file or a study's results that cannot be used; the message names the file."""


def check_labelled(entries, key, allowed, mapping_hint, where):
    """The entries of a study file's list `key` (runs, curves): each a mapping with keys among
    `allowed` and a non-empty label used once. `where(text)` prefixes the file's name;
    StudyError "<file>: <key>[i]: ..." otherwise."""
    labels = set()
    for i, entry in enumerate(entries):
        def at(text, i=i):
            return where(f"{key}[{i}]: {text}")
        if not isinstance(entry, dict):
            raise StudyError(at(mapping_hint))
        unknown = set(entry) - allowed
        if unknown:
            raise StudyError(at(f"unknown key(s) {', '.join(sorted(unknown))}"))
        if not isinstance(entry.get("label"), str) or not entry["label"]:
            raise StudyError(at("'label' (a string) is required"))
        if entry["label"] in labels:
            raise StudyError(at(f"label '{entry['label']}' is used twice"))
        labels.add(entry["label"])


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


def read_run_csv(folder, name, script, why_missing):
    """A results folder's CSV `name` as read_columns gives it, and its summary.json (or {});
    exits naming the script, the file and `why_missing` when the file is absent, or when it
    has no rows."""
    path = os.path.join(folder, name)
    if not os.path.isfile(path):
        sys.exit(f"{script}: {path}: no such file ({why_missing})")
    cols = read_columns(path)
    if not cols:
        sys.exit(f"{script}: {path}: no rows")
    summary = {}
    if os.path.isfile(os.path.join(folder, "summary.json")):
        with open(os.path.join(folder, "summary.json")) as f:
            summary = json.load(f)
    return cols, summary


def read_vtu(path):
    """An ASCII VTU file as hpcontact writes it (solution.vtu, contact.vtu): the point
    coordinates (n x 2, reference configuration), the cells as arrays of point indices, the point
    arrays {name: values} (vectors n x components) and the cell arrays {name: values}.
    ValueError naming the file if it is not such a file."""
    import numpy as np

    def numbers(data_array, dtype=float):
        return np.array((data_array.text or "").split(), dtype=dtype)

    try:
        piece = ET.parse(path).getroot().find("UnstructuredGrid/Piece")
    except ET.ParseError as e:
        raise ValueError(f"{path}: not an XML file ({e})")
    if piece is None or piece.find("Points/DataArray") is None or piece.find("Cells") is None:
        raise ValueError(f"{path}: no UnstructuredGrid/Piece with points and cells")
    points = numbers(piece.find("Points/DataArray")).reshape(-1, 3)[:, :2]
    cells_xml = {a.get("Name"): a for a in piece.find("Cells")}
    connectivity = numbers(cells_xml["connectivity"], np.int64)
    offsets = numbers(cells_xml["offsets"], np.int64)
    cells = np.split(connectivity, offsets[:-1])

    def arrays(section):
        out = {}
        for a in piece.find(section) if piece.find(section) is not None else []:
            values = numbers(a)
            k = int(a.get("NumberOfComponents", "1"))
            out[a.get("Name")] = values.reshape(-1, k) if k > 1 else values
        return out

    return points, cells, arrays("PointData"), arrays("CellData")

