"""thespis.lighting and thespis.scene from Python: SH evaluation and rotation, irradiance, probe
projection on real probes, loading a real glTF character, and the transfer bake (progress,
cancel by Ctrl-C, determinism, bake files)."""

import math
import os
import signal
import threading
from pathlib import Path

import numpy as np
import pytest

import thespis
from thespis import lighting, scene

DATA = Path(os.environ.get("THESPIS_SHARED_DATA", Path(__file__).resolve().parents[3] / "shared" / "data"))
ROBOT = DATA / "characters" / "RobotExpressive" / "RobotExpressive.glb"
CESIUM = DATA / "characters" / "CesiumMan" / "CesiumMan.glb"
PROBE_HDR = DATA / "probes" / "polyhaven_1k" / "royal_esplanade_1k.hdr"
PROBE_EXR = DATA / "probes" / "blender_studiolights" / "courtyard.exr"


def need(path):
    if not path.exists():
        pytest.fail(f"{path} is missing (../shared/data)")
    return path


def random_unit_quaternion(rng):
    q = rng.normal(size=4)
    return tuple(q / np.linalg.norm(q))


def rotate(q, v):
    x, y, z, w = q
    u = np.array([x, y, z])
    t = 2 * np.cross(u, v)
    return v + w * t + np.cross(u, t)


# --- spherical harmonics ------------------------------------------------------------------------

def test_band_one_is_the_graphics_convention():
    c = math.sqrt(3 / (4 * math.pi))
    d = np.array([0.2, -0.3, 0.9])
    d /= np.linalg.norm(d)
    y = lighting.sh_evaluate(2, d)
    assert y.shape == (4,)
    assert y[0] == pytest.approx(0.5 / math.sqrt(math.pi), abs=1e-15)
    assert y[lighting.sh_index(1, -1)] == pytest.approx(c * d[1], abs=1e-14)
    assert y[lighting.sh_index(1, 0)] == pytest.approx(c * d[2], abs=1e-14)
    assert y[lighting.sh_index(1, 1)] == pytest.approx(c * d[0], abs=1e-14)


def test_many_directions_at_once_match_one_by_one():
    rng = np.random.default_rng(3)
    directions = rng.normal(size=(50, 3))
    values = lighting.sh_evaluate(11, directions)
    assert values.shape == (50, 121)
    for i in (0, 17, 49):
        assert np.allclose(values[i], lighting.sh_evaluate(11, directions[i]), atol=1e-14)


def test_rotation_turns_the_function():
    rng = np.random.default_rng(7)
    order = 6
    coefficients = rng.normal(size=order * order)
    q = random_unit_quaternion(rng)
    rotated = lighting.ShRotation(order, q).apply(coefficients)
    q_inverse = (-q[0], -q[1], -q[2], q[3])
    for d in rng.normal(size=(20, 3)):
        d /= np.linalg.norm(d)
        # f'(ω) = f(R⁻¹ω)
        expected = lighting.sh_evaluate(order, rotate(q_inverse, d)) @ coefficients
        assert lighting.sh_evaluate(order, d) @ rotated == pytest.approx(expected, abs=1e-10)


def test_rotation_bands_are_orthonormal_and_rgb_rows_rotate_alike():
    rotation = lighting.ShRotation(5, random_unit_quaternion(np.random.default_rng(1)))
    for band in range(5):
        m = rotation.band(band)
        assert m.shape == (2 * band + 1, 2 * band + 1)
        assert np.allclose(m @ m.T, np.eye(2 * band + 1), atol=1e-12)
    rgb = np.random.default_rng(2).normal(size=(3, 25))
    out = rotation.apply(rgb)
    for c in range(3):
        assert np.allclose(out[c], rotation.apply(rgb[c]))
    with pytest.raises(ValueError, match="order"):
        rotation.apply(np.zeros(16))
    with pytest.raises(ValueError, match="order"):
        lighting.ShRotation(12, (0, 0, 0, 1))


def test_irradiance_of_constant_light_is_pi_times_radiance():
    radiance = np.zeros(9)
    radiance[0] = 2 * math.sqrt(math.pi)  # L(ω) = 1 everywhere
    irradiance = lighting.irradiance_from_radiance(radiance)
    assert irradiance[0] * 0.5 / math.sqrt(math.pi) == pytest.approx(math.pi, rel=1e-12)
    assert [lighting.clamped_cosine_kernel(l) for l in range(5)] == pytest.approx(
        [math.pi, 2 * math.pi / 3, math.pi / 4, 0, -math.pi / 24], abs=1e-15)


# --- probes -------------------------------------------------------------------------------------

def test_real_probes_read_and_project():
    for path in (need(PROBE_HDR), need(PROBE_EXR)):
        pixels = lighting.read_hdr(path)
        assert pixels.ndim == 3 and pixels.shape[2] == 3 and pixels.shape[1] == 2 * pixels.shape[0]
        assert np.isfinite(pixels).all() and pixels.min() >= 0
        light = lighting.project_probe(path, lighting.ProbeLayout.LATLONG, 3)
        assert light.shape == (3, 9)
        assert (light[:, 0] > 0).all()  # some light arrives
        assert np.allclose(lighting.project_image(pixels, lighting.ProbeLayout.LATLONG, 3), light)


