"""The README's install-and-launch command works as root without sudo and as a user with it.

The command is run as written in README.md, by ``/bin/sh``, with every program
it calls replaced by a stand-in that records its call: ``apt-get``,
``python3`` (whose venv's ``pip``, ``python`` and ``stepdeck`` record too),
and, for the user, ``sudo``.  Nothing is installed; what is checked is that
each step is reached, in order, with ``sudo`` exactly where there is one.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[2] / "README.md"

RECORDER = """#!/bin/sh
echo "{name} $*" >> "$LOG"
"""

FAKE_PYTHON = """#!/bin/sh
echo "python3 $*" >> "$LOG"
mkdir -p .venv/bin
for tool in pip python stepdeck; do
  printf '#!/bin/sh\\necho "venv-%s $*" >> "$LOG"\\n' "$tool" > .venv/bin/$tool
  chmod +x .venv/bin/$tool
done
"""

FAKE_SUDO = """#!/bin/sh
echo "sudo $*" >> "$LOG"
exec "$@"
"""


def launch_command() -> str:
    text = README.read_text(encoding="utf-8")
    match = re.search(r"<!-- launch-command -->\s*```sh\n(.*?)\n```", text, re.DOTALL)
    assert match, "README.md has no launch command"
    return match.group(1)


def run(tmp_path: Path, *, with_sudo: bool) -> list[str]:
    tools = tmp_path / "bin"
    tools.mkdir()
    for name, body in (("apt-get", RECORDER.format(name="apt-get")), ("python3", FAKE_PYTHON)):
        (tools / name).write_text(body, encoding="utf-8")
    if with_sudo:
        (tools / "sudo").write_text(FAKE_SUDO, encoding="utf-8")
    for name in ("mkdir", "chmod"):  # what the stand-in python3 itself needs
        found = shutil.which(name)
        assert found is not None
        (tools / name).symlink_to(found)
    for path in tools.iterdir():
        if not path.is_symlink():
            path.chmod(0o755)
    work = tmp_path / "checkout"
    work.mkdir()
    log = tmp_path / "log"
    # Only the stand-ins on PATH: a real sudo or apt-get of this machine is never reached.
    env = {"PATH": str(tools), "LOG": str(log), "HOME": str(tmp_path)}
    result = subprocess.run(
        ["/bin/sh", "-c", launch_command()],
        cwd=work,
        env=env,
        capture_output=True,
        text=True,
        timeout=30,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    return log.read_text(encoding="utf-8").splitlines()


@pytest.mark.skipif(not Path("/bin/sh").exists() or os.name != "posix", reason="POSIX sh")
@pytest.mark.parametrize("with_sudo", [False, True], ids=["root without sudo", "user with sudo"])
def test_the_launch_command_reaches_stepdeck(tmp_path: Path, with_sudo: bool) -> None:
    calls = run(tmp_path, with_sudo=with_sudo)
    apt = [c for c in calls if c.startswith("apt-get")]
    assert [c.split()[1] for c in apt] == ["update", "install"]
    sudo = [c for c in calls if c.startswith("sudo")]
    assert sudo == (["sudo " + c for c in apt] if with_sudo else [])
    steps = [c.split()[0] for c in calls if not c.startswith(("sudo", "apt-get"))]
    # no step between the install and StepDeck: nothing is compiled on the user's machine
    assert steps == ["python3", "venv-pip", "venv-stepdeck"]
    assert calls[-1] == "venv-stepdeck "  # the last step opens StepDeck
