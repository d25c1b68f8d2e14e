"""Thread-count determinism: the element loops run in parallel (OpenMP), and the results shall
not depend on how many threads ran them — byte for byte, not only to round-off."""
import json
import os

import pytest

FILES = ("solution.vtu", "contact.csv", "contact.vtu", "pressure.csv", "path.csv")


def outputs(hpcontact, root, case, out, threads):
    env_threads = {"OMP_NUM_THREADS": str(threads)}
    old = {k: os.environ.get(k) for k in env_threads}
    os.environ.update(env_threads)
    try:
        r = hpcontact("run", os.path.join(root, case), "--out", out, "-q")
    finally:
        for k, v in old.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
    assert r.returncode == 0, r.stderr
    files = {name: (out / name).read_bytes() for name in FILES if (out / name).exists()}
    summary = json.loads((out / "summary.json").read_text())
    summary.pop("wall_time_s", None)  # the one figure that may differ
    return files, summary


@pytest.mark.parametrize("case", ["examples/hertz/p8.yaml",          # condensation, contact
                                  "examples/axle-ring/ring2-p4.yaml",  # finite strain
                                  "examples/two-bars/coulomb.yaml"])   # two bodies, friction
def test_results_do_not_depend_on_the_thread_count(hpcontact, root, tmp_path, case):
    """1, 2 and 4 threads write byte-identical solution.vtu, contact.csv, contact.vtu,
    pressure.csv and path.csv, and the same summary.json but for its wall time."""
    runs = [outputs(hpcontact, root, case, tmp_path / f"t{n}", n) for n in (1, 2, 4)]
    files, summary = runs[0]
    assert "solution.vtu" in files and "contact.csv" in files
    for other_files, other_summary in runs[1:]:
        assert other_files.keys() == files.keys()
        for name in files:
            assert other_files[name] == files[name], name
        assert other_summary == summary
