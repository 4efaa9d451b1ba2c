"""``floatmoor report RESULTS_DIR``: the design verdict of ``floatmoor run`` seeds over every limit
state, as a self-contained HTML report (and Markdown, CSV, netCDF).

Reads the per-seed netCDF files that ``floatmoor run`` wrote in RESULTS_DIR (seeds that failed,
``*.error.txt``, are left out and listed), removes the transient recorded in the files
(``transient`` attribute), fits a Gumbel distribution to the seed maxima of every line, takes
its 90 % value as the characteristic tension (Wang (2016) section 5.4.4) and checks the design
equation S_C >= T_C-mean gamma_mean + T_C-dyn gamma_dyn of the design code (``--code``, default
DNV-OS-E301 October 2008; ``api-rp-2sk-2005``, ``dnv-st-0119-2021`` or a code file:
:mod:`floatmoor.post.design_codes`), with S_C the end-of-life (corroded) capacity of the weakest
segment where the code asks for it.  The MBS per line comes from the results (``mbs``
variable), else from the scene's mooring.

Analysis type: the partial factors follow the line model of the results -- finite-element
lines the dynamic-analysis factors, quasi-static lines the quasi-static ones -- unless
``--daf FILE`` gives the dynamic amplification factor of ``floatmoor lines`` per line (it
multiplies T_C-dyn and the dynamic factors apply); ``--analysis dynamic|quasi-static``
overrides this for every line, and the report prints it as an override.

``--daf FILE``: the netCDF file written by ``floatmoor lines SCENE --motion SEED.nc --out FILE``
(its variable ``daf(line)``, dimensionless, coordinate ``line`` holding the line names), or a
CSV file with a header row naming the columns ``line`` and ``daf``.  Lines without a finite DAF
keep the quasi-static factors.  A DAF below 1 is applied as 1.

The scene named in the results (``scene_file``) gives the environment, the mooring (anchor
types and capacities, design life and corrosion: :mod:`floatmoor.io.mooring_design`) and the
offset limits and named points (``limits:``, :mod:`floatmoor.io.limits_section`) of the
anchor, offset and fibre-rope checks; the mooring must reproduce the recorded tensions (a
mooring file changed since the run is refused).  Without the scene file those checks are
reported as not checked.

ALS: ``--als-dir DIR`` is a second folder of ``floatmoor run`` results of the same mooring with
one line failed (a scene whose ``mooring`` lists ``failed_lines``, or whose ``forces`` has
``line_failure``: the transient after the failure is then part of the statistics when the
failure time is after ``analysis.transient``).  The failed line is found in the results (its
tension is zero at the end of every seed) or named with ``--failed-line NAME``.

FLS: ``--fatigue FILE`` adds the result of ``floatmoor fatigue --out FILE`` (its check redone
with the code's fatigue safety factor).

Fibre ropes with ``analysis.fibre_stiffness: both``: RESULTS_DIR holds the sub-folders
``fibre_lower`` and ``fibre_upper`` of ``floatmoor run``; the report is written for each
(``--out``/fibre_lower, ``--out``/fibre_upper) and ``fibre_bounds.md``/``fibre_bounds.csv``
show both side by side with the governing bound (the larger ULS utilisation); exit status 1
if a check fails in either bound.

``--fd FILE`` adds the frequency-domain result of ``floatmoor fd SCENE --out FILE`` beside the
time-domain values (per-line maximum tension and safety factor, offsets).

Writes report.html (self-contained: no network needed), report.md (+ PNG plots), summary.csv
and summary.nc into ``--out`` (default RESULTS_DIR/report), and prints the verdict: one line per
limit state and check (PASS, FAIL or NOT CHECKED) and the verdict over all of them.

Exit status (for scripts):
  0  no check fails (checks that could not be made are listed as NOT CHECKED)
  1  at least one check fails: a line tension (ULS, ALS), fatigue (FLS), an anchor, an offset
     or point limit, a fibre rope (the report is still written)
  2  bad input: missing folder, no result files, results of different scenes, durations or
     input fingerprints (seeds run before and after an edit of the scene, mooring, vessel...),
     a line whose MBS is unknown, unknown line, unreadable file, a DAF file of other lines, a
     mooring file that no longer reproduces the recorded tensions (message on stderr, no
     traceback)
"""

