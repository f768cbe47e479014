"""English, Czech and Slovak: the language chosen, every panel in it, the live switch,
plurals, numbers, and .ts files with nothing left to translate.

Each test removes the translations it installed, so the rest of the suite reads English.
"""

from __future__ import annotations

import subprocess
import sys
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from pathlib import Path

import PySide6
import pytest
from PySide6.QtCore import QCoreApplication, QLocale, QSettings
from PySide6.QtWidgets import QAbstractButton, QApplication, QDockWidget, QGroupBox, QLabel, QWidget
from pytestqt.qtbot import QtBot

from app import i18n
from app.jobs.loaders import load_job
from app.jobs.program import JobFileError, OpKind, check_limits
from app.machine import LinkState
from app.profiles import available_profiles, load_profile
from app.settings import StationSettings
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow
from widgets.number_field import NumberField, format_number

ROOT = Path(__file__).resolve().parents[2]
SETTINGS_LEFT = "%n settings could not be used; defaults are used instead"


@pytest.fixture(autouse=True)
def english_afterwards(qapp: object) -> Iterator[None]:
    yield
    i18n.remove()


def _window(qtbot: QtBot, harness: StationHarness, tmp_path: Path) -> MainWindow:
    settings = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    window = MainWindow(
        harness.station,
        settings,
        checkpoint_dir=tmp_path / "checkpoints",
        i18n_cache=tmp_path / "qm",
    )
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


# --- every panel and dock, switched while the window is open ------------------------

#: Letters only these languages write: a text holding one is not English.
NATIVE = {"cs": "ěščřžýáíéůúňťď", "sk": "ôäľĺŕšžčťňýáíéú"}
#: Words an engineer expects on the machine's controls, by language.
KNOWN = {
    "cs": {"Připojit", "Odpojit", "Spustit", "Pozastavit", "Přerušit", "Zastavit vše"},
    "sk": {"Pripojiť", "Odpojiť", "Spustiť", "Pozastaviť", "Prerušiť", "Zastaviť všetko"},
}


def _texts(root: QWidget) -> list[str]:
    """What the operator reads on ``root``: captions, labels, group and dock titles."""
    widgets = [root, *root.findChildren(QWidget)]
    found = []
    for widget in widgets:
        if isinstance(widget, (QLabel, QAbstractButton)):
            text = widget.text()
        elif isinstance(widget, QGroupBox):
            text = widget.title()
        elif isinstance(widget, QDockWidget):
            text = widget.windowTitle()
        else:
            continue
        found.append(text)
    return found


def _panels(window: MainWindow) -> dict[str, QWidget]:
    names = [
        "manual_panel", "static_panel", "connection_panel", "info_panel", "absolute_panel",
        "relative_panel", "drill_panel", "usb3_panel", "gcode_panel", "dynamics_panel",
        "jobs_dock", "telemetry_dock", "developer_pane",
    ]  # fmt: skip
    return {n: getattr(window, n) for n in names if hasattr(window, n)}


def _switch(qtbot: QtBot, window: MainWindow, language: str, connect: str) -> None:
    """Choose ``language`` in the menu; Qt delivers the change through the event loop."""
    window.language_actions[language].trigger()
    qtbot.waitUntil(lambda: window.connection_panel.connect_button.text() == connect)
    QApplication.processEvents()


@pytest.mark.parametrize("profile", available_profiles())
@pytest.mark.parametrize(("language", "connect"), [("cs", "Připojit"), ("sk", "Pripojiť")])
def test_every_panel_and_dock_changes_language_in_the_open_window(
    qtbot: QtBot, tmp_path: Path, profile: str, language: str, connect: str
) -> None:
    harness = StationHarness(load_profile(profile))
    try:
        window = _window(qtbot, harness, tmp_path)
        english = {name: _texts(panel) for name, panel in _panels(window).items()}
        menus = _menus(window)
        _switch(qtbot, window, language, connect)
        assert _menus(window) != menus
        shown: set[str] = set()
        for name, panel in _panels(window).items():
            before, after = english[name], _texts(panel)
            assert len(after) == len(before), name  # nothing rebuilt, nothing lost
            worded = [(a, b) for a, b in zip(before, after, strict=True) if _is_wording(a)]
            changed = [b for a, b in worded if a != b]
            # Names (X, Y, Bluetooth LE, STOP, Reset…) stay; the words around them do not.
            assert len(changed) >= 0.6 * len(worded), (name, [a for a, b in worded if a == b])
            shown.update(changed)
        assert sum(bool(set(NATIVE[language]) & set(text)) for text in shown) >= 10
        assert KNOWN[language] & {t.replace("&", "") for t in shown}
        window.close()
    finally:
        harness.close()


