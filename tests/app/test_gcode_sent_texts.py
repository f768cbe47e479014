"""What a G-code operation sends, kept as spans of the file's bytes: the same texts as written.

The loader keeps the file once and each plain move as its span of it; lines
with spaces around them, a comment after them or words changed have texts of
their own.  Whatever the storage, each operation must send what it always did.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np
import pytest

from app.jobs.formats.gcode.loader import load_gcode
from app.jobs.formats.gcode.sent_texts import SentTexts, SentTextsBuilder
from app.profiles import load_profile

LINES = [
    "G21",
    "G1 F1200",
    "G1 X1 Y2",  # sent as written: a span of the file
    "  G1 X3 Y4",  # spaces before
    "G0 X5 Y6   ",  # spaces after
    "G1 X7 Y8 ; a note",  # a comment after
    "G1 X9 Y10 (žluťoučký kůň)",  # a comment with letters beyond ASCII
    "M3 S1000",
    "g1 x11 y12",  # lower case: the full parser's
    "G1\tX13\tY14 F900",
]
SENT = [
    "G21",
    "G1 F1200",
    "G1 X1 Y2",
    "G1 X3 Y4",
    "G0 X5 Y6",
    "G1 X7 Y8",
    "G1 X9 Y10",
    "M3 S1000",
    "g1 x11 y12",
    "G1\tX13\tY14 F900",
]


@pytest.mark.parametrize("ending", ["\n", "\r\n"])
def test_each_operation_sends_its_line_as_written_without_comments_or_spaces(
    tmp_path: Path, ending: str
) -> None:
    path = tmp_path / "mixed.gcode"
    path.write_bytes(ending.join(LINES).encode("utf-8"))  # no line end after the last
    profile = load_profile("grbl-plotter")
    program = load_gcode(path, [axis.name for axis in profile.axes], profile.gcode)
    sent = [op.line for op in program]
    assert sent == SENT
    assert list(program.data.sent) == SENT
    assert program.data.texts == SENT
    assert [op.source.line for op in program] == list(range(1, len(LINES) + 1))
    # The fingerprint hashes the texts as if joined at once (checkpoints written before the
    # texts were spans still resume).
    digest = hashlib.sha256(program.data.kinds.tobytes())
    digest.update("\n".join(SENT).encode("utf-8"))
    digest.update(repr(sorted(program.data.messages.items())).encode("utf-8"))
    assert program.fingerprint() == digest.hexdigest()[:16]


def test_spans_and_own_texts_keep_their_order_in_slices_and_pieces() -> None:
    builder = SentTextsBuilder()
    builder.set_buffer(b"G1 X1 Y1\nG1 X2 Y2 ; c\nM5\n")
    builder.append("G21")
    builder.extend_spans(np.array([0, 9]), np.array([8, 17]), [(1, "G1 X2 Y2")])
    builder.append("")
    texts = builder.done()
    assert isinstance(texts, SentTexts)
    expected = ["G21", "G1 X1 Y1", "G1 X2 Y2", ""]
    assert list(texts) == expected and len(texts) == 4
    assert (
        texts[-2] == "G1 X2 Y2"
        and texts[1:3] == expected[1:3]
        and texts[::2] == ["G21", "G1 X2 Y2"]
    )
    assert b"".join(texts.encoded_joined()) == "\n".join(expected).encode()
    assert texts.any()
    with pytest.raises(IndexError):
        texts[4]
