"""The scripting API and ``stepdeck run`` against the emulator in its own process.

Real time, over a pseudo-terminal as over a USB cable: the same path a
script on a lab computer takes to the machine.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import stepdeck
from tests.conftest import ROOT
from tests.helpers.emulator_process import emulator_on_pty

STAGE = ("--profile", "xy-stage")


def test_a_script_moves_the_stage_over_a_serial_port(qapp: object) -> None:
    with emulator_on_pty(*STAGE) as path:
        machine = stepdeck.connect("xy-stage", port=path)
        try:
            assert machine.status.link == "connected"
            assert machine.move_by(X=1.5, Y=0.5) == pytest.approx({"X": 1.5, "Y": 0.5}, abs=0.002)
            with pytest.raises(stepdeck.MotionRefused, match="outside the travel"):
                machine.move_to(X=51)
            assert machine.read_parameters()["Y"]["travel"] == 50.0
        finally:
            machine.close()


def test_a_port_with_no_machine_behind_it_is_named_in_the_error(qapp: object) -> None:
    with emulator_on_pty("--profile", "usb3") as path:
        with pytest.raises(stepdeck.ConnectionFailed, match="is this a XY positioning stage"):
            stepdeck.connect("xy-stage", port=path, timeout=4.0)


def run_cli(*args: str, stdin: int | None = subprocess.DEVNULL) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-m", "app", "run", *args],
        cwd=ROOT,
        env={**os.environ, "QT_QPA_PLATFORM": "offscreen"},
        stdin=stdin,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def test_ctrl_c_stops_the_run_keeps_the_checkpoint_and_resume_finishes(tmp_path: Path) -> None:
    job = tmp_path / "route.txt"
    job.write_text("".join(f"{x}, {x}\n" for x in (2, 6, 10, 14, 18, 22, 26, 30)))
    checkpoints = tmp_path / "ck"
    common = (str(job), "--profile", "xy-stage", "--checkpoints", str(checkpoints))
    with emulator_on_pty(*STAGE) as path:
        process = run_cli(*common, "--port", path, "--no-progress")
        deadline = time.monotonic() + 30
        while not list(checkpoints.glob("*.json")) and process.poll() is None:
            assert time.monotonic() < deadline, "the job never recorded an operation"
            time.sleep(0.05)
        process.send_signal(signal.SIGINT)
        _, err = process.communicate(timeout=30)
        assert process.returncode == 130, err
        assert "the machine was stopped" in err
        assert list(checkpoints.glob("*.json"))
        again = run_cli(*common, "--port", path)
        _, err = again.communicate(timeout=30)
        assert again.returncode == 2, err
        assert "--resume carries on there" in err
        resumed = run_cli(*common, "--port", path, "--resume")
        out, err = resumed.communicate(timeout=60)
    assert resumed.returncode == 0, err
    assert "done: route, 8 operations" in out
    assert "Checking whether" in err  # the interrupted operation was re-examined first
    assert not list(checkpoints.glob("*.json"))


@pytest.mark.parametrize(
    ("content", "extra", "status", "said"),
    [
        ("1, 1\n2, 2\n", ("--yes",), 0, "done: job, 2 operations"),
        ("1, 1\n99, 2\n", (), 2, "job.txt:2"),
        ("1, 1\nwait: load the sample\n2, 2\n", (), 3, "load the sample"),
    ],
)
def test_exit_status_says_done_refused_or_failed(
    tmp_path: Path, content: str, extra: tuple[str, ...], status: int, said: str
) -> None:
    job = tmp_path / "job.txt"
    job.write_text(content)
    process = run_cli(
        str(job),
        "--profile",
        "xy-stage",
        "--emulator",
        "--simulate",
        "--checkpoints",
        str(tmp_path / "ck"),
        *extra,
    )
    out, err = process.communicate(timeout=60)
    assert process.returncode == status, err
    assert said in out + err


def test_usage_errors_exit_1(tmp_path: Path) -> None:
    process = run_cli(str(tmp_path / "x.txt"), "--profile", "xy-stage", "--simulate", "--port", "p")
    _, err = process.communicate(timeout=60)
    assert process.returncode == 1
    assert "--simulate" in err
