"""What a user of the repository reads points only at what the repository holds: no path into
the project's shared folder (a user does not have it), no document of it named as if it were
here, and the license and citation files are present and well formed."""
import os
import re

import yaml

# Built from parts, so that this file does not match itself.
SHARED = "/".join(["..", "shared"])
SHARED_ABSOLUTE = "/".join(["", "work", "shared"])
# Documents of the shared folder: named anywhere, they must exist in the repository.
DOCUMENT = re.compile(r"\b([A-Z][A-Z_]+\.md)\b")


def texts(root, files):
    for f in files:
        try:
            with open(os.path.join(root, f), encoding="utf-8") as fh:
                yield f, fh.read()
        except (UnicodeDecodeError, OSError):
            continue  # images, binary meshes: nothing a reader follows


def test_no_file_points_at_the_shared_folder(root, tracked_files):
    bad = []
    for f, text in texts(root, tracked_files):
        for n, line in enumerate(text.splitlines(), 1):
            if SHARED in line or SHARED_ABSOLUTE in line:
                bad.append(f"{f}:{n}: {line.strip()[:100]}")
    assert not bad, "these lines point at the shared folder, which users do not have:\n" + "\n".join(bad)


def test_every_document_named_in_capitals_exists(root, tracked_files):
    """README.md, BENCHMARKS.md, CONVERGENCE.md, ... are files of the repository; the shared
    folder's design, cases and results documents are not (what users need of them is in docs/)."""
    names = {os.path.basename(f) for f in tracked_files}
    bad = []
    for f, text in texts(root, tracked_files):
        for n, line in enumerate(text.splitlines(), 1):
            bad += [f"{f}:{n}: {m}" for m in DOCUMENT.findall(line) if m not in names]
    assert not bad, "documents named but not in the repository:\n" + "\n".join(bad)


def test_license_and_citation(root):
    """A BSD-3-Clause LICENSE, and a CITATION.cff (Citation File Format 1.2.0) whose license,
    version and references agree with the repository."""
    with open(os.path.join(root, "LICENSE")) as f:
        license_text = f.read()
    assert license_text.startswith("BSD 3-Clause License")
    assert "Neither the name of the copyright holder" in license_text
    with open(os.path.join(root, "CITATION.cff")) as f:
        cff = yaml.safe_load(f)
    assert cff["cff-version"] == "1.2.0" and cff["license"] == "BSD-3-Clause"
    with open(os.path.join(root, "CMakeLists.txt")) as f:
        version = re.search(r"project\(hpcontact VERSION ([0-9.]+)", f.read()).group(1)
    assert str(cff["version"]) == version
    assert all({"type", "title", "authors"} <= set(ref) for ref in cff["references"])
    assert "Franke" in cff["message"]
    cited = {ref["authors"][0]["family-names"] for ref in cff["references"]}
    assert {"Szabó", "Gordon", "Crisfield", "Shtayerman"} <= cited
