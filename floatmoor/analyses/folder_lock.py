"""One writer per results folder, and the disk-full and worker-lifetime guards of the writers.

:func:`folder_lock` is held by ``floatmoor run`` (:func:`floatmoor.run_seeds`) and ``floatmoor
campaign`` for as long as they write into a folder: a second run into the same folder is
refused at once, naming the process that holds it (two runs into one folder used to compute
the same seeds at once and lose one of them).  The lock is an advisory ``flock`` on
``DIR/.floatmoor.lock``: the operating system releases it when its process ends, however it
ends (a killed run leaves no stale lock), and the file keeps the holder's process id, command
and start time for the message.  Worker processes forked while it is held close their copy
(:func:`release_inherited`), so that only the process that took it holds it.  On systems
without ``fcntl`` (Windows) there is no lock.

:func:`check_free_space` and :func:`disk_full_error` report a full disk as such: the netCDF
library answers a write to a full disk with "NetCDF: HDF error", which says nothing of the
cause.
"""

from __future__ import annotations

import contextlib
import errno
import os
import shutil
import time
from pathlib import Path

from ..core.errors import SceneError

__all__ = ["LOCK_NAME", "DiskFull", "check_free_space", "disk_full_error", "die_with_parent",
           "folder_lock", "release_inherited", "temp_name"]

LOCK_NAME = ".floatmoor.lock"
"""The lock file in a results folder."""

_HELD: dict[str, int] = {}   # folder -> file descriptor of the lock this process holds


class DiskFull(OSError):
    """A result could not be written: no space left on the device.  ``filename`` is the
    folder; ``strerror`` says how much is free, what was kept and how to resume."""

    def __init__(self, folder, message: str):
        super().__init__(errno.ENOSPC, message, os.fspath(folder))


def temp_name(path) -> Path:
    """The temporary file a result is written to before it is renamed to ``path``: unique
    per process (``<name>.<pid>.tmp``), so that a worker left over from a killed run never
    writes into the file of the run that resumes it."""
    p = Path(path)
    return p.with_name(f"{p.name}.{os.getpid()}.tmp")


def _describe_holder(path: Path) -> str:
    try:
        text = path.read_text().strip()
    except OSError:
        text = ""
    return text or "another process"


@contextlib.contextmanager
def folder_lock(folder, command: str):
    """Hold the lock of ``folder`` (created) for the block; a SceneError naming the folder
    and the process that holds it when another process does."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    key = os.fspath(folder.resolve())
    if key in _HELD:  # this process holds it already (a batch inside a command)
        yield
        return
    try:
        import fcntl
    except ImportError:  # pragma: no cover - not POSIX: no lock
        yield
        return
    path = folder / LOCK_NAME
    fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        os.close(fd)
        raise SceneError(folder, "", "an output folder that no other floatmoor process is "
                         "writing into", f"in use by {_describe_holder(path)}",
                         "two runs into one folder would compute the same results at once; "
                         "wait for that one to finish (then the same command resumes), or "
                         "give another --out folder") from None
    stamp = time.strftime("%Y-%m-%d %H:%M:%S")
    os.ftruncate(fd, 0)
    os.write(fd, f"pid {os.getpid()} ({command}, since {stamp})\n".encode())
    _HELD[key] = fd
    try:
        yield
    finally:
        _HELD.pop(key, None)
        with contextlib.suppress(OSError):
            os.ftruncate(fd, 0)
        os.close(fd)  # releases the lock


def release_inherited() -> None:
    """In a forked worker process: close the locks inherited from the parent (the parent
    alone holds them; a worker outliving a killed parent must not keep its folder locked)."""
    for key in list(_HELD):
        with contextlib.suppress(OSError):
            os.close(_HELD.pop(key))


def die_with_parent() -> None:
    """In a worker process (Linux): be killed when the parent process dies, so that no
    worker of a killed run goes on computing and writing beside the run that resumes it."""
    try:
        import ctypes
        import signal
        libc = ctypes.CDLL("libc.so.6", use_errno=True)
        libc.prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):  # pragma: no cover - not Linux
        pass


MIN_FREE = 1 << 20
"""Free bytes below which a failed write is taken for a full disk."""


def free_bytes(folder) -> int:
    try:
        return shutil.disk_usage(folder).free
    except OSError:
        return -1


def _mb(n: float) -> str:
    return f"{n / 1e6:.3g} MB"


def check_free_space(folder, need: int, what: str) -> None:
    """:class:`DiskFull` before writing ``need`` bytes of ``what`` into ``folder`` when less
    is free."""
    free = free_bytes(folder)
    if 0 <= free < need:
        raise DiskFull(folder, f"no space left on the device for {what} ({_mb(need)} needed, "
                       f"{_mb(free)} free)")


def disk_full_error(exc: BaseException, folder, need: int, what: str) -> DiskFull | None:
    """The :class:`DiskFull` that explains the write error ``exc`` (ENOSPC, or the netCDF
    library's error with less than ``max(need, MIN_FREE)`` bytes free), else None."""
    if isinstance(exc, DiskFull):
        return exc
    free = free_bytes(folder)
    full = (isinstance(exc, OSError) and exc.errno in (errno.ENOSPC, errno.EDQUOT)) or (
        0 <= free < max(int(need), MIN_FREE))
    if not full:
        return None
    return DiskFull(folder, f"no space left on the device writing {what} ({_mb(free)} free, "
                    f"about {_mb(need)} needed): {type(exc).__name__}: {exc}")
