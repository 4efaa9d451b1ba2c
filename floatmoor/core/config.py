"""Reading validated configuration from YAML files.

:class:`Node` wraps one mapping read from a file and remembers the file and the key path, so
that every getter can raise a :class:`~floatmoor.core.errors.SceneError` naming the file, the key,
what was expected and what was found.  Parsers of scene, vessel, metocean and line-type files use
it like this::

    node = Node.load("scene.yaml")
    waves = node.child("environment").child("waves")
    hs = waves.float("hs", gt=0.0, unit="m")
    heading = waves.angle_deg("heading_deg", default=0.0)   # returned in radians
    waves.reject_unknown({"spectrum", "hs", "tp", "gamma", "heading_deg"})

Conventions enforced here: SI units; angles only in keys ending ``_deg`` (returned in radians).
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

import numpy as np
import yaml

from .errors import SceneError

__all__ = ["Node", "MISSING", "type_name", "parse_yaml_text"]

MISSING = SceneError.MISSING

_ANGLE_WORDS = ("heading", "direction", "azimuth", "angle", "yaw", "roll", "pitch")


def type_name(value) -> str:
    """A user-facing name of a YAML value's type."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "a boolean"
    if isinstance(value, int):
        return "an integer"
    if isinstance(value, float):
        return "a number"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, Mapping):
        return "a mapping"
    if isinstance(value, (list, tuple)):
        return "a list"
    return type(value).__name__


class _UniqueKeyLoader(yaml.SafeLoader):
    """SafeLoader that refuses duplicate keys (a silent overwrite hides mistakes)."""


def _construct_mapping(loader, node, deep=False):
    seen = set()
    for key_node, _ in node.value:
        key = loader.construct_object(key_node, deep=deep)
        if key in seen:
            raise yaml.constructor.ConstructorError(
                None, None, f"duplicate key {key!r}", key_node.start_mark)
        seen.add(key)
    return yaml.SafeLoader.construct_mapping(loader, node, deep=deep)


_UniqueKeyLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)

# PyYAML follows YAML 1.1, where ``1.73e8`` and ``1e8`` (no sign or no dot) are strings.  Engineers
# write them all the time; resolve them as floats, as YAML 1.2 does.
import re as _re  # noqa: E402

_FLOAT_12 = _re.compile(r"""^[-+]?(?:[0-9][0-9_]*(?:\.[0-9_]*)?|\.[0-9_]+)(?:[eE][-+]?[0-9]+)$""", _re.X)
_UniqueKeyLoader.yaml_implicit_resolvers = {
    k: list(v) for k, v in yaml.SafeLoader.yaml_implicit_resolvers.items()}
_UniqueKeyLoader.add_implicit_resolver("tag:yaml.org,2002:float", _FLOAT_12, list("-+0123456789."))


MAX_YAML_NODES = 200_000
"""Most values (mappings, lists and scalars, counting each alias as a full copy) a YAML file may
expand to.  The largest shipped input (a vessel with slender elements) holds about a thousand;
the bound refuses alias bombs ("billion laughs") before they are expanded."""

MAX_YAML_DEPTH = 50
"""Deepest nesting of lists and mappings in a YAML file (scene files use fewer than 8 levels)."""

MAX_NUMBER_CHARS = 40
"""Longest number literal (digits, sign, dot and exponent) accepted; a longer one is refused before
it is converted (a 5000-digit integer would otherwise stall or overflow the conversion)."""

MAX_SCALAR_CHARS = 10_000
"""Longest single value (a name, a description, a number) accepted in a YAML file."""

_NUMBER_TAGS = ("tag:yaml.org,2002:int", "tag:yaml.org,2002:float")


def _where(mark) -> str:
    return "" if mark is None else f"line {mark.line + 1}, column {mark.column + 1}"


