"""GRBL's own verdict on each line of a file: grbl-sim in ``$C`` check mode (G7-10).

The file goes to grbl-sim on its standard input after ``$C``; GRBL answers
every line (an empty or comment-only one too) with ``ok`` or ``error:N``, so the
n-th answer after ``$C``'s is the n-th line's.  The simulator is the copy built by
:func:`tests.helpers.grbl_sim_timing.build`: with grbl-sim's receive ring wrapped as
GRBL's, no byte of a file read this fast is lost.  Why grbl-sim fell silent before
a file's last lines in the earlier attempt: check mode counts as idle for
grbl-sim's exit test (``sys.state < STATE_HOMING``), so it quits as soon as it
reads the end of its input, with up to 127 bytes of lines still in GRBL's
receive buffer, unanswered; and lines lost bytes whenever the buffer was full.
Blank lines after the file (more than the buffer holds) keep the end of the
input behind the last line's answer.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import tempfile
from pathlib import Path

from tests.helpers import grbl_sim

TAIL_BLANKS = 300
_ANSWER = re.compile(r"^(ok|error:\d+)$")


def check_mode_verdicts(exe: Path, lines: list[str], timeout: float = 900.0) -> list[str]:
    """``ok`` or ``error:N`` for each of ``lines``, as GRBL 1.1 answers it in check mode."""
    with tempfile.TemporaryDirectory() as work:
        folder = Path(work)
        shutil.copyfile(grbl_sim.cache_dir() / "EEPROM.DAT", folder / "EEPROM.DAT")
        stream = folder / "program.nc"
        stream.write_bytes(
            ("$C\n" + "".join(f"{line}\n" for line in lines) + "\n" * TAIL_BLANKS).encode(
                "ascii", "replace"
            )
        )
        with stream.open("rb") as stdin:
            result = subprocess.run(
                [str(exe), "-n", "-t", "100", "-b", "/dev/null"],
                cwd=folder,
                stdin=stdin,
                capture_output=True,
                timeout=timeout,
            )
    answers = [
        text
        for text in result.stdout.decode("ascii", "replace").splitlines()
        if _ANSWER.match(text.strip())
    ]
    answers = [a.strip() for a in answers]
    if not answers or answers[0] != "ok":
        raise RuntimeError(f"grbl-sim did not take $C: {answers[:3]}")
    verdicts = answers[1 : 1 + len(lines)]
    # Up to a buffer's worth of the blank lines go unanswered: the simulator ends then.
    if len(verdicts) != len(lines):
        raise RuntimeError(f"grbl-sim answered {len(verdicts)} lines of {len(lines)}")
    return verdicts
