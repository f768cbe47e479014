"""The launch benchmark measures the start an operator gets: from compiled modules."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from tools.benchmark import launch_env


def test_launches_compile_once_even_where_the_caller_writes_no_bytecode(tmp_path: Path) -> None:
    """A caller with PYTHONDONTWRITEBYTECODE (as some shells and CI runners set) made every
    measured launch compile StepDeck from source, a cost no operator's second start has."""
    source = tmp_path / "src"
    source.mkdir()
    (source / "probe_module.py").write_text("VALUE = 1\n")
    env = launch_env(tmp_path / "home", {"PYTHONDONTWRITEBYTECODE": "1", "PATH": "/usr/bin"})
    subprocess.run([sys.executable, "-c", "import probe_module"], cwd=source, env=env, check=True)
    compiled = list((tmp_path / "home").rglob("probe_module.*.pyc"))
    assert len(compiled) == 1
    assert not (source / "__pycache__").exists()  # the tree measured is left as it was
    assert env["XDG_CONFIG_HOME"].startswith(str(tmp_path / "home"))