def _check_yaml_tree(root, path: Path) -> None:
    """Refuse, before construction, a composed YAML node graph that is cyclic (a recursive
    alias), nested deeper than :data:`MAX_YAML_DEPTH`, expands to more than
    :data:`MAX_YAML_NODES` values, or holds an oversized scalar.  Linear in the distinct nodes
    (expanded sizes are memoised per node), so an alias bomb costs nothing to detect."""
    sizes: dict[int, int] = {}
    active: set[int] = set()

    def visit(node, depth: int) -> int:
        key = id(node)
        if key in sizes:
            return sizes[key]
        if key in active:
            raise SceneError(path, _where(node.start_mark), "a YAML value that does not contain "
                             "itself", "a recursive alias (an anchor used inside its own value)")
        if depth > MAX_YAML_DEPTH:
            raise SceneError(path, _where(node.start_mark),
                             f"lists and mappings nested at most {MAX_YAML_DEPTH} deep",
                             "deeper nesting")
        if isinstance(node, yaml.ScalarNode):
            n = len(node.value)
            if n > MAX_SCALAR_CHARS:
                raise SceneError(path, _where(node.start_mark),
                                 f"a value of at most {MAX_SCALAR_CHARS} characters",
                                 f"a value of {n} characters")
            if node.tag in _NUMBER_TAGS and n > MAX_NUMBER_CHARS:
                raise SceneError(path, _where(node.start_mark),
                                 f"a number of at most {MAX_NUMBER_CHARS} characters",
                                 f"a {n}-character number starting {node.value[:20]}...")
            sizes[key] = 1
            return 1
        active.add(key)
        total = 1
        if isinstance(node, yaml.SequenceNode):
            children = node.value
        else:
            children = [c for pair in node.value for c in pair]
        for child in children:
            total += visit(child, depth + 1)
            if total > MAX_YAML_NODES:
                raise SceneError(path, _where(node.start_mark),
                                 f"a file expanding to at most {MAX_YAML_NODES} values",
                                 "more (aliases that repeat anchors many times over: an alias "
                                 "bomb?)")
        active.discard(key)
        sizes[key] = total
        return total

    visit(root, 0)


def parse_yaml_text(text: str, path: Path | str | None = None):
    """Parse YAML ``text`` safely: duplicate keys, recursive or exploding aliases, excessive
    nesting and oversized numbers are refused with a :class:`SceneError` naming ``path`` (and the
    line), before any value is constructed; so is a control character (binary data)."""
    try:
        loader = _UniqueKeyLoader(text)
    except yaml.reader.ReaderError as exc:  # a control character (binary data, a stray BEL)
        line = text.count("\n", 0, exc.position) + 1
        column = exc.position - (text.rfind("\n", 0, exc.position) + 1) + 1
        raise SceneError(path, f"line {line}, column {column}", "a YAML text file (printable "
                         "characters only)", f"the control character #x{exc.character:02x}",
                         "a binary file, or a stray control character: remove it") from None
    try:
        try:
            root = loader.get_single_node()
        except RecursionError:
            raise SceneError(path, "", f"lists and mappings nested at most {MAX_YAML_DEPTH} "
                             "deep", "deeper nesting") from None
        if root is None:
            return None
        _check_yaml_tree(root, path)
        return loader.construct_document(root)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        problem = getattr(exc, "problem", None) or str(exc)
        raise SceneError(path, _where(mark), "valid YAML", f"a syntax error: {problem}") from None
    finally:
        loader.dispose()


def _read_yaml(path: Path, key: str = "", referenced_from: Node | None = None):
    file_for_error = referenced_from.file if referenced_from is not None else path
    if not path.exists():
        raise SceneError(file_for_error, key, "a path to an existing file", str(path))
    if path.is_dir():
        raise SceneError(file_for_error, key, "a path to a file, not a directory", str(path))
    try:
        size = path.stat().st_size
        if size > MAX_YAML_BYTES:
            raise SceneError(path, "", f"a YAML file of at most {MAX_YAML_BYTES // 2**20} MiB",
                             f"{size / 2**20:.0f} MiB")
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise SceneError(path, "", "a readable UTF-8 YAML file", f"unreadable file ({exc})") from None
    return parse_yaml_text(text, path)


MAX_YAML_BYTES = 16 * 2**20
"""Largest YAML file read (scene, vessel, mooring and metocean files are a few kB)."""


