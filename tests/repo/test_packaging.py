"""A wheel built from the repository works installed on its own, from any folder.

Built as a packager would (sdist, then the wheel from the sdist), installed
non-editable into a fresh venv, and run from a folder outside the repository:
the machine profiles and the compiled translations must come from the
package, not from a checkout that happens to be beside it.

To stay fast the build uses this venv's setuptools and PySide6 (``--no-isolation``:
no throwaway build env with Qt unpacked into it), and the fresh venv borrows this
venv's dependencies through a ``.pth`` line instead of installing them again;
StepDeck itself is installed there from the wheel alone (``--no-deps --no-index``).
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import sysconfig
import tarfile
import tomllib
import zipfile
from dataclasses import dataclass
from pathlib import Path

import pytest

from app import i18n

pytestmark = pytest.mark.packaging

ROOT = Path(__file__).resolve().parents[2]
BUNNY = ROOT / "tests" / "data" / "realdata" / "gcode" / "CNC-Drawinger_unicorn_BUNNY.gcode"
VERSION = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]["version"]
#: Generous for a loaded machine; the whole module takes about 15 s on a quiet one.
TIMEOUT_S = 240

#: The window as ``stepdeck`` opens it, looked at once its event loop runs, then closed.
LOOK_AT_WINDOW = """
import json, sys
from pathlib import Path
from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QApplication, QMainWindow
import app
from app.__main__ import main
from app.version import station_version

qapp = QApplication(sys.argv[:1])
seen = {"app": app.__file__, "version": station_version()}

def look() -> None:
    windows = [w for w in QApplication.topLevelWidgets() if isinstance(w, QMainWindow)]
    seen["menus"] = [a.text().replace("&", "") for w in windows for a in w.menuBar().actions()]
    drawn = QApplication.windowIcon().pixmap(32, 32).toImage()
    seen["icon"] = [drawn.width(), drawn.pixelColor(16, 16).alpha()]
    QApplication.quit()

