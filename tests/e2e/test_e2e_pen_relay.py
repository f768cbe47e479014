"""A pen down lost on the wire, through the project's fault relay, as an operator runs a job.

Relay grbl-plotter seed 144: 17 bytes lost take ``000Y5.000`` and the pen down of the
first row (``G0X5.000Y5.000`` + ``M3S1000`` arrive as ``G0X5.``).  Before the pen was
supervised the row ran pen-up and the job said done (wrong); now the pen watch stops it
(``app/machines/gcode/pen_watch.py``): the next line's ``ok`` is counted for the pen down,
and the machine is found short of where GRBL must be once a pen line is answered.
Judged from the emulator's own log (:mod:`tests.helpers.relay_judge`).
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from tests.helpers.relay_judge import Verdict
from tests.helpers.relay_run import DIALECTS, run_once

pytestmark = pytest.mark.skipif(not hasattr(os, "openpty"), reason="no pseudo-terminals here")


def test_a_lost_pen_down_ends_in_a_clean_stop_never_done(tmp_path: Path) -> None:
    result = run_once(DIALECTS["grbl-plotter"], 144, tmp_path)
    assert result.fired
    said = (tmp_path / "station.err").read_text("utf-8", errors="replace")
    assert result.judgement.verdict is Verdict.STOPPED, (result.judgement, said)
    assert "Job failed" in said and "Machine stopped" in said, said
