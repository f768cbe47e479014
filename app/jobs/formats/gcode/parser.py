"""The G-code parser: a file's lines through the modal state the machine will have.

The model is kept in machine coordinates and millimetres, as the limit check
and the preview need it: G20 inch coordinates are scaled, G92 offsets added,
G91 distances accumulated, arcs flattened for the preview.  The machine is
assumed to start at its origin (where homing leaves it) for G91 and G92.

Plain ``G0``/``G1`` moves take the fast path (:mod:`app.jobs.formats.gcode.plain_moves`);
every other line is read here, one at a time, into the modal state and the
operations it makes, checked against the machine's repertoire, and kept in
:class:`~app.jobs.formats.gcode.columns.OperationColumns`.

The pre-flight: a line GRBL 1.1 would answer with an error is refused at
load time on its line (``file:N: reason (error:n)``), because on the board
it would fail mid-job after the lines before it had moved the machine:
a negative F, N, P, T or S (``error:4``), two motion words on a line
(``error:21``), G1/G2/G3 before any feed rate where the machine needs one
(``error:22``), a word given twice (``error:25``), an arc without an axis
word (``error:26``) and the arc checks of :mod:`app.jobs.formats.gcode.arcs`.
Words outside the machine's repertoire (GRBL's ``error:20``) and lines too
long (``error:11``) are listed per line for the runner to refuse, or skipped
at the operator's choice.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from app.jobs.formats.gcode.arcs import MAX_ARC_VERTICES, flatten_arc
from app.jobs.formats.gcode.columns import OperationColumns
from app.jobs.formats.gcode.pen import DOWN, UP, PenRules
from app.jobs.formats.gcode.plain_moves import PlainMoves
from app.jobs.formats.gcode.program import (
    CCW_ARC,
    COMMENT,
    CW_ARC,
    GCODE,
    HOME,
    LINEAR,
    MOVE,
    PEN_DOWN,
    PEN_UP,
    RAPID,
    WAIT,
    GcodeData,
    GcodeProblem,
)
from app.jobs.formats.gcode.sent_texts import SentTextsBuilder
from app.jobs.formats.gcode.state import Pending, State
from app.jobs.formats.gcode.tool_change import tool_change, tool_prompt
from app.jobs.formats.gcode.words import (
    EXPONENT,
    MAX_LINE_CHARS,
    MESSAGE_RE,
    PARAMETERS,
    REALTIME,
    SYSTEM,
    TOKEN_CACHE_SIZE,
    WAIT_RE,
    Tokenizer,
    normal,
    render,
)
from app.jobs.names import quoted
from app.jobs.program import JobFileError
from app.profiles import GcodeSettings
from protocol.gcode.words import Word, grbl_text, split_comment, strip_checksum, take_line_number

INCH_MM = 25.4


#: Translated where it is used (a parameter line is refused in the operator's language).
PARAMETER_REASON = str(
    QT_TRANSLATE_NOOP("JobFile", "named parameters/expressions are not G-code this machine runs")
)

MOTION_WORDS = {"G0": RAPID, "G1": LINEAR, "G2": CW_ARC, "G3": CCW_ARC}
MOTION_NAMES = {code: word for word, code in MOTION_WORDS.items()}

AXIS_LETTERS = "XYZABCUVWE"
#: Words GRBL refuses negative (error:4).
_NOT_NEGATIVE = frozenset("FNPTS")
#: GRBL's largest tool number (error:38) and line number (error:27).
MAX_TOOL_NUMBER = 255
#: Refusals collected from one file before reading stops (the first ones are what matter).
MAX_REFUSALS = 1000
MAX_LINE_NUMBER = 10_000_000
_LINEAR_AXES = frozenset("XYZUVWE")  # scaled by G20; A B C are degrees


class Parser:
    """One file read for one machine: :meth:`parse`, then :meth:`data` and :meth:`notes`."""

    def __init__(
        self,
        file: str,
        axis_names: Sequence[str],
        settings: GcodeSettings,
        translate_pen: bool,
        skip_unsupported: bool,
        machine_title: str,
    ) -> None:
        self.file = file
        self.machine_axes = frozenset(a.upper() for a in axis_names)
        self.words = frozenset(w.upper() for w in settings.words)
        #: Lines go to the board compact (``GcodeSettings.compact_lines``): the line limit is
        #: the compact line's, what the board's line buffer really holds.
        self.compact = settings.compact_lines
        #: A GRBL board (it takes ``$J``): its error codes are GRBL 1.1's own.
        self.grbl = "$J" in self.words
        self.translate = translate_pen
        self.skip = skip_unsupported
        self.who = (
            QCoreApplication.translate("JobFile", "the {0}").format(machine_title)
            if machine_title
            else QCoreApplication.translate("JobFile", "this machine")
        )
        self.title = machine_title or QCoreApplication.translate("JobFile", "machine")
        self.z_is_pen = settings.z_is_pen
        self.feed_required = settings.feed_required
        #: A bare ``G92`` makes the current position the origin (the CoreXY plotter's
        #: firmware); GRBL refuses it (error:26).
        self.bare_g92 = settings.bare_g92
        self.dwell_p_seconds = settings.dwell_p_seconds
        # The firmware ignores F (the CoreXY plotter, FIDELITY S1-01): its power-on step
        # interval, and how many lines carry an F all the same (worth a note).
        self.step_interval_us = settings.step_interval_us
        self.f_lines = 0
        #: A G4 with P was read (its unit is worth a note where it is seconds).
        self.dwell_p_seen = False
        #: Inner arc vertices the file's arcs may still have (arcs.MAX_ARC_VERTICES in all).
        self.arc_budget = MAX_ARC_VERTICES
        self.pens = PenRules(settings)

        self.columns: list[str] = ["X", "Y"]
        self.state = State([math.nan, math.nan], [0.0, 0.0])
        self.tokens = Tokenizer(file)
        #: Lines whose operations depend on nothing but their text (pen commands, dwells):
        #: the pen state they set, their operations and the machine's objections.
        self.memo: dict[str, tuple[int | None, list[Pending], tuple[str, ...]]] = {}

        #: Lines refused at load (GRBL's errors, malformed text), in file order.
        self.refusals: list[JobFileError] = []
        # Output, in operation order.
        self.out = OperationColumns()
        self.problems: list[GcodeProblem] = []
        self.skipped: list[tuple[int, str, tuple[str, ...]]] = []
        self.g21_dropped = 0
        #: Columns whose positions count from wherever the machine stands when the job
        #: starts (a G91 move or a G92 before the file set them): taken here as from 0.
        self.start_relative: set[int] = set()
        self.realtime_dropped = 0
        self.z_dropped = 0
        self.checked_texts: dict[str, tuple[str, ...]] = {}

        # Plain moves (the fast path).
        self.plain = PlainMoves(file)

    # --- driving -------------------------------------------------------------------

    def fast_path_allowed(self) -> bool:
        """Plain moves need no checks only where G0, G1, X and Y are all the machine's."""
        return {"G0", "G1"} <= self.words and {"X", "Y"} <= self.machine_axes

    def parse(self, text: str) -> None:
        """Read ``text`` (the caller's reference handed over: it is let go once encoded).

        The file is kept as UTF-8 bytes, which the operations' texts are spans
        of (:mod:`app.jobs.formats.gcode.sent_texts`); only the lines the full
        parser reads become strings.
        """
        if not text.endswith("\n"):
            text += "\n"
        buffer = text.encode("utf-8", "surrogatepass")
        del text  # the caller's is gone too (the loader hands it over): 25 MB a million lines
        ends = np.flatnonzero(np.frombuffer(buffer, dtype=np.uint8) == ord("\n"))
        kind = np.int32 if len(buffer) < 2**31 - 1 else np.int64  # offsets in half the memory
        ends = ends.astype(kind)
        starts = np.concatenate(([0], ends[:-1] + 1)).astype(kind)
        plain = self.plain.find(buffer, starts, ends, self.fast_path_allowed())
        self.out.texts.set_buffer(buffer)
        slow = np.flatnonzero(~plain)
        lines = [
            buffer[a:b].decode("utf-8", "surrogatepass")
            for a, b in zip(starts[slow].tolist(), ends[slow].tolist(), strict=True)
        ]
        del starts, ends
        self.pens.prescan(lines, self.tokens)
        plain_before = (np.cumsum(plain) - plain)[slow].tolist()
        place, texts, line = self._place, self.out.texts, self._guarded
        done = 0
        for i, raw, before in zip(slow.tolist(), lines, plain_before, strict=True):
            if before > done:
                place(done, before, self.state, texts)
                done = before
            line(i + 1, raw)
        if done < len(self.plain):
            place(done, len(self.plain), self.state, texts)
        self._raise_refusals()

    def _guarded(self, number: int, raw: str) -> None:
        """One line; refused, it changes nothing (as on GRBL) and reading goes on."""
        saved = self.state.copy()
        try:
            self._line(number, raw)
        except JobFileError as exc:
            while len(saved.position) < len(self.columns):
                saved.position.append(math.nan)
                saved.offset.append(0.0)
            self.state = saved
            self._add_refusals([exc])

    def _cannot(self, word: str) -> str:
        """A word outside the machine's repertoire, with the error its firmware answers: GRBL's
        ``error:3`` for a ``$`` command it does not know, ``error:20`` for a G or M code
        (the emulated firmwares answer the same codes)."""
        reason = QCoreApplication.translate("JobFile", "{0} cannot execute {1}").format(
            self.who, word
        )
        return f"{reason} (error:{self._error_code(word)})"

    def _error_code(self, word: str) -> int:
        """GRBL reads an M number into a byte and refuses what is left over (``gcode.c``:
        "No Mxx.x commands"): ``M300`` or ``M1.5`` is error:23 there, not unknown (20)."""
        if word.startswith("$"):
            return 3
        if self.grbl and word[:1] == "M":
            try:
                value = float(word[1:])
            except ValueError:
                return 20
            if not (value.is_integer() and 0 <= value < 256):
                return 23
        return 20

    def _add_refusals(self, found: Sequence[JobFileError]) -> None:
        self.refusals += found
        if len(self.refusals) >= MAX_REFUSALS:
            self._raise_refusals()

    def _raise_refusals(self) -> None:
        """The first refusal, carrying the others: the whole file is refused."""
        if self.refusals:
            first, *more = self.refusals[:MAX_REFUSALS]
            first.more = tuple(more)
            raise first

    def _place(self, k0: int, k1: int, st: State, texts: SentTextsBuilder) -> None:
        """A run of plain moves, refused where GRBL would refuse one (feed rules)."""
        self._add_refusals(self.plain.check_feeds(k0, k1, st.feed, self.feed_required))
        self.f_lines += int(np.count_nonzero(~np.isnan(self.plain.f[k0:k1])))
        self.plain.place(k0, k1, st, texts, self.start_relative)

    def _refuse(self, number: int, reason: str, code: str = "") -> None:
        """A line GRBL would answer with an error: the whole job is refused at load.

        A line too long for the board is refused as that (it is listed with the
        unsupported lines): GRBL never parses it, so it has no other error.
        """
        if self._sent_length(code) > MAX_LINE_CHARS:
            return
        raise JobFileError(self.file, number, reason)

    def _sent_length(self, text: str) -> int:
        """The characters of ``text`` as the board is sent it (compact on GRBL)."""
        if self.compact and len(text) > MAX_LINE_CHARS:
            return len(grbl_text(text) or text)
        return len(text)

    def _grbl_rules(self, number: int, code: str, words: Sequence[Word]) -> None:
        """GRBL's word-level errors on one line: negative values, repeats, motion conflicts."""
        seen: set[str] = set()
        motions = 0
        for word in words:
            if word.letter in "GM":
                motions += word.letter == "G" and normal("G", word.value) in MOTION_WORDS
                continue
            if word.letter in seen:
                self._refuse(
                    number,
                    QCoreApplication.translate(
                        "JobFile", "word repeated: {0} twice (error:25): {1}"
                    ).format(word.letter, quoted(code)),
                    code,
                )
            seen.add(word.letter)
            if word.letter == "T" and word.value > MAX_TOOL_NUMBER:
                self._refuse(
                    number,
                    QCoreApplication.translate(
                        "JobFile", "max value exceeded: T{0} above T{1} (error:38)"
                    ).format(word.text, MAX_TOOL_NUMBER),
                    code,
                )
            if word.letter in _NOT_NEGATIVE and word.value < 0:
                self._refuse(
                    number,
                    QCoreApplication.translate(
                        "JobFile", "negative value: {0} cannot be negative (error:4)"
                    ).format(word.letter + word.text),
                    code,
                )
        if motions > 1:
            self._refuse(
                number,
                QCoreApplication.translate(
                    "JobFile", "modal group violation: two motion words (error:21): {0}"
                ).format(quoted(code)),
                code,
            )

    # --- one line ------------------------------------------------------------------

    def _column(self, letter: str) -> int:
        if letter not in self.columns:
            self.columns.append(letter)
            self.state.position.append(math.nan)
            self.state.offset.append(0.0)
        return self.columns.index(letter)

    def _line(self, number: int, raw: str) -> None:
        code, comment = split_comment(raw)
        code = code.strip()
        if not code:
            if comment:
                self._commit(number, "", [Pending(COMMENT, "", message=comment)], ())
            return
        if code.startswith("%"):
            return
        digits, rest = take_line_number(code)
        if digits is not None:
            significant = digits.lstrip("0") or "0"
            if len(significant) > 8 or int(significant) > MAX_LINE_NUMBER:
                shown = (
                    digits
                    if len(digits) <= 20
                    else QCoreApplication.translate("JobFile", "{0}… ({1} digits)").format(
                        digits[:12], len(digits)
                    )
                )
                self._refuse(
                    number,
                    QCoreApplication.translate(
                        "JobFile", "invalid line number: N{0} above N{1} (error:27)"
                    ).format(shown, MAX_LINE_NUMBER),
                )
            code = rest
        code = strip_checksum(code).strip()
        if not code:
            return
        replay = self.memo.get(code)
        if replay is not None:
            pen, pending, reasons = replay
            if pen is not None:
                self.state.pen = pen
            self._commit(number, code, pending, reasons)
        elif code[0] == "$":
            self._system(number, code)
        elif code in REALTIME:
            self._realtime(number, code)
        elif PARAMETERS.search(code):
            self._commit(
                number,
                code,
                [Pending(GCODE, code)],
                (QCoreApplication.translate("JobFile", PARAMETER_REASON),),
            )
        elif wait := WAIT_RE.match(code):
            message = (
                comment
                or code[wait.end() :].strip()
                or QCoreApplication.translate("JobFile", "M{0}: paused").format(wait.group(1))
            )
            self._commit(number, code, [Pending(WAIT, "", message=message)], ())
        elif (tool := tool_change(code)) is not None:
            self._commit(number, code, [Pending(WAIT, "", message=tool_prompt(tool, comment))], ())
        elif display := MESSAGE_RE.match(code):
            word = f"M{display.group(1)}"
            reasons = () if word in self.words else (self._cannot(word),)
            self._commit(number, code, [Pending(GCODE, code, checked=True)], reasons)
        else:
            self._words(number, code, self.tokens.words(code, number))

    def _system(self, number: int, code: str) -> None:
        """A GRBL ``$`` command: sent as written where the machine knows it."""
        match = SYSTEM.match(code)
        word = "$" + (match.group(1) or "").upper() if match else "$"
        reasons = () if word in self.words else (self._cannot(word),)
        self._commit(number, code, [Pending(GCODE, code, checked=True)], reasons)

    def _realtime(self, number: int, code: str) -> None:
        """A real-time byte on a line: the station sends ``?`` itself; the others never belong."""
        what = QCoreApplication.translate("JobFile", REALTIME[code])
        if code == "?":
            self.realtime_dropped += 1
            message = QCoreApplication.translate(
                "JobFile", "? not sent: the station asks for the status itself"
            )
            self._commit(number, code, [Pending(COMMENT, "", message=message)], ())
            return
        reason = QCoreApplication.translate(
            "JobFile", "{0} ({1}) is a real-time command, not a line of a job"
        ).format(what, quoted(code))
        self._commit(number, code, [Pending(GCODE, code, checked=True)], (reason,))

    def _words(self, number: int, code: str, words: tuple[Word, ...]) -> None:
        """A line of words: modal changes, pen commands, then what remains as one operation."""
        st = self.state
        saved = st.copy()
        self._grbl_rules(number, code, words)
        commands: dict[str, int] = {}
        params: dict[str, int] = {}
        for index, word in enumerate(words):
            if word.letter in "GM":
                commands.setdefault(normal(word.letter, word.value), index)
            else:
                params[word.letter] = index
        pending: list[Pending] = []
        previous_motion = st.motion

        def value(letter: str) -> float:
            return words[params[letter]].value

        removed, notes, extra = _modal_words(st, commands, g21_sent="G21" in self.words)
        non_modal = {"G92", "G28", "G10", "G4"} & commands.keys()

        # The pen: a pen command word, or a Z height on a machine whose pen Z is.
        pen, pen_words = self.pens.pen_command(commands, params, words)
        z_index = params.get("Z")
        z_only = False
        if z_index is not None and self.z_is_pen:
            if "G92" in commands:
                st.z_work = value("Z") * st.scale
                if self.translate:
                    removed.add(z_index)
            elif not non_modal:
                if self.pens.z_pen:
                    z = value("Z") * st.scale
                    base = 0.0 if math.isnan(st.z_work) else st.z_work
                    st.z_work = base + z if st.relative else z
                    if pen is None:
                        pen = UP if st.z_work > 0 else DOWN
                        pen_words = {z_index}
                        z_only = not (set(params) & set(AXIS_LETTERS)) - {"Z"}
                if self.translate:
                    removed.add(z_index)
                    if not self.pens.z_pen:
                        notes.append("z")
        split = False
        if pen is not None:
            changed = pen != st.pen or z_only or pen_words != {z_index}
            if self.translate:
                removed |= pen_words
                if changed:
                    pending.append(self._pen_pending(code, words, pen_words, pen))
                    split = True
            st.pen = pen
        whole = pen is not None and not self.translate  # the pen line goes out as written

        rest = (
            list(range(len(words))) if whole else [i for i in range(len(words)) if i not in removed]
        )
        if rest:
            op = self._operation(number, code, words, rest, removed, commands, params, pen, whole)
            if not (split and op.kind == GCODE and self._redundant(op.sent, previous_motion)):
                pending.append(op)
        if not pending and ("M2" in commands or "M30" in commands):
            pending.append(Pending(COMMENT, "", message="program end"))
        elif not pending and "g21" in notes:
            message = "G21 not sent: the machine works in mm"
            pending.append(Pending(COMMENT, "", message=message))
        reasons = self._check(pending) + tuple(extra)
        # F is read in the units in force, axes move from where the machine is: not pure.
        pure = not any(letter in AXIS_LETTERS or letter == "F" for letter in params) and all(
            name == "G4" or (name[0] == "M" and name not in ("M0", "M1", "M2", "M30"))
            for name in commands
        )
        if pure and not (reasons and self.skip) and len(self.memo) < TOKEN_CACHE_SIZE:
            self.memo[code] = (pen, pending, reasons)
        if reasons and self.skip:
            while len(saved.position) < len(self.columns):
                saved.position.append(math.nan)
                saved.offset.append(0.0)
            self.state = saved
        else:
            self.g21_dropped += notes.count("g21")
            self.z_dropped += notes.count("z")
        self._commit(number, code, pending, reasons)

    def _operation(
        self,
        number: int,
        code: str,
        words: tuple[Word, ...],
        rest: list[int],
        removed: set[int],
        commands: Mapping[str, int],
        params: Mapping[str, int],
        pen: int | None,
        whole: bool,
    ) -> Pending:
        """The operation the words a line sends make: an offset, home, a dwell or a move.

        ``rest``: the indices of those words (the pen's and the dropped ones are
        ``removed``); ``whole``: the line is a pen line sent as written.
        """
        st = self.state
        non_modal = {"G92", "G28", "G10", "G4"} & commands.keys()

        def value(letter: str) -> float:
            return words[params[letter]].value

        text = code if whole or not removed else render(code, removed)
        sent = [words[i] for i in rest]
        op = Pending(GCODE, text, sent)
        if "F" in params:
            st.feed = value("F") * st.scale
            self.f_lines += 1
        if "F" in params and params["F"] in rest:
            op.feed = value("F") * st.scale
        axes = [i for i in rest if self._is_axis(words[i].letter)]
        if "G92" in commands or "G92.1" in commands:
            self._set_offsets(number, code, commands, words, axes)
        elif "G28" in commands:
            op.kind, op.motion = MOVE, HOME
            op.target = dict.fromkeys(range(len(self.columns)), 0.0)
            for c in op.target:
                st.position[c] = 0.0
        elif "G4" in commands:
            # P in the machine's unit (GRBL: seconds; the profile's dwell_p), S in seconds.
            self.dwell_p_seen = self.dwell_p_seen or "P" in params
            op.dwell = (
                value("P") * self.dwell_p_seconds
                if "P" in params
                else value("S")
                if "S" in params
                else 0.0
            )
        elif axes and not non_modal:
            self._motion(number, code, words, params, commands, op, axes)
        elif {"G2", "G3"} & commands.keys() and not non_modal:
            self._refuse(
                number,
                QCoreApplication.translate(
                    "JobFile", "arc without axis words (error:26): {0}"
                ).format(quoted(code)),
                code,
            )
        if whole:
            op.pen = pen if pen is not None else -1
            if op.kind != MOVE:
                op.kind = PEN_DOWN if pen == DOWN else PEN_UP
        return op

    def _is_axis(self, letter: str) -> bool:
        """An axis of the model (on a machine whose pen Z is, Z is no axis)."""
        return letter in AXIS_LETTERS and not (self.z_is_pen and letter == "Z")

    def _redundant(self, sent: Sequence[Word], previous_motion: int) -> bool:
        """What is left of a pen line is only the motion word already in force."""
        if len(sent) != 1 or sent[0].letter != "G":
            return False
        return MOTION_WORDS.get(normal("G", sent[0].value)) == previous_motion

    def _pen_pending(
        self, code: str, words: Sequence[Word], pen_words: set[int], pen: int
    ) -> Pending:
        """The pen part of a line: as written if it is the profile's own command, else that."""
        own = self.pens.pen_down if pen == DOWN else self.pens.pen_up
        kind = PEN_DOWN if pen == DOWN else PEN_UP
        written = [words[i] for i in sorted(pen_words)]
        commands = [normal(w.letter, w.value) for w in written if w.letter in "GM"]
        s_values = [w.value for w in written if w.letter == "S"]
        if (
            commands == [own.word]
            and len(written) == len(commands) + len(s_values)
            and (s_values == ([own.s] if own.s is not None else []))
        ):
            text = render(code, set(range(len(words))) - pen_words)
            return Pending(kind, text, written)
        return Pending(kind, own.text, translated=True, checked=False)

    def _set_offsets(
        self,
        number: int,
        code: str,
        commands: Mapping[str, int],
        words: Sequence[Word],
        axes: Sequence[int],
    ) -> None:
        """G92: the current machine position is called the given values from now on.

        As GRBL keeps it (offset = machine position - given value, per named axis),
        so the preview and the travel check show where the machine really goes; a
        bare ``G92`` on a firmware that takes it (the CoreXY plotter's) calls the
        current position 0 on every axis.
        """
        st = self.state
        if "G92.1" in commands:
            st.offset = [0.0] * len(st.offset)
            return
        if "G92" in commands and not any(self._is_axis(w.letter) for w in words):
            if not self.bare_g92:
                self._refuse(
                    number,
                    QCoreApplication.translate(
                        "JobFile", "G92 without axis words (error:26): {0}"
                    ).format(quoted(code)),
                    code,
                )
                return
            for c, here in enumerate(st.position):
                if math.isnan(here):
                    self.start_relative.add(c)
                st.offset[c] = 0.0 if math.isnan(here) else here
            return
        for index in axes:
            word = words[index]
            if self.z_is_pen and word.letter == "Z":
                continue
            c = self._column(word.letter)
            scale = st.scale if word.letter in _LINEAR_AXES else 1.0
            here = st.position[c]
            if math.isnan(here):
                self.start_relative.add(c)
            st.offset[c] = (0.0 if math.isnan(here) else here) - word.value * scale

    def _motion(
        self,
        number: int,
        code: str,
        words: Sequence[Word],
        params: Mapping[str, int],
        commands: Mapping[str, int],
        op: Pending,
        axes: Sequence[int],
    ) -> None:
        """A move: its machine target, and the arc's inner vertices when it is one."""
        st = self.state
        op.kind = MOVE
        op.motion = st.motion
        if op.motion != RAPID and self.feed_required and not st.feed > 0:
            name = MOTION_NAMES.get(op.motion, "G1")
            self._refuse(
                number,
                QCoreApplication.translate(
                    "JobFile", "feed rate undefined: {0} before any F sets one (error:22): {1}"
                ).format(name, quoted(code)),
                code,
            )
        machine = "G53" in commands
        start = list(st.position)
        for index in axes:
            word = words[index]
            c = self._column(word.letter)
            scale = st.scale if word.letter in _LINEAR_AXES else 1.0
            if machine:
                target = word.value * scale
            elif st.relative:
                here = st.position[c]
                if math.isnan(here):
                    self.start_relative.add(c)
                target = (0.0 if math.isnan(here) else here) + word.value * scale
            else:
                target = word.value * scale + st.offset[c]
            op.target[c] = target
        while len(start) < len(self.columns):
            start.append(math.nan)
        if op.motion in (CW_ARC, CCW_ARC) and st.plane == 17:
            op.target.setdefault(0, 0.0 if math.isnan(start[0]) else start[0])
            op.target.setdefault(1, 0.0 if math.isnan(start[1]) else start[1])
            offsets = {k: words[params[k]].value * st.scale for k in "IJR" if k in params}
            clockwise = op.motion == CW_ARC
            op.arc = flatten_arc(
                self.file,
                number,
                code,
                start,
                op.target,
                offsets,
                clockwise,
                len(self.columns),
                self.arc_budget,
                # A machine without arcs refuses (or skips) the line anyway: no board rule.
                grbl_rules=MOTION_NAMES[op.motion] in self.words,
            )
            self.arc_budget -= len(op.arc)
        for c, target in op.target.items():
            st.position[c] = target

    # --- checks and output -----------------------------------------------------------

    def _check(self, pending: Sequence[Pending]) -> tuple[str, ...]:
        """Why the machine could not execute what this line sends (empty: it can)."""
        reasons: list[str] = []
        for op in pending:
            if op.kind in (COMMENT, WAIT) or not op.text:
                continue
            if op.translated or op.checked:
                found = self._check_text(op.text) if op.translated else ()
            else:
                found = self._check_words(op)
            if not op.text.isascii():
                found += (
                    QCoreApplication.translate("JobFile", "{0} is not ASCII").format(
                        quoted(op.text)
                    ),
                )
            length = self._sent_length(op.text)
            if length > MAX_LINE_CHARS:
                found += (
                    QCoreApplication.translate(
                        "JobFile", "{0} characters; a line holds at most {1}"
                    ).format(length, MAX_LINE_CHARS),
                )
            reasons += [r for r in found if r not in reasons]
        return tuple(reasons)

    def _check_words(self, op: Pending) -> tuple[str, ...]:
        found: list[str] = []
        explicit_motion = False
        for word in op.sent:
            if word.letter in "GM":
                name = normal(word.letter, word.value)
                explicit_motion |= name in MOTION_WORDS
                if name not in self.words:
                    found.append(self._cannot(name))
            elif word.letter in AXIS_LETTERS and word.letter not in self.machine_axes:
                exponent = EXPONENT.search(op.text) if word.letter == "E" else None
                if exponent is not None:
                    # "X1e308": G-code numbers have no exponent, so it reads as X1 and E308
                    found.append(
                        QCoreApplication.translate(
                            "JobFile",
                            "{0} is not a G-code number (G-code has no exponent): "
                            "it reads as {1} and {2}, and {3} has no {4} axis",
                        ).format(
                            exponent[0],
                            exponent[1],
                            "E" + exponent[2][1:],
                            self.who,
                            word.letter,
                        )
                    )
                    continue
                found.append(
                    QCoreApplication.translate("JobFile", "{0} has no {1} axis").format(
                        self.who, word.letter
                    )
                )
        if op.kind == MOVE and op.motion in MOTION_NAMES and not explicit_motion:
            name = MOTION_NAMES[op.motion]
            if name not in self.words:
                found.append(self._cannot(name))
        return tuple(found)

    def _check_text(self, text: str) -> tuple[str, ...]:
        """The profile's own pen command, checked once like any line."""
        if text not in self.checked_texts:
            words = self.tokens.words_or_none(text) or ()
            self.checked_texts[text] = self._check_words(Pending(GCODE, text, words))
        return self.checked_texts[text]

    def _commit(
        self, number: int, code: str, pending: Sequence[Pending], reasons: Sequence[str]
    ) -> None:
        if reasons and self.skip:
            reason_text = "; ".join(reasons)
            message = QCoreApplication.translate("JobFile", "not sent: {0} ({1})").format(
                code, reason_text
            )
            pending = [Pending(COMMENT, "", message=message)]
            self.skipped.append((number, code, tuple(reasons)))
        else:
            self.problems += [GcodeProblem(number, code, reason) for reason in reasons]
        self.out.add(number, pending)

    # --- the result ------------------------------------------------------------------

    def data(self) -> GcodeData:
        return self.out.data(self.file, self.columns, self.plain)

    def notes(self, data: GcodeData) -> tuple[str, ...]:
        """What the operator should know about how the file was taken."""
        notes: list[str] = []
        pens = self.pens
        translated = self.out.translated
        if translated:
            # One text per English form; the translations word it around the count.
            text = (
                QCoreApplication.translate("JobFile", "{0} pen line sent as the {1}'s {2}/{3}")
                if translated == 1
                else QCoreApplication.translate(
                    "JobFile", "{0} pen lines sent as the {1}'s {2}/{3}"
                )
            )
            notes.append(text.format(translated, self.title, pens.pen_up.text, pens.pen_down.text))
        for word, (down, up) in sorted(pens.servo.items()):
            notes.append(
                QCoreApplication.translate(
                    "JobFile", "pen servo {0}: S{1:g} lowers the pen, S{2:g} lifts it"
                ).format(word, down, up)
            )
        if pens.z_pen:
            notes.append(
                QCoreApplication.translate(
                    "JobFile", "Z heights are the pen: above 0 up, 0 or below down"
                )
            )
        if self.z_dropped:
            notes.append(
                QCoreApplication.translate(
                    "JobFile",
                    "Z not sent on {0} line(s): Z is the {1}'s pen and this file's Z never lifts "
                    "it",
                ).format(self.z_dropped, self.title)
            )
        if self.g21_dropped:
            text = (
                QCoreApplication.translate(
                    "JobFile", "{0} G21 line not sent: the machine works in mm"
                )
                if self.g21_dropped == 1
                else QCoreApplication.translate(
                    "JobFile", "{0} G21 lines not sent: the machine works in mm"
                )
            )
            notes.append(text.format(self.g21_dropped))
        if self.realtime_dropped:
            notes.append(
                QCoreApplication.translate(
                    "JobFile", "? not sent: the station asks for the status itself"
                )
            )
        if self.dwell_p_seen and self.dwell_p_seconds == 1.0:
            total = float(data.dwell_s.sum())
            notes.append(
                QCoreApplication.translate(
                    "JobFile",
                    "G4 P is seconds on the {0} (GRBL): {1} dwell(s) wait {2} in all; a file "
                    "written for milliseconds (Marlin, Inkscape Unicorn) waits a thousand times "
                    "too long here",
                ).format(self.title, len(data.dwell_s), _duration(total))
            )
        if self.f_lines and self.step_interval_us is not None:
            notes.append(
                QCoreApplication.translate(
                    "JobFile",
                    "this plotter ignores F ({0} line(s) carry it): G0 and G1 run alike, the "
                    "speed is set by M98 <µs> (the step interval, {1:g} µs at power-on)",
                ).format(self.f_lines, self.step_interval_us)
            )
        if not data.pen_info and (data.kinds == MOVE).any():
            notes.append(
                QCoreApplication.translate(
                    "JobFile", "no pen commands: G0 moves are shown as travel, G1/G2/G3 as work"
                )
            )
        by_reason: dict[str, list[int]] = {}
        for number, _code, reasons in self.skipped:
            for reason in reasons:
                by_reason.setdefault(reason, []).append(number)
        for reason, numbers in by_reason.items():
            shown = ", ".join(str(n) for n in numbers[:10])
            more = (
                QCoreApplication.translate("JobFile", " and {0} more").format(len(numbers) - 10)
                if len(numbers) > 10
                else ""
            )
            if len(numbers) == 1:
                note = QCoreApplication.translate("JobFile", "skipped 1 line: {0} (line {1})")
                notes.append(note.format(reason, shown))
                continue
            notes.append(
                QCoreApplication.translate(
                    "JobFile", "skipped {0} line(s): {1} (lines {2}{3})"
                ).format(len(numbers), reason, shown, more)
            )
        return tuple(notes)