from __future__ import annotations

import argparse
import re
import sys
import warnings
from pathlib import Path

HELP = ("design verdict of floatmoor run results over every limit state (ULS, ALS, FLS, anchors, "
        "offsets, fibre ropes): HTML, Markdown, CSV, netCDF")

STANDARDS = ("dnv-os-e301",)
"""The old ``--standard`` values (the code ``dnv-os-e301-2008``)."""
EXIT_PASS = 0
EXIT_FAIL = 1
"""Exit status when a check fails."""

_VARIABLES = ("motion", "line_tension", "mbs", "anchor_tension", "line_model",
              "grounded_length")
MAX_DAF = 10.0
"""A larger dynamic amplification factor is a wrong file or column."""


def add_arguments(p: argparse.ArgumentParser) -> None:
    """Arguments of ``floatmoor report``."""
    p.add_argument("results_dir", metavar="RESULTS_DIR",
                   help="folder of per-seed netCDF files written by floatmoor run")
    p.add_argument("--code", metavar="CODE", default=None,
                   help="design code and edition: dnv-os-e301-2008 (default), api-rp-2sk-2005, "
                        "dnv-st-0119-2021, or a code file (floatmoor/data/codes format); on a "
                        "campaign folder the campaign's, which this overrides")
    p.add_argument("--standard", choices=STANDARDS, default=None,
                   help="the same as --code dnv-os-e301-2008 (kept for old scripts)")
    p.add_argument("--consequence-class", type=int, choices=(1, 2), default=None,
                   help="consequence class 1 or 2 (default 2; on a campaign folder the "
                        "campaign's, which this overrides)")
    p.add_argument("--analysis", choices=("auto", "dynamic", "quasi-static"), default=None,
                   help="analysis of the WF line tension, selects the partial factors: auto "
                        "(default) follows the line model (finite-element lines dynamic, "
                        "quasi-static lines quasi-static unless --daf gives their DAF); "
                        "dynamic or quasi-static override it for every line (printed as an "
                        "override; on a campaign folder they override the campaign's)")
    p.add_argument("--daf", metavar="FILE", default=None,
                   help="dynamic amplification factor per line from floatmoor lines (its "
                        "netCDF output, variable daf(line); or a CSV with columns line, daf): "
                        "quasi-static lines with a DAF get T_C-dyn x DAF and the dynamic "
                        "factors")
    p.add_argument("--als-dir", metavar="DIR", default=None,
                   help="folder of floatmoor run results with a failed line (ALS check)")
    p.add_argument("--failed-line", metavar="NAME", action="append", default=None,
                   help="name of the failed line in the --als-dir results (repeat for several; "
                        "default: found from the results)")
    p.add_argument("--fd", metavar="FILE.nc", default=None,
                   help="frequency-domain result of the same scene (floatmoor fd --out FILE.nc) "
                        "to show beside the time-domain values")
    p.add_argument("--fatigue", metavar="FILE.nc", default=None,
                   help="fatigue result (floatmoor fatigue --out FILE.nc): adds the FLS section")
    p.add_argument("--out", metavar="DIR", default=None,
                   help="output folder (default RESULTS_DIR/report)")


def _scene_error(file, key, expected, found, hint=None):
    from ..core.errors import SceneError
    return SceneError(file, key, expected, found, hint) if hint else \
        SceneError(file, key, expected, found)


def _seed_of(path: Path) -> str:
    m = re.search(r"_seed(\d+)", path.name)
    return str(int(m.group(1))) if m else path.name


