"""The output contract: every run writes all its outputs or none, and never an input.

One rule for every algorithm that writes files (Sithole-style "no partial result"):

1. before anything is written, every output path is checked against every input of
   every kind (clouds, rasters, GCP files, tables, check points — links and hard
   links resolved) and against every other output (:func:`check_paths`);
2. each output is written under a temporary name in its own folder
   (:func:`temp_path`: ``.<stem>.part-<8 hex><ext>``, one scheme, never nested);
3. only when every output was written are they renamed to their final names
   (pre-existing files are moved aside first and restored if a rename fails);
4. on an error, a cancel, ``SIGTERM`` or interpreter exit every temporary is removed
   and pre-existing files are left untouched.

A contract whose outputs are the temporaries of an outer contract (a chain of steps
under one contract, e.g. ``geomatics:lidartodtm``) writes them directly and leaves the
renaming to the outer contract.

Examples
--------
>>> with OutputContract({"OUTPUT": "dtm.tif", "OUTPUT_HTML": "dtm.html"},
...                     inputs={"INPUT": "cloud.laz"}) as out:   # doctest: +SKIP
...     write_geotiff(out.path("OUTPUT"), ...)
...     write_text(out.path("OUTPUT_HTML"), html)
"""
from __future__ import annotations

import atexit
import contextlib
import os
import signal
import tempfile
import threading
import uuid
from pathlib import Path
from typing import Dict, Iterable, Iterator, Mapping, Optional, Sequence, Union

from ..errors import InputError

PathLike = Union[str, os.PathLike]
TEMP_MARK = ".part-"

#: Temporary files alive in this process (removed at exit if still there).
_LIVE: set = set()
_LOCK = threading.Lock()


class Terminated(BaseException):  # noqa: N818 - mirrors KeyboardInterrupt
    """Raised in the main thread when the process receives ``SIGTERM``."""


def is_temp(path: PathLike) -> bool:
    """Return True when ``path`` is a temporary name of this contract."""
    name = Path(path).name
    return name.startswith(".") and TEMP_MARK in name


def final_path(path: PathLike) -> Path:
    """Return the final name a temporary name stands for (``path`` itself otherwise).

    ``.dtm.part-1a2b3c4d.tif`` -> ``dtm.tif`` (the inverse of :func:`temp_path`).
    """
    path = Path(path)
    if not is_temp(path):
        return path
    name = path.name
    return path.with_name(name[1:name.index(TEMP_MARK)] + path.suffix)


def temp_path(final: PathLike) -> Path:
    """Return a fresh temporary name beside ``final`` keeping its extension.

    ``dtm.tif`` -> ``.dtm.part-1a2b3c4d.tif``. A path that already is a temporary
    name is returned unchanged (temporaries are never nested).
    """
    final = Path(final)
    if is_temp(final):
        return final
    return final.with_name(f".{final.stem}{TEMP_MARK}{uuid.uuid4().hex[:8]}{final.suffix}")


def _register(path: Path) -> None:
    with _LOCK:
        _LIVE.add(str(path))


def _forget(path: Path) -> None:
    with _LOCK:
        _LIVE.discard(str(path))


def remove_temp(tmp: PathLike) -> None:
    """Remove a temporary file and its sidecars (``.aux.xml``, journals)."""
    tmp = Path(tmp)
    folder = tmp.parent if str(tmp.parent) else Path(".")
    for leftover in _with_sidecars(folder, tmp.name):
        with contextlib.suppress(OSError):
            leftover.unlink()
    _forget(tmp)


@atexit.register
def _remove_live_temps() -> None:  # pragma: no cover - runs at interpreter exit
    for name in list(_LIVE):
        remove_temp(name)


def _identity(path: Path):
    """(device, inode) of an existing file, or None."""
    try:
        st = path.stat()
    except OSError:
        return None
    return (st.st_dev, st.st_ino)


def _flatten(inputs: Mapping[str, object]) -> Iterator:
    for name, value in inputs.items():
        if value in (None, ""):
            continue
        if isinstance(value, (list, tuple, set)):
            for v in value:
                if v not in (None, ""):
                    yield name, Path(v)
        else:
            yield name, Path(value)


