"""Macros kept per profile, exported and imported as TOML: what is hostile changes nothing."""

from __future__ import annotations

import tempfile
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PySide6.QtCore import QSettings

from app.macros.store import (
    MAX_MACROS,
    Macro,
    MacroError,
    MacroStore,
    checked_list,
    checked_macro,
)
from app.macros.toml_file import export_macros, import_macros, macros_toml, merged, parse_macros
from app.settings import StationSettings

PARK = Macro("Park", "G90\nG0 X0 Y0")
PEN = Macro("Pen test", "M3 S1000\nG4 P0.5\nM5")


def ini(tmp_path: Path) -> QSettings:
    return QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)


def test_macros_are_kept_per_profile_across_a_restart(tmp_path: Path) -> None:
    odd = Macro("Čára, ☃ = 1", 'G0 X1, Y2 ; "q" \\ back\t;\n\n[comment]\n@ %')
    settings = StationSettings(ini(tmp_path))
    MacroStore(settings, "grbl-plotter").save([PARK, PEN, odd])
    MacroStore(settings, "corexy-plotter").save([Macro("Home", "G28")])
    again = StationSettings(ini(tmp_path))
    assert MacroStore(again, "grbl-plotter").load() == [PARK, PEN, odd]
    assert MacroStore(again, "corexy-plotter").load() == [Macro("Home", "G28")]
    assert MacroStore(again, "string-art").load() == []
    assert again.take_warnings() == []


def test_saving_fewer_macros_forgets_the_others(tmp_path: Path) -> None:
    settings = StationSettings(ini(tmp_path))
    store = MacroStore(settings, "grbl-plotter")
    store.save([PARK, PEN])
    store.save([PEN])
    assert MacroStore(StationSettings(ini(tmp_path)), "grbl-plotter").load() == [PEN]


def test_corrupt_macro_settings_give_no_macro_and_a_warning_never_a_crash(tmp_path: Path) -> None:
    store = ini(tmp_path)
    group = "machines/grbl-plotter/macros"
    store.setValue(f"{group}/count", "3")
    store.setValue(f"{group}/0/name", "Park")
    store.setValue(f"{group}/0/code", "G0 X0")
    store.setValue(f"{group}/1/name", "bad\x1bname")  # an escape in a name
    store.setValue(f"{group}/1/code", "G0 X1")
    store.setValue(f"{group}/2/name", "Park")  # the same name twice
    store.setValue(f"{group}/2/code", "G0 X2")
    store.sync()
    settings = StationSettings(ini(tmp_path))
    assert MacroStore(settings, "grbl-plotter").load() == [Macro("Park", "G0 X0")]
    warnings = settings.take_warnings()
    assert any(f"{group}/1/name" in w for w in warnings), warnings


@pytest.mark.parametrize("count", ["many", "-1", "999", "1e3", "true", ""])
def test_a_count_that_is_no_count_yields_no_macros(tmp_path: Path, count: str) -> None:
    store = ini(tmp_path)
    store.setValue("machines/grbl-plotter/macros/count", count)
    store.setValue("machines/grbl-plotter/macros/0/name", "Park")
    store.sync()
    settings = StationSettings(ini(tmp_path))
    assert MacroStore(settings, "grbl-plotter").load() == []


def test_a_count_past_the_entries_reads_what_is_there(tmp_path: Path) -> None:
    store = ini(tmp_path)
    store.setValue("machines/grbl-plotter/macros/count", 5)
    store.setValue("machines/grbl-plotter/macros/0/name", "Park")
    store.setValue("machines/grbl-plotter/macros/0/code", "G0 X0")
    store.sync()
    assert MacroStore(StationSettings(ini(tmp_path)), "grbl-plotter").load() == [
        Macro("Park", "G0 X0")
    ]


def test_a_malformed_settings_file_gives_no_macros(tmp_path: Path) -> None:
    path = tmp_path / "stepdeck.ini"
    path.write_bytes(b"[machines]\ngrbl-plotter\\macros\\count=\xff\xfe\x00\n[[[\n")
    settings = StationSettings(QSettings(str(path), QSettings.Format.IniFormat))
    assert MacroStore(settings, "grbl-plotter").load() == []


@pytest.mark.parametrize(
    ("name", "code"),
    [
        ("", "G0 X0"),
        (" Park", "G0 X0"),
        ("x" * 41, "G0 X0"),
        ('say "hi"', "G0 X0"),
        ("new\nline", "G0 X0"),
        ("Park", "G0 X0\x00"),
        ("Park", "G0 X0\n" * 201),
        ("Park", "G0 X0 " * 2000),
        (3, "G0 X0"),
        ("Park", None),
    ],
)
def test_a_macro_that_is_not_one_is_refused_with_a_reason(name: object, code: object) -> None:
    with pytest.raises(MacroError, match=r"\w"):
        checked_macro(name, code)