def read_results(folder, key: str = "RESULTS_DIR"):
    """Read the per-seed results of ``floatmoor run`` in ``folder``.

    Parameters
    ----------
    folder : path
        Folder holding ``<scene>_seedNNNN.nc`` files (and ``*.error.txt`` of failed seeds).
    key : str
        Name of the input in error messages.

    Returns
    -------
    (datasets, failed) : list of xarray.Dataset (``motion``, ``line_tension``, ``mbs`` loaded
        in memory, attributes kept; sorted by seed) and a list of "seed N: first error line"
        strings of the failed seeds.

    Raises
    ------
    SceneError
        No such folder, no result file, an unreadable file, results of different scenes,
        durations, time steps, input fingerprints or line sets, or a seed twice.  NetCDF files that are not
        floatmoor run results (e.g. a ``floatmoor fd --out`` file) are skipped with a warning.
    """
    import xarray as xr

    folder = Path(folder)
    if not folder.is_dir():
        raise _scene_error(folder, key, "a folder of floatmoor run results",
                           "no such folder" if not folder.exists() else "not a folder")
    files = sorted(folder.glob("*.nc"))
    failed = []
    for err in sorted(folder.glob("*.error.txt")):
        if err.with_suffix("").with_suffix(".nc").exists():
            continue                       # an old error of a seed that later succeeded
        first = err.read_text(errors="replace").strip().splitlines()
        failed.append(f"seed {_seed_of(err)}: {first[0] if first else 'failed'}")
    if not files:
        extra = f" ({len(failed)} failed seed(s): see *.error.txt)" if failed else ""
        raise _scene_error(folder, key, "per-seed result files *.nc written by floatmoor run",
                           "none" + extra)
    datasets, ignored = [], []
    for f in files:
        try:
            with xr.open_dataset(f) as ds:
                names = list(map(str, ds.data_vars))
                ok = "line_tension" in ds and "time" in ds.dims
                ds = ds[[v for v in _VARIABLES if v in ds]].load() if ok else None
        except (OSError, ValueError) as exc:
            raise _scene_error(f, key, "a readable netCDF file",
                               f"{type(exc).__name__}: {exc}") from None
        if ds is None:                     # e.g. a floatmoor fd --out file put beside the seeds
            ignored.append(f"{f.name} (variables {', '.join(names[:5])}...)")
            continue
        from ..analyses.result_check import check_series_file
        check_series_file(f, ds)           # NaN, sign-flipped tensions: refused naming the file
        ds.attrs["source_file"] = str(f)
        datasets.append(ds)
    if ignored and datasets:
        from ..core.errors import FloatmoorWarning
        warnings.warn(f"{key} {folder}: ignored {len(ignored)} netCDF file(s) that are not "
                      "floatmoor run results (no line_tension(time, line)): "
                      + "; ".join(ignored), FloatmoorWarning, stacklevel=2)
    if not datasets:
        raise _scene_error(folder, key, "per-seed result files *.nc written by floatmoor run "
                           "(with line_tension(time, line))",
                           f"only other netCDF files: {', '.join(i.split(' ')[0] for i in ignored)}")
    _check_consistent(datasets, key)
    datasets.sort(key=lambda d: int(d.attrs.get("seed", 0)))
    return datasets, failed


