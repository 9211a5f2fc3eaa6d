"""Overhead of a farm bake: thespis.farm on a 2-worker LocalCluster (one thread each, 127.0.0.1)
against the local bake of the same character on 2 threads (the same cores), medians of N runs.

thespis-bench (google-benchmark, C++) cannot start a Dask cluster, so this is a script:

    PYTHONPATH=build/python /usr/bin/python3 tests/bench/farm_bench.py [--rays 1024] [--order 5] [--runs 5]

The cluster is started and warmed up (a first bake, in which each worker imports thespis and
loads the character) before timing: the figures are of a running farm, as `--scheduler` uses it.
Every farm bake is checked bit-identical to the local one.
"""

import argparse
import os
import statistics
import time
from pathlib import Path

import distributed

from thespis import farm, lighting

REPO = Path(__file__).resolve().parents[2]
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", REPO.parent / "shared" / "data"))
ROBOT = DATA / "characters" / "RobotExpressive" / "RobotExpressive.glb"


def timed(function):
    started = time.perf_counter()
    result = function()
    return time.perf_counter() - started, result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--character", default=str(ROBOT))
    parser.add_argument("--order", type=int, default=5)
    parser.add_argument("--rays", type=int, default=1024)
    parser.add_argument("--runs", type=int, default=5)
    arguments = parser.parse_args()
    settings = dict(order=arguments.order, rays=arguments.rays)

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, host="127.0.0.1", processes=True,
                                  dashboard_address=":0") as cluster, \
            distributed.Client(cluster, set_as_default=False) as client:
        client.wait_for_workers(2)
        cold, _ = timed(lambda: farm.bake(arguments.character, scheduler=client, order=1, rays=1))
        local_seconds, farm_seconds = [], []
        for _ in range(arguments.runs):
            # The character is loaded in both timings: farm.bake loads it to plan the bake.
            seconds, local = timed(lambda: lighting.bake(lighting.load_bake_character(arguments.character),
                                                         threads=2, **settings))
            local_seconds.append(seconds)
            seconds, farmed = timed(lambda: farm.bake(arguments.character, scheduler=client, **settings))
            farm_seconds.append(seconds)
            assert farmed == local, "the farm bake differs from the local bake"
    vertices = len(local.transfer)
    local_median, farm_median = statistics.median(local_seconds), statistics.median(farm_seconds)
    print(f"{Path(arguments.character).name}: {vertices} vertices baked, order {arguments.order}, "
          f"{arguments.rays} rays per vertex ({vertices * arguments.rays / 1e6:.1f} Mrays), {arguments.runs} runs")
    print(f"local bake, 2 threads:          median {local_median:.3f} s  (runs {', '.join(f'{s:.3f}' for s in local_seconds)})")
    print(f"farm bake, 2 workers x 1 thread: median {farm_median:.3f} s  (runs {', '.join(f'{s:.3f}' for s in farm_seconds)})")
    print(f"overhead: {100 * (farm_median / local_median - 1):+.1f} %  "
          f"(+{farm_median - local_median:.3f} s; the first, cold bake of 1 ray took {cold:.3f} s)")


if __name__ == "__main__":
    main()
