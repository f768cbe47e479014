"""Nothing POSIX-only on the way to the window, the built-in emulator and the commands.

The machines' original programs were Windows tools, and StepDeck's window,
``check``, ``run`` and ``string-art`` need nothing Linux has and Windows lacks.
Each check runs in a fresh interpreter where ``termios``, ``fcntl``, ``tty`` and
``pty`` cannot be imported by StepDeck's own modules (tests/helpers/no_posix.py).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = ("app", "widgets", "protocol", "stepdeck")
#: StepDeck's modules that may need a POSIX system to be imported, and why.  Empty: the
#: emulator's pty serving (protocol/emulator/pty.py) imports ``tty`` only when it
#: starts serving, and says in one line why it cannot where there is none.
POSIX_ONLY_MODULES: dict[str, str] = {}
TIMEOUT_S = 300


def _modules() -> list[str]:
    names = []
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            parts = path.relative_to(ROOT).with_suffix("").parts
            names.append(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return names


def _blocked_python(
    code: str, importers: str = "no_posix.FIRST_PARTY"
) -> subprocess.CompletedProcess[str]:
    prelude = f"from tests.helpers import no_posix\nno_posix.block({importers})\n"
    return subprocess.run(
        [sys.executable, "-c", prelude + code],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=TIMEOUT_S,
        env={**os.environ, "QT_QPA_PLATFORM": "offscreen"},
    )


IMPORT_ALL = """
import importlib, json
failed = {}
for name in NAMES:
    try:
        importlib.import_module(name)
    except ImportError as exc:
        failed[name] = str(exc)
print(json.dumps(failed))
"""


def test_every_module_imports_without_termios_fcntl_tty_or_pty() -> None:
    names = _modules()
    assert "protocol.emulator.__main__" in names and "widgets.main_window" in names
    # The check bites: a test helper that imports fcntl at its top is refused.
    names_and_probe = [*names, "tests.helpers.grbl_sim"]
    result = _blocked_python(f"NAMES = {names_and_probe!r}\n" + IMPORT_ALL)
    assert result.returncode == 0, result.stderr
    failed = json.loads(result.stdout.strip().splitlines()[-1])
    assert "blocked as on Windows" in failed.pop("tests.helpers.grbl_sim")
    assert failed.keys() == POSIX_ONLY_MODULES.keys(), failed


def test_the_emulator_command_helps_without_a_terminal_module() -> None:
    result = _blocked_python(
        "import sys\nfrom protocol.emulator.__main__ import main\nsys.exit(main(['--help']))",
        importers="None",
    )
    assert result.returncode == 0, result.stderr
    assert "--pty" in result.stdout and "--profile" in result.stdout


def test_the_emulator_says_in_one_line_why_pty_needs_a_posix_system() -> None:
    result = _blocked_python(
        "import sys\nfrom protocol.emulator.__main__ import main\n"
        "sys.exit(main(['--pty', '--profile', 'grbl-plotter']))",
        importers="None",
    )
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert "--pty needs a POSIX system" in lines[0] and "tty" in lines[0]
    assert result.stdout == ""  # no pty path printed: nothing was served
