"""The repository stands alone: no file names, and no code opens, a place outside it.

StepDeck was first developed beside a folder of shared material (job files,
GRBL, the first wire contract) that a clone does not have: a fresh clone then
failed 120 tests.  That material now lives in the repository (``tests/data``,
``tests/third_party``, ``docs/protocols.md``), and these checks keep it so.
They read every file git tracks, so a file added later is covered too, and
name each finding as ``path:line``.

The checks are textual and deliberately simple: a reference to a folder
beside the repository, a document that is not in it, a ``Path(__file__)``
chain or a ``..`` that climbs above the repository root, and runtime code
that reads test material.  Each check's scanner is a pure function, tested
below on planted lines so that it is known to fail when it should.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from collections.abc import Iterable, Iterator
from pathlib import Path, PurePosixPath

import pytest

ROOT = Path(__file__).resolve().parents[2]
#: This file holds, as examples, the very references it looks for.
THIS = PurePosixPath(Path(__file__).resolve().relative_to(ROOT).as_posix())

#: A folder beside the repository: ``../shared``, ``shared/…`` as a path, ``"shared"`` joined.
OUTSIDE_FOLDER = re.compile(r"\.\.[/\\]shared\b|(?<![\w.-])shared[/\\]|[\"']shared[\"']")
#: The documents of that folder, by name: the repository has its own (docs/protocols.md,
#: docs/fidelity.md), which are written in lower case.
OUTSIDE_DOCUMENT = re.compile(r"\bPROTOCOLS\b|\b(?:DESIGN|STYLE|FIDELITY)\.md\b")
#: Text that is not the project's own, kept unchanged: what it names is not ours to fix.
FOREIGN = (PurePosixPath("tests/third_party"), PurePosixPath("tests/data"))
#: Known references in files another change owns, each with the text that must still be
#: there; once fixed, the entry must go (the test says so), so none lingers.
PENDING: dict[PurePosixPath, str] = {}

#: ``Path(__file__)`` followed by ``.resolve()``/``.absolute()`` and parents.
FILE_CHAIN = re.compile(
    r"Path\(\s*__file__\s*\)(?:\.(?:resolve|absolute)\(\))*"
    r"(?P<parents>(?:\.parent\b)*)(?:\.parents\[(?P<index>\d+)\])?"
)
#: A name bound to a chain and nothing more (``ROOT = Path(__file__).resolve().parent``).
ASSIGNED_CHAIN = re.compile(
    r"^\s*(?P<name>[A-Za-z_]\w*)\s*(?::[^=]+)?=\s*" + FILE_CHAIN.pattern + r"\s*(?:#.*)?$"
)
#: A string that climbs: ``".."`` or one starting ``"../"``.
CLIMBING_STRING = re.compile(r"(?P<q>[\"'])\.\.(?:[/\\][^\"']*)?(?P=q)")
#: A line that really needs a ``..`` (a hostile file name for a tmp_path test) says why.
STAYS_INSIDE = "# stays inside:"
#: A shell script going up from its own folder: ``$(dirname "$0")/..``.
SHELL_UP = re.compile(r"dirname\s+\"?\$(?:0|\{BASH_SOURCE\[0\]\})\"?\s*\)\"?(?P<ups>(?:/\.\.)+)")

#: The packages that are StepDeck; they must work without the tests' material.
RUNTIME = ("app", "protocol", "widgets", "stepdeck")
TEST_MATERIAL = re.compile(r"tests[/\\](?:data|third_party)|\bthird_party\b|[\"']tests[\"']")


# -- the scanners (pure) --------------------------------------------------------------


def _lines(text: str) -> Iterator[tuple[int, str]]:
    return enumerate(text.splitlines(), start=1)


def outside_folders(path: PurePosixPath, text: str) -> list[str]:
    """``path:line`` of every reference to a folder beside the repository."""
    return [
        f"{path}:{n}: {line.strip()}" for n, line in _lines(text) if OUTSIDE_FOLDER.search(line)
    ]


def outside_documents(path: PurePosixPath, text: str) -> list[str]:
    """``path:line`` of every mention of a document that lived outside the repository."""
    if any(path.is_relative_to(folder) for folder in FOREIGN):
        return []
    return [
        f"{path}:{n}: {line.strip()}" for n, line in _lines(text) if OUTSIDE_DOCUMENT.search(line)
    ]


def _levels(match: re.Match[str]) -> int:
    """Folders a ``Path(__file__)`` chain climbs from the file itself (``.parent`` is 1)."""
    levels = match["parents"].count(".parent")
    if match["index"] is not None:
        levels += int(match["index"]) + 1
    return levels


def climbing_code(path: PurePosixPath, text: str) -> list[str]:
    """``path:line`` where Python code reaches above the repository root.

    A file at ``tests/helpers/x.py`` may climb three folders (to the root),
    no more; a name bound to such a chain (``ROOT = Path(__file__)…``) carries
    its level into the ``.parent`` and ``/ ".."`` applied to it later.
    """
    allowed = len(path.parts)
    found: list[str] = []
    levels: dict[str, int] = {}
    for n, line in _lines(text):
        assigned = ASSIGNED_CHAIN.match(line)
        if assigned is not None:
            levels[assigned["name"]] = _levels(assigned)
        worst = max((_levels(m) for m in FILE_CHAIN.finditer(line)), default=0)
        for name, level in levels.items():
            for use in re.finditer(
                rf"\b{name}\b(?P<up>(?:\.parent\b|\s*/\s*[\"']\.\.[\"'])*)", line
            ):
                up = use["up"]
                worst = max(worst, level + up.count(".parent") + up.count(".."))
        climbing = CLIMBING_STRING.search(line) is not None and STAYS_INSIDE not in line
        if worst > allowed or climbing:
            found.append(f"{path}:{n}: {line.strip()}")
    return found


def climbing_shell(path: PurePosixPath, text: str) -> list[str]:
    """``path:line`` where a shell script goes above the root from its own folder."""
    allowed = len(path.parts) - 1
    found = []
    for n, line in _lines(text):
        ups = sum(m["ups"].count("..") for m in SHELL_UP.finditer(line))
        if ups > allowed or "../.." in line:
            found.append(f"{path}:{n}: {line.strip()}")
    return found


def runtime_reads_test_material(path: PurePosixPath, text: str) -> list[str]:
    """``path:line`` where StepDeck's own code names the tests' data or third-party code."""
    if path.parts[0] not in RUNTIME:
        return []
    return [f"{path}:{n}: {line.strip()}" for n, line in _lines(text) if TEST_MATERIAL.search(line)]


# -- the repository ---------------------------------------------------------------------


def _tracked() -> list[PurePosixPath]:
    git = shutil.which("git")
    if git is None:
        pytest.skip("git is not installed: the tracked files cannot be listed")
    result = subprocess.run(
        [git, "-C", str(ROOT), "ls-files", "-z"], capture_output=True, timeout=60, check=False
    )
    if result.returncode != 0:
        pytest.skip("not a git checkout: the tracked files cannot be listed")
    names = result.stdout.decode("utf-8", "surrogateescape").split("\0")
    return [PurePosixPath(name) for name in names if name]


def _texts(paths: Iterable[PurePosixPath]) -> Iterator[tuple[PurePosixPath, str]]:
    """Each tracked text file with its content (binary files and this file skipped)."""
    for path in paths:
        if path == THIS:
            continue
        try:
            data = (ROOT / path).read_bytes()
        except (FileNotFoundError, IsADirectoryError):
            continue  # deleted in the working tree, or a submodule
        if b"\0" in data[:8192]:
            continue
        yield path, data.decode("utf-8", "replace")


@pytest.fixture(scope="module")
def tracked_texts() -> list[tuple[PurePosixPath, str]]:
    return list(_texts(_tracked()))


def _is_shell(path: PurePosixPath, text: str) -> bool:
    if any(path.is_relative_to(folder) for folder in FOREIGN):
        return False
    first = text.split("\n", 1)[0]
    return path.suffix == ".sh" or (first.startswith("#!") and "sh" in first.split("/")[-1])


def test_the_tracked_files_are_read(tracked_texts: list[tuple[PurePosixPath, str]]) -> None:
    """The checks below see the whole repository, not an empty list."""
    paths = {path for path, _ in tracked_texts}
    assert PurePosixPath("protocol/stage/codec.py") in paths
    assert PurePosixPath("docs/protocols.md") in paths
    assert PurePosixPath(".ci/run") in paths


def test_no_file_refers_to_a_folder_beside_the_repository(
    tracked_texts: list[tuple[PurePosixPath, str]],
) -> None:
    found = [hit for path, text in tracked_texts for hit in outside_folders(path, text)]
    assert not found, "references to a folder outside the repository:\n" + "\n".join(found)


def test_no_file_names_a_document_that_is_not_in_the_repository(
    tracked_texts: list[tuple[PurePosixPath, str]],
) -> None:
    """The wire contract is docs/protocols.md, the fidelity audit docs/fidelity.md."""
    found = [hit for path, text in tracked_texts for hit in outside_documents(path, text)]
    pending = [
        hit
        for hit in found
        if any(hit.startswith(f"{path}:") and snippet in hit for path, snippet in PENDING.items())
    ]
    stale = [
        f"{path}: {snippet!r}"
        for path, snippet in PENDING.items()
        if not any(hit.startswith(f"{path}:") and snippet in hit for hit in found)
    ]
    unexpected = [hit for hit in found if hit not in pending]
    assert not unexpected, (
        "documents outside the repository (point at docs/protocols.md §N or docs/fidelity.md):\n"
        + "\n".join(unexpected)
    )
    assert not stale, "fixed, so remove from PENDING in this test:\n" + "\n".join(stale)


def test_no_code_reaches_above_the_repository_root(
    tracked_texts: list[tuple[PurePosixPath, str]],
) -> None:
    found = [
        hit
        for path, text in tracked_texts
        if path.suffix == ".py" and not any(path.is_relative_to(f) for f in FOREIGN)
        for hit in climbing_code(path, text)
    ]
    found += [
        hit
        for path, text in tracked_texts
        if _is_shell(path, text)
        for hit in climbing_shell(path, text)
    ]
    assert not found, "code that reaches above the repository root:\n" + "\n".join(found)


def test_stepdeck_itself_never_reads_test_material(
    tracked_texts: list[tuple[PurePosixPath, str]],
) -> None:
    """tests/data and tests/third_party are not installed: the app must not need them."""
    found = [hit for path, text in tracked_texts for hit in runtime_reads_test_material(path, text)]
    assert not found, "runtime code naming the tests' material:\n" + "\n".join(found)


# -- the scanners catch what they should, and only that ------------------------------------


# Planted lines, not references: each is the kind of line the walk above must refuse, so this
# test fails if the scanner stops seeing them (the walk skips this file's own examples).
@pytest.mark.parametrize(
    "line",
    [
        "See ../shared/PROTOCOLS.md for the frames.",
        'DATA = ROOT.parent / "shared" / "realdata"',
        "cp -r shared/grbl $tmp",
        r"..\shared\samples",
    ],
)
def test_a_folder_beside_the_repository_is_found(line: str) -> None:
    path = PurePosixPath("tests/test_x.py")
    assert outside_folders(path, f"first\n{line}\n") == [f"{path}:2: {line}"]


@pytest.mark.parametrize(
    "line",
    [
        "the shared harness, connected",
        "a shared-mime-info type",
        "one lock shared by the reader/writer",
        "widgets/shared_style.py",
    ],
)
def test_the_word_shared_alone_is_no_reference(line: str) -> None:
    assert outside_folders(PurePosixPath("app/x.py"), line) == []


def test_an_outside_document_is_found_but_not_in_foreign_text() -> None:
    text = '"""Codec (PROTOCOLS.md section 1)."""\n# see DESIGN.md\n# docs/protocols.md §1\n'
    assert outside_documents(PurePosixPath("protocol/x.py"), text) == [
        'protocol/x.py:1: """Codec (PROTOCOLS.md section 1)."""',
        "protocol/x.py:2: # see DESIGN.md",
    ]
    assert outside_documents(PurePosixPath("tests/third_party/grbl/doc/x.md"), text) == []


@pytest.mark.parametrize(
    ("path", "line", "climbs"),
    [
        ("tests/test_x.py", "ROOT = Path(__file__).resolve().parent.parent", False),
        ("tests/test_x.py", "UP = Path(__file__).resolve().parent.parent.parent", True),
        ("tests/helpers/x.py", "ROOT = Path(__file__).resolve().parent.parent.parent", False),
        ("tests/helpers/x.py", "UP = Path(__file__).parents[3]", True),
        ("tests/helpers/x.py", "ROOT = Path(__file__).parents[2]", False),
        (".ci/x.py", 'open(Path(__file__).parent.parent.parent / "notes")', True),
        ("tests/test_x.py", 'SHARED = "../data"', True),
        ("tests/test_x.py", 'tmp_path / "../x.txt"  # stays inside: a hostile name', False),
    ],
)
def test_a_path_above_the_root_is_found(path: str, line: str, climbs: bool) -> None:
    assert bool(climbing_code(PurePosixPath(path), line + "\n")) is climbs


def test_a_name_bound_to_the_root_carries_its_level() -> None:
    text = (
        "ROOT = Path(__file__).resolve().parent.parent\n"
        'DATA = ROOT / "tests" / "data"\n'
        'OTHER = ROOT.parent / "elsewhere"\n'
        'AGAIN = ROOT / ".." / "elsewhere"\n'
    )
    found = climbing_code(PurePosixPath("tests/test_x.py"), text)
    assert [hit.split(":")[1] for hit in found] == ["3", "4"]


def test_a_shell_script_above_the_root_is_found() -> None:
    ok = 'cd "$(dirname "$0")/.."\n'
    up = 'cd "$(dirname "$0")/../.."\n'
    assert climbing_shell(PurePosixPath(".ci/run"), ok) == []
    assert climbing_shell(PurePosixPath(".ci/run"), up) == [f".ci/run:1: {up.strip()}"]
    assert climbing_shell(PurePosixPath("run.sh"), ok) != []


def test_runtime_code_naming_test_material_is_found() -> None:
    line = 'SAMPLES = Path(__file__).parent.parent / "tests" / "data"'
    assert runtime_reads_test_material(PurePosixPath("app/jobs/x.py"), line) == [
        f"app/jobs/x.py:1: {line}"
    ]
    assert runtime_reads_test_material(PurePosixPath("tests/test_x.py"), line) == []