def check_paths(outputs: Mapping[str, Optional[PathLike]],
                inputs: Mapping[str, object] = (), *,
                point_clouds: Iterable[str] = ()) -> Dict[str, Path]:
    """Validate output paths against every input and against each other.

    Parameters
    ----------
    outputs : mapping of str to path or None
        Output parameter name -> path (``None``/empty: output not requested).
    inputs : mapping of str to path, sequence of paths or None
        Input parameter name -> path(s) of every file the run reads.
    point_clouds : iterable of str
        Names of the outputs that are LAS/LAZ point clouds: refused up front unless
        they end in .las or .laz (:func:`check_las_output`).

    Returns
    -------
    dict
        The requested outputs as resolved :class:`~pathlib.Path` objects.

    Raises
    ------
    InputError
        When an output is an input (also through a link), two outputs share a path,
        an output is an existing folder or named ``*.copc.laz`` (the toolbox reads COPC
        but writes plain LAS/LAZ), or its folder cannot be written.
    """
    outs = {k: Path(v) for k, v in dict(outputs).items() if v not in (None, "")}
    for name in point_clouds:
        if name in outs:
            check_las_output(name, outs[name])
    ins = list(_flatten(dict(inputs)))
    seen: Dict[Path, str] = {}
    for name, path in outs.items():
        real = path.resolve()
        ident = _identity(real)
        for in_name, src in ins:
            if src.resolve() == real or (ident is not None and _identity(src.resolve()) == ident):
                raise InputError(
                    "The output {name} ({path}) is the same file as the input {in_name} "
                    "({src}); choose another output path — inputs are never overwritten.",
                    name=name,
                    path=path,
                    in_name=in_name,
                    src=src)
        if path.name.lower().endswith(".copc.laz"):
            raise InputError(
                "The output {name} ({path}) is named as a COPC file, but point clouds are "
                "written as plain LAS/LAZ (COPC inputs are read); QGIS would fail to open "
                "it as COPC. Give a name ending in .laz without .copc.",
                name=name, path=path)
        if real in seen:
            raise InputError(
                "The outputs {other} and {name} are both {path}; give each output "
                "its own file.", other=seen[real], name=name, path=path)
        seen[real] = name
        if real.is_dir():
            raise InputError("The output {name} ({path}) is a folder; give a file name.",
                             name=name,
                             path=path)
        _check_writable(real.parent, name)
    return outs


def check_las_output(name: str, path: PathLike) -> None:
    """Refuse a point-cloud output ``name`` whose ``path`` is not .las/.laz (``c.tif``).

    A temporary name of this module is checked as the final name it stands for.
    """
    from .las import LAS_SUFFIXES
    path = final_path(path)
    if not os.fspath(path).lower().endswith(LAS_SUFFIXES):
        raise InputError("The output {name} is a point cloud and cannot be written as "
                         "{path}: LAS/LAZ content under another extension would be mistaken "
                         "for another format. Choose a file name ending in .las or .laz.",
                         name=name, path=os.fspath(path))


def _check_writable(folder: Path, name: str) -> None:
    """Probe the output folder (or its nearest existing parent) with a temporary file."""
    while not folder.exists() and folder != folder.parent:
        folder = folder.parent
    reason = ""
    if not folder.is_dir():
        reason = "it is not a folder"
    else:
        try:
            with tempfile.TemporaryFile(dir=folder, prefix=".probe" + TEMP_MARK):
                pass
        except OSError as exc:
            reason = exc.strerror or str(exc)
    if reason:
        raise InputError(
            "The folder {folder} of the output {name} cannot be written ({reason}); "
            "choose a folder you can write to. Nothing was written.",
            folder=folder,
            name=name,
            reason=reason)


class OutputContract:
    """All-or-nothing outputs of one run (see the module docstring).

    Parameters
    ----------
    outputs : mapping of str to path or None
        Output parameter name -> final path; ``None`` or ``""`` = not requested.
    inputs : mapping of str to path, sequence of paths or None, optional
        Every file the run reads, by parameter name (checked, never written).
    point_clouds : iterable of str, optional
        Names of the LAS/LAZ outputs (their extension is checked before anything runs).
    """

    def __init__(self, outputs: Mapping[str, Optional[PathLike]], *,
                 inputs: Mapping[str, object] = (), point_clouds: Iterable[str] = ()):
        self.finals = check_paths(outputs, inputs, point_clouds=point_clouds)
        self._temps: Dict[str, Path] = {}
        self._sigterm = None
        self.committed = False

    # ------------------------------------------------------------------ paths
    def requested(self, name: str) -> bool:
        """Return True when the output ``name`` was requested."""
        return name in self.finals

    def final(self, name: str) -> Optional[str]:
        """Return the final path of ``name`` (None when not requested)."""
        path = self.finals.get(name)
        return str(path) if path is not None else None

    def path(self, name: str) -> str:
        """Return the temporary path to write the output ``name`` to."""
        if name not in self.finals:
            raise KeyError(f"The output {name} was not requested.")
        if name not in self._temps:
            final = self.finals[name]
            final.parent.mkdir(parents=True, exist_ok=True)
            tmp = temp_path(final)      # == final when final is an outer temporary
            self._temps[name] = tmp
            _register(tmp)
        return str(self._temps[name])

    def write_text(self, name: str, text: str) -> None:
        """Write a text output (HTML, CSV, JSON) as UTF-8."""
        with open(self.path(name), "w", encoding="utf-8", newline="") as fh:
            fh.write(text)

    # ------------------------------------------------------------------ life cycle
    def __enter__(self) -> OutputContract:
        """Start the run: ``SIGTERM`` now removes the temporaries (main thread only)."""
        self._sigterm = sigterm_raises()
        self._sigterm.__enter__()
        return self

    def __exit__(self, exc_type, exc, tb) -> bool:
        """Commit on success, discard on any exception (which propagates)."""
        try:
            if exc_type is None:
                self.commit()
            else:
                self.discard()
        finally:
            self._sigterm.__exit__(None, None, None)
        return False

    def discard(self) -> None:
        """Remove every temporary; final paths are left as they were."""
        for tmp in self._temps.values():
            remove_temp(tmp)
        self._temps.clear()

    def commit(self) -> None:
        """Rename every written temporary to its final name (all or nothing)."""
        missing = [n for n in self.finals if n not in self._temps
                   or not self._temps[n].exists()]
        if missing:
            self.discard()
            raise InputError("Outputs never written: {names}.", names=", ".join(missing))
        backups: Dict[Path, Path] = {}
        done = []
        try:
            for name, tmp in self._temps.items():
                final = self.finals[name]
                if tmp == final:      # an outer contract's temporary: it commits it
                    continue
                if final.exists():
                    backup = temp_path(final)
                    os.replace(final, backup)
                    _register(backup)
                    backups[final] = backup
                _rename_with_sidecars(tmp, final)
                done.append(final)
        except BaseException:
            for final in done:
                with contextlib.suppress(OSError):
                    final.unlink()
            for final, backup in backups.items():
                with contextlib.suppress(OSError):
                    os.replace(backup, final)
                    _forget(backup)
            self.discard()
            raise
        for backup in backups.values():
            remove_temp(backup)
        for tmp in self._temps.values():
            _forget(tmp)
        self._temps.clear()
        self.committed = True


