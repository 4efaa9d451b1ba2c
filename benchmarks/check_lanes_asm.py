"""Do the FE lanes' passes run as SIMD?  Compiles the lane kernels afresh (a temporary numba
cache: the assembly of a kernel loaded from the cache cannot be read), advances the 12 lines of
the coupled FE flagship (scenes/floatel_100yr_fe.yaml) as lanes for a few steps of a small
surge oscillation, then counts in the assembly of every compiled version of every pass the
packed double-precision instructions on 256-bit registers (``v...pd`` on ``ymm``: four lanes at
once) against the scalar ones (``v...sd``: one lane; they include the loops' remainders, which
do not run for four lanes).

A pass whose lane loop vectorises shows packed instructions; one with none runs lane by lane
(what the lanes kernels did before 2026-11-27: LLVM's loop vectoriser took the loop over the
nodes, two per 128-bit register, and numba leaves the SLP vectoriser off; see
``lanes.lanes_in``).  The passes that run lane by lane by design (friction, fibre law, bending,
the current profile lookup) are listed as such.

Run: ``python benchmarks/check_lanes_asm.py`` (about 4 minutes: every FE kernel is compiled).
Needs an x86-64 CPU with AVX2 for packed 256-bit instructions; the CPU name numba compiles for
is printed.
"""

from __future__ import annotations

import os
import re
import sys
import tempfile
import warnings
from pathlib import Path

os.environ["NUMBA_CACHE_DIR"] = tempfile.mkdtemp(prefix="fm_asm_")   # before numba loads

import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

PASSES = {
    "lanes_forces": ("geometry", "tangents", "mass_blocks", "axial_law", "element_forces",
                     "fluid_forces", "seabed_contact", "current_lookup"),
    "lanes_step": ("predict", "kinematics", "residual", "correct", "force_scales"),
    "lanes_blocks": ("tridiag_solve", "tridiag_resolve"),
    "lanes_advance": ("energy", "masked_copy"),
}
BY_LANE = {"lanes_forces": ("current_fix", "friction", "fibre_law", "bending")}


def counts(asm: str) -> tuple[int, int]:
    packed = len(re.findall(r"\tv\w+pd\t[^\n]*ymm", asm))
    scalar = len(re.findall(r"\tv\w+sd\t", asm))
    return packed, scalar


def main() -> None:
    warnings.simplefilter("ignore")
    import importlib

    import bench_fe_lanes as B
    import llvmlite.binding as llvm

    from floatmoor.io.build import build
    from floatmoor.io.scene import load_scene
    from floatmoor.mooring.fe.lanes import LW, build_group
    from floatmoor.mooring.fe.line import FELine

    print(f"numba compiles for {llvm.get_host_cpu_name()}; lanes per block {LW}", flush=True)
    built = build(load_scene(B.FE))
    dt = 0.1
    steps = 20
    x0 = np.zeros(6)
    t = dt * np.arange(steps + 1)
    poses = np.zeros((steps + 1, 6))
    vel = np.zeros((steps + 1, 6))
    poses[:] = x0
    poses[:, 0] += 0.5 * np.sin(2 * np.pi * t / 10.0)
    vel[:, 0] = 0.5 * 2 * np.pi / 10.0 * np.cos(2 * np.pi * t / 10.0)
    print("compiling the lane kernels (a few minutes) ...", flush=True)
    fe, fm, body, lines = B._setup(built, poses[0].copy(), dt)
    bl = [ln.bundle for ln in fm.lines]
    g = build_group([b.par for b in bl], [b.now for b in bl])
    n = bl[0].now.r.shape[0]
    on = np.zeros(g.work.status.shape[0], dtype=np.bool_)
    on[:len(bl)] = True
    fair = np.zeros((steps, len(bl), 3))
    st = B._lanes_steps(poses, vel, dt, fe.substeps, FELine.MAX_SPLIT, body, g, n, on, fair)
    if st:
        raise RuntimeError(f"lane replay failed at step {st}")
    print(f"{'pass':32s} {'versions':>8s} {'packed ymm':>10s} {'scalar':>7s}")
    bad = []
    for modname, names in PASSES.items():
        mod = importlib.import_module(f"floatmoor.mooring.fe.{modname}")
        for name in names:
            fn = getattr(mod, name)
            sigs = list(fn.signatures)
            pk = sc = 0
            for sig in sigs:
                p, s = counts(fn.inspect_asm(sig))
                pk += p
                sc += s
            flag = "" if pk > 0 else "   <- not vectorised"
            if sigs and pk == 0:
                bad.append(f"{modname}.{name}")
            print(f"{modname + '.' + name:32s} {len(sigs):8d} {pk:10d} {sc:7d}{flag}")
    for modname, names in BY_LANE.items():
        print(f"lane by lane by design: {', '.join(modname + '.' + x for x in names)}")
    print("every vectorised pass has packed 256-bit instructions" if not bad
          else f"passes without packed 256-bit instructions: {', '.join(bad)}")


if __name__ == "__main__":
    main()
