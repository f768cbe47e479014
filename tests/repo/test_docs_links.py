"""The README and the manual link only to what exists, and the README leads to every page.

The manual moved out of the README into ``docs/manual/`` (issue 32).  GitHub shows a
link to a renamed page, a reworded heading or a moved screenshot without complaint, so
every relative link and image in the project's own Markdown is followed here: the file
must exist and, for ``#anchor``, the page must have a heading with that anchor (GitHub's
slug).  The scanners are pure functions, tried below on planted text so that they are
known to fail when they should.
"""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path, PurePosixPath

import pytest

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
MANUAL = ROOT / "docs" / "manual"
#: The README is a front page, read in five minutes; the manual holds the rest.
README_MAX_LINES = 250
#: Links to a page another change is writing, each as it is reported below; once the page
#: is there the entry must go (the test says so), so none lingers.
PENDING: set[str] = set()

#: ``[text](target)`` and ``![alt](target)``; a target has no spaces (none of ours does).
LINK = re.compile(r"!?\[[^\]]*\]\((?P<target>[^)\s]+)\)")
FENCE = re.compile(r"^\s*(```|~~~)")
HEADING = re.compile(r"^(#{1,6})\s+(?P<text>.+?)\s*#*\s*$")


def _prose(text: str) -> list[str]:
    """The lines outside fenced code blocks (a ``# comment`` in a shell block is no heading)."""
    lines, fenced = [], False
    for line in text.splitlines():
        if FENCE.match(line):
            fenced = not fenced
        elif not fenced:
            lines.append(line)
    return lines


def slug(heading: str) -> str:
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link keeps its text
    text = re.sub(r"[^\w\- ]", "", text.strip().lower())
    return text.replace(" ", "-")


def anchors(text: str) -> set[str]:
    """Every heading's anchor on a page; a repeated heading gets ``-1``, ``-2`` as on GitHub."""
    seen: Counter[str] = Counter()
    found = set()
    for line in _prose(text):
        match = HEADING.match(line)
        if match is None:
            continue
        base = slug(match["text"])
        found.add(base if not seen[base] else f"{base}-{seen[base]}")
        seen[base] += 1
    return found


def links(text: str) -> list[str]:
    """Relative link and image targets of a page (web addresses and mail left out)."""
    return [
        match["target"]
        for line in _prose(text)
        for match in LINK.finditer(re.sub(r"`[^`]*`", "", line))
        if not re.match(r"[a-z][a-z0-9+.-]*:", match["target"])
    ]


def broken(page: Path, text: str, read: dict[Path, str]) -> list[str]:
    """``page: target`` for each link whose file or heading is not there."""
    found = []
    for target in links(text):
        path_part, _, anchor = target.partition("#")
        goal = (page.parent / path_part).resolve() if path_part else page
        if path_part and not goal.exists():
            found.append(f"{page.relative_to(ROOT)}: {target} (no such file)")
            continue
        if anchor and goal.suffix == ".md":
            body = text if goal == page else read.get(goal)
            if body is None:
                body = goal.read_text(encoding="utf-8")
            if anchor not in anchors(body):
                found.append(f"{page.relative_to(ROOT)}: {target} (no such heading)")
    return found


def _pages() -> dict[Path, str]:
    paths = [README, *sorted((ROOT / "docs").rglob("*.md"))]
    return {path.resolve(): path.read_text(encoding="utf-8") for path in paths}


def test_every_link_and_image_of_the_readme_and_docs_is_there() -> None:
    pages = _pages()
    assert MANUAL.resolve() / "README.md" in pages, "the manual has a contents page"
    found = [hit for path, text in pages.items() for hit in broken(path, text, pages)]
    unexpected = [hit for hit in found if hit not in PENDING]
    stale = sorted(PENDING - set(found))
    assert not unexpected, "links to nothing:\n" + "\n".join(unexpected)
    assert not stale, "there now, so remove from PENDING in this test:\n" + "\n".join(stale)


def test_the_readme_and_the_contents_page_lead_to_every_manual_page() -> None:
    pages = {path.resolve() for path in MANUAL.glob("*.md")}
    for index in (README, MANUAL / "README.md"):
        text = index.read_text(encoding="utf-8")
        linked = {(index.parent / t.partition("#")[0]).resolve() for t in links(text)}
        missing = sorted(p.name for p in pages - linked - {index.resolve()})
        assert not missing, f"{index.relative_to(ROOT)} does not link to: {missing}"


def test_the_readme_is_a_front_page() -> None:
    lines = README.read_text(encoding="utf-8").count("\n")
    assert lines <= README_MAX_LINES, (
        f"README.md has {lines} lines (at most {README_MAX_LINES}): move the detail to docs/manual/"
    )


# -- the scanners catch what they should -------------------------------------------------


@pytest.mark.parametrize(
    ("heading", "anchor"),
    [
        ("Jobs (Ctrl+J, or View → Jobs)", "jobs-ctrlj-or-view--jobs"),
        ("`stepdeck run`: a job without a window", "stepdeck-run-a-job-without-a-window"),
        ("The PCB drill (`--profile pcb-drill`)", "the-pcb-drill---profile-pcb-drill"),
        ("Install and launch (Linux)", "install-and-launch-linux"),
        ("See [the gate](window.md)", "see-the-gate"),
    ],
)
def test_a_heading_gets_githubs_anchor(heading: str, anchor: str) -> None:
    assert slug(heading) == anchor


def test_a_repeated_heading_is_numbered_and_code_is_no_heading() -> None:
    text = "# Notes\n\n## Notes\n\n```sh\n# not a heading\n```\n"
    assert anchors(text) == {"notes", "notes-1"}


def test_a_link_to_a_missing_page_or_heading_is_found() -> None:
    page = ROOT / "docs" / "manual" / "planted.md"
    text = (
        "[there](window.md) [gone](gone.md) [heading](#planted) [nowhere](#nowhere)\n"
        "![shot](../nothing.png) [web](https://example.org/x)\n"
        "`[in code](gone-too.md)`\n\n# Planted\n"
    )
    found = broken(page, text, {page: text})
    assert [hit.split(": ", 1)[1] for hit in found] == [
        "gone.md (no such file)",
        "#nowhere (no such heading)",
        "../nothing.png (no such file)",  # stays inside: a link in docs/manual/
    ]
    assert PurePosixPath(found[0].split(":")[0]) == PurePosixPath("docs/manual/planted.md")
