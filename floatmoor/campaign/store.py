"""The campaign folder: manifest, campaign record, and loading the FD and TD results.

Layout of ``DIR``::

    campaign.json      the campaign (parameters, design, screening, storage, the case list with
                       the input fingerprint digest of each case's results)
    manifest.csv       one row per task outcome, appended as tasks finish (the last row of a
                       (kind, case, seed) wins); kinds fd, td, series; the fingerprint digest
                       of the inputs each result was computed from
    fd/<case>.nc       frequency-domain result of each case
    td/<case>/seedNNNN.nc   time-domain storms (statistics, and series in full mode)
    series/<case>/seedNNNN.nc  statistics mode: full series of the governing cases
    screening.csv      FD utilisation per case and line, and whether the case went to TD

Every result file carries the JSON fingerprint of its inputs (attribute ``input_fingerprint``,
:func:`floatmoor.analyses.fingerprint.case_fingerprint`).  Reading results back
(:func:`read_result`, :func:`load_fd_table`, :func:`load_td_statistics`) checks that each file
is whole, holds finite and plausible values (:mod:`floatmoor.analyses.result_check`), is the
case and seed its name says, and was computed from the inputs the campaign record expects for
that case: a file that fails is a SceneError naming it (a resume computes it again); a file
that is absent is a result not computed yet (NaN).
"""

from __future__ import annotations

import csv
import json
import os
from pathlib import Path

import numpy as np

from ..core.errors import SceneError

__all__ = [
    "MANIFEST",
    "RECORD",
    "Manifest",
    "fd_path",
    "is_campaign_dir",
    "load_fd_table",
    "load_td_statistics",
    "read_record",
    "read_result",
    "storm_path",
]

MANIFEST = "manifest.csv"
RECORD = "campaign.json"
COLUMNS = ("kind", "case", "seed", "status", "wall_time_s", "path", "bytes", "sha256",
           "sea_state", "hs", "tp", "wave_heading_deg", "wind_heading_deg",
           "current_heading_deg", "condition", "limit_state", "error", "simulate_s", "solve_s",
           "fingerprint")


def is_campaign_dir(path) -> bool:
    return (Path(path) / MANIFEST).is_file() and (Path(path) / RECORD).is_file()


def storm_path(out_dir, case_id: str, seed: int, kind: str = "td") -> Path:
    return Path(out_dir) / kind / case_id / f"seed{int(seed):04d}.nc"


def fd_path(out_dir, case_id: str) -> Path:
    return Path(out_dir) / "fd" / f"{case_id}.nc"


class Manifest:
    """Append-only CSV of task outcomes; :meth:`latest` gives the last row per task."""

    def __init__(self, out_dir):
        self.dir = Path(out_dir)
        self.path = self.dir / MANIFEST
        self.dir.mkdir(parents=True, exist_ok=True)
        if not self.path.exists() or self.path.stat().st_size == 0:
            with open(self.path, "w", newline="") as f:
                csv.writer(f).writerow(COLUMNS)
            return
        with open(self.path, newline="") as f:
            header = next(csv.reader(f), None)
        if header is not None and tuple(header) != COLUMNS:
            # written by another version: rewritten with today's columns (read by name), so
            # that rows appended now are read back by name too
            rows = self.rows()
            tmp = self.path.with_name(MANIFEST + ".tmp")
            with open(tmp, "w", newline="") as f:
                w = csv.writer(f)
                w.writerow(COLUMNS)
                for r in rows:
                    w.writerow([r.get(c, "") or "" for c in COLUMNS])
            os.replace(tmp, self.path)

    def rows(self) -> list[dict]:
        """Every row (a file written by an older version has fewer columns: read by name)."""
        with open(self.path, newline="") as f:
            rows = []
            for r in csv.DictReader(f):
                if r.get("kind") and r.get("status"):  # a torn last line is ignored
                    rows.append(r)
            return rows

    def latest(self) -> dict:
        return {(r["kind"], r["case"], int(r["seed"])): r for r in self.rows()}

    def append(self, outcome: dict, case_row: dict) -> None:
        row = dict(case_row)
        row.update({k: outcome.get(k, "") for k in ("kind", "case", "seed", "status", "bytes",
                                                    "sha256", "error", "fingerprint")})
        row["wall_time_s"] = f"{outcome.get('wall_time_s', 0.0):.3f}"
        for k in ("simulate_s", "solve_s"):
            if k in outcome:
                row[k] = f"{outcome[k]:.3f}"
        p = Path(outcome.get("path", ""))
        row["path"] = os.path.relpath(p, self.dir) if p.is_absolute() else str(p)
        with open(self.path, "a", newline="") as f:
            csv.writer(f).writerow([row.get(c, "") for c in COLUMNS])
            f.flush()

    def is_done(self, row: dict | None, path: Path, verify: bool = False) -> bool:
        """Done when the manifest says so and the file is whole: present, of the recorded size
        (and, with ``verify``, of the recorded SHA-256).  A half-written file fails this."""
        if row is None or row["status"] != "done" or not path.is_file():
            return False
        if str(path.stat().st_size) != str(row.get("bytes")):
            return False
        if verify:
            from .tasks import file_digest
            return file_digest(path) == row.get("sha256")
        return True


