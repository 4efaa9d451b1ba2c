"""The campaign folder: manifest, campaign record, and loading the FD and TD results.

Layout of ``DIR``::

    campaign.json      the campaign (parameters, design, screening, storage, the case list)
    manifest.csv       one row per task outcome, appended as tasks finish (the last row of a
                       (kind, case, seed) wins); kinds fd, td, series
    fd/<case>.nc       frequency-domain result of each case
    td/<case>/seedNNNN.nc   time-domain storms (statistics, and series in full mode)
    series/<case>/seedNNNN.nc  statistics mode: full series of the governing cases
    screening.csv      FD utilisation per case and line, and whether the case went to TD
"""

from __future__ import annotations

import csv
import json
import os
from pathlib import Path

import numpy as np

__all__ = [
    "MANIFEST",
    "RECORD",
    "Manifest",
    "fd_path",
    "is_campaign_dir",
    "load_fd_table",
    "load_td_statistics",
    "storm_path",
]

MANIFEST = "manifest.csv"
RECORD = "campaign.json"
COLUMNS = ("kind", "case", "seed", "status", "wall_time_s", "path", "bytes", "sha256",
           "sea_state", "hs", "tp", "wave_heading_deg", "wind_heading_deg",
           "current_heading_deg", "condition", "limit_state", "error", "simulate_s", "solve_s")


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
                                                    "sha256", "error")})
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


def read_record(out_dir) -> dict:
    return json.loads((Path(out_dir) / RECORD).read_text())


def _read_vars(path, names):
    import netCDF4
    with netCDF4.Dataset(path) as nc:
        nc.set_auto_mask(False)
        return {k: np.asarray(nc.variables[k][...]) for k in names if k in nc.variables}


FD_TABLE_VARS = ("tension_static", "tension_max_total", "mbs", "max_total", "min_total")
"""The variables of an FD file that the screening reads."""
TD_TABLE_VARS = ("line_tension_max", "line_tension_mean", "offset_max", "mbs")
"""The variables of a storm file that the choice of the governing cases reads."""


def load_fd_table(out_dir, case_ids, known: dict | None = None) -> dict:
    """FD per-line arrays (cases x lines) of the cases that have an FD file (NaN otherwise).

    ``known`` maps a case id to its :data:`FD_TABLE_VARS` as written (the values a task of this
    run returned with its outcome): those files are not read again."""
    out = None
    for i, cid in enumerate(case_ids):
        v = (known or {}).get(cid)
        if v is None:
            p = fd_path(out_dir, cid)
            if not p.is_file():
                continue
            v = _read_vars(p, FD_TABLE_VARS)
        if out is None:
            nl = v["mbs"].size
            out = {k: np.full((len(case_ids),) + np.shape(v[k]), np.nan) for k in v}
            out["n_lines"] = nl
        for k in v:
            out[k][i] = v[k]
    return out or {}


def load_td_statistics(out_dir, case_ids, seeds, kind: str = "td",
                       known: dict | None = None) -> dict:
    """Per-storm statistics (cases x seeds x lines), NaN where a storm is missing.

    ``known`` maps (case id, seed) to the storm's :data:`TD_TABLE_VARS` as written: those files
    are not read again."""
    out = None
    for i, cid in enumerate(case_ids):
        for s, seed in enumerate(seeds):
            v = (known or {}).get((cid, int(seed)))
            if v is None:
                p = storm_path(out_dir, cid, seed, kind)
                if not p.is_file():
                    continue
                try:
                    v = _read_vars(p, TD_TABLE_VARS)
                except OSError:
                    continue
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
