#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Executes every notebook of a folder (default: notebooks/) with nbclient and fails on any error.

Usage: run_notebooks.py [--output DIR] [FOLDER] [NAME ...]   (CTest python_notebooks;
scripts/reproduce with --output; PYTHONPATH must reach the module, as CTest sets it).
The notebooks are stored without outputs and are not written back; with --output DIR the
executed copies, with their outputs and figures, are written to DIR (created if missing).
Each runs in a new empty working folder, not in notebooks/: a notebook must find the data
through the repository (ROUGHROLL_SOURCE_DIR, set here to this checkout unless already set),
not through the folder it happens to run in.
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
    argv = list(argv)
    output = None
    if len(argv) > 2 and argv[1] == "--output":
        output = Path(argv[2]).resolve()
        del argv[1:3]
    elif len(argv) > 1 and argv[1].startswith("--output"):
        print("run_notebooks: usage: run_notebooks.py [--output DIR] [FOLDER] [NAME ...]", file=sys.stderr)
        return 2
    source = Path(__file__).resolve().parents[1]
    os.environ.setdefault("ROUGHROLL_SOURCE_DIR", str(source))
    folder = Path(argv[1] if len(argv) > 1 else source / "notebooks").resolve()
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
        if output is not None:
            # Executed copies show their figures: the kernel's inline backend puts each figure
            # into its cell's outputs (Agg, CTest's choice, draws them nowhere).
            os.environ["MPLBACKEND"] = "module://matplotlib_inline.backend_inline"
        else:
            os.environ.setdefault("MPLBACKEND", "Agg")
        failed = 0
        for path in paths:
            nb = nbformat.read(path, as_version=4)
            if any(cell.get("outputs") for cell in nb.cells if cell.cell_type == "code"):
                print(f"FAIL {path.name}: stored with outputs (clear them before committing)")
                failed += 1
                continue
            start = time.monotonic()
            with tempfile.TemporaryDirectory() as work:
                client = NotebookClient(nb, timeout=600, kernel_name="roughroll-python",
                                        resources={"metadata": {"path": work}})
                try:
                    client.execute()
                except CellExecutionError as e:
                    print(f"FAIL {path.name}:\n{e}")
                    failed += 1
                    continue
            if output is not None:
                output.mkdir(parents=True, exist_ok=True)
                nbformat.write(nb, output / path.name)
            print(f"ok   {path.name} ({time.monotonic() - start:.1f} s)" +
                  (f", written to {output / path.name}" if output is not None else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
