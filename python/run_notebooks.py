#!/usr/bin/env python3
"""Executes every notebook of a folder (default: notebooks/) with nbclient and fails on any error.

Usage: run_notebooks.py [FOLDER] [NAME ...]   (CTest python_notebooks; PYTHONPATH must reach the
module, as CTest sets it). The notebooks are stored without outputs and are not written back.
The kernel is this interpreter itself (a kernel spec written to a temporary folder), so the
notebooks see the same Python and packages as this script: Debian's python3 under CTest.
"""

import json
import os
import sys
import tempfile
import time
from pathlib import Path

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError


def main(argv):
    folder = Path(argv[1] if len(argv) > 1 else Path(__file__).resolve().parents[1] / "notebooks").resolve()
    names = argv[2:]
    paths = sorted(folder / n for n in names) if names else sorted(folder.glob("*.ipynb"))
    if not paths:
        print(f"run_notebooks: no notebooks in {folder}", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory() as jupyter:
        spec = Path(jupyter, "kernels", "roughroll-python")
        spec.mkdir(parents=True)
        (spec / "kernel.json").write_text(json.dumps({
            "argv": [sys.executable, "-Xfrozen_modules=off", "-m", "ipykernel_launcher", "-f", "{connection_file}"],
            "display_name": "roughroll (this Python)", "language": "python"}))
        os.environ["JUPYTER_PATH"] = jupyter
        os.environ.setdefault("MPLBACKEND", "Agg")
        failed = 0
        for path in paths:
            nb = nbformat.read(path, as_version=4)
            if any(cell.get("outputs") for cell in nb.cells if cell.cell_type == "code"):
                print(f"FAIL {path.name}: stored with outputs (clear them before committing)")
                failed += 1
                continue
            start = time.monotonic()
            client = NotebookClient(nb, timeout=600, kernel_name="roughroll-python",
                                    resources={"metadata": {"path": str(folder)}})
            try:
                client.execute()
            except CellExecutionError as e:
                print(f"FAIL {path.name}:\n{e}")
                failed += 1
                continue
            print(f"ok   {path.name} ({time.monotonic() - start:.1f} s)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
