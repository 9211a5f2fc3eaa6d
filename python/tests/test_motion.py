"""thespis.motion on the real CMU clips: postures, the posture PCA (eq. 1), the rest categories,
an idle database and the idle blendable, the dependent-joint filter with the shipped bases, and
the training job — NumPy in, NumPy out."""

import math

import numpy as np
import pytest

import thespis
from thespis import motion
from conftest import RESOURCES, mocap


def postures(name, **options):
    return motion.postures_of(mocap(f"cmu/{name}.bvh"), **options)


def test_postures_round_trip_through_frames():
    skeleton = thespis.hanim.skeleton(thespis.hanim.Level.subset25)
    upper = motion.PostureMap(skeleton, motion.PostureSet.upper_body)
    wave = postures("141_16", set=motion.PostureSet.upper_body, rate=10, skip=1)
    assert wave.shape[1] == motion.posture_size(motion.PostureSet.upper_body) == 45
    frames = upper.to_frames(wave)
    np.testing.assert_allclose(upper.to_postures(frames), wave, atol=1e-4)
    assert motion.posture_joints(motion.PostureSet.whole_body)[0] == "humanoid_root"


def test_pca_distance_is_eq1_and_reconstruction_is_exact_with_every_pc():
    data = np.vstack([postures("113_21", skip=2), postures("141_16", skip=1), postures("02_01")])
    basis = motion.PostureBasis.train(motion.PostureSet.whole_body, data)
    assert basis.dimension == 78 and basis.sample_count == len(data)
    assert np.all(np.diff(basis.eigenvalues) <= 0)
    pcs = basis.project(data)
    np.testing.assert_allclose(basis.reconstruct(pcs), data, atol=1e-4)
    assert basis.explained_variance(5) < basis.explained_variance(20) <= 1.0
    covariance = np.cov(data.astype(np.float64), rowvar=False)
    d = data[3] - data[-3]
    assert basis.distance(pcs[3], pcs[-3], 78) == pytest.approx(math.sqrt(d @ covariance @ d), rel=1e-3)
    assert basis.distance(pcs[3], pcs[-3], 5) <= basis.distance(pcs[3], pcs[-3], 78)


def test_rest_categories_follow_the_weight():
    standing = postures("113_21", skip=2)
    categories = motion.rest_categories(standing)
    assert set(np.unique(categories)) == {0, 1, 2}
    sideways = standing[:, 75]  # the root over the feet: + is the body's left
    assert sideways[categories == 0].mean() > sideways[categories == 1].mean() > sideways[categories == 2].mean()


def test_an_idle_database_plays_as_idle_motion(tmp_path):
    db = motion.build_idle([("77_02", postures("77_02", frame_rate=60, skip=2)),
                            ("111_28", postures("111_28", skip=6))])
    assert db.categories == ["left", "both", "right"] and db.transition_count >= 10
    assert {t["source"] for t in db.transitions} == {"77_02", "111_28"}
    db.save(tmp_path / "standing.idle")
    again = motion.load_idle_database(tmp_path / "standing.idle")
    skeleton = thespis.hanim.skeleton(thespis.hanim.Level.loa1)
    idle = motion.idle(again, skeleton, seed=4)
    assert math.isinf(idle.domain.end)
    times = np.linspace(0, 30, 301)
    forward = idle.sample(times)
    backward = motion.idle(again, skeleton, seed=4).sample(times[::-1])[::-1]
    np.testing.assert_array_equal(forward, backward)
    assert np.abs(np.diff(forward, axis=0)).max() > 1e-3  # it moves
    damaged = bytearray((tmp_path / "standing.idle").read_bytes())
    damaged[len(damaged) // 3] ^= 1
    (tmp_path / "damaged.idle").write_bytes(bytes(damaged))
    with pytest.raises(thespis.FormatError, match="damaged"):
        motion.load_idle_database(tmp_path / "damaged.idle")


def test_the_filter_lets_the_spine_follow_a_keyed_arm():
    bases = motion.load_bases(RESOURCES / "motion" / "cmu_postures.pca")
    skeleton = thespis.hanim.skeleton(thespis.hanim.Level.subset25)
    upper = motion.PostureMap(skeleton, motion.PostureSet.upper_body)
    posture = np.zeros(45, dtype=np.float32)
    shoulder = motion.posture_joints(motion.PostureSet.upper_body).index("r_shoulder")
    posture[3 * shoulder + 2] = -1.2  # the right arm raised sideways, nothing else keyed
    frame = upper.to_frames(posture)
    clip = thespis.KeyframeClip(skeleton.frame_layout, 30.0, np.vstack([frame, frame]))
    filtered = motion.dependent_joint_filter(clip, skeleton, bases.upper).evaluate(0.0)
    after = upper.to_postures(filtered)
    pcs_before, pcs_after = bases.upper.project(posture), bases.upper.project(after)
    assert (pcs_after[20:] ** 2).sum() < 0.5 * (pcs_before[20:] ** 2).sum()  # faded from PC 20
    assert (pcs_after[30:] ** 2).sum() < 1e-8  # muted above 30
    spine = [motion.posture_joints(motion.PostureSet.upper_body).index(j) for j in ("vt6", "vt1", "vc4")]
    assert max(np.abs(after[3 * j:3 * j + 3]).max() for j in spine) > 0.01
    with pytest.raises(ValueError):
        motion.dependent_joint_filter(clip, skeleton, bases.whole)


def test_train_writes_the_bases_and_reports_progress(tmp_path):
    reports = []
    bases = motion.train([mocap("cmu/113_21.bvh"), mocap("cmu/141_16.bvh")], tmp_path / "p.pca", rate=15, skip=1,
                         progress=lambda done, total: reports.append((done, total)))
    assert (tmp_path / "p.pca").read_bytes().startswith(b"THSPPCA\0")
    assert bases.whole.dimension == 78 and bases.upper.dimension == 45
    assert reports and all(done <= total or total == 0 for done, total in reports)
    np.testing.assert_array_equal(motion.load_bases(tmp_path / "p.pca").whole.mean, bases.whole.mean)


def test_idle_from_the_library_as_an_edit(tmp_path):
    """What dropping "Idle" on a body track does in the studio, from Python: the shipped database
    plays on a new character, which then stands and moves."""
    from thespis import edit
    scenario = thespis.Scenario()
    edit.add_character(scenario, edit.new_character("Walker")).apply(scenario)
    database = str(RESOURCES / "motion" / "cmu_standing.idle")
    edit.add_idle_action(scenario, (0, 0), database, thespis.seconds_to_ticks(1.0)).apply(scenario)
    clip = scenario.characters[0].clips[-1]
    assert clip.name == "idle" and clip.idle.database == database and clip.idle.seed == 1
    assert scenario.characters[0].layers[0].actions[-1].clip == "idle"
    with pytest.raises(ValueError, match="body layer"):
        edit.add_idle_action(scenario, (0, 1), database)
    walker = thespis.build_runtime(scenario, tmp_path).characters[0]
    frames = np.array([walker.evaluate_body(t) for t in (5.0, 6.0, 30.0)])
    assert np.abs(frames[0] - frames[1]).max() > 1e-3 and np.abs(frames[0] - frames[2]).max() > 1e-3