class Node:
    """A mapping read from a configuration file, with its file and key path.

    Getters take ``default``; without one the key is required and its absence is a SceneError.
    """

    def __init__(self, data: Mapping, file: str | os.PathLike | None = None, path: str = ""):
        self.file = None if file is None else Path(file)
        self.path = path
        if not isinstance(data, Mapping):
            raise SceneError(self.file, path, "a mapping (key: value pairs)", data)
        self.data = dict(data)

    # -- construction -----------------------------------------------------------------------
    @classmethod
    def load(cls, path: str | os.PathLike) -> Node:
        """Read a YAML file whose top level is a mapping."""
        path = Path(path)
        data = _read_yaml(path)
        if data is None:
            raise SceneError(path, "", "a YAML mapping", "an empty file")
        if not isinstance(data, Mapping):
            raise SceneError(path, "", "a YAML mapping at the top level", data)
        return cls(data, path, "")

    # -- helpers ----------------------------------------------------------------------------
    def key(self, name: str | int) -> str:
        """The dotted key path of a child key (``waves.hs``; list items as ``lines[3]``)."""
        if isinstance(name, int):
            return f"{self.path}[{name}]"
        return f"{self.path}.{name}" if self.path else str(name)

    def error(self, name: str | int, expected: str, found=MISSING, hint: str | None = None) -> SceneError:
        """A SceneError for a key of this node (to ``raise`` by the caller)."""
        return SceneError(self.file, self.key(name) if name != "" else self.path, expected, found, hint)

    def __contains__(self, name: str) -> bool:
        return name in self.data

    def keys(self):
        return self.data.keys()

    @property
    def base_dir(self) -> Path:
        return self.file.parent if self.file is not None else Path.cwd()

    def raw(self, name: str, default=MISSING, expected: str = "a value"):
        if name in self.data:
            return self.data[name]
        if default is MISSING:
            raise self.error(name, expected)
        return default

    def reject_unknown(self, allowed: Iterable[str]) -> None:
        """Raise a SceneError for keys not in ``allowed`` (typos must not pass silently)."""
        allowed = list(allowed)
        for k in self.data:
            if k not in allowed:
                hint = None
                if not str(k).endswith("_deg") and f"{k}_deg" in allowed:
                    hint = f"angles are given in degrees in keys ending _deg: use {k}_deg"
                raise self.error(str(k), "one of the keys: " + ", ".join(sorted(allowed)),
                                 f"unknown key {k!r}", hint)

    # -- mappings and lists -------------------------------------------------------------------
    def child(self, name: str, default=MISSING) -> Node | Any:
        """A nested mapping as a Node (``default`` returned when absent)."""
        if name not in self.data:
            if default is MISSING:
                raise self.error(name, "a mapping")
            return default
        value = self.data[name]
        if not isinstance(value, Mapping):
            raise self.error(name, "a mapping (key: value pairs)", value)
        return Node(value, self.file, self.key(name))

    def child_or_file(self, name: str, default=MISSING) -> Node | Any:
        """A nested mapping given inline, or as a relative path to another YAML file."""
        if name not in self.data:
            if default is MISSING:
                raise self.error(name, "a mapping or a path to a YAML file")
            return default
        value = self.data[name]
        if isinstance(value, str):
            path = self.path_value(name)
            data = _read_yaml(path, self.key(name), self)
            if not isinstance(data, Mapping):
                raise SceneError(path, "", "a YAML mapping at the top level", data)
            return Node(data, path, "")
        return self.child(name)

    def list(self, name: str, default=MISSING, *, min_len: int = 0) -> list:
        """A YAML list (items returned raw; use :meth:`item_nodes` for mappings)."""
        if name not in self.data:
            if default is MISSING:
                raise self.error(name, "a list")
            return default
        value = self.data[name]
        if not isinstance(value, list):
            raise self.error(name, "a list", value)
        if len(value) < min_len:
            raise self.error(name, f"a list of at least {min_len} item(s)", value)
        return value

    def item_nodes(self, name: str, default=MISSING, *, min_len: int = 0) -> list[Node]:
        """A list of mappings, each as a Node with key path ``name[i]``."""
        items = self.list(name, default, min_len=min_len)
        if items is default and default is not MISSING:
            return default
        out = []
        for i, item in enumerate(items):
            key = f"{self.key(name)}[{i}]"
            if not isinstance(item, Mapping):
                raise SceneError(self.file, key, "a mapping (key: value pairs)", item)
            out.append(Node(item, self.file, key))
        return out

    # -- scalars ----------------------------------------------------------------------------
    def float(self, name: str, default=MISSING, *, gt=None, ge=None, lt=None, le=None,
              unit: str = "", allow_none: bool = False) -> float:
        """A real number with optional bounds; integers are accepted, booleans and strings not."""
        if name not in self.data:
            if default is MISSING:
                raise self.error(name, _describe_number(gt, ge, lt, le, unit))
            return default
        value = self.data[name]
        if value is None and allow_none:
            return None
        return self._check_number(name, value, gt, ge, lt, le, unit)

    def _check_number(self, name, value, gt, ge, lt, le, unit, what="a number"):
        expected = _describe_number(gt, ge, lt, le, unit, what)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            hint = None
            if isinstance(value, str):
                try:
                    float(value)
                    hint = "remove the quotes"
                except ValueError:
                    if any(c.isalpha() for c in value):
                        hint = "give the value in SI units without a unit suffix"
            raise self.error(name, expected, value, hint)
        try:
            value = float(value)
        except OverflowError:
            raise self.error(name, expected, value) from None
        if not math.isfinite(value):
            raise self.error(name, expected, value)
        if ((gt is not None and not value > gt) or (ge is not None and not value >= ge)
                or (lt is not None and not value < lt) or (le is not None and not value <= le)):
            raise self.error(name, expected, value)
        return value

    def int(self, name: str, default=MISSING, *, ge=None, le=None) -> int:
        if name not in self.data:
            if default is MISSING:
                raise self.error(name, _describe_number(None, ge, None, le, "", "an integer"))
            return default
        value = self.data[name]
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.error(name, _describe_number(None, ge, None, le, "", "an integer"), value)
        self._check_number(name, value, None, ge, None, le, "", "an integer")
        return int(value)

    def bool(self, name: str, default=MISSING) -> bool:
        if name not in self.data:
            if default is MISSING:
                raise self.error(name, "true or false")
            return default
        value = self.data[name]
        if not isinstance(value, bool):
            raise self.error(name, "true or false", value)
        return value

    def str(self, name: str, default=MISSING, *, choices: Iterable[str] | None = None) -> str:
        choices = None if choices is None else list(choices)
        expected = "a string" if choices is None else "one of: " + ", ".join(choices)
        if name not in self.data:
            if default is MISSING:
                raise self.error(name, expected)
            return default
        value = self.data[name]
        if not isinstance(value, str):
            raise self.error(name, expected, value)
        if choices is not None and value not in choices:
            raise self.error(name, expected, value)
        return value

    def choice(self, name: str, registry: Mapping[str, Any], default=MISSING, what: str = "model"):
        """A name looked up in a registry; an unknown name lists the names available."""
        names = sorted(registry)
        expected = f"a {what} name, one of: " + ", ".join(names)
        if name not in self.data:
            if default is MISSING:
                raise self.error(name, expected)
            return default
        value = self.data[name]
        if not isinstance(value, str) or value not in registry:
            raise self.error(name, expected, value)
        return value

    def angle_deg(self, name: str, default=MISSING, *, lo: float = -360.0, hi: float = 360.0) -> float:
        """An angle given in degrees in a key ending ``_deg``; returned in radians.

        A value that is a recognisable multiple of pi (3.1416, 1.5708, 0.7854, 6.2832, ...) is
        taken for radians typed where degrees are expected and refused.
        """
        if not name.endswith("_deg"):
            raise ValueError(f"angle keys must end in _deg (programming error: {name!r})")
        bare = name[: -len("_deg")]
        if bare in self.data:
            raise self.error(bare, f"the angle in degrees under the key {name!r}",
                             self.data[bare], "angles are given in degrees in keys ending _deg")
        if name not in self.data:
            if default is MISSING:
                raise self.error(name, f"an angle in degrees in [{lo:g}, {hi:g}]")
            return default
        value = self._check_number(name, self.data[name], None, lo, None, hi, "deg",
                                   "an angle in degrees")
        if looks_like_radians(value):
            raise self.error(name, "an angle in degrees", self.data[name],
                             f"{value:g} looks like an angle in radians "
                             f"({math.degrees(value):.6g} deg); give it in degrees")
        return math.radians(value)

    # -- arrays and paths --------------------------------------------------------------------
    def array(self, name: str, default=MISSING, *, shape: tuple | None = None, ge=None, gt=None,
              unit: str = "") -> np.ndarray:
        """A (nested) list of numbers as a float array, with an optional exact shape.

        ``shape`` may hold ``None`` for a free dimension, e.g. ``(None, 2)`` for a table.
        """
        shape_txt = "" if shape is None else " of shape (" + ", ".join(
            "n" if s is None else str(s) for s in shape) + ")"
        expected = f"a list of numbers{shape_txt}" + (f" in {unit}" if unit else "")
        if name not in self.data:
            if default is MISSING:
                raise self.error(name, expected)
            return default
        value = self.data[name]
        try:
            if isinstance(value, (str, bytes, Mapping)) or _has_bool(value):
                raise TypeError
            arr = np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            raise self.error(name, expected, value) from None
        if shape is not None:
            if arr.ndim != len(shape) or any(s is not None and s != n for s, n in zip(shape, arr.shape)):
                raise self.error(name, expected, value)
        if not np.all(np.isfinite(arr)):
            raise self.error(name, expected + " (all finite)", value)
        if ge is not None and np.any(arr < ge):
            raise self.error(name, expected + f", each >= {ge:g}", value)
        if gt is not None and np.any(arr <= gt):
            raise self.error(name, expected + f", each > {gt:g}", value)
        if name.endswith("_deg"):
            hint = radians_list_hint(arr)
            if hint:
                raise self.error(name, "angles in degrees", value, hint)
        return arr

    def path_value(self, name: str, default=MISSING, *, must_exist: bool = True) -> Path:
        """A path relative to this file's folder (absolute paths allowed)."""
        if name not in self.data:
            if default is MISSING:
                raise self.error(name, "a path relative to this file")
            return default
        value = self.data[name]
        if not isinstance(value, str) or not value:
            raise self.error(name, "a path relative to this file", value)
        p = Path(value).expanduser()
        if not p.is_absolute():
            p = (self.base_dir / p)
        p = Path(os.path.normpath(p))
        if must_exist and not p.exists():
            raise self.error(name, "a path to an existing file (relative to this file's folder)",
                             value, f"{p} does not exist")
        return p