def write_record(out_dir, record: dict) -> None:
    tmp = Path(out_dir) / (RECORD + ".tmp")
    tmp.write_text(json.dumps(record, indent=1, default=str))
    os.replace(tmp, Path(out_dir) / RECORD)


RECORD_KEYS = ("name", "seeds", "design", "cases")
"""Keys every campaign record has."""


def read_record(out_dir) -> dict:
    """The campaign record ``campaign.json`` of ``out_dir``; a SceneError naming the file when
    it is empty, truncated or not a campaign record (rerunning the campaign writes it again)."""
    path = Path(out_dir) / RECORD
    try:
        text = path.read_text()
    except UnicodeDecodeError as exc:
        raise SceneError(path, "", "the campaign record (JSON) floatmoor writes",
                         f"unreadable text ({exc.reason})", _RECORD_HINT) from None
    if not text.strip():
        raise SceneError(path, "", "the campaign record (JSON) floatmoor writes",
                         "an empty file", _RECORD_HINT)
    try:
        rec = json.loads(text)
    except ValueError as exc:
        raise SceneError(path, "", "the campaign record (JSON) floatmoor writes",
                         f"invalid or truncated JSON ({exc})", _RECORD_HINT) from None
    if not isinstance(rec, dict) or any(k not in rec for k in RECORD_KEYS):
        missing = [k for k in RECORD_KEYS if not isinstance(rec, dict) or k not in rec]
        raise SceneError(path, "", "the campaign record floatmoor writes (keys " +
                         ", ".join(RECORD_KEYS) + ")", "missing: " + ", ".join(missing),
                         _RECORD_HINT)
    return rec


_RECORD_HINT = ("rerun the campaign command with this --out folder to write it again "
                "(finished results whose inputs match are kept)")


def _read_vars(path, names):
    import netCDF4
    with netCDF4.Dataset(path) as nc:
        nc.set_auto_mask(False)
        return {k: np.asarray(nc.variables[k][...]) for k in names if k in nc.variables}


FD_CHECK_VARS = ("tension_static", "tension_max_total", "mbs", "line_failed", "mean",
                 "max_total", "min_total")
"""Variables of an FD file read and checked by :func:`read_result`."""
TD_CHECK_VARS = ("line_tension_max", "line_tension_mean", "line_tension_min",
                 "line_tension_std", "anchor_tension_max", "offset_max", "offset_mean",
                 "motion_max", "motion_min", "motion_mean", "motion_std", "mbs")
"""Variables of a storm file read and checked by :func:`read_result`."""


def read_result(path, kind: str, case_id: str, seed: int = -1,
                expected: str | None = None) -> tuple[dict, dict | None]:
    """The checked values and the stored fingerprint of a campaign result file of ``kind`` (fd,
    td, series) for ``case_id`` (and ``seed``): a SceneError naming the file when it cannot be
    read, lacks a variable, holds values no finished case writes (NaN, negative tensions, ...,
    :mod:`floatmoor.analyses.result_check`), belongs to another case or seed, or, with
    ``expected`` (a fingerprint digest), was computed from other inputs."""
    import netCDF4

    from ..analyses.fingerprint import FINGERPRINT_ATTR, fingerprint_digest
    from ..analyses.result_check import check_fd_values, check_statistics
    names = FD_CHECK_VARS if kind == "fd" else TD_CHECK_VARS
    need = FD_TABLE_VARS if kind == "fd" else TD_TABLE_VARS
    try:
        with netCDF4.Dataset(path) as nc:
            nc.set_auto_mask(False)
            values = {k: np.asarray(nc.variables[k][...]) for k in names if k in nc.variables}
            attrs = {k: nc.getncattr(k) for k in ("case", "seed", FINGERPRINT_ATTR)
                     if k in nc.ncattrs()}
    except (OSError, RuntimeError, KeyError, ValueError, IndexError) as exc:
        raise SceneError(path, "", "a whole campaign result file (netCDF)",
                         f"an unreadable or truncated file ({type(exc).__name__}: {exc})",
                         "rerun the campaign to compute it again") from None
    missing = [k for k in need if k not in values]
    if missing:
        raise SceneError(path, missing[0], f"a {kind} result of a floatmoor campaign",
                         "the variable is missing", "rerun the campaign to compute it again")
    if str(attrs.get("case", case_id)) != case_id:
        raise SceneError(path, "case", f"the result of case {case_id}", attrs.get("case"),
                         "a file copied or renamed by hand: its results belong to another "
                         "case")
    if kind != "fd" and int(attrs.get("seed", seed)) != int(seed):
        raise SceneError(path, "seed", f"the storm of seed {seed}", attrs.get("seed"),
                         "a file copied or renamed by hand")
    if kind == "fd":
        check_fd_values(path, values)
    else:
        check_statistics(path, values)
    fp = None
    text = attrs.get(FINGERPRINT_ATTR)
    if text is not None:
        try:
            fp = json.loads(text)
        except ValueError:
            raise SceneError(path, FINGERPRINT_ATTR, "the JSON input fingerprint floatmoor "
                             "writes", text) from None
    if expected is not None:
        found = fingerprint_digest(fp) if fp is not None else "none"
        if found != expected:
            raise SceneError(path, FINGERPRINT_ATTR, f"the inputs of case {case_id} in the "
                             f"campaign record (fingerprint {expected})", found,
                             "computed before the campaign file, its contour, the base scene, "
                             "a file it reads or floatmoor changed: rerun the campaign (the "
                             "same command) to compute it again")
    return values, fp


