"""Farm bakes: a transfer bake spread over the workers of a running Dask cluster.

``bake(character, scheduler=...)`` loads the character here (to plan the bake and to fail early on
a bad file), splits every baked segment into vertex ranges, packs them into tasks and submits the
tasks to the cluster. Each task loads the character itself on its worker — from the same file, a
glTF, a ``.thespis`` scenario or a ``.thespkg`` package, so the file must be readable by every
worker at the same path (a shared folder) — bakes its ranges with ``thespis.lighting.bake_ranges``
and sends back their floats. Each vertex's transfer depends only on the mesh, the settings and its
index, so the merged bake equals ``thespis.lighting.bake`` of the same character bit for bit.

A worker that dies mid-bake loses its tasks; the scheduler gives them to another worker (up to
Dask's ``distributed.scheduler.allowed-failures`` deaths per task), and a task that still ends
with ``KilledWorker`` is submitted again (``resubmits`` times). ``progress(done, total)`` counts
baked vertices as tasks finish; ``stop()`` returning true, or Ctrl-C, cancels every task and
raises ``thespis.Cancelled`` (a ``KeyboardInterrupt``). With ``out`` the bake file is written
atomically at the end, as ``thespis-cli bake`` writes it.

The cluster's workers need ``thespis`` importable (the same build as here). Example::

    from thespis import farm
    bake = farm.bake("hero.thespkg", scheduler="tcp://10.0.0.5:8786", out="hero.prt",
                     order=5, rays=1024, progress=lambda done, total: print(done, "/", total))
"""

import functools
import math
import os
import time
import uuid
from dataclasses import dataclass
from typing import Callable, Optional, Union

from . import Cancelled, lighting

__all__ = ["Character", "bake", "split_tasks"]

# The tasks' share of a worker thread: a few tasks per thread keep every thread busy to the end
# and bound what a dead worker loses, while each task's fixed cost (loading the character and
# building its occlusion scene) stays small against its rays.
TASKS_PER_THREAD = 4
# Below this a task's fixed cost dominates its rays.
MIN_TASK_VERTICES = 64
# How often the merging loop wakes, when no task ends, to look at stop() and the time limit (seconds).
POLL_SECONDS = 0.1


@dataclass(frozen=True)
class Character:
    """The character to bake, as plain data that travels to the workers (thespis-cli bake's
    CHARACTER, --character, --tags, --scenario and --no-split)."""

    file: str
    character: str = ""
    tags: Optional[str] = None
    tags_scenario: Optional[str] = None
    split_skinned_by_joint: bool = True

    @classmethod
    def of(cls, character) -> "Character":
        if isinstance(character, cls):
            return character
        return cls(file=os.fspath(character))

    def load(self):
        """The mesh (thespis.lighting.load_bake_character); errors name the file or character."""
        return lighting.load_bake_character(self.file, character=self.character, tags=self.tags,
                                            tags_scenario=self.tags_scenario,
                                            split_skinned_by_joint=self.split_skinned_by_joint)


@functools.lru_cache(maxsize=4)
def _worker_mesh(character: Character):
    # A worker runs many tasks of one bake: it loads the character once.
    return character.load()


def _bake_task(character: Character, settings: dict, ranges: list):
    """Runs on a worker: the ranges' floats, with the hash of the mesh they were baked on."""
    mesh = _worker_mesh(character)
    floats = lighting.bake_ranges(mesh, lighting.BakeSettings(**settings), ranges)
    return lighting.geometry_hash(mesh), floats


def split_tasks(plan, threads: int, tasks_per_thread: int = TASKS_PER_THREAD) -> list:
    """The plan's ranges (none crossing a segment) packed into about threads × tasks_per_thread
    tasks of similar vertex counts: a list of lists of (first_vertex, vertex_count)."""
    total = sum(segment.vertex_count for segment in plan.segments if segment.baked)
    size = max(MIN_TASK_VERTICES, math.ceil(total / max(1, threads * tasks_per_thread)))
    tasks, current, filled = [], [], 0
    for first, count in lighting.split_bake(plan, size):
        current.append((first, count))
        filled += count
        if filled >= size:
            tasks.append(current)
            current, filled = [], 0
    if current:
        tasks.append(current)
    return tasks


