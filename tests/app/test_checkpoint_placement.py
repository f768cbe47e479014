"""The checkpoint keeps how a job was put on the board, and gives it back only for that job."""

from __future__ import annotations

import json
import math
from pathlib import Path

from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from app.jobs.registration import Placement, Registration
from app.jobs.run.checkpoint import CheckpointStore

WHERE = SourceRef("b.drl", 1)


def board(x: float = 10.0) -> Program:
    ops = []
    for k in range(3):
        ops += [move(WHERE, X=x + 20.0 * k, Y=5.0 + 7.0 * k), Operation(OpKind.DRILL, WHERE)]
    return Program("b", tuple(ops))


def test_a_placement_written_with_the_checkpoint_comes_back_for_the_same_file(
    tmp_path: Path,
) -> None:
    base = board()
    placement = Placement("X", Registration(math.radians(-1.25), (12.5, -3.0), 1.0004, 0.002))
    placed = placement.apply(base)
    CheckpointStore(tmp_path).write(placed, 2, (base, placement))

    store = CheckpointStore(tmp_path)  # a restarted station
    found = store.placement_for(board())  # the file read again: equal, not the same object
    assert found == placement
    assert found is not None and found.apply(board()).fingerprint() == placed.fingerprint()
    assert store.read(found.apply(board())) == 3  # and the checkpoint is this job's
    assert store.placement_for(board(x=11.0)) is None  # another file: nothing


def test_without_a_placement_or_with_a_spoilt_one_nothing_is_offered(tmp_path: Path) -> None:
    base = board()
    store = CheckpointStore(tmp_path)
    assert store.placement_for(base) is None  # no directory yet
    store.write(base, 1)  # a job run as the file says
    assert store.placement_for(base) is None
    fingerprint = base.fingerprint()
    for name, placement in {
        "nan": {
            "base": fingerprint,
            "side": "",
            "registration": {"angle_rad": "nan", "offset": [0, 0], "scale": 1, "residual_mm": 0},
        },
        "side": {"base": fingerprint, "side": "Z", "registration": None},
        "short": {"base": fingerprint, "side": "", "registration": {"angle_rad": 0.1}},
    }.items():
        (tmp_path / f"{name}.json").write_text(json.dumps({"placement": placement}))
    (tmp_path / "garbage.json").write_text("{not json")
    assert store.placement_for(base) is None
    (tmp_path / "side.json").write_text(
        json.dumps({"placement": {"base": fingerprint, "side": "Y", "registration": None}})
    )
    assert store.placement_for(base) == Placement("Y")
