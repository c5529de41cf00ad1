"""The run the Python reader's tests open: EJECTA_TEST_RUN (CTest's outputs_run fixture runs
tests/outputs/outputs_scene.toml into it), or a fresh run by EJECTA_BINARY when only that is set."""
import os
import shutil
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
sys.path.append(os.path.join(SOURCE, "python"))  # after PYTHONPATH: CTest gives build/python


@pytest.fixture(scope="session")
def run_dir(tmp_path_factory):
    given = os.environ.get("EJECTA_TEST_RUN")
    if given:
        if not os.path.isdir(given):
            pytest.fail("EJECTA_TEST_RUN=%s is not a directory (run the outputs_run fixture)" % given)
        return given
    binary = os.environ.get("EJECTA_BINARY") or shutil.which("ejecta")
    if not binary:
        pytest.skip("neither EJECTA_TEST_RUN nor EJECTA_BINARY is set")
    out = str(tmp_path_factory.mktemp("run") / "outputs_test")
    subprocess.run([binary, "run", os.path.join(SOURCE, "tests", "outputs", "outputs_scene.toml"),
                    "--out", out, "--quiet", "--no-charts", "--threads", "1"], check=True)
    return out


@pytest.fixture()
def copy_of_run(run_dir, tmp_path):
    """A copy of the run to damage."""
    target = tmp_path / "run"
    shutil.copytree(run_dir, target)
    return target
