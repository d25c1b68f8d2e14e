"""`cmake --install` into a fresh prefix gives a user what the README promises: the program, a
CMake package another project builds against, the Python module for /usr/bin/python3, the
scripts and the docs. One installation is shared by the tests of this file."""
import os
import shutil
import subprocess
import sys

import pytest

from conftest import scaled_timeout

PYTHON = "/usr/bin/python3"
LAME = os.path.join("share", "hpcontact", "examples", "lame", "thick-cylinder.yaml")


def run(cmd, timeout=300, **kw):
    r = subprocess.run([str(c) for c in cmd], capture_output=True, text=True,
                       timeout=scaled_timeout(timeout), **kw)
    assert r.returncode == 0, f"{' '.join(map(str, cmd))}: exit {r.returncode}\n{r.stdout}\n{r.stderr}"
    return r


@pytest.fixture(scope="module")
def prefix(build_dir, cmake, tmp_path_factory):
    where = tmp_path_factory.mktemp("install") / "prefix"
    run([cmake, "--install", build_dir, "--prefix", where])
    return where


def package_dir(prefix):
    """The folder of the CMake package, <libdir>/cmake/hpcontact (libdir lib/ or
    lib/<multiarch>/, as GNUInstallDirs chose)."""
    found = [d for d, _, files in os.walk(prefix) if "hpcontactConfig.cmake" in files]
    assert len(found) == 1, f"one hpcontactConfig.cmake under {prefix}, found {found}"
    return found[0]


def test_the_tree_holds_program_headers_package_module_scripts_docs(prefix, build_dir, root):
    """Every part is where cmake/install.cmake says, and nothing points back into the build."""
    exe = prefix / "bin" / "hpcontact"
    assert os.access(exe, os.X_OK)
    assert run([exe, "--version"]).stdout.strip().startswith("hpcontact")
    assert (prefix / "include" / "hpcontact" / "driver" / "run.hpp").is_file()
    assert (prefix / "include" / "hpcontact" / "core" / "error.hpp").is_file()
    package = package_dir(prefix)
    libdir = os.path.dirname(os.path.dirname(package))
    archives = sorted(f for f in os.listdir(libdir) if f.startswith("libhpcontact_"))
    assert "libhpcontact_core.a" in archives and "libhpcontact_driver.a" in archives, archives
    modules = os.listdir(prefix / "lib" / "python3" / "dist-packages")
    assert any(m.startswith("hpcontact") and m.endswith(".so") for m in modules), modules
    scripts = prefix / "share" / "hpcontact" / "scripts"
    for name in ("plot_field.py", "plot_pressure.py", "study_table.py", "plot_study.py"):
        assert os.access(scripts / name, os.X_OK), name
    share = prefix / "share" / "hpcontact"
    for name in ("README.md", "LICENSE", "CITATION.cff", "docs/tutorial.md", "docs/study.md",
                 "examples/tutorial/punch.yaml"):
        assert (share / name).is_file(), name
    assert (prefix / "share" / "doc" / "hpcontact" / "LICENSE").is_file()
    targets = open(os.path.join(package, "hpcontactTargets.cmake")).read()
    assert "hpcontact::hpcontact" in targets
    config = "".join(open(os.path.join(package, f)).read() for f in os.listdir(package))
    for folder in (os.path.abspath(build_dir), root):
        assert folder not in config, f"the CMake package names {folder}"


def test_a_cmake_project_builds_against_the_package_and_solves_lame(prefix, cmake, root, tmp_path):
    """find_package(hpcontact) from another project: it links hpcontact::hpcontact, reads the
    installed Lamé example, solves it through the library and matches the closed form."""
    source = os.path.join(root, "tests", "install", "consumer")
    build = tmp_path / "consumer"
    configure = [cmake, "-S", source, "-B", build, f"-DCMAKE_PREFIX_PATH={prefix}",
                 "-DCMAKE_BUILD_TYPE=Release"]
    if shutil.which("ninja"):
        configure += ["-G", "Ninja"]
    if shutil.which("ccache"):
        configure += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"]
    run(configure)
    run([cmake, "--build", build], timeout=600)
    r = run([build / "lame_consumer", prefix / LAME])
    lines = r.stdout.splitlines()
    assert len(lines) == 4 and all("MISMATCH" not in line for line in lines), r.stdout


def test_python_imports_the_installed_module_and_runs_lame(prefix, tmp_path):
    """/usr/bin/python3 with PYTHONPATH=<prefix>/lib/python3/dist-packages imports the installed
    module (not the build's) and its run of the installed Lamé example has the closed form's
    strain energy, U = p u_r(a) pi a / 4 for the quarter cylinder."""
    code = (
        "import math, sys, hpcontact\n"
        "print(hpcontact.__file__)\n"
        f"s = hpcontact.Problem.from_file(sys.argv[1]).run().summary\n"
        "a, b, p, E, nu = 10.0, 20.0, 100.0, 200000.0, 0.3\n"
        "A = p * a * a / (b * b - a * a)\n"
        "u_a = (1 + nu) / E * ((1 - 2 * nu) * A * a + A * b * b / a)\n"
        "exact = p * u_a * math.pi * a / 4\n"
        "print(s['strain_energy'], exact)\n"
        "sys.exit(0 if abs(s['strain_energy'] - exact) <= 1e-6 * exact else 1)\n")
    env = dict(os.environ, PYTHONPATH=str(prefix / "lib" / "python3" / "dist-packages"),
               PYTHONDONTWRITEBYTECODE="1")
    r = run([PYTHON, "-c", code, prefix / LAME], env=env, cwd=tmp_path)
    assert r.stdout.splitlines()[0].startswith(str(prefix)), r.stdout


def test_installed_scripts_find_the_installed_program(prefix, tmp_path):
    """A script run from <prefix>/share/hpcontact/scripts starts <prefix>/bin/hpcontact when
    no --hpcontact is given (there is no build/ folder beside it)."""
    study = tmp_path / "study.yaml"
    study.write_text(f"study: lame\ncase: {prefix / LAME}\n"
                     "sweep: {discretization.degree: [2, 3]}\n")
    out = tmp_path / "out"
    script = prefix / "share" / "hpcontact" / "scripts" / "study_table.py"
    env = dict(os.environ, PATH="/usr/bin:/bin")   # not on PATH either
    run([PYTHON, script, study, "--out", out], env=env, cwd=tmp_path)
    assert (out / "study.csv").is_file()