def _check_consistent(datasets, key):
    """Refuse a folder mixing scenes, durations, time steps or line sets (or a seed twice)."""
    import numpy as np

    def describe(attr, fn=str):
        groups = {}
        for ds in datasets:
            v = ds.attrs.get(attr)
            groups.setdefault(None if v is None else fn(v), []).append(
                Path(ds.attrs["source_file"]).name)
        return groups

    for attr, what, fn in (("scene_name", "scene", str), ("scene", "scene file text", str),
                           ("duration", "duration (s)", lambda v: f"{float(v):g}"),
                           ("dt", "time step (s)", lambda v: f"{float(v):g}"),
                           ("transient", "transient (s)", lambda v: f"{float(v):g}")):
        groups = describe(attr, fn)
        if len(groups) > 1:
            if attr == "scene":
                found = "; ".join(f"{len(v)} file(s) of one version, e.g. {v[0]}"
                                  for v in groups.values())
            else:
                found = "; ".join(f"{k!s}: {len(v)} file(s), e.g. {v[0]}"
                                  for k, v in groups.items())
            raise _scene_error(Path(datasets[0].attrs["source_file"]).parent, key,
                               f"results of one scene run alike (one {what})", found,
                               "put each scene's (or each run's) results in its own folder")
    _check_fingerprints(datasets, key)
    lines0 = [str(v) for v in datasets[0]["line"].values]
    for ds in datasets[1:]:
        if [str(v) for v in ds["line"].values] != lines0:
            raise _scene_error(ds.attrs["source_file"], key, f"the lines {lines0}",
                               [str(v) for v in ds["line"].values])
    seeds = [ds.attrs.get("seed") for ds in datasets]
    if None in seeds:
        bad = datasets[seeds.index(None)].attrs["source_file"]
        raise _scene_error(bad, key, "a result with a 'seed' attribute (floatmoor run)", "none")
    dup = sorted({int(s) for s in seeds if seeds.count(s) > 1})
    if dup:
        raise _scene_error(Path(datasets[0].attrs["source_file"]).parent, key,
                           "one file per seed", f"seed(s) {dup} more than once")
    if "mbs" in datasets[0]:
        m0 = datasets[0]["mbs"].values
        for ds in datasets[1:]:
            if "mbs" in ds and not np.allclose(ds["mbs"].values, m0, rtol=1e-12, atol=0.0,
                                                     equal_nan=True):
                raise _scene_error(ds.attrs["source_file"], f"{key}.mbs",
                                   f"the MBS of the other seeds {list(m0)} N", list(ds["mbs"].values))


def _check_fingerprints(datasets, key):
    """Refuse seeds computed from different inputs: the ``input_fingerprint`` that ``floatmoor
    run`` stores (:mod:`floatmoor.analyses.fingerprint`) differs, e.g. seeds run before and
    after the mooring file was edited.  As in ``floatmoor run``, a file without a fingerprint
    beside files with one counts as different; files that all lack it (``simulate`` called
    from Python) are not compared."""
    import json

    from ..analyses.fingerprint import FINGERPRINT_ATTR, differing_keys, fingerprint_digest

    groups = {}
    for ds in datasets:
        text = ds.attrs.get(FINGERPRINT_ATTR)
        fp = json.loads(text) if text else None
        digest = fingerprint_digest(fp) if fp is not None else "(no fingerprint)"
        groups.setdefault(digest, (fp, []))[1].append(str(ds.attrs.get("seed", "?")))
    if len(groups) < 2:
        return
    fps = [fp for fp, _ in groups.values()]
    diff = sorted({k for a in fps for b in fps if a is not None and b is not None
                   for k in differing_keys(a, b)})
    found = "; ".join(f"seed(s) {', '.join(seeds)} from inputs {digest}"
                      for digest, (_, seeds) in groups.items())
    raise _scene_error(Path(datasets[0].attrs["source_file"]).parent, key,
                       "seeds computed from the same inputs (one scene fingerprint)",
                       f"{len(groups)} fingerprints",
                       found + "; " + ("they differ in: " + ", ".join(diff) + "; " if diff else "")
                       + "run the seeds of the older inputs again (floatmoor run --force with "
                       "the current scene) or put each version's results in its own folder")


