"""Running a study's samples: in a pool of local worker processes (one per core unless told),
or on a Dask distributed cluster; rows written as they come, a study resumed from its results
file, Ctrl-C stopping cleanly with what is done kept."""
from __future__ import annotations

import multiprocessing
import os
import signal
import sys
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from typing import Any, Callable, Dict, Iterator, List, Optional

from .definition import Sample, Study, StudyError
from .evaluation import Plan, evaluate, plan_of
from .progress import Progress
from .results import ResultsTable

# A pool that loses a worker (killed, out of memory) is started again this often.
_POOL_RESTARTS = 3


@dataclass
class Outcome:
    """What a run came to: every row the results file holds, by id; how many failed; whether
    Ctrl-C stopped it."""

    rows: List[Dict[str, Any]]
    failed: int
    interrupted: bool
    path: str


def _failed_row(sample: Sample, plan: Plan, why: str) -> Dict[str, Any]:
    row: Dict[str, Any] = {"id": sample.id, **sample.values}
    row.update({output["name"]: None for output in plan.outputs})
    row.update(seconds=0.0, error=why, cpacs_path=None)
    return row


_WORKER_PLAN: Optional[Plan] = None


def _start_worker(plan: Plan) -> None:
    """A local worker: Ctrl-C is the parent's to handle (it lets running samples finish)."""
    global _WORKER_PLAN
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _WORKER_PLAN = plan


def _evaluate_in_worker(sample_id: int, values: Dict[str, float]) -> Dict[str, Any]:
    assert _WORKER_PLAN is not None
    return evaluate(_WORKER_PLAN, sample_id, values)


def local_rows(plan: Plan, samples: List[Sample], workers: Optional[int]) -> Iterator[Dict[str, Any]]:
    """The samples' rows as local worker processes finish them (spawned, so that no thread or
    lock of this process is copied into them)."""
    pending = {sample.id: sample for sample in samples}
    count = max(1, workers or os.cpu_count() or 1)
    for _ in range(_POOL_RESTARTS + 1):
        if not pending:
            return
        pool = ProcessPoolExecutor(max_workers=min(count, len(pending)), mp_context=multiprocessing.get_context("spawn"),
                                   initializer=_start_worker, initargs=(plan,))
        try:
            futures = {pool.submit(_evaluate_in_worker, s.id, s.values) for s in pending.values()}
            while futures:
                finished, futures = wait(futures, return_when=FIRST_COMPLETED)
                for future in finished:
                    row = future.result()
                    del pending[row["id"]]
                    yield row
        except BrokenProcessPool:
            continue  # a worker died: the samples not done run again in a new pool
        finally:
            pool.shutdown(wait=True, cancel_futures=True)
    for sample in list(pending.values()):
        yield _failed_row(sample, plan, f"worker processes died {_POOL_RESTARTS + 1} times while it ran")


def dask_rows(plan: Plan, samples: List[Sample], client: Any, scheduler: Optional[str]) -> Iterator[Dict[str, Any]]:
    """The samples' rows as a Dask cluster's workers finish them. The plan goes to every worker
    once; a sample whose worker is lost runs again elsewhere (Dask reschedules it)."""
    try:
        from distributed import Client, as_completed
    except ImportError:
        raise StudyError("a cluster needs Dask distributed (Debian: python3-distributed)") from None
    own = client is None
    if own:
        try:
            client = Client(scheduler, timeout="10s")
        except (OSError, TimeoutError) as error:
            raise StudyError(f"no Dask scheduler answers at {scheduler} ({error})") from None
    futures = []
    try:
        shared = client.scatter(plan, broadcast=True, hash=False)
        futures = [client.submit(evaluate, shared, s.id, s.values, key=f"airshape-{plan.key}-{s.id}", retries=2)
                   for s in samples]
        by_key = {future.key: sample for future, sample in zip(futures, samples)}
        for future in as_completed(futures):
            try:
                row = future.result()
            except Exception as error:  # noqa: BLE001 - a lost sample is a failed row, never a lost one
                row = _failed_row(by_key[future.key], plan, f"{type(error).__name__}: {error}".splitlines()[0])
            yield row
    finally:
        if futures:
            client.cancel(futures)
        if own:
            client.close()


def _check_resumable(rows: List[Dict[str, Any]], samples: List[Sample], path: str) -> None:
    values = {sample.id: sample.values for sample in samples}
    for row in rows:
        expected = values.get(row.get("id"))
        if expected is None or any(row.get(name) != value for name, value in expected.items()):
            raise StudyError(f"{path}: its sample {row.get('id')} is not this study's (other parameter values): "
                             "give another results file, or restart")


def _plot(study: Study, rows: List[Dict[str, Any]], path: str) -> None:
    try:
        from .plot import plot_sweep
        plot_sweep(study, rows, path)
    except ImportError:
        print(f"study: {path} not drawn: matplotlib is missing (Debian: python3-matplotlib)", file=sys.stderr)


def run_study(study: Study, results: str, *, workers: Optional[int] = None, client: Any = None,
              scheduler: Optional[str] = None, progress: bool = True, restart: bool = False,
              on_row: Optional[Callable[[Dict[str, Any]], None]] = None) -> Outcome:
    samples = study.samples()
    columns = (["id"] + [p.name for p in study.parameters] + [o.name for o in study.outputs] +
               ["seconds", "error", "cpacs_path"])
    try:
        table = ResultsTable(results, columns)
    except ValueError as error:
        raise StudyError(str(error)) from None
    try:
        existing = [] if restart else table.read()
    except ValueError as error:
        raise StudyError(f"{error}; restart to write it anew") from None
    _check_resumable(existing, samples, results)
    plan = plan_of(study)
    done = {row["id"]: row for row in existing}
    todo = [sample for sample in samples if sample.id not in done]
    table.start(keep=bool(existing))
    bar = Progress(len(samples), len(done), progress)
    bar.failed = sum(1 for row in existing if row.get("error"))
    rows = dask_rows(plan, todo, client, scheduler) if client or scheduler else local_rows(plan, todo, workers)
    interrupted = False
    try:
        for row in rows:
            table.append(row)
            done[row["id"]] = row
            bar.row(row)
            if on_row:
                on_row(row)
    except KeyboardInterrupt:
        interrupted = True
    bar.finish(interrupted)
    ordered = sorted(done.values(), key=lambda row: row["id"])
    if not interrupted:
        table.rewrite(ordered)
        if study.plot:
            _plot(study, ordered, os.path.splitext(results)[0] + ".png")
    return Outcome(ordered, sum(1 for row in ordered if row.get("error")), interrupted, results)
