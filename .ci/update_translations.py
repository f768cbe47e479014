"""Bring resources/i18n/*.ts up to date with the sources: ``python .ci/update_translations.py``.

Runs the ``lupdate`` PySide6 ships over every module of app/ and widgets/:
new texts appear as unfinished in stepdeck_cs.ts and stepdeck_sk.ts (to be
translated, e.g. in Qt Linguist), texts no longer in the code are dropped, and
stepdeck_en.ts keeps only the English plural forms.  Locations are left out
(``-locations none``): line numbers would change with every edit anywhere and
make two branches' .ts files conflict where their translations do not.

``--check`` changes nothing and fails when a .ts is not current or an entry is
unfinished: what the tests and a merge check ask.
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import PySide6

ROOT = Path(__file__).resolve().parent.parent
I18N = ROOT / "resources" / "i18n"
#: Translated in full; English is the source language and carries its plurals only.
LANGUAGES = ("cs", "sk", "en")
SOURCES = ("app", "widgets")


def lupdate() -> Path:
    return Path(PySide6.__file__).resolve().parent / "lupdate"


def sources() -> list[Path]:
    return sorted(p for folder in SOURCES for p in (ROOT / folder).rglob("*.py"))


def update(ts: Path, language: str) -> str:
    """Run lupdate on ``ts`` in place; returns its report."""
    extra = ["-pluralonly"] if language == "en" else []
    result = subprocess.run(
        [
            str(lupdate()),
            "-locations",
            "none",
            "-no-obsolete",
            "-target-language",
            language,
            *extra,
            *map(str, sources()),
            "-ts",
            str(ts),
        ],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    return result.stdout + result.stderr


def problems(ts: Path, language: str) -> list[str]:
    """What is wrong with an updated .ts: new or unfinished entries."""
    text = ts.read_text(encoding="utf-8")
    found = []
    unfinished = text.count('type="unfinished"')
    if unfinished and language != "en":
        found.append(f"{ts.name}: {unfinished} unfinished")
    if 'type="vanished"' in text or 'type="obsolete"' in text:
        found.append(f"{ts.name}: vanished entries")
    return found


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="change nothing; fail if not current")
    args = parser.parse_args(argv)
    failed: list[str] = []
    with tempfile.TemporaryDirectory() as scratch:
        for language in LANGUAGES:
            source = I18N / f"stepdeck_{language}.ts"
            target = Path(scratch) / source.name if args.check else source
            if args.check:
                shutil.copyfile(source, target)
            report = update(target, language)
            print(f"{source.name}: {report.strip().splitlines()[-1]}")
            failed += problems(target, language)
            if args.check and target.read_bytes() != source.read_bytes():
                failed.append(f"{source.name}: not current (run .ci/update_translations.py)")
    for problem in failed:
        print(problem, file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
