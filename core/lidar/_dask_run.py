"""Running catalog chunks on Dask (private; see :mod:`.catalog`).

A local cluster (workers started by :mod:`._workers`) or an existing scheduler; chunks
submitted largest first, collected with progress, cancel and per-chunk failures;
unfinished chunk outputs swept on cancel.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Dict, List, Optional, Sequence

from ..errors import InputError
from ..io.contract import remove_temp
from ..progress import Cancelled, Monitor
from ._chunks import ChunkTask, process_chunk, read_strip
from ._summary import final, strip_summary, tile_summary
from ._workers import SINGLE_THREAD_ENV, start_local_workers


@dataclass
class CatalogResult:
    """Outcome of :func:`run_catalog`: per-chunk stats, failures, mosaic, timing."""

    chunks: List[dict]
    failed: Dict[str, str]
    skipped: List[str]
    vrt: Optional[str]
    cog: Optional[str]
    seconds: float
    workers: int
    scheduler: str
    settings: dict = field(default_factory=dict)
    timings: Dict[str, list] = field(default_factory=dict)

    @property
    def points(self) -> int:
        """Points processed in this run (skipped chunks excluded)."""
        return int(sum(c["points"] for c in self.chunks if c["key"] not in self.skipped))

    @property
    def points_per_second(self) -> float:
        """Overall throughput of this run (wall time)."""
        return self.points / self.seconds if self.seconds > 0 else float("nan")

    def per_worker(self) -> Dict[str, dict]:
        """Points, chunks, busy seconds and points/s per worker."""
        out: Dict[str, dict] = {}
        for c in self.chunks:
            if c["key"] in self.skipped:
                continue
            w = out.setdefault(c["worker"], dict(points=0, chunks=0, seconds=0.0))
            w["points"] += c["points"]
            w["chunks"] += 1
            w["seconds"] += c["seconds"]
        for w in out.values():
            w["points_per_second"] = w["points"] / w["seconds"] if w["seconds"] else 0.0
        return out


# The local scheduler runs in this (the client) process and the nannies in the workers'
# child process (`_workers.py`), next to the
# workers on the same cores: their periodic callbacks (event-loop tick every 20 ms,
# system monitor every 0.5 s, nanny memory monitor every 0.1 s, work stealing every
# 0.1 s) cost 23 ms of CPU per second of run, measured; with these 7 ms. One chunk per
# task and largest-first submission leave nothing for work stealing to improve.
QUIET = {"distributed.admin.tick.interval": "1s",
         "distributed.admin.system-monitor.interval": "5s",
         "distributed.worker.memory.monitor-interval": "1s",
         "distributed.scheduler.work-stealing": False}


def _client(workers: int, scheduler: str, memory_limit):
    try:
        from distributed import Client
    except ImportError as exc:  # pragma: no cover - install problem
        raise InputError("The Python packages dask and distributed cannot be imported "
                         "({exc}); run 'Install the Python packages this toolbox needs' "
                         "(geomatics:installdependencies).", exc=exc) from exc
    if scheduler:
        try:
            return Client(scheduler, timeout="20s"), None
        except (OSError, TimeoutError) as exc:
            raise InputError("Cannot reach the Dask scheduler {scheduler} ({exc}); start "
                             "it with 'dask scheduler' or leave SCHEDULER empty.",
                             scheduler=scheduler,
                             exc=exc) from exc
    import dask
    environ = dict(dask.config.get("distributed.nanny.pre-spawn-environ", {}) or {})
    environ.update(SINGLE_THREAD_ENV)    # one worker = one core (see single_threaded)
    config = {"distributed.nanny.pre-spawn-environ": environ, **QUIET}
    with dask.config.set(config):
        workers_ = start_local_workers(workers, memory_limit=memory_limit, config=config)
        return Client(workers_.cluster), workers_


def _collect(futures: dict, mon: Monitor, n_total: int, done_before: int, failed: dict,
             on_chunk=None):
    """Wait for the chunk futures; cancel stops scheduling.

    Progress per chunk, and ``on_chunk(stats)``: the stats of each finished chunk or
    ``{"key", "status": "failed", "error"}``.
    """
    pending = set(futures)
    results = []
    while pending:
        if mon.cancelled():
            for f in pending:
                f.cancel()
            raise Cancelled()
        finished, pending = _wait_pending(list(pending))
        pending = set(pending)
        for f in finished:
            key = futures[f]
            if f.status == "finished":
                results.append(f.result())
                event = results[-1]
            else:
                exc = f.exception()
                failed[key] = f"{type(exc).__name__}: {exc}"
                event = {"key": key, "status": "failed", "error": failed[key]}
            if on_chunk is not None:
                on_chunk(event)
            mon.update((done_before + len(results) + len(failed)) / max(n_total, 1))
    return results


def _wait_pending(futures, timeout: float = 0.5):
    from distributed import wait
    try:
        return wait(futures, timeout=timeout, return_when="FIRST_COMPLETED")
    except TimeoutError:
        return set(), set(futures)


def _sweep_temps(folder: Path, tasks: Sequence[ChunkTask]) -> None:
    """Remove unfinished chunk outputs (contract temporaries) left by cancelled chunks."""
    for t in tasks:
        for k in ("LAS", "DTM"):
            final = Path(t.outputs[k])
            for tmp in final.parent.glob(f".{final.stem}.part-*"):
                remove_temp(tmp)
        attempted = Path(t.outputs["DONE"] + ".attempted")
        if attempted.exists():
            attempted.unlink()


def _submit_strips(client, order, plan=None):
    """One strip task per neighbour tile of the tile-mode chunks to run.

    Returns ``({tile path: future}, release)``: each strip holds the tile's points inside
    its consumers' buffered boxes (:func:`._chunks.read_strip`), read once, and is
    dropped (``release(chunk key)``) when its last consumer has finished.
    """
    consumers = {}
    for t in order:
        if t.tile:
            for p in t.neighbours:
                consumers.setdefault(p, []).append(t)
    spec = plan["spec"] if plan is not None else {}   # the first pass rides on the decode
    strips = {p: client.submit(read_strip, p, [t.buffered_box() for t in users],
                               ("classification",), spec.get(p),
                               key=f"strip-{Path(p).stem}-{time.time_ns()}", retries=1,
                               pure=False, priority=10 ** 12)
              for p, users in consumers.items()}
    for t in order:
        t.strip_shares = [1.0 / len(consumers[p]) for p in t.neighbours if p in strips]
    left = {p: len(users) for p, users in consumers.items()}
    by_key = {t.key: t for t in order}

    def release(key):
        t = by_key.get(key)
        for p in (t.neighbours if t is not None and t.tile else ()):
            if p in left:
                left[p] -= 1
                if left[p] == 0:
                    strips.pop(p, None)     # the last reference: Dask frees the strip
    return strips, release


def _submit_first_pass(client, plan, strips):
    """Submit the catalog's first pass to the workers (:mod:`._summary`); its merged future.

    A tile a strip task decodes anyway is summarised by that task (no second decode);
    the others (no neighbour to lend points to, ``CHUNK_SIZE`` boxes) are streamed by
    a task of their own. The merge runs when every tile is summarised, and every chunk
    waits for it.
    """
    parts = [client.submit(strip_summary, strips[p], key=f"summary-{Path(p).stem}-"
                           f"{time.time_ns()}", pure=False, priority=10 ** 12)
             if p in strips else
             client.submit(tile_summary, p, *spec, key=f"summary-{Path(p).stem}-"
                           f"{time.time_ns()}", retries=1, pure=False, priority=10 ** 12)
             for p, spec in plan["spec"].items()]
    return client.submit(final, *parts, counts=plan["counts"], folder=plan["folder"],
                         signature=plan["signature"], key=f"first-pass-{time.time_ns()}",
                         pure=False, priority=10 ** 12)


def _rerun(client, redo, mon, failed, on_chunk=None):
    """Run the chunks ``redo`` again (at the catalog's canopy factor: :mod:`._canopy`).

    Their neighbours are streamed from the files (the strips are gone).

    Only failures reach ``on_chunk`` (each chunk was reported once, when it finished).
    """
    futures = {client.submit(process_chunk, t, key=f"canopy-{t.key}-{time.time_ns()}",
                             retries=1, pure=False, priority=int(t.cost)): t.key
               for t in redo}

    def report(event):
        if on_chunk is not None and event.get("status") == "failed":
            on_chunk(event)
    return _collect(futures, mon, 1, 1, failed, report)


def _run_dask(todo, tasks, folder, nw, scheduler, memory_limit, mon, n_before, failed,
              clock, on_chunk=None, plan=None, settle=None):
    """Run the chunks ``todo`` on Dask; their stats.

    ``settle(results)``, when given and no chunk failed, returns the chunks to run once
    more (at the catalog's canopy factor, :mod:`._canopy`); their new stats replace them.
    """
    client, cluster = _client(nw, scheduler, memory_limit)
    clock.lap("cluster start")
    try:
        # largest chunks first (longest-processing-time order): the last chunk to
        # finish is a small one, so workers idle less at the end of the run. Submitted
        # in that order too: idle workers take the first tasks as they arrive.
        order = sorted(todo, key=lambda t: -t.cost)
        strips, release = _submit_strips(client, order, plan)
        summary = _submit_first_pass(client, plan, strips) if plan is not None else None
        futures = {client.submit(process_chunk, t, *[strips[p] for p in t.neighbours
                                                      if p in strips], summary=summary,
                                 key=f"chunk-{t.key}-{time.time_ns()}", retries=1,
                                 pure=False, priority=int(t.cost)): t.key
                   for t in order}

        def done(event):
            release(event["key"])
            if on_chunk is not None:
                on_chunk(event)

        results = _collect(futures, mon, len(tasks), n_before, failed, done)
        redo = settle(results) if settle is not None and not failed else []
        if redo:
            again = {r["key"]: r for r in _rerun(client, redo, mon, failed, on_chunk)}
            results = [again.pop(r["key"], r) for r in results] + list(again.values())
        clock.lap("compute")
        return results
    except BaseException:
        client.close()
        if cluster is not None:
            cluster.close()
        client = cluster = None
        _sweep_temps(folder, tasks)          # the chunks run again among them
        raise
    finally:
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()
        clock.lap("cluster close")
        for t in todo:
            flag = Path(t.outputs["DONE"] + ".attempted")
            if flag.exists():
                flag.unlink()
