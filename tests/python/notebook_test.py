"""docs/python-sweep.ipynb executed as a user would (Debian's nbconvert with the python3 kernel), in
a scratch folder, so that it can never go stale: every cell runs without an error, the figures
it saves are PNGs, and the runs' progress shows in the notebook (the sweep cell's output). Run by ctest (python.notebook) with PYTHONPATH=build/python."""
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

SOURCE = pathlib.Path(os.environ["TRAPDEM_SOURCE_DIR"])


def test_the_sweep_notebook_runs():
    work = pathlib.Path(tempfile.mkdtemp(prefix="trapdem-notebook-"))
    try:
        shutil.copy(SOURCE / "docs" / "python-sweep.ipynb", work)
        subprocess.run([sys.executable, "-m", "nbconvert", "--to", "notebook", "--execute", "--ExecutePreprocessor.timeout=600",
                        "--output", "executed.ipynb", "python-sweep.ipynb"], cwd=work, check=True,
                       env=dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=os.pathsep.join(
                           str(pathlib.Path(p).resolve()) for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p)))
        for name in ("sweep_grc.png", "sweep_strain.png"):
            assert (work / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", name
        assert (work / "sweep" / "mu-0.6" / "trapdoor.csv").is_file()
        shown = "".join("".join(output.get("text", "")) for cell in json.loads((work / "executed.ipynb").read_text())["cells"]
                        for output in cell.get("outputs", []) if output.get("output_type") == "stream")
        assert shown.count("finished after") == 3, shown[-2000:]  # each run of the sweep says it ended
    finally:
        shutil.rmtree(work, ignore_errors=True)
