"""Do the line kernel's flat passes (``mooring/fe/flat.py``) run as SIMD?  Compiles them afresh
(a temporary numba cache: the assembly of a kernel loaded from the cache cannot be read) by
running the OC3 line (40 elements) for a few steps of a harmonic fairlead motion, then counts
in the assembly of every compiled version of every pass the packed double-precision
instructions on 256-bit registers (``v...pd`` on ``ymm``: four elements or nodes at once)
against the scalar ones (``v...sd``: the loops' remainders and the end nodes).

A pass without packed instructions runs element by element: in this code that happened when a
helper function returned the element law (even inlined by numba), and when a loaded value was
selected against a constant (``x if c else 0.0``); see the comment above
``flat.element_pass``.

Run: ``python benchmarks/check_flat_asm.py`` (about a minute).  Needs an x86-64 CPU with AVX2
for packed 256-bit instructions; the CPU name numba compiles for is printed.
"""

from __future__ import annotations

import os
import re
import sys
import tempfile
import warnings
from pathlib import Path

os.environ["NUMBA_CACHE_DIR"] = tempfile.mkdtemp(prefix="fm_asm_")   # before numba loads

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

PASSES = ("element_geometry_flat", "element_pass", "element_pass_jac", "block_sums", "node_sums",
          "fluid_pass", "fluid_pass_jac")


def counts(asm: str) -> tuple[int, int]:
    packed = len(re.findall(r"\tv\w+pd\t[^\n]*ymm", asm))
    scalar = len(re.findall(r"\tv\w+sd\t", asm))
    return packed, scalar


def main() -> None:
    warnings.simplefilter("ignore")
    import llvmlite.binding as llvm

    from floatmoor.mooring.fe import FELine, FELineSpec, FESegment, Friction, Seabed, flat
    from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed
    from floatmoor.mooring.line_types import LineType

    print(f"numba compiles for {llvm.get_host_cpu_name()}", flush=True)
    # the OC3-Hywind line 1 (Jonkman 2010; as tests/mooring/fe/conftest.py)
    d = 0.09
    lt = LineType(name="oc3", material="user", diameter=d, mass_per_length=77.7066,
                  displaced_volume=3.141592653589793 * d * d / 4, ea=384.243e6,
                  ea_dynamic=384.243e6, mbs=6.0e6, cdn=1.6, cdt=0.1 * 3.141592653589793,
                  can=1.0, cat=0.0)
    spec = FELineSpec(name="oc3", anchor=(853.87, 0.0, -320.0), fairlead=(5.2, 0.0, -70.0),
                      segments=(FESegment(line_type=lt, length=902.2, n_elements=40,
                                          internal_damping=-0.8),),
                      seabed=Seabed(depth=320.0), friction=Friction())
    line = FELine(spec)
    line.solve_static()
    line.start()
    print("compiling the line kernels (about a minute) ...", flush=True)
    run_prescribed(line, HarmonicMotion(amplitude=(-1.0, 0.0, 0.0), period=10.0), 2.0, 0.1)
    print(f"{'pass':28s} {'versions':>8s} {'packed ymm':>10s} {'scalar':>7s}")
    bad = []
    for name in PASSES:
        fn = getattr(flat, name)
        sigs = list(fn.signatures)
        pk = sc = 0
        for sig in sigs:
            p, s = counts(fn.inspect_asm(sig))
            pk += p
            sc += s
        flag = "" if pk > 0 else "   <- not vectorised"
        if pk == 0:
            bad.append(name)
        print(f"{name:28s} {len(sigs):8d} {pk:10d} {sc:7d}{flag}")
    print("every flat pass has packed 256-bit instructions" if not bad
          else f"passes without packed 256-bit instructions: {', '.join(bad)}")


if __name__ == "__main__":
    main()
