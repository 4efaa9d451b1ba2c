"""numba's cache folder keyed by the kernel sources (floatmoor.core.numba_cache).

The hazard it removes is numba's own: a cached caller is reused when only the file of a callee
it compiled in (inlined) has changed, so the caller runs the old callee.  The subprocess test
shows the hazard with numba's default cache and its absence with :func:`configure`.
"""

import os
import subprocess
import sys
import textwrap
from pathlib import Path

from floatmoor.core import numba_cache
from floatmoor.core.numba_cache import PREFIX, configure, source_tag


def _package(root: Path, value: int) -> Path:
    pkg = root / "kpkg"
    pkg.mkdir(exist_ok=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "callee.py").write_text(textwrap.dedent(f"""
        from numba import njit

        @njit(cache=True, inline="always")
        def f():
            return {value}
    """))
    caller = pkg / "caller.py"
    if not caller.exists():
        caller.write_text(textwrap.dedent("""
            from numba import njit
            from .callee import f

            @njit(cache=True)
            def g():
                return f() + 0
        """))
    (pkg / "notes.py").write_text("# no kernels here\n")
    return pkg


def _run(root: Path, keyed: bool, env_cache: str | None) -> int:
    pkg = str(root / "kpkg")
    code = (f"import sys; sys.path.insert(0, {str(root)!r})\n"
            + (f"from floatmoor.core.numba_cache import configure; configure({pkg!r})\n"
               if keyed else "")
            + "from kpkg.caller import g; print(g())")
    env = dict(os.environ)
    env.pop("NUMBA_CACHE_DIR", None)
    env.pop("NUMBA_DISABLE_JIT", None)
    if env_cache:
        env["NUMBA_CACHE_DIR"] = env_cache
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                         timeout=300, check=True)
    return int(out.stdout.strip().splitlines()[-1])


def test_tag_follows_kernel_sources_only(tmp_path):
    pkg = _package(tmp_path, 1)
    t1 = source_tag(pkg)
    (pkg / "notes.py").write_text("# edited, still no kernels\n")
    assert source_tag(pkg) == t1
    _package(tmp_path, 2)
    assert source_tag(pkg) != t1


def test_folder_under_the_users_root_and_stable_in_child_processes(tmp_path, monkeypatch):
    pkg = _package(tmp_path, 1)
    root = tmp_path / "cache"
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(root))
    folder = configure(pkg)
    assert Path(folder) == root / (PREFIX + source_tag(pkg))
    assert os.environ["NUMBA_CACHE_DIR"] == folder
    # a child process inherits the folder, not a folder inside it
    assert configure(pkg) == folder


def test_old_folders_pruned_to_two(tmp_path, monkeypatch):
    pkg = _package(tmp_path, 1)
    root = tmp_path / "cache"
    for i in range(4):
        d = root / f"{PREFIX}old{i}"
        d.mkdir(parents=True)
        os.utime(d, (1000 + i, 1000 + i))
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(root))
    folder = configure(pkg)
    left = sorted(p.name for p in root.iterdir())
    assert left == sorted([Path(folder).name, f"{PREFIX}old3", f"{PREFIX}old2"])
    assert numba_cache.KEEP_OLD == 2


def test_edited_inlined_callee_recompiles_its_caller(tmp_path):
    """numba's default cache (in-tree ``__pycache__``): after the callee's file changes, the
    caller's cache is still taken as fresh and the old callee runs (1 instead of 2).  With the
    folder keyed by the sources the caller is compiled again and returns the new value."""
    plain = tmp_path / "plain"
    plain.mkdir()
    _package(plain, 1)
    assert _run(plain, keyed=False, env_cache=None) == 1
    _package(plain, 2)
    assert _run(plain, keyed=False, env_cache=None) == 1  # numba's hazard, shown

    keyed = tmp_path / "keyed"
    keyed.mkdir()
    _package(keyed, 1)
    cache = str(tmp_path / "keyed_cache")
    assert _run(keyed, keyed=True, env_cache=cache) == 1
    _package(keyed, 2)
    assert _run(keyed, keyed=True, env_cache=cache) == 2
    assert _run(keyed, keyed=True, env_cache=cache) == 2  # and from its own cache