def _is_wording(text: str) -> bool:
    """Text made of words (not a number, an axis name, a unit or an empty label)."""
    return sum(c.isalpha() for c in text) >= 3


def test_the_switch_keeps_the_link_the_job_and_the_fields_and_sends_nothing(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    harness.connect()
    window = _window(qtbot, harness, tmp_path)
    job = tmp_path / "square.csv"
    job.write_text("5, 5\n20, 5\n20, 20\n5, 20\n", encoding="utf-8")
    assert window.jobs_dock.open_path(job)
    program = window.job_runner.program
    session = harness.station.session
    window.absolute_panel.targets[0].setText("12,5")
    sent = len(harness.written)

    _switch(qtbot, window, "sk", "Pripojiť")

    assert harness.station.session is session
    assert window.model.link_state is LinkState.CONNECTED
    assert window.job_runner.program is program and window.jobs_dock.run_button.isEnabled()
    assert window.jobs_dock.run_button.text() == "Spustiť"
    assert "4 operácie" in window.jobs_dock.file_label.text()
    assert window.absolute_panel.targets[0].text() == "12,5"
    assert window.absolute_panel.targets[0].value() == 12.5
    assert len(harness.written) == sent  # a language switch is no command
    assert window.link_status.text().startswith("Spojenie: pripojené")
    assert window.message_label.text() == "Jazyk: Slovenčina"
    # The link goes on answering in the new language, and English comes back whole.
    harness.run(0.2)
    assert window.model.link_state is LinkState.CONNECTED
    _switch(qtbot, window, "en", "Connect")
    assert window.jobs_dock.run_button.text() == "Run"
    assert "4 operations" in window.jobs_dock.file_label.text()
    assert _menus(window) == ["File", "Machine", "View", "Help"]


def test_the_language_chosen_is_kept_for_the_next_start(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    window = _window(qtbot, harness, tmp_path)
    assert window.language_actions["system"].isChecked()
    _switch(qtbot, window, "sk", "Pripojiť")
    assert window.language_actions["sk"].isChecked()
    window.close()
    again = _window(qtbot, harness, tmp_path)
    assert again.language_actions["sk"].isChecked()
    stored = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    assert stored.value("view/language") == "sk"


# --- numbers ------------------------------------------------------------------------


@pytest.mark.parametrize(("language", "shown"), [("en", "1.500"), ("cs", "1,500"), ("sk", "1,500")])
def test_numbers_show_the_languages_decimal_separator_and_take_either(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path, language: str, shown: str
) -> None:
    assert i18n.install(language, tmp_path / "qm") == language
    assert format_number(1.5, 3) == shown
    field = NumberField(0.0, 10.0, decimals=3)
    qtbot.addWidget(field)
    field.setValue(1.5)
    assert field.text() == shown
    for typed in ("2.25", "2,25"):
        field.setText(typed)
        assert field.value() == 2.25 and field.is_acceptable()
    harness.connect()
    window = _window(qtbot, harness, tmp_path)
    position = window.info_panel.positions[0].text()
    decimal = shown[1]
    assert decimal in position and ("," if decimal == "." else ".") not in position


# --- the .ts files --------------------------------------------------------------------


@pytest.mark.parametrize(("language", "forms"), [("cs", 3), ("sk", 3), ("en", 2)])
def test_every_entry_is_translated_with_all_its_plural_forms(language: str, forms: int) -> None:
    """Czech and Slovak in full (one, two to four, five and more); English its plurals."""
    path = ROOT / "resources" / "i18n" / f"stepdeck_{language}.ts"
    messages = list(ET.parse(path).getroot().iter("message"))
    assert len(messages) > (500 if language != "en" else 20)
    for message in messages:
        source = message.findtext("source")
        translation = message.find("translation")
        assert translation is not None and translation.get("type") is None, source
        if message.get("numerus") == "yes":
            texts = [form.text or "" for form in translation.iter("numerusform")]
            assert len(texts) == forms and all("%n" in text for text in texts), source
        else:
            assert language != "en", source  # English keeps its plural forms only
            assert (translation.text or "").strip(), source


def test_lupdate_finds_every_string_already_translated() -> None:
    """The documented command, in its checking mode: nothing new, unfinished or vanished."""
    result = subprocess.run(
        [sys.executable, str(ROOT / ".ci" / "update_translations.py"), "--check"],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    assert "(0 new and" in result.stdout


@pytest.mark.parametrize(
    ("language", "counts"),
    [
        ("cs", {1: "zapsána 1 hodnota", 3: "zapsány 3 hodnoty", 5: "zapsáno 5 hodnot"}),
        ("sk", {1: "zapísaná 1 hodnota", 3: "zapísané 3 hodnoty", 5: "zapísaných 5 hodnôt"}),
        ("en", {1: "1 value written", 3: "3 values written", 5: "5 values written"}),
    ],
)
def test_panel_plurals_take_the_languages_three_forms(
    tmp_path: Path, language: str, counts: dict[int, str]
) -> None:
    assert i18n.install(language, tmp_path / "qm") == language
    for count, expected in counts.items():
        text = QCoreApplication.translate("DynamicsPanel", "%n value(s) written", "", count)
        assert text == expected


DRILL_FILE = "M48\nINCH,TZ\nT01C0.0315\n%\nT01\nX1000Y1000\nX2000Y1000\nX3000Y1000\nM30\n"
UNKNOWN_TOOL = "M48\nINCH,TZ\nT01C0.0315\n%\nT02\nX1000Y1000\nM30\n"


@pytest.mark.parametrize(
    ("language", "refusal", "prompt", "travel", "outside"),
    [
        (
            "cs",
            "neznámý nástroj: ",
            "vložte T01, 0,80 mm, otvorů: 3",
            "pojezd mezi otvory: ",
            "najet na X5,080 Y2,540 — X 5,08 je mimo meze pojezdu 0…3",
        ),
        (
            "sk",
            "neznámy nástroj: ",
            "vložte T01, 0,80 mm, otvorov: 3",
            "pojazd medzi otvormi: ",
            "nabehnúť na X5,080 Y2,540 — X 5,08 je mimo rozsahu posuvu 0…3",
        ),
    ],
)
def test_a_refused_job_file_and_the_bit_prompts_speak_the_language(
    tmp_path: Path, language: str, refusal: str, prompt: str, travel: str, outside: str
) -> None:
    """Texts made on the loading thread are in the language installed when they are made."""
    bad = tmp_path / "bad.drl"
    bad.write_text(UNKNOWN_TOOL)
    good = tmp_path / "good.drl"
    good.write_text(DRILL_FILE)
    assert i18n.install(language, tmp_path / "qm") == language

    with pytest.raises(JobFileError) as refused:
        load_job(bad, ("X", "Y"))
    assert refused.value.line == 5
    assert refused.value.reason.startswith(refusal)
    assert "T02" in refused.value.reason
    program = load_job(good, ("X", "Y"))
    assert [op.message for op in program if op.kind is OpKind.WAIT] == [prompt]
    assert any(travel in note for note in program.notes)
    beyond = check_limits(program, {"X": (0.0, 3.0), "Y": (0.0, 3.0)})
    assert len(beyond) == 2  # the holes at 0.2 and 0.3 inch
    assert str(beyond[0]).endswith(outside)

    i18n.remove()  # back in English, the same files read as before
    with pytest.raises(JobFileError, match="unknown tool: "):
        load_job(bad, ("X", "Y"))
    english = load_job(good, ("X", "Y"))
    assert [op.message for op in english if op.kind is OpKind.WAIT] == [
        "insert T01, 0.80 mm, 3 holes"
    ]


@pytest.mark.parametrize(
    ("language", "expected"),
    [
        ("cs", "nelze číst: složka, ne soubor úlohy"),
        ("sk", "nedá sa čítať: priečinok, nie súbor úlohy"),
    ],
)
def test_a_folder_opened_as_a_job_is_refused_in_the_language(
    tmp_path: Path, language: str, expected: str
) -> None:
    folder = tmp_path / "job.nc"
    folder.mkdir()
    i18n.install(language, tmp_path / "qm")
    with pytest.raises(JobFileError) as refused:
        load_job(folder, ("X", "Y"))
    assert refused.value.reason == expected


@pytest.mark.parametrize(
    ("language", "malformed", "bad_value"),
    [
        ("cs", "je poškozený: použijí se výchozí hodnoty", "Nastavení link/baud v souboru "),
        ("sk", "je poškodený: použijú sa predvolené hodnoty", "Nastavenie link/baud v súbore "),
    ],
)
def test_settings_warnings_speak_the_language_installed_when_they_are_shown(
    tmp_path: Path, language: str, malformed: str, bad_value: str
) -> None:
    """The settings are read before the language is installed: their warnings wait for it."""
    broken = tmp_path / "broken.ini"
    broken.write_bytes(b"[main_window\npage=2")
    corrupt = StationSettings(QSettings(str(broken), QSettings.Format.IniFormat))
    odd = tmp_path / "odd.ini"
    odd.write_text("[link]\nbaud=-5\n")
    wrong = StationSettings(QSettings(str(odd), QSettings.Format.IniFormat))
    # Read (and found wrong, as it is moved to the last machine's) while still English.
    assert wrong.machine(wrong.profile).baud is None
    i18n.install(language, tmp_path / "qm")
    (warning,) = corrupt.take_warnings()
    assert str(broken) in warning
    assert malformed in warning
    (warning,) = wrong.take_warnings()
    assert warning.startswith(bad_value)
