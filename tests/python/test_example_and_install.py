"""The docs' example script runs on the test run; `pip install ./python` gives an importable
package outside the source tree; `python3 -m ejecta RUN` reads the run."""
import os
import shutil
import subprocess
import sys
import venv

import pytest

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def test_the_example_script_draws_its_pictures(run_dir, tmp_path):
    pytest.importorskip("matplotlib")
    result = subprocess.run([sys.executable, os.path.join(SOURCE, "docs", "examples", "read_run.py"),
                             run_dir, str(tmp_path)], capture_output=True, text=True, check=True)
    assert "outputs_test: completed" in result.stdout
    assert "granite" in result.stdout and "crater: depth" in result.stdout
    for name in ("particles.png", "crater.png", "energy.png"):
        assert (tmp_path / name).stat().st_size > 1000, name


def test_the_module_prints_what_a_run_holds(run_dir):
    result = subprocess.run([sys.executable, "-m", "ejecta", run_dir], capture_output=True, text=True,
                            cwd=os.path.join(SOURCE, "python"))
    assert result.returncode == 0, result.stderr
    assert "4 snapshots" in result.stdout and "material 1: aluminium" in result.stdout
    missing = subprocess.run([sys.executable, "-m", "ejecta", run_dir + "_missing"], capture_output=True,
                             text=True, cwd=os.path.join(SOURCE, "python"))
    assert missing.returncode == 1 and "no such run directory" in missing.stderr


def test_pip_installs_the_package_into_a_virtual_environment(run_dir, tmp_path):
    # Offline: the build backend (setuptools) and the dependencies (numpy, h5py) come from the
    # system's packages (Debian: python3-setuptools, python3-numpy, python3-h5py).
    pytest.importorskip("ensurepip", reason="Debian's python3-venv is not installed")
    pytest.importorskip("setuptools", reason="Debian's python3-setuptools is not installed")
    env_dir = tmp_path / "venv"
    venv.EnvBuilder(system_site_packages=True, with_pip=True).create(env_dir)
    python = str(env_dir / "bin" / "python")
    # From a copy: without build isolation setuptools writes build/ and *.egg-info beside the
    # sources, which must stay clean.
    package = tmp_path / "package"
    shutil.copytree(os.path.join(SOURCE, "python"), package,
                    ignore=shutil.ignore_patterns("__pycache__", "build", "*.egg-info"))
    subprocess.run([python, "-m", "pip", "install", "--quiet", "--no-index", "--no-build-isolation",
                    "--no-deps", str(package)], check=True, cwd=tmp_path,
                   env=dict(os.environ, TMPDIR=str(tmp_path), PIP_CACHE_DIR=str(tmp_path / "cache")))
    probe = ("import ejecta, sys; run = ejecta.load_run(sys.argv[1]); "
             "print(ejecta.__file__); print(len(run.series[-1]))")
    clean = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}  # CTest's build/python
    result = subprocess.run([python, "-c", probe, run_dir], capture_output=True, text=True, check=True,
                            cwd=tmp_path, env=clean)
    location, particles = result.stdout.split()
    assert location.startswith(str(env_dir)), location  # the installed copy, not the source tree
    assert int(particles) == ejecta_particles(run_dir)


def ejecta_particles(run_dir):
    import ejecta
    return len(ejecta.load_run(run_dir).series[-1])


def test_the_build_tree_holds_an_importable_package(tmp_path):
    build_python = os.environ.get("EJECTA_BUILD_PYTHON")
    if not build_python:
        pytest.skip("EJECTA_BUILD_PYTHON is set by CTest (build/python)")
    result = subprocess.run([sys.executable, "-c", "import ejecta; print(ejecta.__file__)"], capture_output=True,
                            text=True, cwd=tmp_path, env=dict(os.environ, PYTHONPATH=build_python))
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip().startswith(build_python)