def test_a_list_with_a_name_twice_or_too_long_is_refused() -> None:
    with pytest.raises(MacroError, match="two macros"):
        checked_list([PARK, Macro("park", "G0 X1")])
    with pytest.raises(MacroError, match="more than"):
        checked_list([Macro(f"M{i}", "G0 X0") for i in range(MAX_MACROS + 1)])


def test_toml_round_trip_keeps_every_character(tmp_path: Path) -> None:
    odd = Macro("Čára \\ ☃", 'G0 X1 ; "quoted" \\ back\tslash\n(comment)\nM5')
    path = export_macros(tmp_path / "macros.toml", [PARK, PEN, odd], "grbl-plotter")
    macros, profile = import_macros(path)
    assert macros == [PARK, PEN, odd]
    assert profile == "grbl-plotter"


def _entries(code_size: int, count: int) -> st.SearchStrategy[list[tuple[str, str]]]:
    """Names and snippets of any text (lines kept whole: no line or paragraph separators)."""
    return st.lists(
        st.tuples(
            st.text(st.characters(blacklist_categories=("Cc", "Cs", "Zl", "Zp")), max_size=40),
            st.text(st.characters(blacklist_categories=("Cs", "Zl", "Zp")), max_size=code_size),
        ),
        max_size=count,
    )


def _valid_macros(entries: list[tuple[str, str]]) -> list[Macro]:
    """The entries the store would take, in order (a name or snippet it refuses is left out)."""
    macros: list[Macro] = []
    for name, code in entries:
        try:
            macro = checked_macro(name, code)
            checked_list([*macros, macro])
        except MacroError:
            continue
        macros.append(macro)
    return macros


@settings(max_examples=60, deadline=None)
@given(_entries(200, 5))
def test_any_valid_macros_round_trip_through_toml(entries: list[tuple[str, str]]) -> None:
    macros = _valid_macros(entries)
    assert parse_macros(macros_toml(macros, "grbl-plotter"), "m.toml")[0] == macros


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("format = 1\n[[macro]\n", "not TOML"),
        ("format = 2\n", "not a StepDeck macro file"),
        ("[[macro]]\nname = 'x'\ncode = 'G0'\n", "not a StepDeck macro file"),
        ("format = 1\nmacro = 'G0 X1'\n", "list of at most"),
        ("format = 1\nmacro = [1, 2]\n", "is not a table"),
        ("format = 1\n[[macro]]\nname = 7\ncode = 'G0'\n", "macro 1: a macro needs a name"),
        ("format = 1\n[[macro]]\nname = 'a'\ncode = \"G0\\u0000\"\n", "macro 1: line 1"),
        ("format = 1\n[[macro]]\nname = 'a'\ncode = ['G0']\n", "not text"),
        ("format = 1\n[[macro]]\nname = 'a'\n[[macro]]\nname = 'A'\n", "two macros"),
        ("format = 1\n" + "[[macro]]\nname = 'a'\n" * 40, "list of at most"),
    ],
)
def test_hostile_toml_is_refused_with_the_file_and_the_reason(text: str, reason: str) -> None:
    with pytest.raises(MacroError, match=reason) as caught:
        parse_macros(text, "evil.toml")
    assert str(caught.value).startswith("evil.toml: ")


def test_an_unreadable_macro_file_is_refused_not_raised_through(tmp_path: Path) -> None:
    binary = tmp_path / "binary.toml"
    binary.write_bytes(b"format = 1\n\xff\xfe")
    big = tmp_path / "big.toml"
    big.write_text("# " + "x" * 600_000)
    for path, reason in (
        (binary, "not readable"),
        (big, "too large"),
        (tmp_path, "not a file"),
        (tmp_path / "absent.toml", "not a file"),
    ):
        with pytest.raises(MacroError, match=reason):
            import_macros(path)


def test_an_import_replaces_macros_of_the_same_name_and_adds_the_rest() -> None:
    park2, new = Macro("PARK", "G0 X5"), Macro("New", "G0 Y1")
    assert merged([PARK, PEN], [park2, new]) == [park2, PEN, new]


@settings(max_examples=30, deadline=None)
@given(_entries(120, 4))
def test_any_valid_macros_survive_the_settings_file(entries: list[tuple[str, str]]) -> None:
    macros = _valid_macros(entries)
    with tempfile.TemporaryDirectory() as folder:
        MacroStore(StationSettings(ini(Path(folder))), "grbl-plotter").save(macros)
        again = StationSettings(ini(Path(folder)))
        assert MacroStore(again, "grbl-plotter").load() == macros
        assert again.take_warnings() == []
