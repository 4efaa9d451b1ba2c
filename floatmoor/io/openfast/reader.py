"""OpenFAST input files read as OpenFAST reads them.

An OpenFAST input file is a sequence of lines ``value  Name  - description``: the first word is
the value, the second the variable's name (for a quoted string value, the text between the
quotes).  OpenFAST reads the lines in a fixed order: ElastoDyn and the tower and blade files
with ``ReadVar``, which takes the first word and ignores the name; HydroDyn, SeaState and the
driver (from v3.1) with ``ParseVar``, which stops when the name is not the expected one.  The
order and the names changed between versions (keys added, e.g. ``PtfmXYIner`` in ElastoDyn
v4 or ``PitchDOF`` in v5; renamed, e.g. ``BldFile(1)`` written ``BldFile1``; moved, e.g. the
waves from HydroDyn to SeaState in v4, the gravity from ElastoDyn to the driver in v3.1).

:class:`InputFile` reads a file against a *schema*: the keys of every version from 2.0 in their
order (:mod:`floatmoor.io.openfast.schemas`), each with its known aliases.  A key is found by
its name or an alias (case-insensitive, as ``ParseVar`` compares); a key whose line carries an
unknown name is read by position, between its neighbours of the schema found by name, as
``ReadVar`` would (the read records it in :attr:`InputFile.notes`).  A key that is neither is
missing: a required key is a :class:`~floatmoor.core.errors.SceneError` naming the file, the
key, the line where it was expected and what that line holds.

Tables (``NJoints`` followed by two header lines and the rows, as OpenFAST reads them) and
matrices (six rows, the first carrying the name after its numbers) are read from their named
line.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...core.errors import SceneError

__all__ = ["InputFile", "Key", "Line", "is_separator", "split_words"]

_SEPARATOR = re.compile(r"^\s*(-{3,}|={3,})")


def is_separator(text: str) -> bool:
    """A section line (``---- WAVES ----``) or a comment line (``!``, ``#``)."""
    s = text.strip()
    return bool(_SEPARATOR.match(text)) or s.startswith("!") or s.startswith("#")


def split_words(text: str) -> list[str]:
    """The words of a line: a quoted first word is one word (its quotes removed); words are
    separated by blanks, tabs or commas (OpenFAST's ``GetWords`` also splits at commas)."""
    s = text.strip()
    words = []
    if s[:1] in ("'", '"'):
        q = s[0]
        end = s.find(q, 1)
        if end > 0:
            words.append(s[1:end])
            s = s[end + 1:]
    words += [w for w in re.split(r"[\s,;]+", s) if w]
    return words


@dataclass(frozen=True, kw_only=True)
class Key:
    """A key of a schema: its name as the newest OpenFAST writes it, the other names it had
    (``aliases``), whether files of some versions lack it (``optional``)."""

    name: str
    aliases: tuple = ()
    optional: bool = False

    def names(self) -> tuple:
        """Every accepted spelling, upper case: the name, its aliases and, for an indexed name
        ``X(k)``, ``Xk``."""
        out = [self.name, *self.aliases]
        m = re.fullmatch(r"(\w+)\((\d+)\)", self.name)
        if m:
            out.append(m.group(1) + m.group(2))
        return tuple(n.upper() for n in out)


@dataclass(frozen=True, kw_only=True)
class Line:
    """A key as read: the value text, the line number (1-based), the name written on that
    line, and how it was found (``name`` or ``position``)."""

    key: str
    value: str
    line: int
    written: str
    how: str


def _number(text: str) -> float | None:
    t = text.strip().replace("D", "E").replace("d", "e")
    try:
        v = float(t)
    except ValueError:
        return None
    return v


def _written_name(words):
    """The name written on a line: the word after the value (after all the leading numbers
    for a matrix row such as ``0 0 0 0 0 0 AddCLin``), or the first word when a number follows
    it (``Name value``, which ParseVar accepts too)."""
    if len(words) < 2:
        return None
    if _number(words[0]) is not None:
        for w in words[1:]:
            if _number(w) is None:
                return w if w[:1].isalpha() else None
        return None
    if words[1][:1].isalpha():
        return words[1]
    if words[0][:1].isalpha() and _number(words[1]) is not None:
        return words[0]
    return None


class InputFile:
    """One OpenFAST input file read against a schema (a list of :class:`Key`).

    ``what`` names the file's kind in messages (``ElastoDyn``, ``HydroDyn``, ...).
    ``header_lines``: the lines OpenFAST reads as comments at the top (two: the version line
    and the title).
    """

    def __init__(self, path, schema, what: str, *, header_lines: int = 2):
        self.path = Path(path)
        self.what = what
        if not self.path.is_file():
            raise SceneError(self.path, "", f"an existing {what} input file", "no such file")
        raw = self.path.read_bytes().decode("utf-8", errors="replace")
        self.lines = raw.replace("\r\n", "\n").replace("\r", "\n").split("\n")
        self.header_lines = header_lines
        self.schema = list(schema)
        self.notes: list[str] = []
        self.unknown: list[tuple[int, str]] = []
        self._read()

    # -- reading --------------------------------------------------------------------------
    def _data_lines(self):
        """(index, words) of every line that may hold a value: not a header, blank or
        section line."""
        out = []
        for i, text in enumerate(self.lines):
            if i < self.header_lines or not text.strip() or is_separator(text):
                continue
            out.append((i, split_words(text)))
        return out

    def _read(self):
        data = self._data_lines()
        by_name: dict[str, int] = {}        # upper-case written name -> index in data
        for k, (_i, w) in enumerate(data):
            name = _written_name(w)
            if name is not None:
                by_name.setdefault(name.upper(), k)
        found: dict[str, int] = {}
        for key in self.schema:
            for n in key.names():
                if n in by_name:
                    found[key.name] = by_name[n]
                    break
        self._data = data
        self._found = found
        self.values: dict[str, Line] = {}
        for key in self.schema:
            if key.name in found:
                k = found[key.name]
                i, w = data[k]
                first_is_name = w[0].upper() in key.names() and len(w) >= 2
                value = w[1] if first_is_name else w[0]
                written = _written_name(w) or ""
                self.values[key.name] = Line(key=key.name, value=value, line=i + 1,
                                             written=written, how="name")
        # keys not found by name: by position between their neighbours found by name
        names = [k.name for k in self.schema]
        taken = {self.values[n].line for n in self.values}
        for j, key in enumerate(self.schema):
            if key.name in self.values:
                continue
            prev = next((names[p] for p in range(j - 1, -1, -1) if names[p] in found), None)
            nxt = next((names[p] for p in range(j + 1, len(names)) if names[p] in found), None)
            if prev is None or nxt is None:
                continue
            k0, k1 = found[prev], found[nxt]
            between = [data[k] for k in range(k0 + 1, k1)
                       if data[k][0] + 1 not in taken]
            missing = [names[p] for p in range(names.index(prev) + 1, names.index(nxt))
                       if names[p] not in self.values]
            required = [m for m in missing
                        if not next(x for x in self.schema if x.name == m).optional]
            # the unnamed lines stand for the keys between the neighbours: all of them, or,
            # when there are fewer lines, the required ones (a file of a version without
            # the optional ones)
            slots = missing if len(between) == len(missing) else (
                required if len(between) == len(required) else None)
            if slots is None or key.name not in slots:
                continue
            i, w = between[slots.index(key.name)]
            if not w:
                continue
            self.values[key.name] = Line(key=key.name, value=w[0], line=i + 1,
                                         written=w[1] if len(w) > 1 else "", how="position")
            taken.add(i + 1)
            self.notes.append(f"{self.path.name} line {i + 1}: read as {key.name} by its "
                              f"position (its name reads {w[1] if len(w) > 1 else 'nothing'!r})")

    # -- access ---------------------------------------------------------------------------
    def has(self, name: str) -> bool:
        return name in self.values

    def line(self, name: str) -> int | None:
        v = self.values.get(name)
        return None if v is None else v.line

    def where(self, name: str) -> str:
        """``line N (Name)`` for messages (the key alone when it was not read)."""
        v = self.values.get(name)
        return f"line {v.line} ({name})" if v is not None else name

    def _missing(self, name: str, expected: str):
        names = [k.name for k in self.schema]
        j = names.index(name) if name in names else -1
        prev = next((names[p] for p in range(j - 1, -1, -1) if names[p] in self.values), None)
        if prev is not None:
            after = self.values[prev].line
            nxt = next(((i, w) for i, w in self._data if i + 1 > after), None)
            found = (f"line {nxt[0] + 1}: {' '.join(nxt[1][:3])}" if nxt is not None
                     else "the end of the file")
            return SceneError(self.path, name, f"{expected} after {prev} (line {after})", found)
        return SceneError(self.path, name, expected, SceneError.MISSING)

    def text(self, name: str, default=None) -> str:
        v = self.values.get(name)
        if v is None:
            if default is not None:
                return default
            raise self._missing(name, f"a line 'value {name} - description'")
        return v.value

    def is_default(self, name: str) -> bool:
        return self.has(name) and self.text(name).strip('"').upper() == "DEFAULT"

    def float(self, name: str, default=None, *, default_word: float | None = None) -> float:
        """The value as a number; ``default`` when the key is absent (else a SceneError);
        ``default_word`` for the word DEFAULT."""
        if name not in self.values:
            if default is not None:
                return float(default)
            raise self._missing(name, f"a line 'number {name} - description'")
        v = self.values[name]
        if v.value.strip('"').upper() == "DEFAULT" and default_word is not None:
            return float(default_word)
        x = _number(v.value)
        if x is None or not math.isfinite(x):
            raise SceneError(self.path, self.where(name), "a finite number", v.value)
        return x

    def int(self, name: str, default=None) -> int:
        x = self.float(name, default)
        if x != int(x):
            raise SceneError(self.path, self.where(name), "a whole number", self.text(name))
        return int(x)

    def flag(self, name: str, default: bool | None = None) -> bool:
        if name not in self.values and default is not None:
            return default
        t = self.text(name).strip('"').upper()
        if t in ("TRUE", "T", ".TRUE."):
            return True
        if t in ("FALSE", "F", ".FALSE."):
            return False
        raise SceneError(self.path, self.where(name), "TRUE or FALSE", self.text(name))

    def file(self, name: str) -> Path | None:
        """A file name relative to this file's folder (None for unused/none/empty)."""
        v = self.text(name, "").strip('"')
        if v.lower() in ("unused", "none", ""):
            return None
        p = Path(v)
        return p if p.is_absolute() else self.path.parent / p

    def numbers_after(self, name: str, nrow: int, ncol: int) -> np.ndarray:
        """The ``nrow`` x ``ncol`` numbers starting at the line of ``name`` (a matrix whose
        first row carries the name after its numbers, as HydroDyn's AddCLin)."""
        if name not in self.values:
            raise self._missing(name, f"the {name} rows")
        start = self.values[name].line - 1
        rows = []
        for r in range(nrow):
            i = start + r
            words = split_words(self.lines[i]) if i < len(self.lines) else []
            vals = []
            for w in words:
                x = _number(w)
                if x is None:
                    break
                vals.append(x)
            if len(vals) < ncol:
                raise SceneError(self.path, f"line {i + 1} ({name} row {r + 1})",
                                 f"{ncol} numbers", " ".join(words) or "nothing")
            rows.append(vals[:ncol])
        return np.array(rows, float)

    def leading_numbers(self, name: str) -> int:
        """How many numbers precede the name on the line of ``name``."""
        i = self.values[name].line - 1
        n = 0
        for w in split_words(self.lines[i]):
            if _number(w) is None:
                break
            n += 1
        return n

    def table(self, count_key: str, *, header_lines: int = 2, min_cols: int = 1):
        """The rows of the table after ``count_key`` (its header lines skipped), as lists
        of words, with their line numbers: ``[(line, words), ...]``."""
        n = self.int(count_key, 0) if self.has(count_key) else 0
        if n < 0:
            raise SceneError(self.path, self.where(count_key), "a count >= 0", n)
        if n == 0:
            return []
        i = self.values[count_key].line - 1 + 1 + header_lines
        out = []
        while len(out) < n:
            if i >= len(self.lines):
                raise SceneError(self.path, self.where(count_key), f"{n} table rows",
                                 f"{len(out)} before the end of the file")
            text = self.lines[i]
            if text.strip():
                words = split_words(text.split("!")[0])
                if is_separator(text) or len(words) < min_cols:
                    raise SceneError(self.path, f"line {i + 1}", f"row {len(out) + 1} of the "
                                     f"{n} rows of {count_key} ({min_cols} or more columns)",
                                     text.strip())
                out.append((i + 1, words))
            i += 1
        return out

    def section_rows(self, title: str, count: int, ncol: int, *, header_lines: int = 2):
        """``count`` rows of ``ncol`` numbers after the section line containing ``title``
        and its header lines (the distributed-property tables of tower and blade files)."""
        start = next((i for i, t in enumerate(self.lines)
                      if is_separator(t) and title.upper() in t.upper()), None)
        if start is None:
            raise SceneError(self.path, title, f"a section '{title}'", SceneError.MISSING)
        rows = []
        i = start + 1 + header_lines
        for k in range(count):
            words = split_words(self.lines[i + k]) if i + k < len(self.lines) else []
            vals = [_number(w) for w in words[:ncol]]
            if len(vals) < ncol or any(v is None for v in vals):
                raise SceneError(self.path, f"line {i + k + 1}", f"{ncol} or more numbers (row "
                                 f"{k + 1} of {count} after the {title} header)",
                                 " ".join(words) or "nothing")
            rows.append(vals)
        return np.array(rows, float)
