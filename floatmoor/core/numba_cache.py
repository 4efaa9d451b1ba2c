"""Where numba keeps floatmoor's compiled kernels: one folder per version of the kernel sources.

numba's own cache decides that a cached function is stale from the time stamp of the function's
own source file only.  floatmoor's kernels inline and call kernels of other files (the time loop
compiles the mooring, force and FE kernels into itself), so after an update that changes, say,
``mooring/fe/kernels.py`` but not ``solvers/fe_coupling.py``, numba would load the coupled
kernel compiled from the old FE code: silently wrong or stale results (this happened while
developing; a fresh clone is not affected, but ``git pull`` into an editable install is).

:func:`configure` therefore points numba's cache at a folder named after a hash of the content
of every floatmoor source file that uses numba: any change to any kernel source gives a new
folder and a clean compile of everything (once), and unchanged sources reuse their folder.
The folder is ``<root>/floatmoor-<hash>``, ``<root>`` being, in this order: the user's
``NUMBA_CACHE_DIR`` if set, the package's own ``__pycache__/numba`` if writable, else
``$XDG_CACHE_HOME/floatmoor`` (``~/.cache/floatmoor``).  When a new folder is made, all but the
two most recent older ``floatmoor-*`` folders of the root are removed.

The setting is numba's process-wide one (``NUMBA_CACHE_DIR``, inherited by child processes
such as Dask workers), so numba functions of other packages used in the same process cache
under the same folder; numba keeps their files apart by source path.

It must run before numba reads its configuration or any floatmoor kernel is decorated, i.e.
from ``floatmoor/__init__.py``; it does not import numba (``import floatmoor`` stays light)
unless numba was already imported, in which case its configuration is updated directly.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import sys
from pathlib import Path

__all__ = ["configure", "source_tag"]

PREFIX = "floatmoor-"
KEEP_OLD = 2


def source_tag(package_dir: Path | None = None) -> str:
    """Hash (12 hex digits) of the relative path and content of every ``.py`` file of the
    package that mentions numba."""
    pkg = Path(package_dir) if package_dir is not None else Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    for p in sorted(pkg.rglob("*.py")):
        data = p.read_bytes()
        if b"numba" in data:
            h.update(p.relative_to(pkg).as_posix().encode())
            h.update(b"\0")
            h.update(data)
    return h.hexdigest()[:12]


def _writable(d: Path) -> bool:
    try:
        d.mkdir(parents=True, exist_ok=True)
    except OSError:
        return False
    return os.access(d, os.W_OK)


def _prune(root: Path, keep: Path) -> None:
    old = [p for p in root.glob(PREFIX + "*") if p.is_dir() and p != keep]
    old.sort(key=lambda p: p.stat().st_mtime, reverse=True)
    for p in old[KEEP_OLD:]:
        shutil.rmtree(p, ignore_errors=True)


def configure(package_dir: Path | None = None) -> str:
    """Set numba's cache folder for this version of the kernel sources (of ``package_dir``,
    default floatmoor's); returns it."""
    pkg = Path(package_dir) if package_dir is not None else Path(__file__).resolve().parents[1]
    tag = source_tag(pkg)
    current = os.environ.get("NUMBA_CACHE_DIR", "")
    if current and Path(current).name == PREFIX + tag:
        folder = Path(current)  # set by the parent process (e.g. a Dask or multiprocessing worker)
    else:
        if current:
            root = Path(current)
        else:
            root = pkg / "__pycache__" / "numba"
            if not _writable(root):
                xdg = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"),
                                                                       ".cache")
                root = Path(xdg) / "floatmoor"
        folder = root / (PREFIX + tag)
        new = not folder.exists()
        if _writable(folder) and new:
            _prune(root, folder)
    os.environ["NUMBA_CACHE_DIR"] = str(folder)
    numba_config = sys.modules.get("numba.core.config")
    if numba_config is not None:
        numba_config.CACHE_DIR = str(folder)
    return str(folder)
