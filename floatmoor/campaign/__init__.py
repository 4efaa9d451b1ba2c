"""Design campaigns: many cases (sea states x headings x mooring conditions), screened in the
frequency domain, the governing ones in the time domain, on one machine or a Dask cluster.

Modules (each small, in the order of the work):

* :mod:`.spec` -- the campaign file (YAML, validated; every mistake a SceneError);
* :mod:`.matrix` -- the cases and the scene of one case derived from the base scene;
* :mod:`.tasks` -- pure task functions (FD of a batch of cases, one TD storm) writing their own
  compressed netCDF result files;
* :mod:`.screening` -- DNV-OS-E301 utilisation of a case (FD and TD) and the screening rule;
* :mod:`.store` -- the campaign folder: manifest, record, loading results;
* :mod:`.engine` -- serial or Dask execution, resume, progress;
* :mod:`.estimate` -- the dry run: matrix, calibration, wall time and storage;
* :mod:`.seedconv` -- confidence interval of the characteristic tension from the seeds;
* :mod:`.report` -- the report across the matrix;
* :mod:`._api` -- the only place that calls the rest of floatmoor (scene loading and building,
  the two solvers).

Command line: ``floatmoor campaign`` (:mod:`floatmoor.commands.campaign`) and ``floatmoor
report DIR`` on a campaign folder.
"""
