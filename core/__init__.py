"""Qt-free computational core of the Geomatics Toolbox.

Everything below this package takes and returns numpy arrays (or plain Python
objects) and never imports ``qgis``, ``PyQt`` or ``processing``: the Processing
algorithms in ``algorithms/`` are thin wrappers around it and the headless tests
exercise it directly.

Conventions shared by every module:

* options are keyword-only;
* invalid input raises :class:`ValueError` with a message that names the
  parameter, the problem and the fix;
* long-running functions accept ``progress`` (a callable taking a fraction in
  ``[0, 1]``) and ``cancel`` (a callable returning ``True`` to stop), both
  optional; a cancelled run raises :class:`~.progress.Cancelled`;
* file outputs are written to a temporary name and renamed on success
  (:func:`~.atomic.atomic_output`), so a failure or a cancel leaves nothing.
"""
