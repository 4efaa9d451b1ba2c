"""Scene-level analyses: the user API behind :mod:`floatmoor`'s plain functions.

* :mod:`.statics`: static equilibrium and restoring curves of a scene
  (``floatmoor.equilibrium``, ``floatmoor.restoring_curves``);
* :mod:`.simulate`: one time-domain realisation (``floatmoor.simulate``), its Dataset built
  from the variable table of :mod:`.td_dataset`;
* :mod:`.runner`: many seeds in parallel, resumable (``floatmoor.run_seeds``);
* :mod:`.frequency_domain`: the frequency-domain analysis (``floatmoor.frequency_domain``),
  computed into an :class:`~.fd_result.FDResult` (``floatmoor.frequency_domain_result``) and
  turned into a Dataset by :mod:`.fd_dataset` (one table of variables with units; also the
  text table ``floatmoor.format_fd_table``); its helpers: :mod:`.fd_loads` (rotations,
  interpolation, QTF) and :mod:`.fd_maxima` (Rayleigh maxima, eq. 2.49 combination, tension
  columns); the force models' own frequency-domain terms (:mod:`floatmoor.forces`) make its
  linear system;
* :mod:`.fatigue`: the fatigue limit state over a scatter diagram (``floatmoor.fatigue_analysis``);
* :mod:`.convergence`: time-step convergence (``floatmoor.convergence_study``);
* :mod:`.calibration`: the Floatel-like vessel calibrated to the inputs Wang (2016) publishes.

Each module builds the scene (:func:`floatmoor.io.build.build`) and calls the numerical solvers
of :mod:`floatmoor.solvers`; nothing here runs inside a time loop.  This package imports nothing
on its own, so ``import floatmoor`` stays light.
"""
