"""``$RST=$``/``#``/``*`` and a reset in motion: what real GRBL 1.1h (grbl-sim) says, and
the emulated board says the same.

The same bytes go to grbl-sim (on its standard input, a fresh EEPROM) and to the
emulator (on a manual clock); the replies are compared line for line, the status
reports by their state only (the positions differ with the timing).  Each step
waits for the answers it expects, never a fixed time.
"""

from __future__ import annotations

import os
import select
import shutil
import subprocess
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from protocol.emulator.gcode_firmware import grbl_plotter_config
from tests.helpers import grbl_sim
from tests.protocol.test_gcode_firmware import Bench

UNLOCK = "[MSG:'$H'|'$X' to unlock]"
#: A step: bytes to send, then how many reply lines to wait for (not counting status reports
#: unless asked) — what the step must say whichever board hears it.
Step = tuple[bytes, int]


def _shown(line: str) -> str:
    """A reply as compared: a status report by its state alone."""
    return line.split("|", 1)[0] + ">" if line.startswith("<") else line


class Sim:
    """grbl-sim on pipes: lines in, reply lines out."""

    def __init__(self, exe: Path, workdir: Path) -> None:
        shutil.copyfile(grbl_sim.cache_dir() / "EEPROM.DAT", workdir / "EEPROM.DAT")
        self.process = subprocess.Popen(
            grbl_sim.command(exe),
            cwd=workdir,
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            bufsize=0,
        )
        assert self.process.stdout is not None
        os.set_blocking(self.process.stdout.fileno(), False)
        self.buffer = b""
        self.lines: list[str] = []

    def read_until(self, done: Callable[[list[str]], bool], timeout: float = 30.0) -> None:
        assert self.process.stdout is not None
        deadline = time.monotonic() + timeout
        while not done(self.lines):
            if time.monotonic() > deadline:
                raise AssertionError(f"grbl-sim said only {self.lines}")
            ready, _, _ = select.select([self.process.stdout], [], [], 0.05)
            if ready:
                self.buffer += self.process.stdout.read(4096) or b""
                *whole, self.buffer = self.buffer.split(b"\n")
                self.lines += [
                    t for t in (w.decode("ascii", "replace").strip() for w in whole) if t
                ]

    def send(self, data: bytes) -> None:
        assert self.process.stdin is not None
        self.process.stdin.write(data)

    def close(self) -> None:
        self.process.terminate()
        self.process.wait(timeout=10)
        for pipe in (self.process.stdin, self.process.stdout):
            if pipe is not None:
                pipe.close()


@pytest.fixture(scope="module")
def grbl_sim_exe() -> Path:
    if grbl_sim.compiler() is None:
        pytest.skip("no C compiler and make: grbl-sim cannot be built (.ci/run installs them)")
    return grbl_sim.build(Path(__file__).resolve().parents[1] / "third_party" / "grbl")


@pytest.fixture
def sim(grbl_sim_exe: Path, tmp_path: Path) -> Iterator[Sim]:
    board = Sim(grbl_sim_exe, tmp_path)
    try:
        board.read_until(lambda lines: any(line.startswith("Grbl ") for line in lines))
        # The simulator may miss a line sent as it boots: empty lines until one is answered.
        for _ in range(20):
            board.send(b"\n")
            try:
                board.read_until(lambda lines: "ok" in lines, timeout=1.0)
                break
            except AssertionError:
                continue
        board.read_until(lambda lines: "ok" in lines)
        board.lines.clear()
        yield board
    finally:
        board.close()


def _on_sim(sim: Sim, steps: list[Step]) -> list[str]:
    for data, answers in steps:
        want = len(sim.lines) + answers
        sim.send(data)
        sim.read_until(lambda lines, want=want: len(lines) >= want)
    return [_shown(line) for line in sim.lines]


def _on_emulator(steps: list[Step]) -> list[str]:
    bench = Bench(grbl_plotter_config())
    raw = bytearray()
    bench.fw.set_output(raw.extend)  # the lines as sent, not as the station decodes them
    lines: list[str] = []
    for data, answers in steps:
        want = len(lines) + answers
        bench.fw.receive(data)
        for _ in range(3000):  # 30 emulated seconds at most
            *whole, rest = bytes(raw).split(b"\n")
            raw[:] = rest
            lines += [t for t in (w.decode("ascii", "replace").strip() for w in whole) if t]
            if len(lines) >= want:
                break
            bench.run(0.01)
    return [_shown(line) for line in lines]


RESTORES: list[Step] = [
    (b"G10 L2 P1 X5 Y7\n", 1),
    (b"$RST=#\n", 3),  # [MSG:Restoring defaults], ok, the banner
    (b"$#\n", 12),  # G54…G59, G28, G30, G92, TLO, PRB, ok: G54 is zero again
    (b"$RST=x\n$RST=\n$RST=##\n$RS\n", 4),  # error:3 each
    (b"$1=100\n", 1),
    (b"$RST=$\n", 3),
    (b"$$\n", 35),  # every setting back to its default, then ok
    (b"$RST=*\n", 3),
]


def test_restores_answer_as_grbl_does(sim: Sim) -> None:
    real = _on_sim(sim, RESTORES)
    emulated = _on_emulator(RESTORES)
    assert real[:4] == ["ok", "[MSG:Restoring defaults]", "ok", "Grbl 1.1h ['$' for help]"]
    assert "[G54:0.000,0.000,0.000]" in real and real.count("error:3") == 4
    settings = [line for line in real if line.startswith("$")]
    assert "$1=25" in settings  # $RST=$ put the step idle delay back
    # The emulated board's settings are its machine's, not a bare GRBL's: compared apart.
    assert [line for line in emulated if not line.startswith("$")] == [
        line for line in real if not line.startswith("$")
    ]
    assert "$1=25" in emulated


def test_a_reset_in_motion_raises_alarm_3_then_restarts_in_alarm(sim: Sim) -> None:
    steps: list[Step] = [
        (b"G1 X50 F500\n", 1),
        (b"?", 1),  # moving
        (b"\x18", 3),  # ALARM:3, the banner, the unlock message
        (b"?", 1),
        (b"$X\n", 2),
        (b"?", 1),
    ]
    real = _on_sim(sim, steps)
    emulated = _on_emulator(steps)
    assert real == [
        "ok",
        "<Run>",
        "ALARM:3",
        "Grbl 1.1h ['$' for help]",
        UNLOCK,
        "<Alarm>",
        "[MSG:Caution: Unlocked]",
        "ok",
        "<Idle>",
    ]
    assert emulated == real


def test_a_reset_standing_raises_no_alarm(sim: Sim) -> None:
    steps: list[Step] = [(b"\x18", 1), (b"?", 1)]
    real = _on_sim(sim, steps)
    assert real == ["Grbl 1.1h ['$' for help]", "<Idle>"]
    assert _on_emulator(steps) == real


def test_a_status_report_is_compared_by_its_state() -> None:
    """The comparison's own check: a report shown by its state, any other line as sent."""
    assert _shown("<Run|MPos:1.000,2.000,0.000|FS:500,0>") == "<Run>"
    assert _shown(UNLOCK) == UNLOCK and _shown("ALARM:3") == "ALARM:3"