def _modal_words(
    st: State, commands: Mapping[str, int], *, g21_sent: bool
) -> tuple[set[int], list[str], list[str]]:
    """A line's modal words into ``st``: units, distance mode, plane, motion mode.

    Returns the words not sent (``G21`` where the machine does not take it,
    ``M2``/``M30``), the notes to count once the line is kept, and the reasons
    the line cannot run as written.
    """
    removed: set[int] = set()
    notes: list[str] = []
    extra: list[str] = []
    if "G20" in commands:
        st.scale = INCH_MM
    if "G21" in commands:
        st.scale = 1.0
        if not g21_sent:
            removed.add(commands["G21"])
            notes.append("g21")
    if "G90" in commands:
        st.relative = False
    if "G91" in commands:
        st.relative = True
    for plane in (17, 18, 19):
        if f"G{plane}" in commands:
            st.plane = plane
    for name, motion in MOTION_WORDS.items():
        if name in commands:
            st.motion = motion
    for end in ("M2", "M30"):
        if end in commands:
            removed.add(commands[end])
    if "M0" in commands or "M1" in commands:
        extra.append("M0/M1 must stand on a line of its own (the station asks the operator)")
    return removed, notes, extra


def _duration(seconds: float) -> str:
    """Seconds as the operator reads them: "2.5 s", "4 min 10 s", "15 h 23 min"."""
    if seconds < 60:
        return f"{seconds:g} s"
    minutes, rest = divmod(round(seconds), 60)
    if minutes < 60:
        return f"{minutes} min {rest} s"
    hours, minutes = divmod(minutes, 60)
    return f"{hours} h {minutes} min"