def test_probe_errors_are_clear(tmp_path):
    with pytest.raises(FileNotFoundError):
        lighting.read_hdr(tmp_path / "missing.hdr")
    junk = tmp_path / "junk.hdr"
    junk.write_bytes(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 4\n\x02")
    with pytest.raises(thespis.FormatError, match="junk.hdr"):
        lighting.read_hdr(junk)
    with pytest.raises(ValueError, match="layout|angular"):
        lighting.parse_probe_layout("fisheye")


def test_hdr_write_read_round_trip(tmp_path):
    pixels = np.random.default_rng(5).uniform(0.01, 50, size=(8, 16, 3)).astype(np.float32)
    lighting.write_hdr(tmp_path / "x.hdr", pixels)
    again = lighting.read_hdr(tmp_path / "x.hdr")
    assert again.shape == pixels.shape
    # RGBE shares one exponent per pixel: 8 bits of mantissa relative to the brightest channel.
    brightest = pixels.max(axis=2, keepdims=True)
    assert (np.abs(again - pixels) <= brightest / 128).all()


# --- characters and the bake --------------------------------------------------------------------

@pytest.fixture(scope="module")
def robot():
    return scene.load_gltf_mesh(need(ROBOT))


def test_robot_loads_with_segments(robot):
    assert robot.vertex_count > 1000 and len(robot.segments) > 5
    assert robot.positions.shape == (robot.vertex_count, 3)
    assert np.allclose(np.linalg.norm(robot.normals, axis=1), 1, atol=1e-4)
    assert robot.triangles.max() < robot.vertex_count
    covered = sum(s.vertex_count for s in robot.segments)
    assert covered == robot.vertex_count
    robot.validate()


def test_tags_apply_by_name_or_fail_whole(robot):
    mesh = scene.load_gltf_mesh(need(ROBOT))
    name = mesh.segments[1].name
    mesh.apply_tags([scene.SegmentTag(name, scene.SegmentRole.RECEIVER)])
    assert mesh.find_segment(name).role == scene.SegmentRole.RECEIVER
    with pytest.raises(ValueError, match="nobody"):
        mesh.apply_tags([scene.SegmentTag(mesh.segments[2].name, scene.SegmentRole.OCCLUDER),
                         scene.SegmentTag("nobody")])
    assert mesh.segments[2].role == scene.SegmentRole.NONE  # nothing applied


def test_bake_reports_progress_and_is_thread_independent(robot, tmp_path):
    reports = []
    one = lighting.bake(robot, order=3, rays=16, transfer="ds", threads=1, progress=lambda d, t: reports.append((d, t)))
    two = lighting.bake(robot, order=3, rays=16, transfer="ds", threads=2)
    assert one == two
    assert reports and reports[-1] == (robot.vertex_count, robot.vertex_count)
    assert all(a[0] <= b[0] for a, b in zip(reports, reports[1:]))
    assert one.transfer.shape == (robot.vertex_count, 9)
    one.save(tmp_path / "robot.prt")
    assert lighting.TransferBake.load(tmp_path / "robot.prt") == one


def test_shadowed_transfer_is_darker_than_unshadowed(robot):
    light = lighting.project_probe(need(PROBE_HDR), lighting.ProbeLayout.LATLONG, 3)
    du = lighting.bake(robot, order=3, rays=64, transfer="du").shade(robot, light)
    dsm = lighting.bake(robot, order=3, rays=64, transfer="dsm").shade(robot, light)
    assert du.shape == (robot.vertex_count, 3)
    assert dsm.sum() < du.sum()


def test_bad_settings_raise_value_error(robot):
    with pytest.raises(ValueError, match="glossy|transfer"):
        lighting.bake(robot, transfer="glossy")
    with pytest.raises(ValueError, match="order"):
        lighting.bake(robot, order=0)
    with pytest.raises(ValueError, match="ray"):
        lighting.bake(robot, rays=0)


def test_ctrl_c_cancels_the_bake(robot):
    # SIGINT arrives while the workers bake (many rays, one thread): KeyboardInterrupt, no result.
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            lighting.bake(robot, order=5, rays=65536, threads=1)
    finally:
        timer.cancel()


def test_an_exception_in_progress_stops_the_bake(robot):
    def stop(done, total):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        lighting.bake(robot, order=5, rays=65536, threads=1, progress=stop)


def test_corrupt_bake_file_is_refused(robot, tmp_path):
    path = tmp_path / "robot.prt"
    lighting.bake(robot, order=2, rays=4, transfer="du").save(path)
    data = bytearray(path.read_bytes())
    data[len(data) // 2] ^= 0xFF
    path.write_bytes(bytes(data))
    with pytest.raises(thespis.FormatError):
        lighting.TransferBake.load(path)


def test_split_cesium_man_by_joint():
    whole = scene.load_gltf_mesh(need(CESIUM), split_skinned_by_joint=False)
    split = scene.load_gltf_mesh(need(CESIUM))
    assert len(whole.segments) == 1 and len(split.segments) > 5
    assert split.triangle_count == whole.triangle_count