QTimer.singleShot(0, look)
seen["code"] = main([])
print(json.dumps(seen))
"""


def _run(
    command: list[str | Path], cwd: Path | None = None, env: dict[str, str] | None = None
) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [str(part) for part in command],
        cwd=cwd,
        env=env,
        capture_output=True,
        text=True,
        timeout=TIMEOUT_S,
    )


@pytest.fixture(scope="module")
def dist(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """The sdist and the wheel, the wheel built from the sdist."""
    out = tmp_path_factory.mktemp("dist")
    built = _run([sys.executable, "-m", "build", "--no-isolation", "--outdir", out, ROOT])
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    (sdist,) = out.glob("stepdeck-*.tar.gz")
    (wheel,) = out.glob("stepdeck-*.whl")
    return sdist, wheel


@pytest.fixture(scope="module")
def installed(dist: tuple[Path, Path], tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A fresh venv's ``bin`` with the wheel installed in it, non-editable."""
    venv = tmp_path_factory.mktemp("venv")
    made = _run([sys.executable, "-m", "venv", "--without-pip", venv])
    assert made.returncode == 0, made.stderr
    python = venv / "bin" / "python"
    _, wheel = dist
    pip = [sys.executable, "-m", "pip", "--python", python, "install", "--no-deps", "--no-index"]
    done = _run([*pip, "--no-compile", wheel])
    assert done.returncode == 0, done.stderr
    site = _run([python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"])
    ours = {sysconfig.get_paths()["purelib"], sysconfig.get_paths()["platlib"]}
    (Path(site.stdout.strip()) / "stepdeck-test-dependencies.pth").write_text(
        "".join(f"{path}\n" for path in sorted(ours)), encoding="utf-8"
    )
    return venv / "bin"


@dataclass
class Elsewhere:
    cwd: Path
    env: dict[str, str]


@pytest.fixture
def elsewhere(tmp_path: Path) -> Elsewhere:
    """A folder outside the repository to run in, with its own home, settings and cache."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "LC_", "LANG"))}
    env |= {
        "HOME": str(tmp_path / "home"),
        "XDG_CONFIG_HOME": str(tmp_path / "config"),
        "XDG_CACHE_HOME": str(tmp_path / "cache"),
        "PYTHONNOUSERSITE": "1",
        "QT_QPA_PLATFORM": "offscreen",
    }
    cwd = tmp_path / "cwd"
    cwd.mkdir()
    return Elsewhere(cwd, env)


def test_the_sdist_holds_the_sources_and_no_tests_or_tools(dist: tuple[Path, Path]) -> None:
    sdist, _ = dist
    with tarfile.open(sdist) as archive:
        names = {name.partition("/")[2] for name in archive.getnames()}
    for needed in (
        "setup.py",
        "build_backend.py",
        "LICENSE",
        "THIRD_PARTY_NOTICES.md",
        "resources/i18n/stepdeck_cs.ts",
        "resources/machines/grbl-plotter.toml",
        "app/__main__.py",
    ):
        assert needed in names
    assert not [n for n in names if n.startswith(("tests/", "tools/", "resources/screenshots"))]
    assert not [n for n in names if n.endswith(".qm")]  # build output, built from the .ts


def test_the_wheel_ships_profiles_icon_and_compiled_translations(dist: tuple[Path, Path]) -> None:
    _, wheel = dist
    names = set(zipfile.ZipFile(wheel).namelist())
    resources = {n.removeprefix("stepdeck_resources/") for n in names}
    for language in ("en", "cs", "sk"):
        assert f"i18n/stepdeck_{language}.qm" in resources
    profiles = {path.name for path in (ROOT / "resources" / "machines").glob("*.toml")}
    assert {f"machines/{name}" for name in profiles} <= resources
    assert {"icons/stepdeck.svg", "stepdeck.desktop", "stepdeck-mime.xml"} <= resources
    assert not [n for n in names if n.startswith(("tests/", "tools/")) or n.endswith(".ts")]
    assert not [n for n in names if "screenshots" in n]
    assert f"stepdeck-{VERSION}.dist-info/licenses/LICENSE" in names


def test_installed_check_finds_its_machine_profiles_from_any_folder(
    installed: Path, elsewhere: Elsewhere
) -> None:
    command: list[str | Path] = [
        installed / "stepdeck",
        "check",
        BUNNY,
        "--profile",
        "grbl-plotter",
    ]
    result = _run(command, elsewhere.cwd, elsewhere.env)
    assert "no machine profile" not in result.stderr
    assert result.returncode in (0, 2), result.stderr
    assert BUNNY.name in result.stdout + result.stderr  # the job was read and judged


def test_installed_emulator_command_starts(installed: Path, elsewhere: Elsewhere) -> None:
    result = _run([installed / "stepdeck-emulator", "--help"], elsewhere.cwd, elsewhere.env)
    assert result.returncode == 0, result.stderr
    assert "grbl-plotter" in result.stdout  # the profiles it offers come from the package


@pytest.mark.parametrize("command", ["run", "string-art"])
def test_installed_subcommands_start(installed: Path, elsewhere: Elsewhere, command: str) -> None:
    result = _run([installed / "stepdeck", command, "--help"], elsewhere.cwd, elsewhere.env)
    assert result.returncode == 0, result.stderr
    assert f"stepdeck {command}" in result.stdout


def test_installed_window_opens_in_czech_with_its_icon(
    installed: Path, elsewhere: Elsewhere
) -> None:
    # A fresh start's language is "system": the locale's.
    env = elsewhere.env | {"LANG": "cs_CZ.UTF-8", "LC_ALL": "cs_CZ.UTF-8"}
    result = _run([installed / "python", "-c", LOOK_AT_WINDOW], elsewhere.cwd, env)
    assert result.returncode == 0, result.stderr[-3000:]
    seen = json.loads(result.stdout.strip().splitlines()[-1])
    assert Path(seen["app"]).is_relative_to(installed.parent)  # the wheel's, not the checkout's
    assert seen["version"] == VERSION
    assert seen["code"] == 0
    assert seen["menus"][:2] == ["Soubor", "Stroj"]
    assert seen["icon"] == [32, 255]  # the icon is drawn, not an empty placeholder
    # The shipped .qm was read: nothing was compiled into the cache at start.
    assert not list(Path(env["XDG_CACHE_HOME"]).rglob("*.qm"))


def test_a_shipped_translation_gives_way_to_a_newer_source_beside_it(tmp_path: Path) -> None:
    qm = tmp_path / "stepdeck_cs.qm"
    assert i18n.shipped("cs", tmp_path) is None
    qm.write_bytes(b"compiled")
    assert i18n.shipped("cs", tmp_path) == qm  # an installed wheel: no .ts at all
    ts = tmp_path / "stepdeck_cs.ts"
    ts.write_text("<TS/>", encoding="utf-8")
    os.utime(ts, (qm.stat().st_mtime + 10,) * 2)
    assert i18n.shipped("cs", tmp_path) is None  # a checkout whose .ts moved on
    os.utime(qm, (ts.stat().st_mtime + 10,) * 2)
    assert i18n.shipped("cs", tmp_path) == qm


def test_every_runtime_dependency_is_in_the_third_party_notices() -> None:
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    notices = (ROOT / "THIRD_PARTY_NOTICES.md").read_text(encoding="utf-8").lower()
    names = [re.split(r"[ <>=!~;\[]", requirement)[0] for requirement in project["dependencies"]]
    assert names and not [name for name in names if name.lower() not in notices]


def test_a_checkout_run_without_installing_finds_its_resources_beside_app(tmp_path: Path) -> None:
    # No site-packages (-S): neither an editable install's finder nor an installed wheel.
    code = "from app.resources import MACHINES_DIR; print(MACHINES_DIR)"
    result = _run([sys.executable, "-S", "-c", code], tmp_path, {"PYTHONPATH": str(ROOT)})
    assert result.returncode == 0, result.stderr
    assert Path(result.stdout.strip()) == ROOT / "resources" / "machines"
