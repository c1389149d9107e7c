"""A catalog run's state in its output folder (private; see :mod:`.catalog`).

``<out>/.catalog/``: the run's settings (``settings.json``, what a resume is checked
against), the first pass's ``summary.json``, one done marker per finished chunk
(``<key>.done.json``: its stats, the canopy counts among them) and the chunks'
``.gap.npz`` until the gap distance is derived. Finished chunks are kept for a resume;
a run that ends before any chunk has finished leaves the folder as it found it.
"""
from __future__ import annotations

import json
import os
from pathlib import Path
from typing import List, Optional, Sequence

from ..errors import InputError
from ._catalog_checks import SETTINGS_FILE, STATE_DIR
from ._gap import drop_gap_files
from ._lowcells import FACTORS

__all__ = ["finished_chunks", "check_markers", "read_text", "undo_run", "untrusted_error",
           "write_settings"]

DONE_SUFFIX = ".done.json"


def finished_chunks(out_folder) -> List[str]:
    """Keys of the chunks whose done marker is in ``out_folder`` (kept for a resume)."""
    state = Path(out_folder) / STATE_DIR
    return sorted(p.name[:-len(DONE_SUFFIX)] for p in state.glob(f"*{DONE_SUFFIX}")) \
        if state.is_dir() else []


def untrusted_error(folder, files) -> InputError:
    """Refusal of a resume whose finished chunks' values cannot be read back."""
    return InputError(
        "The output folder {folder} holds finished chunks of an earlier run but not the "
        "values they were made with ({files}: missing, damaged or from an older version); "
        "resuming would mix two runs. Choose another output folder, or delete that "
        "folder's outputs and its .catalog folder to start again.",
        folder=folder, files=", ".join(files[:6]) + (", …" if len(files) > 6 else ""))


def check_markers(folder, previous: dict) -> None:
    """Refuse finished chunks whose markers lack valid canopy counts (an older version).

    ``previous``: chunk key -> its marker's stats (None: not finished). The catalog's
    canopy factor is chosen from every chunk's counts (:func:`._canopy.settle`).
    """
    old = sorted(f"{STATE_DIR}/{k}{DONE_SUFFIX}" for k, s in previous.items()
                 if s is not None and not _counts_ok(s.get("canopy")))
    if old:
        raise untrusted_error(folder, old)


def _counts_ok(canopy) -> bool:
    """Return True for canopy counts as this version writes them (one per factor, a factor)."""
    if not isinstance(canopy, dict) or canopy.get("factor") not in (0, *FACTORS):
        return False
    counts = [canopy.get("pits"), canopy.get("blocks")]
    return all(isinstance(c, list) and len(c) == len(FACTORS)
               and all(isinstance(v, int) and not isinstance(v, bool) for v in c)
               for c in counts)


def write_settings(folder: Path, settings: dict) -> None:
    """``.catalog/settings.json``, written atomically."""
    path = folder / STATE_DIR / SETTINGS_FILE
    tmp = path.with_suffix(".tmp")
    tmp.write_text(json.dumps(settings, indent=1), encoding="utf-8")
    os.replace(tmp, path)


def read_text(path: Path) -> Optional[str]:
    """Return the text of ``path``, or None when it cannot be read."""
    try:
        return path.read_text(encoding="utf-8")
    except (OSError, ValueError):
        return None


def undo_run(todo: Sequence, made: Sequence[Path], restore=None) -> None:
    """Remove what this run wrote (chunk outputs, markers, folders it created).

    ``restore``: the state files (name -> text, None: absent) as the run found them,
    put back when the state folder was already there and no finished chunk of an
    earlier run is left in it (those were made with these files: a resume needs them).
    """
    drop_gap_files(todo)
    for t in todo:
        for path in t.outputs.values():
            if os.path.exists(path):
                os.remove(path)
    for p in reversed(made):
        if p.name == STATE_DIR and p.is_dir():
            for f in p.iterdir():
                f.unlink()
        if p.is_dir() and not any(p.iterdir()):
            p.rmdir()
    state = Path(todo[0].outputs["DONE"]).parent if todo else None
    if restore and state is not None and state.is_dir() and not finished_chunks(state.parent):
        for f in state.glob("*.tmp"):           # an atomic write cut short
            f.unlink()
        for name, text in restore.items():
            if text is None:
                (state / name).unlink(missing_ok=True)
            else:
                (state / name).write_text(text, encoding="utf-8")


