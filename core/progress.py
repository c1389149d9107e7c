"""Progress reporting and cancellation as plain callables (no Qt)."""
from __future__ import annotations

from typing import Callable, Optional

ProgressFn = Optional[Callable[[float], None]]
CancelFn = Optional[Callable[[], bool]]


class Cancelled(Exception):  # noqa: N818 - public name since 0.1
    """Raised by core functions when the ``cancel`` callable returns True."""


class Monitor:
    """Bundle an optional progress callable and an optional cancel callable.

    Parameters
    ----------
    progress : callable, optional
        Called with a fraction in ``[0, 1]``.
    cancel : callable, optional
        Returns ``True`` when the caller wants the work stopped.
    start, stop : float
        The sub-range of the caller's progress this monitor maps ``[0, 1]`` onto.

    Examples
    --------
    >>> seen = []
    >>> mon = Monitor(seen.append)
    >>> mon.sub(0.5, 1.0).update(0.5)
    >>> seen
    [0.75]
    """

    __slots__ = ("_progress", "_cancel", "_start", "_stop")

    def __init__(self, progress: ProgressFn = None, cancel: CancelFn = None,
                 start: float = 0.0, stop: float = 1.0):
        self._progress = progress
        self._cancel = cancel
        self._start = float(start)
        self._stop = float(stop)

    def update(self, fraction: float) -> None:
        """Report ``fraction`` (0..1) of this monitor's range as done."""
        if self._progress is not None:
            f = min(max(float(fraction), 0.0), 1.0)
            self._progress(self._start + (self._stop - self._start) * f)

    def cancelled(self) -> bool:
        """Return True when the caller asked to stop."""
        return bool(self._cancel is not None and self._cancel())

    def check(self) -> None:
        """Raise :class:`Cancelled` when the caller asked to stop."""
        if self.cancelled():
            raise Cancelled("cancelled by the user")

    def step(self, fraction: float) -> None:
        """:meth:`check` then :meth:`update` — the usual per-block call."""
        self.check()
        self.update(fraction)

    def sub(self, start: float, stop: float) -> "Monitor":
        """Return a monitor whose ``[0, 1]`` maps to ``[start, stop]`` of this one."""
        span = self._stop - self._start
        return Monitor(self._progress, self._cancel,
                       self._start + span * start, self._start + span * stop)
