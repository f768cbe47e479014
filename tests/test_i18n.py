"""English, Czech and Slovak: the language chosen, the main window in it, plurals, lupdate.

Each test removes the translations it installed, so the rest of the suite reads English.
"""

from __future__ import annotations

import shutil
import subprocess
from collections.abc import Iterator
from pathlib import Path

import PySide6
import pytest
from PySide6.QtCore import QCoreApplication, QLocale, QSettings
from pytestqt.qtbot import QtBot

from app import i18n
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

ROOT = Path(__file__).resolve().parent.parent
SETTINGS_LEFT = "%n settings could not be used; defaults are used instead"


@pytest.fixture(autouse=True)
def english_afterwards(qapp: object) -> Iterator[None]:
    yield
    i18n.remove()


def _window(qtbot: QtBot, harness: StationHarness, tmp_path: Path) -> MainWindow:
    settings = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    window = MainWindow(harness.station, settings, checkpoint_dir=tmp_path / "checkpoints")
    qtbot.addWidget(window)
    return window


def _menus(window: MainWindow) -> list[str]:
    return [a.text().replace("&", "") for a in window.menuBar().actions()]


def test_the_system_locale_chooses_unless_a_language_is_set() -> None:
    assert i18n.chosen_language("system", QLocale("cs_CZ")) == "cs"
    assert i18n.chosen_language("system", QLocale("sk_SK")) == "sk"
    assert i18n.chosen_language("system", QLocale("de_DE")) == "en"
    assert i18n.chosen_language("sk", QLocale("cs_CZ")) == "sk"


@pytest.mark.parametrize(
    ("language", "menus", "locked"),
    [
        ("cs", ["Soubor", "Stroj", "Zobrazení", "Nápověda"], "Pohyb zablokován: "),
        ("sk", ["Súbor", "Stroj", "Zobrazenie", "Pomocník"], "Pohyb zablokovaný: "),
    ],
)
def test_the_main_window_speaks_the_language_installed(
    qtbot: QtBot,
    harness: StationHarness,
    tmp_path: Path,
    language: str,
    menus: list[str],
    locked: str,
) -> None:
    english = _window(qtbot, harness, tmp_path)
    english_pages = [
        b.text() for b in english.menu_panel.findChildren(PySide6.QtWidgets.QPushButton)
    ]
    assert i18n.install(language, tmp_path / "qm") == language
    window = _window(qtbot, harness, tmp_path)
    assert _menus(window) == menus
    assert window.lock_label.text().startswith(locked)
    pages = [b.text() for b in window.menu_panel.findChildren(PySide6.QtWidgets.QPushButton)]
    assert pages != english_pages and len(pages) == len(english_pages)
    # The page keys stay the same in every language: Alt+M, Alt+A, Alt+R, Alt+L.
    letters = [p[p.index("&") + 1].upper() for p in pages]
    english_letters = [p[p.index("&") + 1].upper() for p in english_pages]
    assert letters == english_letters
    assert window.show_about().windowTitle() != "About StepDeck"


@pytest.mark.parametrize(
    ("language", "counts"),
    [
        ("cs", {1: "hodnota", 3: "hodnoty", 5: "hodnoty"}),
        ("sk", {1: "nastavenie sa nedalo", 3: "nastavenia sa nedali", 5: "nastavení sa nedalo"}),
        ("en", {1: "1 setting could not", 3: "3 settings could not", 5: "5 settings"}),
    ],
)
def test_plurals_take_the_languages_forms(
    tmp_path: Path, language: str, counts: dict[int, str]
) -> None:
    assert i18n.install(language, tmp_path / "qm") == language
    for count, expected in counts.items():
        text = QCoreApplication.translate("MainWindow", SETTINGS_LEFT, "", count)
        assert expected in text and str(count) in text


def test_the_language_menu_choice_is_kept(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    window = _window(qtbot, harness, tmp_path)
    assert window.language_actions["system"].isChecked()
    window.language_actions["sk"].trigger()
    assert "starts again" in window.message_label.text()
    window.close()
    again = _window(qtbot, harness, tmp_path)
    assert again.language_actions["sk"].isChecked()


def test_lupdate_finds_no_new_or_unfinished_string(tmp_path: Path) -> None:
    lupdate = Path(PySide6.__file__).resolve().parent / "lupdate"
    for language in ("cs", "sk", "en"):
        copy = tmp_path / f"stepdeck_{language}.ts"
        shutil.copyfile(ROOT / "resources" / "i18n" / copy.name, copy)
        extra = ["-pluralonly"] if language == "en" else []
        result = subprocess.run(
            [str(lupdate), *extra, str(ROOT / "widgets" / "main_window.py"), "-ts", str(copy)],
            capture_output=True,
            text=True,
            timeout=60,
            check=True,
        )
        if language != "en":  # the English file keeps the plural forms only
            assert "(0 new and" in result.stdout, result.stdout
        text = copy.read_text(encoding="utf-8")
        assert 'type="unfinished"' not in text and 'type="vanished"' not in text
