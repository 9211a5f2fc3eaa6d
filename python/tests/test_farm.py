"""thespis.farm: transfer bakes on a Dask LocalCluster (two worker processes on 127.0.0.1) equal
the local bake bit for bit — from a glTF file with tags and from a package, also when a worker is
killed mid-bake — report progress, stop when asked, and name a missing file. Real character:
RobotExpressive from ../shared/data.

Every bake has a time limit (farm.bake's timeout) so that a lost cluster fails the test instead
of hanging it; clusters are closed by their fixtures.
"""

import json
import os
import signal
import time

import numpy as np
import pytest

import thespis
from conftest import SHARED_DATA
from thespis import farm, lighting

import distributed  # noqa: E402  (python3-distributed, which scripts/install-deps.sh installs)
import dask  # noqa: E402  (installed with distributed)

ROBOT = SHARED_DATA / "characters" / "RobotExpressive" / "RobotExpressive.glb"
LIMIT = 120  # seconds for any one farm bake

# Modest settings: a bake of 7336 vertices in well under a second locally.
SETTINGS = dict(order=3, rays=32, seed=5)


def start_cluster():
    return distributed.LocalCluster(n_workers=2, threads_per_worker=1, host="127.0.0.1", processes=True,
                                    dashboard_address=":0")


@pytest.fixture(scope="module")
def client():
    with start_cluster() as cluster, distributed.Client(cluster, set_as_default=False) as client:
        client.wait_for_workers(2, timeout=LIMIT)
        yield client


@pytest.fixture(scope="module")
def robot():
    if not ROBOT.exists():
        pytest.fail(f"missing real test data {ROBOT} (expected ../shared/data beside the repository)")
    return ROBOT


@pytest.fixture(scope="module")
def tagged(robot, tmp_path_factory):
    """RobotExpressive with an occluder (a hole in the bake) and a receiver, from a tags file."""
    segments = lighting.load_bake_character(robot).segments
    tags = tmp_path_factory.mktemp("tags") / "tags.json"
    tags.write_text(json.dumps({segments[1].name: "occluder", segments[3].name: "receiver"}))
    return farm.Character(str(robot), tags=str(tags))


def assert_bit_identical(farmed, local):
    assert farmed.geometry_hash == local.geometry_hash
    assert [s.name for s in farmed.segments] == [s.name for s in local.segments]
    a, b = farmed.transfer, local.transfer
    assert a.dtype == b.dtype == np.float32 and a.shape == b.shape and a.size > 0
    assert a.tobytes() == b.tobytes()
    assert farmed == local


def test_farm_bake_equals_the_local_bake_bit_for_bit(client, tagged, tmp_path):
    reports = []
    out = tmp_path / "farm.prt"
    farmed = farm.bake(tagged, scheduler=client, out=out, progress=lambda done, total: reports.append((done, total)),
                       timeout=LIMIT, **SETTINGS)
    local = lighting.bake(tagged.load(), **SETTINGS)
    assert_bit_identical(farmed, local)
    assert not any(s.baked for s in farmed.segments if s.role == thespis.scene.SegmentRole.OCCLUDER)

    local.save(tmp_path / "local.prt")
    assert out.read_bytes() == (tmp_path / "local.prt").read_bytes()
    assert sorted(os.listdir(tmp_path)) == ["farm.prt", "local.prt"]  # no temporary left

    total = len(local.transfer)
    assert reports[0] == (0, total) and reports[-1] == (total, total)
    assert len(reports) > 3, "progress comes as tasks finish, not only at the end"
    assert all(a[0] < b[0] for a, b in zip(reports, reports[1:]))


def test_scheduler_address_and_package(client, robot, tmp_path):
    # The character of a scenario package, its tags inside: each worker opens the package itself.
    document = thespis.Scenario()
    character = thespis.Character("Robot", "hanim-loa1")
    character.model = str(robot)
    segment = thespis.scene.load_gltf_character(robot).mesh.segments[2].name  # a scenario body's segments
    character.segment_tags = [thespis.scene.SegmentTag(segment, thespis.scene.SegmentRole.OCCLUDER)]
    document.characters = [character]
    package = tmp_path / "robot.thespkg"
    thespis.export_package(document, package, base_dir=tmp_path, scenario_entry="robot.thespis")

    farmed = farm.bake(farm.Character(str(package), character="Robot"), scheduler=client.scheduler.address,
                       timeout=LIMIT, **SETTINGS)
    local = lighting.bake(lighting.load_bake_character(package, character="Robot"), **SETTINGS)
    assert_bit_identical(farmed, local)
    assert not farmed.segments[2].baked


