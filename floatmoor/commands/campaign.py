"""``floatmoor campaign CAMPAIGN.yaml --out DIR``: a DNV-OS-E301 design campaign.

The frequency domain screens every case of the matrix (sea states x headings x conditions), the
time domain runs the storms of the cases that can govern, on a Dask ``LocalCluster`` of this
machine (default), an existing Dask scheduler (``--scheduler tcp://HOST:8786``) or serially in
one worker process (``--scheduler serial``).  Rerunning the same command resumes: only missing,
failed, half-written, corrupted or stale results (computed from other inputs: an edited
campaign file, contour, base scene or file it reads, another floatmoor) run again, and the run
says which and why.  An --out folder holding another campaign's results is refused unless
``--force``; a folder in use by another campaign or run is refused.  ``--dry-run`` prints the matrix, a wall-time estimate
from a short calibration run and the storage the campaign will need, and runs nothing else.
The campaign file format: :mod:`floatmoor.campaign.spec`.  Report: ``floatmoor report DIR``.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .argtypes import positive_float

HELP = "design campaign: FD screening of every case, TD storms of the governing ones (Dask)"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("campaign", metavar="CAMPAIGN.yaml", help="the campaign file")
    p.add_argument("--out", metavar="DIR", default=None,
                   help="output folder (default results/<campaign name>)")
    p.add_argument("--scheduler", default="local", metavar="local|serial|ADDRESS",
                   help="local: a Dask LocalCluster here (default); serial: one process; "
                        "tcp://HOST:8786: an existing Dask scheduler")
    p.add_argument("--workers", type=int, default=None, metavar="N",
                   help="LocalCluster worker processes (default: the local cores)")
    p.add_argument("--dry-run", action="store_true",
                   help="print the matrix, the estimated wall time and storage; run nothing")
    p.add_argument("--fd-budget", type=positive_float, default=5.0, metavar="S",
                   help="--dry-run: run the FD screening of every case when it is estimated to "
                        "take at most S seconds here, for the exact TD count (default 5)")
    p.add_argument("--seeds", default=None, metavar="LIST",
                   help='replace the campaign\'s seeds, e.g. "1-3" (smoke runs)')
    p.add_argument("--duration", type=positive_float, default=None, metavar="S",
                   help="replace the storm duration (s, smoke runs)")
    p.add_argument("--verify", action="store_true",
                   help="check the SHA-256 of finished files before skipping them on resume")
    p.add_argument("--force", action="store_true",
                   help="reuse an --out folder that holds another campaign's (or other) "
                        "results: results whose inputs match a case of this campaign are "
                        "kept, the others computed again (default: refuse)")


def run(args: argparse.Namespace) -> int:
    import os

    from ..campaign.spec import load_campaign
    from ..cli import EXIT_NUMERICAL_ERROR, EXIT_OK, UsageError
    from ..io.analysis import seeds_from_text

    spec = load_campaign(args.campaign)
    seeds = None
    if args.seeds is not None:
        try:
            seeds = seeds_from_text(args.seeds)
        except ValueError as exc:
            raise UsageError(f"--seeds {args.seeds!r}: {exc}") from None
    if args.workers is not None and args.workers < 1:
        raise UsageError(f"--workers must be >= 1, found {args.workers}")
    overrides = {"duration": args.duration} if args.duration else {}
    workers = args.workers or (1 if args.scheduler == "serial" else len(os.sched_getaffinity(0)))
    print(f"campaign: {spec.name}  [{spec.file}]")
    if args.dry_run:
        from ..campaign.estimate import estimate, format_estimate
        print(format_estimate(estimate(spec, workers=workers, seeds=seeds, overrides=overrides,
                                        fd_budget=args.fd_budget)))
        return EXIT_OK
    from ..campaign.engine import run_campaign
    out = Path(args.out) if args.out else Path("results") / spec.name
    r = run_campaign(spec, out, scheduler=args.scheduler, workers=args.workers,
                     seeds=seeds, analysis_overrides=overrides, verify=args.verify,
                     echo=lambda s: print(s, flush=True), force=args.force)
    ran = ", ".join(f"{k} {v}" for k, v in r.ran.items()) or "nothing"
    skipped = ", ".join(f"{k} {v}" for k, v in r.skipped.items() if v) or "none"
    print(f"{r.n_cases} case(s), {r.n_td_cases} in the time domain; ran: {ran}; already done: "
          f"{skipped}; {len(r.failed)} failed; wall time {r.wall_time:.1f} s "
          f"(tasks {r.task_time:.1f} s)")
    print(f"results: {out}  (manifest.csv; report: floatmoor report {out})")
    if r.failed:
        for kind, case, seed, err in r.failed[:20]:
            print(f"floatmoor: error: {kind} {case}" + (f" seed {seed}" if seed >= 0 else "")
                  + f": {err}", file=sys.stderr)
        return EXIT_NUMERICAL_ERROR
    return EXIT_OK


def report_campaign(args: argparse.Namespace) -> int:
    """``floatmoor report DIR`` on a campaign folder (called by :mod:`.report`): the report
    across the matrix and its verdict; exit status 1 when a check fails, else 0.  ``--code``,
    ``--consequence-class`` and ``--analysis``, when given, override the campaign's (the report
    says so); not given, the campaign's apply."""
    from ..campaign.report import write_report
    from ..cli import UsageError
    code = getattr(args, "code", None)
    if getattr(args, "standard", None):
        if code is not None:
            raise UsageError("give the design code once: --code (or the old --standard)")
        code = "dnv-os-e301-2008"
    if getattr(args, "daf", None):
        raise UsageError("--daf is for the report of one scene's seeds; a campaign's analysis "
                         "type follows its line model (or the campaign file's design: "
                         "analysis)")
    a = write_report(args.results_dir, args.out,
                     consequence_class=getattr(args, "consequence_class", None),
                     analysis=getattr(args, "analysis", None), code=code)
    for line in a["summary_lines"]:
        print(line)
    print("governing case per line and limit state:")
    for g in a["governing"]:
        print(f"  {g['limit_state']} {g['line']:>8s}: {g['case']}  utilisation "
              f"{g['utilisation']:.3f} {'PASS' if g['passed'] else 'FAIL'}")
    for v in a["verdict"]:
        print(v.cli())
    status, sentence = a["overall"]
    print("verdict: " + sentence + (" (exit status 1)" if status != "PASS" else ""))
    rd = a["report_dir"]
    print(f"report: {rd / 'report.html'}  (also report.md, governing.csv, td_cases.csv, "
          "summary.nc)")
    return 0 if status == "PASS" else 1

