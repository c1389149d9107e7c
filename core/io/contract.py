"""Write outputs under a temporary name and rename them only on success."""
from __future__ import annotations

import contextlib
import os
import uuid
from pathlib import Path
from typing import Iterator, Union

PathLike = Union[str, os.PathLike]


def check_not_input(output: PathLike, *inputs: PathLike) -> None:
    """Refuse an output path that would overwrite one of the inputs.

    Raises
    ------
    ValueError
        If ``output`` resolves to the same file as any of ``inputs``.
    """
    out = Path(output).resolve()
    for src in inputs:
        if src is not None and Path(src).resolve() == out:
            raise ValueError(
                f"The output {output} is the same file as the input {src}; "
                "choose another output path (inputs are never overwritten).")


@contextlib.contextmanager
def atomic_output(path: PathLike, *, suffix: str | None = None) -> Iterator[str]:
    """Yield a temporary path beside ``path``; rename it to ``path`` on success.

    On any exception (including :class:`~.progress.Cancelled`) the temporary file
    is removed and ``path`` is left as it was, so a failed or cancelled run never
    leaves a partial output behind. The temporary name keeps the extension of
    ``path`` (drivers such as laspy and GDAL choose the format by extension).

    Parameters
    ----------
    path : str or path-like
        Final output path. Its folder is created if missing.
    suffix : str, optional
        Extension for the temporary file; defaults to the extension of ``path``.
    """
    final = Path(path)
    if final.parent and not final.parent.exists():
        final.parent.mkdir(parents=True, exist_ok=True)
    ext = suffix if suffix is not None else "".join(final.suffixes[-1:])
    tmp = final.with_name(f".{final.stem}.{uuid.uuid4().hex[:8]}.part{ext}")
    try:
        yield str(tmp)
        os.replace(tmp, final)
    except BaseException:
        for leftover in (tmp, Path(str(tmp) + ".aux.xml")):
            with contextlib.suppress(OSError):
                leftover.unlink()
        raise