def _expected(out_dir, kind: str, expected):
    """``expected`` digests by case id, else the campaign record's (None: a record written
    before fingerprints were kept, or no record)."""
    if expected is not None:
        return expected
    try:
        rec = read_record(out_dir)
    except (OSError, SceneError):
        return None
    out = {}
    for c in rec.get("cases", []):
        d = (c.get("fingerprints") or {}).get(kind)
        if d:
            out[c["case"]] = d
    return out or None


FD_TABLE_VARS = ("tension_static", "tension_max_total", "mbs", "max_total", "min_total")
"""The variables of an FD file that the screening reads."""
TD_TABLE_VARS = ("line_tension_max", "line_tension_mean", "offset_max", "mbs")
"""The variables of a storm file that the choice of the governing cases reads."""


def load_fd_table(out_dir, case_ids, known: dict | None = None,
                  expected: dict | None = None) -> dict:
    """FD per-line arrays (cases x lines) of the cases that have an FD file (NaN otherwise).

    ``known`` maps a case id to its :data:`FD_TABLE_VARS` as written (the values a task of this
    run returned with its outcome, or read and checked by this run): those files are not read
    again.  Every other file is read with :func:`read_result` (checked; its fingerprint against
    ``expected``, a digest by case id, default the campaign record's): a file that fails is a
    SceneError naming it."""
    out = None
    exp = _expected(out_dir, "fd", expected)
    for i, cid in enumerate(case_ids):
        v = (known or {}).get(cid)
        if v is None:
            p = fd_path(out_dir, cid)
            if not p.is_file():
                continue
            v, _ = read_result(p, "fd", cid, expected=(exp or {}).get(cid))
            v = {k: v[k] for k in FD_TABLE_VARS if k in v}
        if out is None:
            nl = v["mbs"].size
            out = {k: np.full((len(case_ids),) + np.shape(v[k]), np.nan) for k in v}
            out["n_lines"] = nl
        for k in v:
            out[k][i] = v[k]
    return out or {}


def load_td_statistics(out_dir, case_ids, seeds, kind: str = "td",
                       known: dict | None = None, expected: dict | None = None) -> dict:
    """Per-storm statistics (cases x seeds x lines), NaN where a storm has no file (not run
    yet, or failed).

    ``known`` maps (case id, seed) to the storm's :data:`TD_TABLE_VARS` as written (or read
    and checked by this run): those files are not read again.  Every other file is read with
    :func:`read_result` (checked: a truncated file, a NaN maximum or a sign-flipped tension is
    a SceneError naming the file, never a seed silently left out of a fit)."""
    out = None
    exp = _expected(out_dir, kind, expected)
    for i, cid in enumerate(case_ids):
        for s, seed in enumerate(seeds):
            v = (known or {}).get((cid, int(seed)))
            if v is None:
                p = storm_path(out_dir, cid, seed, kind)
                if not p.is_file():
                    continue
                v, _ = read_result(p, kind, cid, int(seed), expected=(exp or {}).get(cid))
            if out is None:
                nl = v["mbs"].size
                out = {"line_tension_max": np.full((len(case_ids), len(seeds), nl), np.nan),
                       "line_tension_mean": np.full((len(case_ids), len(seeds), nl), np.nan),
                       "offset_max": np.full((len(case_ids), len(seeds)), np.nan),
                       "mbs": v["mbs"]}
            out["line_tension_max"][i, s] = v["line_tension_max"]
            out["line_tension_mean"][i, s] = v["line_tension_mean"]
            out["offset_max"][i, s] = float(v["offset_max"])
    return out or {}