def mbs_of(datasets):
    """MBS per line (N): the results' ``mbs`` variable, else the mooring of the scene file named
    in the results' ``scene_file`` attribute."""
    import numpy as np

    from ..post.dnv_os_e301 import require_known_mbs

    ds = datasets[0]
    lines = [str(v) for v in ds["line"].values]
    if "mbs" in ds:
        mbs = np.asarray(ds["mbs"].values, float)
        require_known_mbs(mbs, lines, file=ds.attrs.get("source_file"), key="mbs",
                          detail=(ds["mbs"].attrs.get("unknown", "") + "; then run the seeds "
                                  "again (the results store the MBS of the scene they came "
                                  "from)").lstrip("; "))
        return mbs, "results (mbs variable)"
    scene_file = ds.attrs.get("scene_file")
    if not scene_file or not Path(scene_file).is_file():
        raise _scene_error(ds.attrs.get("source_file"), "mbs",
                           "an 'mbs' variable in the results, or the scene file they name",
                           f"no mbs variable; scene file {scene_file!r} not found")
    from ..io.mooring_section import parse_mooring
    from ..io.scene import load_scene

    scene = load_scene(scene_file)
    if scene.mooring is None:
        raise _scene_error(scene_file, "mooring", "a mooring section (for the MBS)", "none")
    site = scene.site
    ms = parse_mooring(scene.mooring_node(), water_depth=site.water_depth,
                       water_density=site.water_density, gravity=site.gravity)
    names = [str(n) for n in ms.names]
    if names != lines:
        raise _scene_error(scene_file, "mooring", f"the lines of the results {lines}", names)
    ms.require_mbs("the DNV-OS-E301 design report")
    mbs = np.asarray(ms.mbs, float)
    return mbs, f"scene mooring ({scene_file})"


def _read_fd(path, td_scene):
    import xarray as xr


    path = Path(path)
    if not path.is_file():
        raise _scene_error(path, "--fd", "a frequency-domain result file (floatmoor fd --out)",
                           "no such file")
    try:
        with xr.open_dataset(path) as ds:
            fd = ds.load()
    except (OSError, ValueError) as exc:
        raise _scene_error(path, "--fd", "a readable netCDF file",
                           f"{type(exc).__name__}: {exc}") from None
    if "tension_max_total" not in fd:
        raise _scene_error(path, "--fd", "a floatmoor fd result (tension_max_total per line)",
                           "variables " + ", ".join(list(map(str, fd.data_vars))[:8]))
    fd_scene = fd.attrs.get("scene_name")
    if fd_scene and fd_scene != td_scene:
        raise _scene_error(path, "--fd", f"a frequency-domain result of scene {td_scene!r}",
                           f"scene {fd_scene!r}")
    return fd


def _read_fatigue(path):
    """The ``floatmoor fatigue --out`` file (SceneError if it is not one)."""
    import xarray as xr

    from ..post.fatigue_report import check_fatigue_result
    try:
        with xr.open_dataset(path) as ds:
            ds = ds.load()
        check_fatigue_result(ds)
    except (OSError, ValueError) as exc:
        raise _scene_error(path, "--fatigue", "a fatigue result (floatmoor fatigue --out "
                           "FILE.nc)", str(exc)) from None
    return ds


