"""The figures the README quotes from a floatmoor run, regenerated (and checked against it).

Each figure is computed here from the shipped scenes by the command the README names, and
compared with the text of ``README.md`` (``--check``: exit status 1 naming the figure when the
README no longer says what the code gives; ``tests/test_readme_figures.py`` runs it).  Figures
that come from long measurements (storm timings, the seeds of coupled FE storms) are not
regenerated here: the README gives the date of their measurement and the section of
``benchmarks/RESULTS.md`` that holds it.

Figures:

* ``lf_surge_std``: the LF surge standard deviation of ``floatmoor fd scenes/floatel_100yr.yaml``
  without and with ``--line-damping fe`` (m, 2 decimals), as in the README's ``fd`` row.

Run:  PYTHONPATH=. python benchmarks/readme_figures.py [--check]
"""

from __future__ import annotations

import argparse
import re
import sys
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"


def lf_surge_std() -> tuple[float, float]:
    """LF surge std (m) of the flagship scene's FD without and with FE line damping."""
    import floatmoor
    scene = ROOT / "scenes" / "floatel_100yr.yaml"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        without = float(floatmoor.frequency_domain(scene)["lf_std"].values[0])
        with_fe = float(floatmoor.frequency_domain(scene, line_damping="fe")["lf_std"]
                        .values[0])
    return without, with_fe


def readme_text(without: float, with_fe: float) -> str:
    """The README's wording of the figure (what ``--check`` looks for)."""
    return f"LF surge std {without:.2f} m without, {with_fe:.2f} m with"


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--check", action="store_true",
                   help="exit status 1 when README.md does not quote the figures computed now")
    a = p.parse_args(argv)
    without, with_fe = lf_surge_std()
    text = readme_text(without, with_fe)
    print(f"lf_surge_std: {text}")
    if a.check:
        readme = README.read_text()
        if text not in readme:
            found = re.search(r"LF surge std [0-9.]+ m without, [0-9.]+ m with", readme)
            print(f"README.md says {found.group(0) if found else 'nothing'!r}; the code gives "
                  f"{text!r}", file=sys.stderr)
            return 1
        print("README.md agrees")
    return 0


if __name__ == "__main__":
    sys.exit(main())
