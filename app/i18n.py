"""Which language the station speaks, and loading its translation.

The ``.ts`` sources live in ``resources/i18n`` (edited with Qt Linguist and
kept current with ``pyside6-lupdate``).  The compiled ``.qm`` files are never
kept in the repository: building the wheel compiles them into the package
(setup.py), so an installed station reads them as shipped.  A source checkout
has only the ``.ts``: its first start in a language compiles it with the
``lrelease`` PySide6 ships, into the station's cache, and later starts reuse
that until the ``.ts`` changes.  English is the source language; its own
``.ts`` carries only the plural forms ("1 setting", "2 settings").
"""

from __future__ import annotations

import logging
import subprocess
from pathlib import Path

import PySide6
from PySide6.QtCore import (
    QT_TRANSLATE_NOOP,
    QCoreApplication,
    QEvent,
    QLibraryInfo,
    QLocale,
    QStandardPaths,
    QTranslator,
)

from app import profiles
from app.jobs import texts
from app.resources import I18N_DIR

#: The languages offered, by code, each named in itself (a user who cannot read the
#: current language still finds their own).
LANGUAGES = {"en": "English", "cs": "Čeština", "sk": "Slovenčina"}
#: Compiling one file takes a few tens of milliseconds; more means something is wrong.
LRELEASE_TIMEOUT_S = 10.0

_log = logging.getLogger(__name__)
_installed: list[QTranslator] = []


def chosen_language(choice: str, system: QLocale | None = None) -> str:
    """The language for ``choice``: one of LANGUAGES, or "system" (the locale's, else English)."""
    if choice in LANGUAGES:
        return choice
    name = (system or QLocale.system()).name().split("_")[0]
    return name if name in LANGUAGES else "en"


def _cache_dir() -> Path:
    location = QStandardPaths.StandardLocation.CacheLocation
    return Path(QStandardPaths.writableLocation(location)) / "i18n"


def shipped(language: str, folder: Path = I18N_DIR) -> Path | None:
    """The ``.qm`` the wheel's build compiled, unless a newer ``.ts`` lies beside it.

    An installed station has no ``.ts`` and takes the ``.qm`` as it is; a checkout
    where one was compiled in place must not keep reading it after the ``.ts`` moved on.
    """
    qm = folder / f"stepdeck_{language}.qm"
    if not qm.is_file():
        return None
    source = qm.with_suffix(".ts")
    if source.is_file() and source.stat().st_mtime > qm.stat().st_mtime:
        return None
    return qm


def compiled(language: str, cache_dir: Path | None = None) -> Path | None:
    """The ``.qm`` of ``language``: the shipped one, else its ``.ts`` compiled into the cache.

    The cached one is compiled now if it is missing or older than its ``.ts``.
    """
    ready = shipped(language)
    if ready is not None:
        return ready
    source = I18N_DIR / f"stepdeck_{language}.ts"
    if not source.is_file():
        return None
    target = (cache_dir or _cache_dir()) / f"stepdeck_{language}.qm"
    if target.is_file() and target.stat().st_mtime >= source.stat().st_mtime:
        return target
    lrelease = Path(PySide6.__file__).resolve().parent / "lrelease"
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        subprocess.run(
            [str(lrelease), "-silent", str(source), "-qm", str(target)],
            check=True,
            capture_output=True,
            timeout=LRELEASE_TIMEOUT_S,
        )
    except (OSError, subprocess.SubprocessError) as exc:
        # The station still works, in English: a missing tool must not stop it.
        _log.warning("Translation %s not compiled: %s", source, exc)
        return None
    return target if target.is_file() else None


def remove() -> None:
    """Back to the source language (English, with its plain plural fallbacks)."""
    app = QCoreApplication.instance()
    while _installed and app is not None:
        app.removeTranslator(_installed.pop())
    QLocale.setDefault(QLocale(QLocale.Language.English, QLocale.Country.UnitedStates))
    texts.use(QCoreApplication.translate)  # and numbers with a decimal point again


def install(choice: str, cache_dir: Path | None = None) -> str:
    """Make the application speak ``choice`` from now on; returns the language used.

    Widgets built afterwards are in that language; those already built hear of it
    through Qt's ``LanguageChange`` event (see widgets/retranslate.py).  Numbers
    follow the language too: the default locale is set to it, so Czech and Slovak
    show a decimal comma.
    """
    app = QCoreApplication.instance()
    assert app is not None
    remove()
    texts.use(QCoreApplication.translate)  # job texts made without Qt follow it too
    profiles.use(QCoreApplication.translate)  # and the machines' titles
    language = chosen_language(choice)
    path = compiled(language, cache_dir)
    if path is None:
        _tell_widgets(app)
        return "en"
    translator = QTranslator(app)
    if not translator.load(str(path)):
        _tell_widgets(app)
        return "en"
    QLocale.setDefault(QLocale(language))
    texts.use(QCoreApplication.translate, QLocale().decimalPoint())
    _install_qt_own(app, language)
    app.installTranslator(translator)
    _installed.append(translator)
    translator.setObjectName(language)
    return language


#: Qt's standard buttons, which Slovak's ``qtbase`` leaves in English (it has them only under
#: an older context): the station's own translation says them in both languages.
STANDARD_BUTTONS = (
    QT_TRANSLATE_NOOP("QPlatformTheme", "OK"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Cancel"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Close"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Save"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Open"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Apply"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Discard"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Reset"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Help"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "&Yes"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "&No"),
)


def _install_qt_own(app: QCoreApplication, language: str) -> None:
    """Qt's own texts (OK, Cancel, Close, the file dialog) from the ``qtbase`` PySide6 ships.

    Without them a Czech window's dialogs still say "Cancel".  Missing files are no
    error: those few buttons stay English.
    """
    folder = QLibraryInfo.path(QLibraryInfo.LibraryPath.TranslationsPath)
    qt_own = QTranslator(app)
    if qt_own.load(f"qtbase_{language}", folder):
        app.installTranslator(qt_own)
        _installed.insert(0, qt_own)


def current() -> str | None:
    """The language whose translation is installed (None: none, the bare source texts)."""
    return _installed[-1].objectName() if _installed else None


def _tell_widgets(app: QCoreApplication) -> None:
    """Back in English: removing a translator told the widgets only if one was installed."""
    app.postEvent(app, QEvent(QEvent.Type.LanguageChange))
