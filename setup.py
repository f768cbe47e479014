"""The parts of the build pyproject.toml cannot declare.

- The repository keeps its shipped files in ``resources/`` at the root (the
  layout is fixed); they are installed as the package ``stepdeck_resources``,
  a name no other distribution uses, so ``importlib.resources`` finds them in a
  wheel and in an editable checkout alike.  A renamed folder is a ``package_dir``
  entry, which an explicit package list must accompany.
- The translations are compiled while the wheel is built, with the ``lrelease``
  PySide6 ships, so an installed station never needs a compiler at start.  The
  ``.qm`` files are build output, never committed; an editable install skips
  them (app/i18n.py compiles a checkout's ``.ts`` into its cache instead).
"""

from __future__ import annotations

import subprocess
from pathlib import Path

from setuptools import find_packages, setup
from setuptools.command.build_py import build_py

ROOT = Path(__file__).resolve().parent
TOP_LEVEL = ("app", "widgets", "protocol", "stepdeck")
RESOURCES_PACKAGE = "stepdeck_resources"
TRANSLATIONS = ROOT / "resources" / "i18n"
#: One file takes a few tens of milliseconds; more means something is wrong.
LRELEASE_TIMEOUT_S = 60


def lrelease() -> Path:
    """PySide6's own ``lrelease`` (build_backend.py asks for PySide6 for wheel builds)."""
    try:
        import PySide6
    except ImportError as exc:
        raise SystemExit(
            "building StepDeck's wheel compiles its translations with PySide6's lrelease: "
            f"install PySide6-Essentials in the build environment ({exc})"
        ) from exc
    return Path(PySide6.__file__).resolve().parent / "lrelease"


class BuildPyWithTranslations(build_py):
    """``build_py`` that also compiles ``resources/i18n/*.ts`` into the package's ``.qm``."""

    def run(self) -> None:
        super().run()
        if not self.editable_mode:
            self.compile_translations()

    def _qm_targets(self) -> list[tuple[Path, Path]]:
        target = Path(self.build_lib) / RESOURCES_PACKAGE / "i18n"
        return [
            (ts, target / ts.with_suffix(".qm").name) for ts in sorted(TRANSLATIONS.glob("*.ts"))
        ]

    def compile_translations(self) -> None:
        tool = lrelease()
        pairs = self._qm_targets()
        if not pairs:
            raise SystemExit(f"no translations found in {TRANSLATIONS}")
        for source, target in pairs:
            target.parent.mkdir(parents=True, exist_ok=True)
            subprocess.run(
                [str(tool), "-silent", str(source), "-qm", str(target)],
                check=True,
                timeout=LRELEASE_TIMEOUT_S,
            )
            if not target.is_file():
                raise SystemExit(f"lrelease made no {target.name} from {source}")

    def get_outputs(self, include_bytecode: bool = True) -> list[str]:
        outputs = list(super().get_outputs(include_bytecode))
        if not self.editable_mode:
            outputs += [str(target) for _, target in self._qm_targets()]
        return outputs


setup(
    packages=[
        *find_packages(include=[f"{top}{sub}" for top in TOP_LEVEL for sub in ("", ".*")]),
        RESOURCES_PACKAGE,
    ],
    package_dir={RESOURCES_PACKAGE: "resources"},
    cmdclass={"build_py": BuildPyWithTranslations},
)