def _with_sidecars(folder: Path, name: str) -> list:
    """``folder/name`` and every file whose name starts with ``name`` (sidecars)."""
    try:
        return [folder / n for n in os.listdir(folder) if n.startswith(name)]
    except OSError:
        return []


def _rename_with_sidecars(tmp: Path, final: Path) -> None:
    for side in sorted(p for p in _with_sidecars(tmp.parent, tmp.name) if p != tmp):
        with contextlib.suppress(OSError):
            os.replace(side, final.with_name(final.name + side.name[len(tmp.name):]))
    os.replace(tmp, final)


def _raise_terminated(signum, frame):  # pragma: no cover - exercised in a subprocess test
    raise Terminated(f"Terminated by signal {signum}; no output was written.")


@contextlib.contextmanager
def sigterm_raises():
    """While inside, ``SIGTERM`` raises :class:`Terminated` (main thread only).

    A run that makes its outputs outside one :class:`OutputContract` (a catalog: chunks
    on workers, state files) cleans up in its own ``except BaseException`` handlers.
    """
    old = None
    if threading.current_thread() is threading.main_thread():
        with contextlib.suppress(ValueError, OSError):
            old = signal.signal(signal.SIGTERM, _raise_terminated)
    try:
        yield
    finally:
        if old is not None:
            with contextlib.suppress(ValueError, OSError):
                signal.signal(signal.SIGTERM, old)


# ---------------------------------------------------------------------- one output
def check_not_input(output: PathLike, *inputs: PathLike) -> None:
    """Refuse an output path that would overwrite one of the inputs.

    Raises
    ------
    InputError
        If ``output`` resolves to the same file as any of ``inputs``.
    """
    check_paths({"output": output}, {"input": [p for p in inputs if p is not None]})


@contextlib.contextmanager
def atomic_output(path: PathLike, *, suffix: str | None = None) -> Iterator[str]:
    """Yield a temporary path beside ``path``; rename it to ``path`` on success.

    On any exception (including :class:`~..progress.Cancelled`) the temporary file is
    removed and ``path`` is left as it was. When ``path`` already is a temporary of an
    :class:`OutputContract` it is yielded unchanged: temporaries are never nested.

    Parameters
    ----------
    path : str or path-like
        Final output path. Its folder is created if missing.
    suffix : str, optional
        Extension for the temporary file; defaults to the extension of ``path``.
    """
    final = Path(path)
    if is_temp(final):
        yield str(final)
        return
    if final.parent and not final.parent.exists():
        final.parent.mkdir(parents=True, exist_ok=True)
    tmp = temp_path(final)
    if suffix is not None:
        tmp = tmp.with_suffix(suffix)
    _register(tmp)
    try:
        yield str(tmp)
        os.replace(tmp, final)
        _forget(tmp)
    except BaseException:
        remove_temp(tmp)
        raise


def as_paths(values: Iterable[Optional[PathLike]]) -> Sequence[str]:
    """Return the non-empty values as strings (helper for optional inputs)."""
    return [str(v) for v in values if v not in (None, "")]