def read_daf(path, lines, scene: str):
    """The DAF per line of a ``floatmoor lines`` output (netCDF, variable ``daf(line)``) or a
    CSV with ``line`` and ``daf`` columns: ``({line: daf}, description)``.  SceneError for a
    file that is not one, a line that is not in the results, a DAF outside (0, 10] or a file
    of another scene."""
    import numpy as np
    path = Path(path)
    if not path.is_file():
        raise _scene_error(path, "--daf", "a DAF file of floatmoor lines (netCDF) or a CSV with "
                           "columns line, daf", "no such file")
    lines = [str(x) for x in lines]
    if path.suffix.lower() == ".csv":
        rows = [r.strip() for r in path.read_text(errors="replace").splitlines() if r.strip()]
        if not rows:
            raise _scene_error(path, "--daf", "a header row with the columns line, daf",
                               "an empty file")
        head = [h.strip().lower() for h in rows[0].split(",")]
        if "line" not in head or "daf" not in head:
            raise _scene_error(path, "--daf", "a header row with the columns line, daf",
                               rows[0][:80])
        il, idf = head.index("line"), head.index("daf")
        names, vals = [], []
        for k, r in enumerate(rows[1:], start=2):
            cells = [c.strip() for c in r.split(",")]
            try:
                names.append(cells[il])
                vals.append(float(cells[idf]))
            except (IndexError, ValueError):
                raise _scene_error(path, f"row {k}", "a line name and a number (daf)",
                                   r[:80]) from None
        where = f"{path} (CSV)"
    else:
        import xarray as xr
        try:
            with xr.open_dataset(path) as ds:
                ds = ds.load()
        except (OSError, ValueError) as exc:
            raise _scene_error(path, "--daf", "a readable netCDF file (floatmoor lines --out)",
                               f"{type(exc).__name__}: {exc}") from None
        if "daf" not in ds or ds["daf"].dims != ("line",):
            raise _scene_error(path, "daf", "a variable daf(line) (floatmoor lines --out)",
                               "variables " + ", ".join(list(map(str, ds.data_vars))[:8]))
        other = ds.attrs.get("scene_name")
        if other is None:
            title = str(ds.attrs.get("title", ""))
            marker = "line analysis of "
            other = title.split(marker, 1)[1].strip() if marker in title else None
        if other and other != scene:
            raise _scene_error(path, "--daf", f"the DAF of scene {scene!r}",
                               f"the DAF of scene {other!r}")
        names = [str(v) for v in ds["line"].values]
        vals = [float(v) for v in ds["daf"].values]
        if "selfcheck" in ds:
            # a DAF whose FE line broke a bound of its self-check is no number to design with
            failed = {str(n): str(c) for n, c in zip(ds["line"].values, ds["selfcheck"].values)
                      if str(c) not in ("ok", "-")}
            if failed:
                raise _scene_error(path, "selfcheck", "finite-element lines whose self-check "
                                   "passed (floatmoor lines prints it)",
                                   "; ".join(f"{n}: {c}" for n, c in failed.items()))
        where = f"{path} (floatmoor lines"
        if ds.attrs.get("driving_motion"):
            where += f", driven by the {ds.attrs['driving_motion']}"
        where += ")"
    unknown = [n for n in names if n not in lines]
    if unknown:
        raise _scene_error(path, "line", f"lines of the results {lines}", unknown)
    out = {}
    for n, v in zip(names, vals):
        if np.isnan(v):
            continue                      # floatmoor lines could not compute it
        if not (0.0 < v <= MAX_DAF):
            raise _scene_error(path, f"daf[{n}]", f"a dynamic amplification factor in (0, "
                               f"{MAX_DAF:g}]", v)
        out[n] = v
    if not out:
        raise _scene_error(path, "daf", "at least one finite DAF", "none")
    return out, where


def report_context(results):
    """The :class:`~floatmoor.post.report.ReportContext` from the scene file the results name
    (None when it is not found: the checks that need the scene are then not made)."""
    from ..io.report_context import scene_context
    from ..io.scene import load_scene
    scene_file = results[0].attrs.get("scene_file")
    if not scene_file or not Path(scene_file).is_file():
        return None, (f"the scene file {scene_file!r} of the results was not found: the "
                      "environment, end-of-life capacity, anchor, offset and fibre-rope "
                      "checks need it")
    scene = load_scene(scene_file)
    return scene_context(scene, results), ""


