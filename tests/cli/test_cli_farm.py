"""thespis-cli bake --scheduler: the bake on a running Dask cluster (a LocalCluster of two worker
processes on 127.0.0.1, scheduler on a free port) writes the local bake's file byte for byte,
draws the same progress, and Ctrl-C cancels it without a file. Real character: RobotExpressive.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data; PYTHONPATH (CTest sets
it) lets the workers import the thespis package.
"""

import json
import os
import signal
import subprocess
import time
from pathlib import Path

import pytest

from thespis import lighting

import distributed  # noqa: E402  (python3-distributed, which scripts/install-deps.sh installs)

CLI = os.environ.get("THESPIS_CLI")
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", Path(__file__).resolve().parents[3] / "shared" / "data"))
ROBOT = DATA / "characters" / "RobotExpressive" / "RobotExpressive.glb"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

INVALID, CANCELLED = 3, 130
LIMIT = 120  # seconds for any one command


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=LIMIT)


@pytest.fixture(scope="module")
def cluster():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, host="127.0.0.1", scheduler_port=0,
                                  processes=True, dashboard_address=":0") as cluster, \
            distributed.Client(cluster, set_as_default=False) as client:
        client.wait_for_workers(2, timeout=LIMIT)
        yield cluster, client


@pytest.fixture(scope="module")
def robot():
    if not ROBOT.exists():
        pytest.fail(f"missing real test data {ROBOT} (expected ../shared/data beside the repository)")
    return ROBOT


def test_the_farm_bake_writes_the_local_bake_byte_for_byte(cluster, robot, tmp_path):
    address = cluster[0].scheduler_address
    segments = lighting.load_bake_character(robot).segments
    tags = tmp_path / "tags.json"
    tags.write_text(json.dumps({segments[2].name: "occluder", segments[4].name: "receiver"}))
    common = [robot, "--order", 3, "--rays", 48, "--seed", 3, "--tags", tags]

    farm = run("bake", *common, "--scheduler", address, "--out", tmp_path / "farm.prt")
    assert farm.returncode == 0, farm.stderr
    local = run("bake", *common, "--out", tmp_path / "local.prt")
    assert local.returncode == 0, local.stderr

    assert (tmp_path / "farm.prt").read_bytes() == (tmp_path / "local.prt").read_bytes()
    assert f"on the Dask cluster at {address}" in farm.stdout
    assert farm.stdout.splitlines()[0] == local.stdout.splitlines()[0]  # "Baked dsm transfer of …: N vertices, …"
    # The same progress lines as the local bake (stderr is not a terminal here).
    lines = [line for line in farm.stderr.splitlines() if line.startswith("bake: ")]
    assert len(lines) > 2 and lines[-1].endswith("(100%)"), farm.stderr


def test_ctrl_c_cancels_the_farm_bake_without_writing(cluster, robot, tmp_path):
    address, client = cluster[0].scheduler_address, cluster[1]
    out = tmp_path / "cancelled.prt"
    # Many rays on two single-thread workers: seconds of work, so the interrupt finds it running.
    process = subprocess.Popen([CLI, "bake", str(robot), "--rays", "8192", "--scheduler", address, "--out", str(out)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        first = process.stderr.readline()
        assert first.startswith("bake: "), first
        process.send_signal(signal.SIGINT)
        stdout, stderr = process.communicate(timeout=LIMIT)
    finally:
        process.kill()
    assert process.returncode == CANCELLED, stderr
    assert "cancelled" in stderr and "was not written" in stderr
    assert list(tmp_path.iterdir()) == []
    assert "Baked" not in stdout
    # The cluster's tasks were cancelled with it.
    deadline = time.monotonic() + 30
    while any(client.processing().values()) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert not any(client.processing().values())


def test_a_missing_character_is_named_before_the_cluster_is_asked(cluster, tmp_path):
    result = run("bake", tmp_path / "nobody.glb", "--scheduler", cluster[0].scheduler_address,
                 "--out", tmp_path / "x.prt")
    assert result.returncode == INVALID and "nobody.glb" in result.stderr
    assert not (tmp_path / "x.prt").exists()


def test_help_names_the_scheduler_option():
    result = run("bake", "--help")
    assert result.returncode == 0
    assert "--scheduler tcp://HOST:PORT" in result.stdout