def looks_like_radians(value_deg: float) -> bool:
    """True when a value given as degrees is, to 4 significant digits, a multiple of pi/4 (not 0).

    3.1416, 1.5708, 0.7854, 4.7124 and 6.2832 are almost never meant as degrees in a mooring
    scene, but are exactly what a user who typed radians would write.
    """
    v = abs(value_deg)
    if v == 0.0 or v > 2.0 * math.pi + 1e-3:
        return False
    ratio = v / (math.pi / 4.0)
    k = round(ratio)
    return k >= 1 and abs(ratio - k) < 5e-4 and abs(v - round(v)) > 1e-9


def radians_list_hint(values_deg) -> str | None:
    """Why a list of angles given in degrees looks like radians, or None.

    Like :func:`looks_like_radians` for one value: every value within +-2 pi and either one of
    them a recognisable multiple of pi/4 (3.1416, 1.5708, ...) or three or more values spanning
    at most 2 pi (a table of headings covering less than 6.3 degrees)."""
    v = np.abs(np.asarray(values_deg, float).ravel())
    if v.size == 0 or not np.all(v <= 2.0 * math.pi + 1e-3) or not np.any(v > 0.0):
        return None
    suspects = [float(x) for x in v if looks_like_radians(float(x))]
    if suspects:
        return (f"{suspects[0]:g} looks like an angle in radians ({math.degrees(suspects[0]):.6g}"
                " deg) and every value is within 2 pi; give the angles in degrees")
    if v.size >= 3 and np.ptp(np.asarray(values_deg, float)) <= 2.0 * math.pi + 1e-3:
        return ("all values lie within 2 pi (6.28): they look like radians; give the angles in "
                "degrees")
    return None


def _has_bool(value) -> bool:
    if isinstance(value, bool):
        return True
    if isinstance(value, (list, tuple)):
        return any(_has_bool(v) for v in value)
    return False


def _describe_number(gt, ge, lt, le, unit, what="a number") -> str:
    parts = []
    if gt is not None:
        parts.append(f"> {gt:g}")
    if ge is not None:
        parts.append(f">= {ge:g}")
    if lt is not None:
        parts.append(f"< {lt:g}")
    if le is not None:
        parts.append(f"<= {le:g}")
    text = what + (" " + " and ".join(parts) if parts else "")
    if unit:
        text += f" (in {unit})"
    return text