@pytest.mark.parametrize("allowed_failures", [3, 0], ids=["rescheduled-by-dask", "resubmitted-by-farm"])
def test_a_worker_killed_mid_bake_has_its_ranges_baked_elsewhere(robot, allowed_failures):
    # Enough rays for the bake to last a few seconds on two single-thread workers; small tasks,
    # so that the killed worker is busy with one and more are left. With Dask's default the
    # scheduler gives the lost tasks to the other worker; with no failure allowed they come back
    # as KilledWorker and farm.bake submits them again.
    settings = dict(order=3, rays=384, seed=9)
    killed = {}
    with dask.config.set({"distributed.scheduler.allowed-failures": allowed_failures}), start_cluster() as cluster, \
            distributed.Client(cluster, set_as_default=False) as client:
        client.wait_for_workers(2, timeout=LIMIT)
        pids = client.run(os.getpid)

        def kill_a_busy_worker(done, total):
            if killed or done == 0:
                return
            busy = [address for address, keys in client.processing().items() if keys and address in pids]
            assert busy, "no worker is busy: the bake ended too soon to kill one"
            killed.update(address=busy[0], pid=pids[busy[0]], done=done, total=total)
            os.kill(pids[busy[0]], signal.SIGKILL)

        farmed = farm.bake(robot, scheduler=client, progress=kill_a_busy_worker, tasks_per_thread=12,
                           timeout=LIMIT, **settings)
    assert killed, "the bake finished before a worker could be killed"
    assert killed["done"] < killed["total"]
    with pytest.raises(ProcessLookupError):
        os.kill(killed["pid"], 0)
    assert_bit_identical(farmed, lighting.bake(lighting.load_bake_character(robot), **settings))


def test_stop_cancels_the_tasks_and_writes_nothing(client, robot, tmp_path):
    out = tmp_path / "stopped.prt"
    reports = []
    with pytest.raises(thespis.Cancelled):
        farm.bake(robot, scheduler=client, out=out, order=3, rays=2048, tasks_per_thread=8, timeout=LIMIT,
                  progress=lambda done, total: reports.append(done), stop=lambda: len(reports) >= 2)
    assert not out.exists() and list(tmp_path.iterdir()) == []
    # Cancelled tasks leave the workers: nothing is processing shortly after.
    deadline = time.monotonic() + 30
    while any(client.processing().values()) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert not any(client.processing().values())


def test_a_missing_file_is_named(client, tmp_path):
    missing = tmp_path / "nobody.glb"
    with pytest.raises(FileNotFoundError, match="nobody.glb"):
        farm.bake(missing, scheduler=client, timeout=LIMIT, **SETTINGS)


def test_an_unreachable_scheduler_is_named(robot):
    with pytest.raises(OSError, match="127.0.0.1:9"):
        farm.bake(robot, scheduler="tcp://127.0.0.1:9", timeout=3, **SETTINGS)


def test_tasks_cover_every_baked_vertex_once(tagged):
    plan = lighting.plan_bake(tagged.load(), lighting.BakeSettings(**SETTINGS))
    tasks = farm.split_tasks(plan, threads=2)
    ranges = [r for task in tasks for r in task]
    baked = [(s.first_vertex, s.vertex_count) for s in plan.segments if s.baked]
    assert sum(count for _, count in ranges) == sum(count for _, count in baked)
    # Ranges stay inside their segments and follow the transfer's order.
    covered = sorted(ranges)
    for (first, count), (next_first, _) in zip(covered, covered[1:]):
        assert first + count <= next_first
    assert 4 <= len(tasks) <= 2 * farm.TASKS_PER_THREAD + len(baked)