def run(args: argparse.Namespace) -> int:
    """Run ``floatmoor report``; returns the exit status (0 pass, 1 a check fails)."""
    from ..campaign.store import is_campaign_dir
    from ..cli import UsageError
    from ..post.report import build_report, scene_name
    if is_campaign_dir(args.results_dir):  # a floatmoor campaign folder: the matrix report
        from .campaign import report_campaign
        return report_campaign(args)
    args.consequence_class = 2 if args.consequence_class is None else args.consequence_class
    args.analysis = "auto" if args.analysis is None else args.analysis
    from ..post.design_codes import DEFAULT_CODE, load_code
    if args.code is not None and args.standard is not None:
        raise UsageError("give the design code once: --code (or the old --standard)")
    code = load_code(args.code or DEFAULT_CODE)
    bound_dirs = fibre_bound_dirs(args.results_dir)
    if bound_dirs:  # floatmoor run of a scene with analysis.fibre_stiffness: both
        return report_fibre_bounds(args, bound_dirs)
    if args.failed_line and not args.als_dir:
        raise UsageError("--failed-line names the failed line of the ALS results: give the "
                         "folder of those results with --als-dir (run them with floatmoor run "
                         "on a scene whose mooring lists failed_lines)")
    results, failed = read_results(args.results_dir, "RESULTS_DIR")
    als = als_failed = None
    if args.als_dir:
        als, als_failed = read_results(args.als_dir, "--als-dir")
        lines = [str(v) for v in results[0]["line"].values]
        als_lines = [str(v) for v in als[0]["line"].values]
        if als_lines != lines:
            raise _scene_error(args.als_dir, "--als-dir",
                               f"results of the same mooring (lines {lines})", als_lines)
        if args.failed_line:
            unknown = [n for n in args.failed_line if n not in lines]
            if unknown:
                raise UsageError(f"--failed-line {', '.join(unknown)}: unknown line; lines: "
                                 + ", ".join(lines))
    mbs, mbs_source = mbs_of(results)
    scene = scene_name(results[0])
    fd = _read_fd(args.fd, scene) if args.fd else None
    fatigue = _read_fatigue(args.fatigue) if args.fatigue else None
    daf = daf_source = None
    if args.daf:
        daf, daf_source = read_daf(args.daf, results[0]["line"].values, scene)
    context, context_note = report_context(results)
    out = Path(args.out) if args.out else Path(args.results_dir) / "report"
    extra = [("results folder", str(Path(args.results_dir).resolve())), ("MBS from", mbs_source)]
    if als is not None:
        extra.append(("ALS results folder", f"{Path(args.als_dir).resolve()} (scene "
                      f"{scene_name(als[0])})"))
        if als_failed:
            extra.append(("ALS failed seeds (left out)", "; ".join(als_failed)))
    if fd is not None:
        extra.append(("frequency-domain file", str(Path(args.fd).resolve())))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        if context_note:
            extra.append(("scene", context_note))
        files = build_report(results, mbs, out, als_results=als, failed_lines=args.failed_line,
                             consequence_class=args.consequence_class, analysis=args.analysis,
                             fd=fd, failed_seeds=failed, extra_meta=extra, fatigue=fatigue,
                             code=code, daf=daf, daf_source=daf_source or "",
                             context=context)
    seen = set()
    for w in caught:                       # one line per distinct warning (not one per line)
        key = (w.category, str(w.message))
        if key not in seen:
            seen.add(key)
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    checks = files.checks
    stats = files.statistics
    print(f"scene: {scene}  ({len(results)} seeds from {args.results_dir}"
          + (f"; {len(failed)} failed seed(s) left out: "
             + ", ".join(f.split(":")[0] for f in failed) if failed else "") + ")")
    cc = (f", consequence class {args.consequence_class}" if code.has_classes
          else " (no consequence classes)")
    print(f"{code.name}{cc}; statistics window {stats.attrs['window_start_s']:g} - "
          f"{stats.attrs['window_end_s']:g} s")
    print(f"analysis: {checks.attrs['analysis_summary']}"
          + (" (OVERRIDE)" if int(checks.attrs["analysis_override"]) else "")
          + f" -- {checks.attrs['analysis_reason']}")
    if context_note:
        print(f"note: {context_note}")
    for v in files.verdict:
        print(v.cli())
    if files.unverified:
        print("unverified code values used: " + ", ".join(e.path for e in files.unverified)
              + f" ({code.file.name}; listed in the report)")
    status, sentence = files.overall
    print("verdict: " + sentence + (" (exit status 1)" if status == "FAIL" else ""))
    print(f"report: {files.html}  (also report.md, summary.csv, summary.nc)")
    sys.stdout.flush()
    return EXIT_FAIL if status == "FAIL" else EXIT_PASS


FIBRE_BOUNDS = ("lower", "upper")


