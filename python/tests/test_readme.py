"""The README's Python examples run as written (from the repository root), and its Slurm recipe
renders a job script (dask-jobqueue needs no Slurm for that)."""

from __future__ import annotations

import os
import re

import pytest

from conftest import ROOT


def python_blocks():
    text = (ROOT / "README.md").read_text()
    return re.findall(r"```python\n(.*?)```", text, flags=re.S)


def test_the_ten_line_example_runs(capsys):
    first = python_blocks()[0]
    assert len(first.strip().splitlines()) <= 12, "the README promises a short example"
    before = os.getcwd()
    os.chdir(ROOT)
    try:
        exec(compile(first, "README.md", "exec"), {})
    finally:
        os.chdir(before)
    printed = capsys.readouterr().out
    assert printed.startswith("partial-slip -0.666066"), printed
    assert "(300, 200)" in printed


def test_the_slurm_recipe_renders_a_job_script():
    jobqueue = pytest.importorskip("dask_jobqueue")
    recipe = next(b for b in python_blocks() if "SLURMCluster" in b)
    line = next(l for l in recipe.splitlines() if l.startswith("cluster = SLURMCluster("))
    cluster = eval(line.split("=", 1)[1].split("#")[0].strip(), {"SLURMCluster": jobqueue.SLURMCluster})
    try:
        script = cluster.job_script()
    finally:
        cluster.close()
    assert "#SBATCH" in script and "--nworkers 32" in script and "--nthreads 1" in script


def test_every_other_python_example_runs_as_written(capsys):
    # Every ```python block runs from the repository root, except the Slurm recipe (it needs a
    # cluster; its job script is rendered above) and the first (run above, with its output).
    blocks = [b for b in python_blocks()[1:] if "SLURMCluster" not in b]
    assert blocks, "the README has more Python examples"
    before = os.getcwd()
    os.chdir(ROOT)
    try:
        for block in blocks:
            exec(compile(block, "README.md", "exec"), {"halfplane": __import__("halfplane")})
    finally:
        os.chdir(before)
    assert capsys.readouterr().out
