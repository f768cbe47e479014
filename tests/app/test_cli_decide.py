"""``stepdeck run`` with no one at its terminal: a question only an operator can answer
ends the job, and the message says how far it got (it said "stopped after 0 of 0")."""

from __future__ import annotations

import io

import pytest

from app.cli.run import Terminal
from app.scripting.errors import JobAborted
from app.scripting.job import Progress


def _no_one(prompt: str = "") -> str:
    raise EOFError


def test_a_decision_no_one_answers_aborts_with_the_progress_last_reported(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    terminal = Terminal(io.StringIO(), bar=False, yes=True)
    terminal.progress(Progress(17, 30, 4.0, 3.0, "paused"))
    monkeypatch.setattr("builtins.input", _no_one)
    with pytest.raises(JobAborted) as raised:
        terminal.decide("The machine restarted", "resume from 17", "resume after 27")
    assert (raised.value.done, raised.value.total) == (17, 30)
    assert "no one at the terminal" in str(raised.value)


def test_a_question_the_job_just_said_is_not_said_again(monkeypatch: pytest.MonkeyPatch) -> None:
    out = io.StringIO()
    terminal = Terminal(out, bar=False, yes=True)
    monkeypatch.setattr("builtins.input", lambda prompt="": "a")
    terminal.say("The machine restarted during the job")
    assert terminal.decide("The machine restarted during the job", "again", "done") is True
    terminal.decide("Pick the line", "again", "done")
    assert out.getvalue().splitlines() == ["The machine restarted during the job", "Pick the line"]