def fibre_bound_dirs(folder) -> dict[str, Path]:
    """``{"lower": dir, "upper": dir}`` when ``folder`` holds no result file but the
    ``fibre_lower`` and ``fibre_upper`` sub-folders of ``floatmoor run`` (else empty)."""
    folder = Path(folder)
    if not folder.is_dir() or any(folder.glob("*.nc")):
        return {}
    dirs = {b: folder / f"fibre_{b}" for b in FIBRE_BOUNDS}
    if all(d.is_dir() and any(d.glob("*.nc")) for d in dirs.values()):
        return dirs
    return {}


def report_fibre_bounds(args: argparse.Namespace, dirs: dict[str, Path]) -> int:
    """The report of each fibre stiffness bound and the table of both with the governing one
    (the larger ULS utilisation of any line). Returns the exit status."""
    import numpy as np
    import xarray as xr

    out = Path(args.out) if args.out else Path(args.results_dir) / "report"
    status, util, offset, per_line = {}, {}, {}, {}
    for b, d in dirs.items():
        print(f"== fibre stiffness bound: {b} ==")
        sub = argparse.Namespace(**{**vars(args), "results_dir": str(d),
                                    "out": str(out / f"fibre_{b}")})
        status[b] = run(sub)
        with xr.open_dataset(out / f"fibre_{b}" / "summary.nc") as nc:
            c = nc.sel(limit_state="ULS")
            per_line[b] = dict(zip(map(str, c["line"].values),
                                   np.asarray(c["utilisation"].values, float)))
            util[b] = float(np.nanmax(c["utilisation"].values))
            offset[b] = (float(np.mean(nc["seed_offset_max"].values))
                         if "seed_offset_max" in nc else float("nan"))
    gov = max(FIBRE_BOUNDS, key=lambda b: util[b])
    lines = list(per_line[gov])
    md = ["# Fibre rope stiffness bounds", "",
          "DNV-OS-E301 / API RP 2SM: the mean offset with the static (working-curve) stiffness; "
          "the dynamic response with the lower bound (working-curve tangent) and the upper "
          "bound (storm dynamic stiffness at the mean tension); the governing bound has the "
          "larger ULS utilisation.", "",
          "| bound | max ULS utilisation | mean of seed max offset (m) | verdict | report |",
          "|---|---|---|---|---|"]
    for b in FIBRE_BOUNDS:
        md.append(f"| {b}{' (governing)' if b == gov else ''} | {util[b]:.3f} | "
                  f"{offset[b]:.2f} | {'PASS' if status[b] == EXIT_PASS else 'FAIL'} | "
                  f"fibre_{b}/report.md |")
    md += ["", "| line | " + " | ".join(f"ULS utilisation {b}" for b in FIBRE_BOUNDS) + " |",
           "|---" * (1 + len(FIBRE_BOUNDS)) + "|"]
    for ln in lines:
        md.append(f"| {ln} | " + " | ".join(f"{per_line[b].get(ln, float('nan')):.3f}"
                                          for b in FIBRE_BOUNDS) + " |")
    (out / "fibre_bounds.md").write_text("\n".join(md) + "\n", encoding="utf-8")
    rows = ["line," + ",".join(f"utilisation_{b}" for b in FIBRE_BOUNDS) + ",governing_bound"]
    for ln in lines:
        rows.append(f"{ln}," + ",".join(repr(per_line[b].get(ln, float("nan")))
                                        for b in FIBRE_BOUNDS) + f",{gov}")
    (out / "fibre_bounds.csv").write_text("\n".join(rows) + "\n", encoding="utf-8")
    print("fibre stiffness bounds: " + ", ".join(
        f"{b} max ULS utilisation {util[b]:.3f}, mean max offset {offset[b]:.2f} m"
        for b in FIBRE_BOUNDS) + f"; governing: {gov}")
    print(f"report: {out / 'fibre_bounds.md'} (and fibre_lower/, fibre_upper/)")
    sys.stdout.flush()
    return EXIT_FAIL if any(st != EXIT_PASS for st in status.values()) else EXIT_PASS
