"""The keys of the OpenFAST input files floatmoor reads, in their order, for every version from
OpenFAST 2.0 to 5.0.

Taken from the readers of the OpenFAST source at the release tags v2.0.0, v2.6.0, v3.0.0,
v3.2.0, v3.5.5, v4.0.0, v4.2.1 and v5.0.0 (``ElastoDyn_IO.f90: ReadPrimaryFile``,
``HydroDyn_Input.f90``, ``SeaState_Input.f90``, ``FAST_Subs.f90: FAST_ReadPrimaryFile``):
a key that some versions lack is ``optional``; ``aliases`` are the other names the files of
those versions (or the public models written for them) give the key.  Version notes:

* driver (``.fst``): ``Gravity``, ``WtrDens``, ``WtrDpth``... from v3.1 (before: ElastoDyn
  ``Gravity``, HydroDyn ``WtrDens``/``WtrDpth``); ``CompSeaSt`` and ``SeaStFile`` from v4.0;
  ``ModCoupling``, ``NRotors``, ``CompSoil``, ``SoilFile``... from v5.0.
* ElastoDyn: ``Gravity`` up to v3.0; ``PtfmXYIner``/``PtfmYZIner``/``PtfmXZIner`` and the
  yaw-friction block from v4.0; ``PitchDOF``, ``PtfmRefxt``/``PtfmRefyt``, ``PBrIner``,
  ``BlPIner``, ``HubIner_Teeter`` from v5.0; the blade files written ``BldFile1`` by the
  IEA Wind reference models.
* HydroDyn: waves and current up to v3.5 (then in SeaState); ``NBody``, ``PtfmRefxt``... from
  v2.6; ``PotFile`` before ``WAMITULEN`` (v2.0: before ``RdtnMod``); ``AddF0`` one row of six
  (v2.0) or six rows; ``ExctnDisp``... from v4.0; ``NAddDOF`` and rectangular members from v5.0.
"""

from __future__ import annotations

from .reader import Key


def _k(names: str, optional: bool = False):
    return [Key(name=n, optional=optional) for n in names.split()]


def _indexed(base: str, n: int = 3, optional: bool = False):
    return [Key(name=f"{base}({i})", optional=optional) for i in range(1, n + 1)]


FST = (
    _k("Echo AbortLevel TMax DT") + _k("ModCoupling", True) + _k("InterpOrder NumCrctn")
    + _k("RhoInf ConvTol MaxConvIter", True) + _k("DT_UJac UJacSclFact")
    + _k("NRotors", True) + _k("CompElast CompInflow CompAero CompServo")
    + _k("CompSeaSt", True) + _k("CompHydro CompSub CompMooring CompIce")
    + _k("CompSoil MHK MirrorRotor", True)
    + _k("Gravity AirDens WtrDens KinVisc SpdSound Patm Pvap WtrDpth MSL2SWL", True)
    + _k("EDFile") + _indexed("BDBldFile") + _k("InflowFile AeroFile")
    + [Key(name="ServoFile", aliases=("ServoFile(1)",))] + _k("SeaStFile", True)
    + _k("HydroFile SubFile MooringFile IceFile") + _k("SoilFile", True)
)
"""The driver file up to its input-file names."""

ELASTODYN = (
    _k("Echo Method DT") + _k("Gravity", True)
    + _k("FlapDOF1 FlapDOF2 EdgeDOF") + _k("PitchDOF", True)
    + _k("TeetDOF DrTrDOF GenDOF YawDOF TwFADOF1 TwFADOF2 TwSSDOF1 TwSSDOF2 PtfmSgDOF "
         "PtfmSwDOF PtfmHvDOF PtfmRDOF PtfmPDOF PtfmYDOF OoPDefl IPDefl")
    + _indexed("BlPitch")
    + _k("TeetDefl Azimuth RotSpeed NacYaw TTDspFA TTDspSS PtfmSurge PtfmSway PtfmHeave "
         "PtfmRoll PtfmPitch PtfmYaw NumBl TipRad HubRad")
    + _indexed("PreCone")
    + _k("HubCM UndSling Delta3 AzimB1Up OverHang ShftGagL ShftTilt NacCMxn NacCMyn NacCMzn "
         "NcIMUxn NcIMUyn NcIMUzn Twr2Shft TowerHt TowerBsHt PtfmCMxt PtfmCMyt PtfmCMzt")
    + _k("PtfmRefxt PtfmRefyt", True) + _k("PtfmRefzt")
    + _indexed("TipMass") + _indexed("PBrIner", optional=True)
    + _indexed("BlPIner", optional=True)
    + _k("HubMass HubIner") + _k("HubIner_Teeter", True)
    + _k("GenIner NacMass NacYIner YawBrMass PtfmMass PtfmRIner PtfmPIner PtfmYIner")
    + _k("PtfmXYIner PtfmYZIner PtfmXZIner", True)
    + _k("BldNodes") + _indexed("BldFile")
    + _k("TeetMod TeetDmpP TeetDmp TeetCDmp TeetSStP TeetHStP TeetSSSp TeetHSSp")
    + _k("YawFrctMod M_CSmax M_FCSmax M_MCSmax M_CD M_FCD M_MCD sig_v sig_v2 OmgCut", True)
    + _k("GBoxEff GBRatio DTTorSpr DTTorDmp Furling FurlFile TwrNodes TwrFile")
)
"""The ElastoDyn primary file up to ``TwrFile``."""

