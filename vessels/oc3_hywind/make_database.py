"""Convert the public OC3-Hywind WAMIT files (Spar.1, Spar.3, Spar.hst) to database.nc.

Source: OpenFAST r-test, glue-codes/openfast/5MW_Baseline/HydroData/Spar.* (public data,
Apache-2.0, copied into source/; see source/README.md).  Redimensionalised with ULEN = 1 m (HydroDyn WAMITULEN), rho = 1025
kg/m^3, g = 9.80665 m/s^2 (the OpenFAST driver values); water depth 320 m (metadata: the WAMIT
run itself used infinite depth in the OC3 definition).

Usage: python make_database.py [folder holding Spar.1, Spar.3, Spar.hst; default source/]
"""

import sys
from pathlib import Path

import numpy as np

from floatmoor.hydro import read_wamit, save_database

here = Path(__file__).resolve().parent
ref = Path(sys.argv[1]) if len(sys.argv) > 1 else here / "source"
ds = read_wamit(ref / "Spar", ulen=1.0, rho=1025.0, g=9.80665, water_depth=320.0)
# WAMIT writes headings -180 and +180: identical data, keep one (-180 .. 170 deg)
keep = ds.wave_direction.values < np.pi - 1e-9
ds = ds.isel(wave_direction=np.nonzero(keep)[0])
ds.attrs["source"] = "WAMIT Spar.1, Spar.3, Spar.hst (OpenFAST r-test 5MW_Baseline/HydroData)"
ds.attrs["displaced_volume"] = 8029.21  # m^3, HydroDyn PtfmVol0
save_database(ds, here / "database.nc")
print("wrote", here / "database.nc", (here / "database.nc").stat().st_size, "bytes")