def _connect(scheduler, timeout):
    """(client, whether we opened it) from an address or a distributed.Client."""
    import distributed

    if isinstance(scheduler, distributed.Client):
        return scheduler, False
    try:
        return distributed.Client(scheduler, timeout=timeout or 30, set_as_default=False), True
    except OSError as error:
        raise OSError(f"cannot reach the Dask scheduler at {scheduler}: {error}") from error


def bake(character: Union[str, os.PathLike, Character], *, scheduler, out=None, order: int = 5,
         rays: int = 1024, transfer: str = "dsm", backend: str = "embree", epsilon: float = 1.71e-4,
         seed: int = 1, threads_per_task: int = 1, tasks_per_thread: int = TASKS_PER_THREAD,
         progress: Optional[Callable[[int, int], object]] = None,
         stop: Optional[Callable[[], bool]] = None, timeout: Optional[float] = None,
         resubmits: int = 2):
    """Bakes `character` on the Dask cluster at `scheduler` (an address such as
    "tcp://HOST:PORT", or a distributed.Client) and returns the thespis.lighting.TransferBake,
    equal bit for bit to thespis.lighting.bake with the same settings; with `out`, also writes it.

    threads_per_task: the bake threads each task uses on its worker (workers run one task per
    Dask thread). timeout: seconds for the whole bake (TimeoutError when exceeded; None: no
    limit); it also bounds connecting to the scheduler.
    """
    import distributed

    character = Character.of(character)
    settings = dict(order=order, rays=rays, transfer=transfer, backend=backend, epsilon=epsilon,
                    seed=seed, threads=threads_per_task)
    mesh = character.load()
    plan = lighting.plan_bake(mesh, lighting.BakeSettings(**settings))
    per_vertex = order * order
    total = len(plan.transfer)
    deadline = None if timeout is None else time.monotonic() + timeout

    client, owned = _connect(scheduler, timeout)
    futures = {}  # future → its ranges
    try:
        threads = sum(w["nthreads"] for w in client.scheduler_info()["workers"].values())
        if threads == 0:
            raise RuntimeError(f"the Dask cluster at {client.scheduler.address} has no workers")
        tag = uuid.uuid4().hex[:12]
        submitted = 0

        def submit(ranges):
            nonlocal submitted
            submitted += 1
            future = client.submit(_bake_task, character, settings, ranges, pure=False,
                                   key=f"thespis-bake-{tag}-{submitted}")
            futures[future] = ranges
            return future

        for task in split_tasks(plan, threads, tasks_per_thread):
            submit(task)
        lost = {}  # first vertex of a task → times it came back KilledWorker
        done = 0
        if progress:
            progress(0, total)
        while futures:
            if stop is not None and stop():
                raise Cancelled("The farm bake was cancelled.")
            if deadline is not None and time.monotonic() > deadline:
                raise TimeoutError(f"the farm bake of {character.file} did not finish within {timeout} s "
                                   f"({done} of {total} vertices baked)")
            try:
                # Wakes as soon as a task ends, else after POLL_SECONDS to look at stop().
                with client.as_current():  # wait() asks for the default client; this one is not
                    finished, _ = distributed.wait(list(futures), timeout=POLL_SECONDS, return_when="FIRST_COMPLETED")
            except TimeoutError:
                continue
            for future in finished:
                ranges = futures.pop(future)
                if future.status == "error":
                    error = future.exception()
                    key = ranges[0][0]
                    if isinstance(error, distributed.KilledWorker) and lost.get(key, 0) < resubmits:
                        lost[key] = lost.get(key, 0) + 1
                        submit(ranges)
                        continue
                    raise error
                geometry, floats = future.result()
                if geometry != plan.geometry_hash:
                    raise ValueError(f"a worker loaded a different {character.file} than this machine "
                                     "(its geometry differs): the workers must see the same file")
                offset = 0
                for first, count in ranges:
                    plan.place_range(first, count, floats[offset:offset + count * per_vertex])
                    offset += count * per_vertex
                    done += count
                if progress:
                    progress(done, total)
    except BaseException:
        # Ctrl-C, stop(), a failed task or a lost scheduler: nothing of this bake keeps running.
        if futures:
            try:
                client.cancel(list(futures), force=True)
            except Exception:  # the scheduler may be gone; the futures die with the client
                pass
        raise
    finally:
        if owned:
            client.close()
    if out is not None:
        plan.save(out)
    return plan