ELASTODYN_TOWER = _k("NTwInpSt TwrFADmp(1) TwrFADmp(2) TwrSSDmp(1) TwrSSDmp(2) "
                     "FAStTunr(1) FAStTunr(2) SSStTunr(1) SSStTunr(2) AdjTwMa AdjFASt AdjSSSt")
"""The tower file up to its adjustment factors (the distributed properties follow)."""

ELASTODYN_BLADE = _k("NBlInpSt BldFlDmp(1) BldFlDmp(2) BldEdDmp(1) FlStTunr(1) FlStTunr(2) "
                     "AdjBlMs AdjFlSt AdjEdSt")
"""The blade file up to its adjustment factors."""

_WAVES = (
    _k("WaveMod WaveStMod") + _k("WvCrntMod", True)
    + _k("WaveTMax WaveDT WaveHs WaveTp WavePkShp WvLowCOff WvHiCOff WaveDir WaveDirMod "
         "WaveDirSpread WaveNDir WaveDirRange")
    + _indexed("WaveSeed", 2) + _k("WaveNDAmp WvKinFile")
    + [Key(name="WvDiffQTF", aliases=("WvDiffQTFF",), optional=True),
       Key(name="WvSumQTF", aliases=("WvSumQTFF",), optional=True)]
    + _k("WvLowCOffD WvHiCOffD WvLowCOffS WvHiCOffS", True)
    + _k("ConstWaveMod CrestHmax CrestTime CrestXi CrestYi", True)
    + _k("CurrMod CurrSSV0")
    + [Key(name="CurrSSDir", aliases=("CurrSSDirChr",))]
    + _k("CurrNSRef CurrNSV0 CurrNSDir CurrDIV CurrDIDir")
)

SEASTATE = (
    _k("Echo WtrDens WtrDpth MSL2SWL")
    + _k("X_HalfWidth Y_HalfWidth Z_Depth NX NY NZ", True)
    + _WAVES
)
"""The SeaState file (OpenFAST v4 and later) up to its current."""

HYDRODYN = (
    _k("Echo") + _k("WtrDens WtrDpth MSL2SWL", True)
    + [Key(name=k.name, aliases=k.aliases, optional=True) for k in _WAVES]
    + _k("PotMod")
    + _k("ExctnMod ExctnDisp ExctnCutOff PtfmYMod PtfmRefY PtfmYCutOff NExctnHdg RdtnMod "
         "RdtnTMax RdtnDT NBody NBodyMod", True)
    + _k("PotFile WAMITULEN")
    + _k("PtfmRefxt PtfmRefyt PtfmRefzt PtfmRefztRot", True)
    + _k("PtfmVol0 PtfmCOBxt PtfmCOByt") + _k("NAddDOF", True)
    + _k("MnDrift NewmanApp DiffQTF SumQTF", True)
    + _k("PtfmSgF PtfmSwF PtfmHvF PtfmRF PtfmPF PtfmYF", True)
    + _k("AddF0 AddCLin AddBLin AddBQuad")
    + _k("WaveDisp AMMod HstMod", True)
    + _k("NAxCoef NJoints") + [Key(name="NPropSets", aliases=("NPropSetsCyl",))]
    + _k("NPropSetsRec", True)
    + [Key(name="NCoefDpth", aliases=("NCoefDpthCyl",))] + _k("NCoefDpthRec", True)
    + [Key(name="NCoefMembers", aliases=("NCoefMembersCyl",))] + _k("NCoefMembersRec", True)
    + _k("NMembers NFillGroups NMGDepths NMOutputs NJOutputs")
)
"""The HydroDyn file (waves in it up to v3.5) up to its output lists."""
