"""The fault relay's verdicts per dialect and fault kind: exact, clean stop, wrong, hung.

The relay test writes one JSON line per run when ``STEPDECK_RELAY_RESULTS``
names a file; ``python -m tests.helpers.relay_table FILE…`` prints the table
of every run in those files (later runs of a seed replace earlier ones), as
docs/manual/link-faults.md shows it.
"""

from __future__ import annotations

import json
import sys
from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path

from tests.helpers.fault_relay import FAULT_KINDS

VERDICTS = ("exact", "clean stop", "wrong", "hung")


@dataclass(frozen=True)
class Row:
    """One run as the table counts it."""

    dialect: str
    seed: int
    kind: str
    verdict: str
    reason: str
    wall_s: float

    def json(self) -> str:
        return json.dumps(asdict(self), ensure_ascii=False)


def render(rows: Iterable[Row], dialects: Sequence[str]) -> str:
    """Markdown: a cell per dialect and kind, ``exact/clean stop/wrong/hung``, and bad seeds."""
    counts: dict[tuple[str, str], Counter[str]] = {}
    failing: dict[str, list[tuple[int, str]]] = {}
    runs: Counter[str] = Counter()
    for row in rows:
        counts.setdefault((row.dialect, row.kind), Counter())[row.verdict] += 1
        runs[row.dialect] += 1
        if row.verdict in ("wrong", "hung"):
            failing.setdefault(row.dialect, []).append((row.seed, f"{row.kind} {row.verdict}"))
    kinds = [kind.value for kind in FAULT_KINDS]
    lines = [
        "| dialect | runs | " + " | ".join(kinds) + " | wrong or hung: seeds |",
        "|---|---|" + "---|" * (len(kinds) + 1),
    ]
    for dialect in [*dialects, *sorted(set(runs) - set(dialects))]:
        if not runs[dialect]:
            continue
        cells = []
        for kind in kinds:
            c = counts.get((dialect, kind), Counter())
            cells.append("/".join(str(c[v]) for v in VERDICTS))
        bad = sorted(failing.get(dialect, []))
        listed = ", ".join(f"{seed} ({what})" for seed, what in bad[:12])
        if len(bad) > 12:
            listed += f", … {len(bad) - 12} more"
        lines.append(
            f"| {dialect} | {runs[dialect]} | " + " | ".join(cells) + f" | {listed or '—'} |"
        )
    return "\n".join(lines) + "\n"


def read(paths: Iterable[Path]) -> list[Row]:
    """The runs in JSON-lines files; a seed run again replaces its earlier verdict."""
    found: dict[tuple[str, int], Row] = {}
    for path in paths:
        for line in path.read_text(encoding="utf-8").splitlines():
            if line.strip():
                row = Row(**json.loads(line))
                found[(row.dialect, row.seed)] = row
    return list(found.values())


if __name__ == "__main__":
    from tests.helpers.relay_run import DIALECTS

    rows = read(Path(p) for p in sys.argv[1:])
    print(render(rows, [*DIALECTS, "grbl-sim"]), end="")
    total = sum(r.wall_s for r in rows)
    print(f"\n{len(rows)} runs, {total:.0f} s of run time in all")
